"""Exact descriptors of overlapping disks and spheres (the Boolean model), d = 2 and 3.

Centres form a Poisson point process of intensity rho; the d-balls of radius R
are phase 2, their complement is the void (matrix) phase 1. With the reduced
density eta = rho v1(R), v1 = omega_d R^d (omega_d: volume of the unit d-ball,
Ma & Torquato 2020, Eq. 8; omega_d, v1 and rho = eta / v1 are those of
:mod:`randmedia.theory.balls`):

* phi1 = exp(-eta)                                  (Ma & Torquato 2020, Sec. VI A)
* S2^(1)(r) = exp(-rho v2(r; R))                    Eq. (32); v2 = union volume,
  Eq. (33) for d = 2, Torquato, *Random Heterogeneous Materials* (RHM) Eq. (3.16)
  v2/v1 = 1 + (3/4)(r/R) - (1/16)(r/R)^3 for d = 3, both = 2 for r >= 2R.
* s = rho |dB_R| phi1 = d eta phi1 / R              Eq. (34) (d = 2: 2 eta phi1 / R;
  d = 3, D = 2R: 6 phi1 ln(1/phi1) / D, Klatt & Torquato 2016 Sec. III A)

Surface functions (void = phase 1). A point x of the interface lies on the
sphere of one centre c (|x - c| = R) and in no other ball; Poisson
independence gives

* F_sv(r) = (s / phi1) f_out(r) S2^(1)(r)           Eq. (35) for d = 2
  where f_out(r) is the fraction of the sphere |x - c| = R lying outside the
  ball of radius R about x + r: with x = r/(2R) < 1, d = 2: 1 - arccos(x)/pi;
  d = 3: (1 + x)/2; 1 for r >= 2R. (x + r must avoid c's own ball.)
* F_ss(r) = S2^(1)(r) { [(s/phi1) f_out(r)]^2 + rho J(r) }      Eq. (36) for d = 2
  where rho J(r) is the density of centres at distance R from both points,
  J(r) = integral delta(|c| - R) delta(|c - r| - R) dc = (d-1) omega_{d-1}
  (R sin t)^(d-2) R / (r sin t), cos t = r/(2R): d = 2: 2R / (r sqrt(1 - x^2));
  d = 3: 2 pi R^2 / r; 0 for r >= 2R. As r -> 0, F_ss -> rho J phi1 =
  (d-1) omega_{d-1} s / (d omega_d r), the divergence of Ma & Torquato 2020 Sec. II B.

Pore sizes, exclusion probability, lineal path, chords:

* F(delta) = exp(-eta [(1 + delta/R)^d - 1]), P = -dF/ddelta    Eq. (37) for d = 2
* E_V(r) = exp(-rho omega_d r^d)  (the centres are Poisson)      Klatt & Torquato Eq. (20)
* L(z) = phi1^(1 + omega_{d-1} z / (omega_d R))                  Eq. (38) for d = 2
* p(z) = lambda exp(-lambda z), lambda = eta omega_{d-1} / (omega_d R),
  mean chord 1/lambda = pi phi1/s (d = 2), 4 phi1/s (d = 3)       Eqs. (39), (20)
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad

from randmedia.numerics.checks import check_dim, check_fraction, check_positive
from randmedia.theory.balls import poisson_intensity, unit_ball_volume


def reduced_density(phi2: float) -> float:
    """eta = rho v1 = -ln(phi1), from the volume fraction phi2 of the balls."""
    check_fraction(phi2)
    return -math.log1p(-phi2)


def union_volume_ratio(r, radius: float, dim: int = 2) -> np.ndarray:
    """v2(r; R) / v1(R): union of two d-balls of radius R, centres r apart (Eq. 33 for d=2).

    Parameters
    ----------
    r : float or array_like
        Centre separations, >= 0 (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        v2/v1, in [1, 2], same shape as ``r``.
    """
    r = np.asarray(r, dtype=float)
    check_dim(dim)
    check_positive(radius, "radius")
    if np.any(r < 0):
        raise ValueError("distances must be >= 0")
    overlapping = r < 2.0 * radius
    if dim == 2:
        x = np.clip(r / (2.0 * radius), 0.0, 1.0)
        inside = (2.0 / np.pi) * (np.pi + x * np.sqrt(1.0 - x * x) - np.arccos(x))
    else:
        y = r / radius
        inside = 1.0 + 0.75 * y - y**3 / 16.0
    return np.where(overlapping, inside, 2.0)


def s2_void(r, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """Eq. (32): S2 of the void phase, exp(-eta v2/v1) with eta = -ln(1 - phi2).

    Parameters
    ----------
    r : float or array_like
        Distances between the two points, >= 0 (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        S2 of the void phase 1, same shape as ``r``.
    """
    check_positive(radius, "radius")
    check_fraction(phi2)
    return np.exp(-reduced_density(phi2) * union_volume_ratio(r, radius, dim))


def specific_surface(radius: float, phi2: float, dim: int) -> float:
    """Eq. (34): s = d eta phi1 / R.

    Parameters
    ----------
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        s, interface measure per unit volume (1/length).
    """
    check_dim(dim)
    check_positive(radius, "radius")
    check_fraction(phi2)
    return dim * reduced_density(phi2) * (1.0 - phi2) / radius


def _fraction_outside(r, radius: float, dim: int) -> np.ndarray:
    """f_out(r): fraction of a radius-R sphere about x outside the radius-R ball about x + r."""
    x = np.clip(np.asarray(r, dtype=float) / (2.0 * radius), 0.0, 1.0)
    if dim == 2:
        return 1.0 - np.arccos(x) / np.pi
    return 0.5 * (1.0 + x)


def _two_sphere_density(r, radius: float, dim: int) -> np.ndarray:
    """J(r) = integral delta(|c| - R) delta(|c - r| - R) dc; 0 for r >= 2R (diverges at r = 0,
    and for d = 2 also at r = 2R)."""
    r = np.asarray(r, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        if dim == 2:
            x = r / (2.0 * radius)
            value = 2.0 * radius / (r * np.sqrt(1.0 - x * x))
        else:
            value = 2.0 * np.pi * radius**2 / r
    return np.where(r < 2.0 * radius, value, 0.0)


def surface_void(r, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """F_sv(r) with the void (matrix) phase 1 (Eq. 35 for d = 2); F_sv(0) = s/2, F_sv(inf) = s phi1.

    Parameters
    ----------
    r : float or array_like
        Distances between the two points, >= 0 (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        F_sv(r) (1/length), same shape as ``r``.
    """
    check_dim(dim)
    s_over_phi1 = specific_surface(radius, phi2, dim) / (1.0 - phi2)
    return s_over_phi1 * _fraction_outside(r, radius, dim) * s2_void(r, radius, phi2, dim)


def surface_surface(r, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """F_ss(r) (Eq. 36 for d = 2); F_ss(inf) = s^2, diverges as r -> 0 (and at r = 2R in 2D).

    Parameters
    ----------
    r : float or array_like
        Distances between the two points, >= 0 (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        F_ss(r) (1/length^2), same shape as ``r``; inf at r = 0.
    """
    check_dim(dim)
    s_over_phi1 = specific_surface(radius, phi2, dim) / (1.0 - phi2)
    rho = poisson_intensity(phi2, radius, dim)
    pair = (s_over_phi1 * _fraction_outside(r, radius, dim)) ** 2
    return s2_void(r, radius, phi2, dim) * (pair + rho * _two_sphere_density(r, radius, dim))


def pore_size_complementary_cdf(delta, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """F(delta) = exp(-eta [(1 + delta/R)^d - 1]) (RHM Ch. 5; integral of Eq. 37).

    Parameters
    ----------
    delta : float or array_like
        Pore sizes, >= 0 (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        F(delta), same shape as ``delta``.
    """
    check_dim(dim)
    check_positive(radius, "radius")
    check_fraction(phi2)
    delta = np.asarray(delta, dtype=float)
    if np.any(delta < 0):
        raise ValueError("pore sizes must be >= 0")
    return np.exp(-reduced_density(phi2) * ((1.0 + delta / radius) ** dim - 1.0))


def pore_size_density(delta, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """P(delta) = -dF/ddelta = (d eta / R)(1 + delta/R)^(d-1) F(delta)   (Eq. 37 for d = 2).

    Parameters
    ----------
    delta : float or array_like
        Pore sizes, >= 0 (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        P(delta) (1/length), same shape as ``delta``.
    """
    F = pore_size_complementary_cdf(delta, radius, phi2, dim)
    eta = reduced_density(phi2)
    return dim * eta / radius * (1.0 + np.asarray(delta, float) / radius) ** (dim - 1) * F


def pore_size_moment(n: int, radius: float, phi2: float, dim: int = 2) -> float:
    """<delta^n> = n integral delta^(n-1) F(delta) ddelta (Eq. 18), by adaptive quadrature.

    Parameters
    ----------
    n : int
        Moment order, >= 1.
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    float
        <delta^n>, in units of length^n.
    """
    if n < 1:
        raise ValueError(f"moment order must be >= 1, got {n}")
    value, _ = quad(lambda d: n * d ** (n - 1) * pore_size_complementary_cdf(d, radius, phi2, dim),
                    0.0, np.inf, epsabs=0.0, epsrel=1e-11, limit=200)
    return float(value)


def exclusion_probability(r, rho: float, dim: int = 3) -> np.ndarray:
    """E_V(r) = exp(-rho omega_d r^d): no Poisson centre within r of a random point.

    Parameters
    ----------
    r : float or array_like
        Radii of the test ball.
    rho : float
        Number density of the Poisson centres, > 0 (1/length^d).
    dim : int
        Dimension d, 2 or 3 (default 3).

    Returns
    -------
    numpy.ndarray
        E_V(r), same shape as ``r``.
    """
    check_dim(dim)
    if rho <= 0:
        raise ValueError(f"rho must be > 0, got {rho}")
    return np.exp(-rho * unit_ball_volume(dim) * np.asarray(r, dtype=float) ** dim)


def chord_rate(radius: float, phi2: float, dim: int = 2) -> float:
    """lambda = eta omega_{d-1} / (omega_d R): inverse mean chord of the void phase.

    Parameters
    ----------
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    float
        lambda (1/length).
    """
    check_dim(dim)
    check_positive(radius, "radius")
    check_fraction(phi2)
    return reduced_density(phi2) * unit_ball_volume(dim - 1) / (unit_ball_volume(dim) * radius)


def lineal_path_void(z, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """L(z) = phi1 exp(-lambda z) = phi1^(1 + omega_{d-1} z / (omega_d R))   (Eq. 38 for d = 2).

    Parameters
    ----------
    z : float or array_like
        Segment lengths (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        L(z) of the void phase, same shape as ``z``.
    """
    z = np.asarray(z, dtype=float)
    return (1.0 - phi2) * np.exp(-chord_rate(radius, phi2, dim) * z)


def chord_density_void(z, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """p(z) = lambda exp(-lambda z)   (Eq. 39 for d = 2); mean chord 1/lambda (Eq. 20).

    Parameters
    ----------
    z : float or array_like
        Chord lengths (length unit of ``radius``).
    radius : float
        Radius R of the balls, > 0.
    phi2 : float
        Volume fraction of the balls (phase 2), in (0, 1).
    dim : int
        Dimension d, 2 or 3 (default 2).

    Returns
    -------
    numpy.ndarray
        p(z) (1/length), same shape as ``z``.
    """
    rate = chord_rate(radius, phi2, dim)
    return rate * np.exp(-rate * np.asarray(z, dtype=float))
