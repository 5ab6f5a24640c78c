"""Semianalytic and empirical formulas of Debye random media (Ma & Torquato 2020, Sec. V).

The specific surface (Eq. 22 in 2D, 4 phi1 phi2 / a in 3D); Eqs. (24)-(25): F_sv;
Eq. (26): F_ss; the specific Euler characteristic that Eq. (24) implies through Eq. (13);
Eq. (27): the pore-size density, its cumulative form and mean (Eq. 28) with the cubic
p1(phi2) quoted after Eq. (27). The target two-point function (Eq. 21) lives in
:mod:`randmedia.theory.debye`, which the construction depends on; these formulas are kept
apart so that editing them does not invalidate constructed media. Also
:func:`model_specific_surface`, the exact s of the paper's three models (Eqs. 22, 34, 40).
"""

from __future__ import annotations

import numpy as np

from randmedia.numerics.checks import check_dim, check_fraction, check_positive

#: s = c_d phi1 phi2 / a from Eq. (7) (S2'(0) = -s/pi in 2D, -s/4 in 3D) and Eq. (21)
SURFACE_COEFFICIENT = {2: np.pi, 3: 4.0}
#: F_ss ~ s / (c r) as r -> 0 (c = pi in 2D, 2 in 3D): the pair term of Eqs. (26) and (45) is
#: PAIR_COEFFICIENT phi1 phi2 e^{-r/a} / (a r)
PAIR_COEFFICIENT = {2: 1.0, 3: 2.0}


def debye_specific_surface(a: float, phi2: float, dim: int = 2) -> float:
    """Specific surface of Debye random media: Eq. (22) in 2D, s = pi phi1 phi2 / a (from
    Eq. 7, S2'(0) = -s/pi, with Eq. 21); in 3D 4 phi1 phi2 / a (Eq. 7 with S2'(0) = -s/4;
    Sec. VII).

    Parameters
    ----------
    a : float
        Correlation length of Eq. (21), > 0.
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    dim : int, optional
        Dimension, 2 or 3.

    Returns
    -------
    float
        s (1/length).
    """
    check_fraction(phi2)
    check_positive(a, "a")
    check_dim(dim)
    return SURFACE_COEFFICIENT[dim] * phi2 * (1.0 - phi2) / a


def debye_surface_void(r, phi2: float, a: float, dim: int = 2) -> np.ndarray:
    """Eqs. (24)-(25): F_sv(r) = s (1 - phi2 + phi2 e^{-r/a}) / (1 + e^{-r/a}), s of Eq. (22);
    F_sv(0) = s/2, F_sv(inf) = s phi1 (void = phase 1). In 3D (``dim=3``) the conjecture
    Eq. (44), (4 phi2 / a) S2^(1)(r) / (1 + e^{-r/a}), which is the same form with the 3D s.

    Parameters
    ----------
    r : float or array_like
        Distances (same length unit as ``a``).
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    a : float
        Correlation length of Eq. (21), > 0.
    dim : int, optional
        Dimension, 2 (Eq. 24) or 3 (Eq. 44).

    Returns
    -------
    numpy.ndarray
        F_sv(r) (units 1/length), same shape as ``r``.
    """
    check_fraction(phi2)
    check_positive(a, "a")
    decay = np.exp(-np.asarray(r, dtype=float) / a)
    return debye_specific_surface(a, phi2, dim) * (1.0 - phi2 + phi2 * decay) / (1.0 + decay)


def debye_surface_surface(r, phi2: float, a: float, dim: int = 2) -> np.ndarray:
    """Eq. (26): F_ss(r) = (pi^2/a^2) phi1^2 phi2^2 + phi1 phi2 e^{-r/a} / (a r)
    + e^{-r/a} |phi2 - phi1| / (2 a^2 (1 + e^{-r/a})); diverges as s/(pi r) at r -> 0.
    In 3D (``dim=3``) the conjecture Eq. (45): (16/a^2) phi1^2 phi2^2 + 2 phi1 phi2
    e^{-r/a} / (a r) + the same last term; s^2 at large r, s/(2 r) at r -> 0.

    Parameters
    ----------
    r : float or array_like
        Distances (same length unit as ``a``); r = 0 gives inf.
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    a : float
        Correlation length of Eq. (21), > 0.
    dim : int, optional
        Dimension, 2 (Eq. 26) or 3 (Eq. 45).

    Returns
    -------
    numpy.ndarray
        F_ss(r) (units 1/length^2), same shape as ``r``.
    """
    check_fraction(phi2)
    check_positive(a, "a")
    check_dim(dim)
    r = np.asarray(r, dtype=float)
    q = phi2 * (1.0 - phi2)
    decay = np.exp(-r / a)
    with np.errstate(divide="ignore"):
        pair = PAIR_COEFFICIENT[dim] * q * decay / (a * r)
    return ((SURFACE_COEFFICIENT[dim] * q / a) ** 2 + pair
            + decay / (1.0 + decay) * abs(1.0 - 2.0 * phi2) / (2.0 * a * a))


def debye_euler_characteristic(phi2: float, a: float) -> float:
    """Specific Euler characteristic from Eq. (24) and Eq. (13): dF_sv/dr at r = 0,
    pi (phi1 - phi2) phi1 phi2 / (4 a^2) (Sec. V A)."""
    check_fraction(phi2)
    check_positive(a, "a")
    phi1 = 1.0 - phi2
    return np.pi * (phi1 - phi2) * phi1 * phi2 / (4.0 * a * a)


