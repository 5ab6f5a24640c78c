"""Curve fits with uncertainties for the papers' empirical formulas.

One module per paper or descriptor (:mod:`randmedia.fit.debye2020`, ...); the
shared conventions live here. A parameter's value and error come from fitting
every sample separately and taking the mean and standard error over samples
(:func:`per_sample_mean`); a fit weighted by the SEM of the sample-mean curve
gives chi^2 per degree of freedom as the goodness of fit. Points of a
sample-mean curve are correlated (they come from the same images), so
chi^2/dof below 1 is expected.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from randmedia.stats import standard_error


@dataclass(frozen=True)
class FitResult:
    value: float
    error: float
    chi2_per_dof: float
    n_points: int


def per_sample_mean(fits: list[FitResult]) -> tuple[float, float]:
    """Mean of per-sample fitted values and its standard error over samples."""
    values = np.array([f.value for f in fits])
    if values.size < 2:
        raise ValueError("need at least two samples for a standard error")
    return float(values.mean()), float(standard_error(values))
