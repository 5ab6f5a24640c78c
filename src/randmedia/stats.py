"""Statistics over independent samples, shared by every estimator and comparison."""

from __future__ import annotations

import numpy as np


def standard_error(values, axis: int = 0):
    """Standard error of the mean over ``axis`` (ddof = 1); NaN where there is one sample."""
    values = np.asarray(values, dtype=float)
    n = values.shape[axis]
    if n < 2:
        return np.full(np.delete(values.shape, axis), np.nan) if values.ndim > 1 else np.nan
    return values.std(axis=axis, ddof=1) / np.sqrt(n)