#: coefficients c1, c2, c3 of p1 = (c1 phi2 + c2 phi2^2 + c3 phi2^3) / a^2 quoted after Eq. (27)
P1_COEFFICIENTS = (1.05, -2.41, 4.16)


def pore_p1(phi2, a: float, coefficients=P1_COEFFICIENTS):
    """p1 of Eq. (27) from the cubic (c1 phi2 + c2 phi2^2 + c3 phi2^3) / a^2.

    Parameters
    ----------
    phi2 : float or array_like
        Volume fraction(s) of phase 2.
    a : float
        Correlation length of Eq. (21).
    coefficients : tuple of float
        (c1, c2, c3) of the cubic; default :data:`P1_COEFFICIENTS` (the paper's fit).

    Returns
    -------
    float or numpy.ndarray
        p1 (units 1/length^2), shape of ``phi2``.
    """
    phi2 = np.asarray(phi2, dtype=float)
    c1, c2, c3 = coefficients
    return (c1 * phi2 + c2 * phi2**2 + c3 * phi2**3) / (a * a)


def pore_size_ccdf(delta, p1: float, p2: float) -> np.ndarray:
    """F(delta) = exp(-p1 delta^2 - p2 delta): the complementary cumulative distribution whose
    density -dF/ddelta is Eq. (27) with p0 = p2 (the only normalized choice, F(0) = 1).

    Parameters
    ----------
    delta : float or array_like
        Pore sizes (length).
    p1 : float
        Quadratic coefficient of the exponent (1/length^2).
    p2 : float
        Linear coefficient of the exponent (1/length).

    Returns
    -------
    numpy.ndarray
        F(delta), same shape as ``delta``.
    """
    delta = np.asarray(delta, dtype=float)
    return np.exp(-p1 * delta * delta - p2 * delta)


def pore_size_density(delta, p0: float, p1: float, p2: float) -> np.ndarray:
    """Eq. (27): P(delta) = (p0 + 2 p1 delta) exp(-p1 delta^2 - p2 delta).

    Parameters
    ----------
    delta : float or array_like
        Pore sizes (length).
    p0 : float
        Prefactor of Eq. (27) (1/length); p0 = p2 normalizes the density.
    p1 : float
        Quadratic coefficient of the exponent (1/length^2).
    p2 : float
        Linear coefficient of the exponent (1/length).

    Returns
    -------
    numpy.ndarray
        P(delta) (units 1/length), same shape as ``delta``.
    """
    delta = np.asarray(delta, dtype=float)
    return (p0 + 2.0 * p1 * delta) * np.exp(-p1 * delta * delta - p2 * delta)


def mean_pore_size(p1: float, p2: float) -> float:
    """<delta> = integral F = sqrt(pi / p1)/2 exp(p2^2 / (4 p1)) erfc(p2 / (2 sqrt(p1))) for
    Eq. (27) with p0 = p2 (Eq. 18); with p2 = pi phi2 / a and p1 of the cubic this is Eq. (28).
    Evaluated as sqrt(pi/p1)/2 * erfcx(.) to stay finite for small p1."""
    from scipy.special import erfcx

    if p1 <= 0:
        raise ValueError(f"p1 must be > 0, got {p1}")
    x = p2 / (2.0 * np.sqrt(p1))
    return float(0.5 * np.sqrt(np.pi / p1) * erfcx(x))


def debye_mean_pore_size(phi2: float, a: float, coefficients=P1_COEFFICIENTS) -> float:
    """Eq. (28): <delta> with p2 = pi phi2 / a and p1 from the cubic in phi2.

    Parameters
    ----------
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    a : float
        Correlation length of Eq. (21), > 0.
    coefficients : tuple of float
        (c1, c2, c3) of the p1 cubic; default :data:`P1_COEFFICIENTS`.

    Returns
    -------
    float
        Mean pore size <delta>, in the length unit of ``a``.
    """
    check_fraction(phi2)
    check_positive(a, "a")
    return mean_pore_size(float(pore_p1(phi2, a, coefficients)), np.pi * phi2 / a)


def model_specific_surface(model: str, *, phi2: float, a: float | None = None,
                           radius: float | None = None) -> float:
    """Exact s of the three models of Ma & Torquato 2020 (units of 1/length of a or R):
    ``"debye"`` Eq. (22), ``"overlapping_disks"`` Eq. (34), ``"hard_disks"`` Eq. (40).

    Parameters
    ----------
    model : str
        ``"debye"``, ``"overlapping_disks"`` or ``"hard_disks"``.
    phi2 : float
        Volume fraction of phase 2 (the disks for the disk models), in (0, 1).
    a : float or None
        Correlation length; required for ``"debye"``, ignored otherwise.
    radius : float or None
        Disk radius R; required for the two disk models, ignored for ``"debye"``.

    Returns
    -------
    float
        Specific surface s (interface length per unit area in 2D).
    """
    from randmedia.theory import hard_spheres, overlapping

    if model not in ("debye", "overlapping_disks", "hard_disks"):
        raise ValueError(f"unknown model {model!r}; expected debye, overlapping_disks or hard_disks")
    length = a if model == "debye" else radius
    if length is None:
        raise ValueError(f"model {model!r} needs {'a' if model == 'debye' else 'radius'}")
    if model == "debye":
        return debye_specific_surface(a, phi2)
    if model == "overlapping_disks":
        return overlapping.specific_surface(radius, phi2, dim=2)
    if model == "hard_disks":
        return hard_spheres.specific_surface(radius, phi2, 2)
    raise ValueError(f"unknown model {model!r}; expected debye, overlapping_disks or hard_disks")
