"""Fits of the number variance sigma^2_N(R) (Klatt & Torquato 2016, Sec. VI B, Fig. 10).

Two models, linear in their parameters, fitted over R >= R_min (the paper
fits only radii where f_R(N) is close to Gaussian, R > 1.5 D):

* ``"b2_b3"``: sigma^2 = b2 R^2 + b3 R^3 (non-hyperuniform: leading R^3);
* ``"b2"``:    sigma^2 = b2 R^2          (hyperuniform, surface-area scaling).

Conventions of :mod:`randmedia.fit`, adapted to a pooled estimator: the
number variance at large R has fewer throws per sample than there are samples
(one window per sample at R = h_w, Sec. VI B), so it cannot be fitted sample
by sample. The curve is the pooled estimate over all samples; the fit is
weighted by its jackknife SEM (chi^2/dof is reported; neighbouring radii share
windows, so their errors are correlated and chi^2/dof < 1 is expected); the
parameter errors are delete-one-sample jackknife errors of the refitted
parameters (each refit uses the pooled curve without one sample), which
carries the sample-to-sample variation like the per-sample convention.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from randmedia.describe.points import pooled_number_variance

MODELS = {"b2_b3": (2, 3), "b2": (2,)}


@dataclass(frozen=True)
class NumberVarianceFit:
    model: str
    names: tuple[str, ...]
    values: tuple[float, ...]
    errors: tuple[float, ...]
    chi2_per_dof: float
    n_points: int
    r_min: float


def _design(R, model):
    return np.stack([R**p for p in MODELS[model]], axis=1)


def _weighted_lstsq(R, y, sem, model):
    A = _design(R, model) / sem[:, None]
    coef, *_ = np.linalg.lstsq(A, y / sem, rcond=None)
    return coef


def fit_number_variance(R, n_throws, sum_N, sum_N2, *, model: str, r_min: float,
                        length: float = 1.0) -> NumberVarianceFit:
    """Fit ``model`` to the pooled number variance of per-sample window moments.

    ``n_throws``, ``sum_N``, ``sum_N2`` have shape (n_samples, n_radii); ``R``
    the radii. ``length`` is the unit the coefficients refer to (e.g. lambda:
    b2 in units of lambda^-2 when the fit is in R / lambda).

    Parameters
    ----------
    R : array_like
        Window radii, shape (n_radii,).
    n_throws : array_like
        Windows thrown per sample and radius, shape (n_samples, n_radii), n_samples >= 3.
    sum_N : array_like
        Sum of the window counts N, same shape.
    sum_N2 : array_like
        Sum of N^2, same shape.
    model : str
        ``"b2_b3"`` or ``"b2"`` (module docstring).
    r_min : float
        Smallest radius fitted (unit of ``R``).
    length : float
        Length unit of the coefficients (default 1: the unit of ``R``).

    Returns
    -------
    NumberVarianceFit
        Coefficients with jackknife errors, chi2_per_dof, points used and r_min.
    """
    if model not in MODELS:
        raise ValueError(f"model must be one of {sorted(MODELS)}, got {model!r}")
    R = np.asarray(R, dtype=float) / length
    n, s1, s2 = (np.asarray(a, dtype=float) for a in (n_throws, sum_N, sum_N2))
    if n.ndim != 2 or n.shape[0] < 3:
        raise ValueError("need per-sample moments of at least 3 samples, shape (n_samples, n_radii)")
    _, var, _, var_sem = pooled_number_variance(n, s1, s2)
    keep = (R >= r_min / length) & np.isfinite(var_sem) & (var_sem > 0)
    n_par = len(MODELS[model])
    if keep.sum() <= n_par:
        raise ValueError(f"fewer than {n_par + 1} radii with R >= {r_min:g} and a finite SEM")
    coef = _weighted_lstsq(R[keep], var[keep], var_sem[keep], model)
    residual = (var[keep] - _design(R[keep], model) @ coef) / var_sem[keep]
    chi2 = float(residual @ residual / (keep.sum() - n_par))
    # delete-one-sample jackknife of the refitted parameters
    k = n.shape[0]
    refits = []
    for drop in range(k):
        nn, a, b = n.sum(0) - n[drop], s1.sum(0) - s1[drop], s2.sum(0) - s2[drop]
        with np.errstate(invalid="ignore", divide="ignore"):
            v = (b - a * a / nn) / (nn - 1)
        refits.append(_weighted_lstsq(R[keep], v[keep], var_sem[keep], model))
    refits = np.array(refits)
    errors = np.sqrt((k - 1) / k * ((refits - refits.mean(0)) ** 2).sum(0))
    names = tuple(f"b{p}" for p in MODELS[model])
    return NumberVarianceFit(model, names, tuple(map(float, coef)), tuple(map(float, errors)),
                             chi2, int(keep.sum()), float(r_min))


def evaluate(fit: NumberVarianceFit, R, length: float = 1.0) -> np.ndarray:
    """The fitted polynomial at radii R (same ``length`` unit as the fit).

    Parameters
    ----------
    fit : NumberVarianceFit
        A result of :func:`fit_number_variance`.
    R : array_like
        Radii, shape (n,).
    length : float
        The ``length`` the fit was made with (default 1).

    Returns
    -------
    numpy.ndarray
        sigma^2_N at ``R``, shape (n,).
    """
    return _design(np.asarray(R, dtype=float) / length, fit.model) @ np.asarray(fit.values)
