"""Scaled-particle approximations of the void statistics of equilibrium hard disks and spheres.

Sources: Torquato, *Random Heterogeneous Materials* (Springer 2002), Ch. 5 (void
nearest-neighbour functions E_V, H_V, G_V and the pore-size functions); Torquato,
PRE 51, 3170 (1995) (scaled-particle forms of G_V for hard d-dimensional spheres);
Ma & Torquato 2020, Eqs. 40-41 (hard disks); Klatt & Torquato 2016, Eqs. 17, 20, 21
and Sec. V (hard spheres: F(delta), <delta>, <delta^2>, the dashed curve of Fig. 7).

Definitions. Identical particles of diameter D = 2R, packing fraction phi, number density
rho; x = r / D.
  * E_V(r): probability that a d-ball of radius r centred at a random point contains no
    particle centre (the "exclusion probability" of the centres, mrj2016 Sec. II B 1).
  * H_V(r) = -dE_V/dr = rho s1(r) G_V(r) E_V(r), s1(r) = d v1(1) r^(d-1): G_V(r) is the
    mean density of centres at distance r from such an empty ball, divided by rho.
  * Pore sizes (the matrix around the particles): a point of the matrix at distance r > R
    from the nearest centre has pore size delta = r - R, so
    F(delta) = E_V(R + delta) / (1 - phi)  (mrj2016 Eq. 20),
    P(delta) = -dF/d delta = H_V(R + delta) / (1 - phi),
    <delta> = int_0^inf F, <delta^2> = 2 int_0^inf delta F  (mrj2016 Eq. 17 ff.).

Exact for x <= 1/2 (two centres are at least D apart, so a ball of radius r <= R holds at
most one centre): E_V = 1 - rho v1(r) = 1 - phi (2x)^d (mrj2016 Eq. 21; R there is the
particle radius) and G_V = 1 / (1 - phi (2x)^d).

Scaled-particle approximation for x >= 1/2 (Torquato 1995): G_V is a polynomial of degree
d - 1 in 1/x,
    G_V(x) = a_0 + a_1 / x + ... + a_{d-1} / x^(d-1),
whose coefficients satisfy
    (i)   continuity at x = 1/2:  G_V(1/2) = 1 / (1 - phi);
    (ii)  contact:                G_V(1) = g(D+) -- exact, since an empty ball of radius D
          is the region a test particle of diameter D excludes;
    (iii) (d = 3 only, the third coefficient) the large-cavity limit G_V(x -> inf) = a_0 =
          beta p / rho, the reversible work p v1(r) of a macroscopic cavity;
with g(D+) and beta p / rho from an accurate equation of state
(:mod:`randmedia.theory.hard_spheres`). With Carnahan-Starling, (i)-(iii) give exactly
Torquato's 3D coefficients a_0 = (1 + phi + phi^2 - phi^3)/(1 - phi)^3,
a_1 = phi (3 phi^2 - 4 phi - 3) / (2 (1 - phi)^3), a_2 = phi^2 (2 - phi) / (2 (1 - phi)^3)
(tested). In 2D, (i)-(ii) with g(D+) = (1 - c phi)/(1 - phi)^2 give
a_0 = (1 + (1 - 2c) phi) / (1 - phi)^2, a_1 = -(1 - c) phi / (1 - phi)^2; Henderson's
EOS (the 2D default) has c = 7/16 (a_0 = (1 + phi/8)/(1 - phi)^2, a_1 = -(9/16) phi/(1 - phi)^2);
the rounded c = 0.436 (a_0 = (1 + 0.128 phi)/(1 - phi)^2, a_1 = -0.564 phi/(1 - phi)^2) can be
passed as ``contact=`` and changes P(delta) at phi = 0.3 by less than 0.2 % for delta <= 2R.

Integrating H_V / E_V = rho s1 G_V with rho s1(r) dr = 2^d d phi x^(d-1) dx from x = 1/2:
    E_V(x) = (1 - phi) exp{ -2^d d phi sum_k a_k [x^(d-k) - 2^-(d-k)] / (d - k) }.
For d = 2 this is Ma & Torquato's Eq. (41),
    P(delta) = (4 phi2 / R) (a_0 x + a_1) exp[-phi2 (4 a_0 x^2 + 8 a_1 x + a_2)],
    x = delta / (2R) + 1/2,  a_2 = -(a_0 + 4 a_1),
where a_2 is fixed by F(0) = 1; then P(0) = 2 phi2 / (R (1 - phi2)) = s / phi1 with the
specific surface s = 2 phi2 / R (Eq. 40) -- both tested. In d dimensions s = d phi / R
(:func:`randmedia.theory.hard_spheres.specific_surface`).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import quad

from randmedia.numerics.checks import check_dim, check_fraction, check_positive
from randmedia.theory.hard_spheres import DEFAULT_EOS, compressibility_factor, contact_value


def gv_coefficients(phi: float, dim: int, eos: str | None = None, *, contact: float | None = None,
                    pressure: float | None = None) -> np.ndarray:
    """(a_0, ..., a_{d-1}) of G_V(x) = sum_k a_k x^-k for x >= 1/2 (module docstring).

    ``contact`` (g(D+)) and, for d = 3, ``pressure`` (beta p / rho) override the values of
    the equation of state ``eos`` (default: Henderson in 2D, Kolafa in 3D).

    Parameters
    ----------
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    eos : str or None
        Equation of state of :mod:`randmedia.theory.hard_spheres`; None: its default for ``dim``.
    contact : float or None
        g(D+) to use instead of the equation of state's.
    pressure : float or None
        beta p / rho to use instead of the equation of state's (d = 3 only; ignored in 2D).

    Returns
    -------
    numpy.ndarray
        Shape (dim,): a_0, ..., a_{d-1}.
    """
    check_dim(dim)
    check_fraction(phi, "packing fraction")
    eos = eos or DEFAULT_EOS[dim]
    g = contact_value(phi, dim, eos) if contact is None else float(contact)
    rows = [[2.0**k for k in range(dim)], [1.0] * dim]  # G_V(1/2), G_V(1)
    rhs = [1.0 / (1.0 - phi), g]
    if dim == 3:
        z = compressibility_factor(phi, dim, eos) if pressure is None else float(pressure)
        rows.append([1.0, 0.0, 0.0])
        rhs.append(z)
    return np.linalg.solve(np.array(rows), np.array(rhs))


def _cumulative(x, phi, dim, a):
    """2^d d phi int_{1/2}^{x} x'^(d-1) G_V(x') dx' for x >= 1/2."""
    x = np.asarray(x, dtype=float)
    total = np.zeros_like(x)
    for k, coefficient in enumerate(a):
        p = dim - k
        total = total + coefficient * (x**p - 0.5**p) / p
    return 2.0**dim * dim * phi * total


