"""The isotropic Poisson hyperplane process of the Poisson-plane (d = 3) and Poisson-line
(d = 2) tessellations (:mod:`randmedia.generate.poisson_planes`, whose docstring derives
these): the mean crossing fraction kappa_d, the plane area per volume S_V = 1 / (a kappa_d)
that makes the planes cross a line at rate 1/a, and the specific surface s = 2 phi1 phi2 S_V
of independently coloured cells (4 phi1 phi2 / a in 3D; Ma & Torquato 2020, Eq. 22 in 2D).

Apart from the tessellation's descriptors (:mod:`randmedia.theory.poisson_planes`) because the
generator draws its planes with kappa_d: editing the descriptors does not invalidate
generated media (the workflow reruns a rule when a module its script imports changes).
"""

from __future__ import annotations

import math

from randmedia.numerics.checks import check_dim, check_fraction, check_positive

__all__ = ["crossing_fraction", "plane_area_density", "specific_surface"]


def crossing_fraction(dim: int) -> float:
    """kappa_d = E|u.e| for u uniform on S^(d-1): Gamma(d/2) / (sqrt(pi) Gamma((d+1)/2));
    2/pi for d = 2, 1/2 for d = 3.

    Parameters
    ----------
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        kappa_d, the mean |cosine| between a uniform direction and a fixed one.
    """
    check_dim(dim)
    return math.gamma(dim / 2) / (math.sqrt(math.pi) * math.gamma((dim + 1) / 2))


def plane_area_density(a: float, dim: int) -> float:
    """S_V = 1 / (a kappa_d): hyperplane area per volume giving lambda_L = 1/a crossings per
    unit length (Cauchy-Crofton).

    Parameters
    ----------
    a : float
        Correlation length a = 1 / lambda_L, > 0.
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        S_V, in 1 / (unit of ``a``).
    """
    check_positive(a, "a")
    return 1.0 / (a * crossing_fraction(dim))


def specific_surface(a: float, phi2: float, dim: int) -> float:
    """s = 2 phi1 phi2 S_V = 2 phi1 phi2 / (a kappa_d): 4 phi1 phi2 / a (3D), Eq. (22) (2D).

    Parameters
    ----------
    a : float
        Correlation length a = 1 / lambda_L (> 0), in pixels.
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        Specific surface s (interface area per volume), in 1 / (unit of ``a``).
    """
    check_fraction(phi2)
    check_positive(a, "a")
    return 2.0 * phi2 * (1.0 - phi2) * plane_area_density(a, dim)
