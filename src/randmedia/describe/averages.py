"""Mean and standard error over samples of per-sample descriptor curves that are
undefined (NaN) in some samples: a k bin empty in some cells, radii beyond a
sample's range. Any ensemble of samples; the plain (NaN-free) SEM is
:func:`randmedia.stats.standard_error`."""

from __future__ import annotations

import numpy as np

from randmedia.stats import standard_error


def nan_mean_sem(values):
    """Mean and standard error over axis 0 ignoring NaN (e.g. a k bin empty in some cells);
    the SEM is NaN where fewer than two samples have a value. Without NaN this is
    exactly the mean and :func:`randmedia.stats.standard_error`."""
    values = np.asarray(values, dtype=float)
    valid = np.isfinite(values)
    if valid.all():
        return values.mean(axis=0), standard_error(values, axis=0)
    count = valid.sum(axis=0)
    filled = np.where(valid, values, 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = filled.sum(axis=0) / count
        var = (np.where(valid, values - mean, 0.0) ** 2).sum(axis=0) / (count - 1)
        sem = np.sqrt(var / count)
    sem = np.where(count >= 2, sem, np.nan)
    # +-inf (e.g. F_ss at r = 0) stays as the mean where all samples agree
    infinite = np.isinf(values).all(axis=0) & (np.sign(values) == np.sign(values[:1])).all(axis=0)
    mean = np.where(infinite, values[0] if values.shape[0] else np.nan, mean)
    sem = np.where(infinite, 0.0, sem)
    return mean, sem