def exclusion_probability(r, phi: float, dim: int, diameter: float = 1.0, eos: str | None = None,
                          **overrides) -> np.ndarray:
    """E_V(r) of the centres: exact 1 - phi (2r/D)^d for r <= D/2, scaled-particle beyond.

    Parameters
    ----------
    r : float or array_like
        Radii of the empty ball, >= 0 (length unit of ``diameter``).
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D, > 0 (default 1).
    eos : str or None
        Equation of state; None: the default for ``dim``.
    **overrides
        ``contact=``, ``pressure=`` passed to :func:`gv_coefficients`.

    Returns
    -------
    numpy.ndarray
        E_V(r), same shape as ``r``.
    """
    check_positive(diameter, "diameter")
    a = gv_coefficients(phi, dim, eos, **overrides)
    x = np.asarray(r, dtype=float) / diameter
    if np.any(x < 0):
        raise ValueError("distances must be >= 0")
    inner = 1.0 - phi * (2.0 * np.minimum(x, 0.5)) ** dim
    outer = (1.0 - phi) * np.exp(-_cumulative(np.maximum(x, 0.5), phi, dim, a))
    return np.where(x <= 0.5, inner, outer)


def gv(r, phi: float, dim: int, diameter: float = 1.0, eos: str | None = None, **overrides):
    """G_V(r): exact 1/(1 - phi (2x)^d) for x <= 1/2, the polynomial in 1/x beyond.

    Parameters
    ----------
    r : float or array_like
        Radii of the empty ball (length unit of ``diameter``).
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D (default 1).
    eos : str or None
        Equation of state; None: the default for ``dim``.
    **overrides
        ``contact=``, ``pressure=`` passed to :func:`gv_coefficients`.

    Returns
    -------
    numpy.ndarray
        G_V(r), same shape as ``r``.
    """
    a = gv_coefficients(phi, dim, eos, **overrides)
    x = np.asarray(r, dtype=float) / diameter
    safe = np.maximum(x, 0.5)
    outer = sum(coefficient * safe ** (-k) for k, coefficient in enumerate(a))
    return np.where(x <= 0.5, 1.0 / (1.0 - phi * (2.0 * np.minimum(x, 0.5)) ** dim), outer)


