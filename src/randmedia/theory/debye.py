"""Debye random media: the target two-point statistics (Ma & Torquato 2020, Sec. III).

Eq. (21): chi_V(r) = phi1 phi2 exp(-r / a), so the two-point function of
phase 2 is S2(r) = phi2^2 + phi1 phi2 exp(-r / a). With Eq. (7),
S2'(0) = -s / pi in two dimensions, Eq. (22) gives s = pi phi1 phi2 / a
(:func:`randmedia.theory.debye_formulas.debye_specific_surface`, which the construction does
not need).
"""

from __future__ import annotations

import numpy as np

from randmedia.numerics.checks import check_fraction, check_positive


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
    check_fraction(phi2)
    check_positive(a, "a")
    r = np.asarray(r, dtype=float)
    return phi2 * phi2 + phi2 * (1.0 - phi2) * np.exp(-r / a)
