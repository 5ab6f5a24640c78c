"""Debye random media: the target two-point statistics (Ma & Torquato 2020, Sec. III).

Eq. (21): chi_V(r) = phi1 phi2 exp(-r / a), so the two-point function of
phase 2 is S2(r) = phi2^2 + phi1 phi2 exp(-r / a). With Eq. (7),
S2'(0) = -s / pi in two dimensions, Eq. (22) gives s = pi phi1 phi2 / a.
"""

from __future__ import annotations

import numpy as np


def debye_s2(r, phi2: float, a: float) -> np.ndarray:
    """S2 of phase 2 of Debye random media, Eq. (21): phi2^2 + phi1 phi2 exp(-r/a).

    Parameters
    ----------
    r : float or array_like
        Distances (same length unit as ``a``).
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    a : float
        Correlation length of Eq. (21), > 0.

    Returns
    -------
    numpy.ndarray
        S2(r) of phase 2, same shape as ``r``.
    """
    if not 0.0 < phi2 < 1.0:
        raise ValueError(f"phi2 must lie in (0, 1), got {phi2}")
    if a <= 0:
        raise ValueError(f"a must be > 0, got {a}")
    r = np.asarray(r, dtype=float)
    return phi2 * phi2 + phi2 * (1.0 - phi2) * np.exp(-r / a)


def debye_specific_surface(phi2: float, a: float) -> float:
    """Eq. (22) in 2D: s = pi phi1 phi2 / a (from Eq. 7, S2'(0) = -s/pi)."""
    return np.pi * phi2 * (1.0 - phi2) / a