def pore_size_ccdf(delta, phi: float, dim: int, diameter: float = 1.0, eos: str | None = None,
                   **overrides) -> np.ndarray:
    """F(delta) = E_V(R + delta) / (1 - phi), delta >= 0 (mrj2016 Eq. 20).

    Parameters
    ----------
    delta : float or array_like
        Pore sizes, >= 0 (length unit of ``diameter``).
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D = 2R (default 1).
    eos : str or None
        Equation of state; None: the default for ``dim``.
    **overrides
        ``contact=``, ``pressure=`` passed to :func:`gv_coefficients`.

    Returns
    -------
    numpy.ndarray
        F(delta), same shape as ``delta``.
    """
    delta = np.asarray(delta, dtype=float)
    if np.any(delta < 0):
        raise ValueError("pore sizes must be >= 0")
    return exclusion_probability(delta + diameter / 2.0, phi, dim, diameter, eos,
                                 **overrides) / (1.0 - phi)


def pore_size_density(delta, phi: float, dim: int, diameter: float = 1.0, eos: str | None = None,
                      **overrides) -> np.ndarray:
    """P(delta) = rho s1(R + delta) G_V E_V / (1 - phi) (Eq. 41 for d = 2).

    Parameters
    ----------
    delta : float or array_like
        Pore sizes, >= 0 (length unit of ``diameter``).
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D = 2R (default 1).
    eos : str or None
        Equation of state; None: the default for ``dim``.
    **overrides
        ``contact=``, ``pressure=`` passed to :func:`gv_coefficients`.

    Returns
    -------
    numpy.ndarray
        P(delta) (1/length), same shape as ``delta``.
    """
    delta = np.asarray(delta, dtype=float)
    r = delta + diameter / 2.0
    x = r / diameter
    rho_s1 = 2.0**dim * dim * phi * x ** (dim - 1) / diameter
    return rho_s1 * gv(r, phi, dim, diameter, eos, **overrides) * pore_size_ccdf(
        delta, phi, dim, diameter, eos, **overrides)


def pore_size_moments(phi: float, dim: int, diameter: float = 1.0, eos: str | None = None,
                      **overrides) -> tuple[float, float]:
    """(<delta>, <delta^2>) = (int F, 2 int delta F) by adaptive quadrature.

    Parameters
    ----------
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D (default 1).
    eos : str or None
        Equation of state; None: the default for ``dim``.
    **overrides
        ``contact=``, ``pressure=`` passed to :func:`gv_coefficients`.

    Returns
    -------
    tuple of float
        (<delta>, <delta^2>) in units of D and D^2 (length of ``diameter``).
    """
    def ccdf(delta):
        return float(pore_size_ccdf(delta, phi, dim, diameter, eos, **overrides))

    first = quad(ccdf, 0.0, np.inf, epsabs=1e-12, epsrel=1e-10)[0]
    second = 2.0 * quad(lambda d: d * ccdf(d), 0.0, np.inf, epsabs=1e-12, epsrel=1e-10)[0]
    return first, second


# --------------------------------------------------------------------------- Ma & Torquato Eq. 41


def eq41_coefficients(phi2: float, eos: str | None = None, **overrides) -> tuple[float, float, float]:
    """(a_0, a_1, a_2) of debye2020 Eq. (41): a_0, a_1 of G_V and a_2 = -(a_0 + 4 a_1)."""
    a0, a1 = gv_coefficients(phi2, 2, eos, **overrides)
    return float(a0), float(a1), float(-(a0 + 4.0 * a1))


def eq41_pore_size_density(delta, phi2: float, radius: float, eos: str | None = None,
                           **overrides) -> np.ndarray:
    """debye2020 Eq. (41) as printed: P(delta) = (4 phi2/R)(a_0 x + a_1)
    exp[-phi2 (4 a_0 x^2 + 8 a_1 x + a_2)], x = delta/(2R) + 1/2.

    Parameters
    ----------
    delta : float or array_like
        Pore sizes (length unit of ``radius``).
    phi2 : float
        Area fraction of the hard disks, in (0, 1).
    radius : float
        Disk radius R.
    eos : str or None
        2D equation of state; None: Henderson.
    **overrides
        ``contact=`` passed to :func:`gv_coefficients`.

    Returns
    -------
    numpy.ndarray
        P(delta) (1/length), same shape as ``delta``.
    """
    a0, a1, a2 = eq41_coefficients(phi2, eos, **overrides)
    x = np.asarray(delta, dtype=float) / (2.0 * radius) + 0.5
    return 4.0 * phi2 / radius * (a0 * x + a1) * np.exp(-phi2 * (4 * a0 * x**2 + 8 * a1 * x + a2))
