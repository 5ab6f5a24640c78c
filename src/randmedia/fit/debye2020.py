"""Fits of Ma & Torquato, PRE 102, 043310 (2020): the lineal-path size L_w (Eq. 29)
and <R^2>/<R> (Eq. 30). Conventions (per-sample fits, SEM, chi^2/dof): :mod:`randmedia.fit`.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import curve_fit

from randmedia.fit import FitResult


def lineal_path_length(z, lineal_path, phi1: float, sem=None, *,
                       min_fraction: float = 0.01) -> FitResult:
    """L_w of Ma & Torquato 2020, Eq. (29): L(z) = phi1 exp(-z / L_w), phi1 fixed.

    Fitted over the z with L(z) >= ``min_fraction`` * phi1 (beyond, the curve is
    dominated by the few longest chords). With ``sem`` the fit is weighted and
    its error statistical; without, unweighted (error from the residuals) and
    chi2_per_dof is NaN.
    """
    z, lineal_path = np.asarray(z, dtype=float), np.asarray(lineal_path, dtype=float)
    weighted = sem is not None
    sem = np.asarray(sem, dtype=float) if weighted else np.ones_like(lineal_path)
    keep = (lineal_path >= min_fraction * phi1) & (sem > 0)
    if keep.sum() < 3:
        raise ValueError("fewer than 3 points with L(z) above the fit threshold")
    guess = -z[keep][-1] / np.log(lineal_path[keep][-1] / phi1) if z[keep][-1] > 0 else 1.0

    def model(x, length):
        return phi1 * np.exp(-x / length)

    (length,), covariance = curve_fit(model, z[keep], lineal_path[keep], p0=[guess],
                                      sigma=sem[keep] if weighted else None,
                                      absolute_sigma=weighted)
    residual = (lineal_path[keep] - model(z[keep], length)) / sem[keep]
    dof = max(1, keep.sum() - 1)
    chi2 = float(residual @ residual / dof) if weighted else float("nan")
    return FitResult(float(length), float(np.sqrt(covariance[0, 0])), chi2, int(keep.sum()))


def r2_over_r(lineal_length: float, phi1: float) -> float:
    """<R^2>/<R> of overlapping polydisperse disks with the same L_w (Eq. 30):
    L_w = -pi / (2 ln phi1) <R^2>/<R>."""
    return -2.0 * np.log(phi1) * lineal_length / np.pi
