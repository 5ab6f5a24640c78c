"""Closed forms for spherical-cap windows on the sphere of radius R (sphere2019, Sec. II).

A spherical cap of *base radius* a (0 < a <= R, upper hemisphere only, as in the
paper) has angular radius phi = arcsin(a / R) and area

    s(a) = 2 pi R^2 [1 - sqrt(1 - (a/R)^2)] = 4 pi R^2 sin^2(phi/2)        (Sec. II)

* :func:`cap_intersection_fraction`: alpha2(x; a), the area common to two caps
  whose centres lie a geodesic distance x = R psi apart, divided by s(a), Eq. (9)
  (Brauchart et al.):

      alpha2 = 1 - [arcsin(sin(psi/2)/sin phi) - arcsin(tan(psi/2)/tan phi) cos phi]
                   / (pi sin^2(phi/2))         for psi <= 2 phi, 0 otherwise.

  (The prefactor is 1/(pi sin^2(phi/2)); checked against a Monte Carlo estimate
  of the intersection in tests/test_sphere_theory.py.) As R -> infinity at fixed
  x and a it tends to the Euclidean disk-intersection fraction of Torquato &
  Stillinger (:func:`disk_intersection_fraction`).
* :func:`uniform_variance`: Eq. (6), canonical (N fixed) uncorrelated points,
  sigma^2 = rho s (1 - s / (4 pi R^2)) = rho pi a^2 exactly.
* :func:`poisson_variance`: Eq. (7), grand canonical uncorrelated points,
  sigma^2 = <rho> s.
* :func:`variance_from_g2`: Eq. (4) (canonical) and Eq. (5) (grand canonical) from a
  binned geodesic pair correlation function g2(x); the integral over the sphere
  int g2(x) alpha2(x; a) dA, dA = 2 pi R sin(x/R) dx, is evaluated with g2
  constant on each bin and alpha2 integrated exactly (Gauss-Legendre, split at the
  kink x = 2 R phi) over the bin (:func:`cap_intersection_weights`). With g2 = 1
  the weights sum to s(a) (the identity used below Eq. 6) and Eq. (4) reduces to
  Eq. (6).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit



def _positive(value, what: str) -> float:
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{what} must be a finite number > 0, got {value!r}") from None
    if isinstance(value, bool) or not (number > 0 and math.isfinite(number)):
        raise ValueError(f"{what} must be a finite number > 0, got {value!r}")
    return number


def check_radius(radius: float) -> None:
    _positive(radius, "sphere radius R")


def check_density(rho: float) -> None:
    _positive(rho, "number density rho")


def check_base_radius(a, radius: float) -> np.ndarray:
    """``a`` as an array, after checking 0 <= a <= R (caps of the upper hemisphere only)."""
    check_radius(radius)
    a = np.asarray(a, dtype=float)
    if np.any(~np.isfinite(a)) or np.any(a < 0):
        raise ValueError("cap base radius a must be finite and >= 0")
    if np.any(a > radius * (1 + 1e-12)):
        raise ValueError(f"cap base radius a = {float(np.max(a)):g} exceeds R = {radius:g}: the "
                         "paper's caps cover at most a hemisphere (0 <= phi <= pi/2, a <= R)")
    return np.minimum(a, radius)


def cap_grid(radius: float, n_a: int) -> np.ndarray:
    """Cap base radii a_k = R k / n_a, k = 1..n_a."""
    check_radius(radius)
    if not (isinstance(n_a, (int, np.integer)) and n_a >= 2):
        raise ValueError(f"number of cap radii n_a must be an integer >= 2, got {n_a!r}")
    return radius * np.arange(1, n_a + 1) / n_a


def cos_thresholds(a, radius: float) -> np.ndarray:
    """cos(phi) = sqrt(1 - (a/R)^2) for increasing a: a point p lies in the cap of base radius
    a about the unit vector c iff p.c / R >= cos(phi)."""
    a = check_base_radius(a, radius)
    if np.any(np.diff(a) <= 0):
        raise ValueError("cap radii must increase")
    return np.sqrt(np.clip(1.0 - (a / radius) ** 2, 0.0, 1.0))


@njit(cache=True)
def first_cap_containing(thresholds, value):
    """Index of the smallest cap holding a point with p.c / R = ``value``: the first k with
    ``thresholds[k] <= value`` for the decreasing :func:`cos_thresholds` (bisection), or
    ``thresholds.size`` if it lies in none. A histogram of these indices, summed cumulatively,
    gives the counts in every cap of the grid at once."""
    lo, hi = 0, thresholds.size
    while lo < hi:
        mid = (lo + hi) // 2
        if thresholds[mid] <= value:
            hi = mid
        else:
            lo = mid + 1
    return lo


def cap_angle(a, radius: float) -> np.ndarray:
    """Angular radius phi = arcsin(a / R) of the cap of base radius a."""
    a = check_base_radius(a, radius)
    return np.arcsin(a / radius)


def cap_area(a, radius: float) -> np.ndarray:
    """s(a) = 2 pi R^2 (1 - sqrt(1 - (a/R)^2)), written as 4 pi R^2 sin^2(phi/2) (no cancellation)."""
    phi = cap_angle(a, radius)
    return 4.0 * np.pi * radius**2 * np.sin(phi / 2.0) ** 2


def cap_intersection_fraction(x, a, radius: float) -> np.ndarray:
    """alpha2(x; a) of Eq. (9): intersection area of two caps of base radius a whose centres
    are a geodesic distance x apart, over s(a). Broadcasts over x and a.

    Parameters
    ----------
    x : float or array_like
        Geodesic distances between the cap centres, in [0, pi R].
    a : float or array_like
        Cap base radii, 0 <= a <= R (broadcast against ``x``).
    radius : float
        Sphere radius R, > 0 (same length unit as ``x`` and ``a``).

    Returns
    -------
    numpy.ndarray
        alpha2 in [0, 1], of the broadcast shape of ``x`` and ``a``.
    """
    check_radius(radius)
    phi = cap_angle(a, radius)
    x = np.asarray(x, dtype=float)
    if np.any(x < 0) or np.any(x > np.pi * radius * (1 + 1e-12)):
        raise ValueError(f"geodesic distances must lie in [0, pi R] = [0, {np.pi * radius:g}]")
    psi, phi = np.broadcast_arrays(x / radius, phi)
    sin_phi, cos_phi = np.sin(phi), np.cos(phi)
    with np.errstate(divide="ignore", invalid="ignore"):
        first = np.arcsin(np.clip(np.sin(psi / 2.0) / sin_phi, -1.0, 1.0))
        # arcsin(tan(psi/2) / tan(phi)) cos(phi), finite at phi = pi/2
        second = np.arcsin(np.clip(np.tan(psi / 2.0) * cos_phi / sin_phi, -1.0, 1.0)) * cos_phi
        value = 1.0 - (first - second) / (np.pi * np.sin(phi / 2.0) ** 2)
    inside = (psi < 2.0 * phi) & (phi > 0)
    return np.where(inside, np.clip(value, 0.0, 1.0), 0.0)


def disk_intersection_fraction(r, a) -> np.ndarray:
    """Euclidean limit of Eq. (9): intersection area of two disks of radius a whose centres are
    r apart, over pi a^2 (Torquato & Stillinger 2003) = 2 - v2/v1 of two overlapping disks."""
    from randmedia.theory.overlapping import union_volume_ratio  # scipy-heavy; only tests need it

    return 2.0 - union_volume_ratio(r, float(a), dim=2)


def uniform_variance(a, radius: float, rho: float) -> np.ndarray:
    """Eq. (6): sigma^2 = rho s (1 - s / (4 pi R^2)) (canonical, g2 = 1); equals rho pi a^2.

    Parameters
    ----------
    a : float or array_like
        Cap base radii, 0 <= a <= R.
    radius : float
        Sphere radius R.
    rho : float
        Number density N / (4 pi R^2), > 0.

    Returns
    -------
    numpy.ndarray
        sigma^2(a), same shape as ``a``.
    """
    check_density(rho)
    s = cap_area(a, radius)
    return rho * s * (1.0 - s / (4.0 * np.pi * radius**2))


def poisson_variance(a, radius: float, rho: float) -> np.ndarray:
    """Eq. (7): sigma^2 = <rho> s (grand canonical, Poisson points).

    Parameters
    ----------
    a : float or array_like
        Cap base radii, 0 <= a <= R.
    radius : float
        Sphere radius R.
    rho : float
        Mean number density <rho>, > 0.

    Returns
    -------
    numpy.ndarray
        sigma^2(a), same shape as ``a``.
    """
    check_density(rho)
    return rho * cap_area(a, radius)


def cap_intersection_weights(x_edges, a, radius: float, nodes: int = 12) -> np.ndarray:
    """W[k, b] = integral over geodesic bin b of alpha2(x; a_k) dA(x), dA = 2 pi R sin(x/R) dx.

    Each bin is split at the kink x = 2 R phi_k and integrated by ``nodes``-point
    Gauss-Legendre; sum_b W[k, b] = s(a_k) when the bins cover [0, pi R].

    Parameters
    ----------
    x_edges : array_like
        Strictly increasing geodesic bin edges, shape (n_bins + 1,), within [0, pi R].
    a : float or array_like
        Cap base radii, 0 <= a <= R; a scalar counts as one cap.
    radius : float
        Sphere radius R.
    nodes : int
        Gauss-Legendre points per (piece of a) bin (default 12).

    Returns
    -------
    numpy.ndarray
        W, shape (n_caps, n_bins), in units of area (length^2).
    """
    check_radius(radius)
    edges = np.asarray(x_edges, dtype=float)
    if edges.ndim != 1 or edges.size < 2 or np.any(np.diff(edges) <= 0):
        raise ValueError("x_edges must be a strictly increasing 1D array of at least 2 values")
    a = np.atleast_1d(check_base_radius(a, radius))
    t, w = np.polynomial.legendre.leggauss(nodes)
    weights = np.zeros((a.size, edges.size - 1))

    def integrate(lo, hi, ak):
        """Gauss-Legendre integral of alpha2 dA over [lo_b, hi_b] for arrays of bins."""
        xs = 0.5 * (hi - lo)[:, None] * t[None, :] + 0.5 * (hi + lo)[:, None]
        area = 2.0 * np.pi * radius * np.sin(xs / radius)
        return 0.5 * (hi - lo) * np.sum(w * area * cap_intersection_fraction(xs, ak, radius), axis=1)

    lo, hi = edges[:-1], edges[1:]
    for k, phi in enumerate(np.arcsin(a / radius)):
        kink = 2.0 * phi * radius
        split = (lo < kink) & (kink < hi)
        weights[k] = integrate(lo, hi, a[k])
        if split.any():  # integrate the bin holding the kink in two pieces
            weights[k, split] = (integrate(lo[split], np.full(split.sum(), kink), a[k])
                                 + integrate(np.full(split.sum(), kink), hi[split], a[k]))
    return weights


def variance_from_g2(a, radius: float, rho: float, x_edges, g2, *, n_particles: float | None,
                     ensemble: str = "canonical") -> np.ndarray:
    """sigma^2(a) from a binned geodesic g2 by Eq. (4) (canonical: N fixed, pass n_particles)
    or Eq. (5) (grand canonical: rho is <rho>, n_particles ignored).

    Eq. (4): rho s [1 - rho s + rho (1 - 1/N) int g2(x) alpha2(x; a) dA];
    Eq. (5): <rho> s [1 - <rho> s + <rho> int g2(x) alpha2(x; a) dA].

    Parameters
    ----------
    a : float or array_like
        Cap base radii, 0 <= a <= R.
    radius : float
        Sphere radius R.
    rho : float
        Number density (canonical) or mean number density <rho> (grand canonical), > 0.
    x_edges : array_like
        Geodesic bin edges of ``g2``, shape (n_bins + 1,).
    g2 : array_like
        Binned geodesic pair correlation function, shape (n_bins,).
    n_particles : float or None
        Particle number N (>= 2) for ``"canonical"``; ignored for ``"grand_canonical"``.
    ensemble : str
        ``"canonical"`` (Eq. 4, default) or ``"grand_canonical"`` (Eq. 5).

    Returns
    -------
    numpy.ndarray
        sigma^2(a), same shape as ``a``.
    """
    check_density(rho)
    g2 = np.asarray(g2, dtype=float)
    if g2.shape != (np.asarray(x_edges).size - 1,):
        raise ValueError(f"g2 has shape {g2.shape}, expected one value per bin of x_edges")
    s = cap_area(a, radius)
    integral = cap_intersection_weights(x_edges, a, radius) @ g2
    if ensemble == "canonical":
        if n_particles is None or n_particles < 2:
            raise ValueError("the canonical Eq. (4) needs the particle number N >= 2")
        factor = 1.0 - 1.0 / n_particles
    elif ensemble == "grand_canonical":
        factor = 1.0
    else:
        raise ValueError(f"ensemble must be 'canonical' or 'grand_canonical', got {ensemble!r}")
    return rho * s * (1.0 - rho * s + rho * factor * integral.reshape(s.shape))
