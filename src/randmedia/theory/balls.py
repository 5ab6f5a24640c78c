"""The volume of a d-ball and the intensity of overlapping balls: one home for both.

* omega_d = pi^(d/2) / Gamma(1 + d/2), the volume of the unit d-ball, and
  v1(R) = omega_d R^d (Ma & Torquato 2020, Eq. 8);
* the Boolean model (overlapping balls, Poisson centres of intensity rho): the balls cover
  phi2 = 1 - exp(-rho v1(R)), so rho = -ln(1 - phi2) / v1(R) (Ma & Torquato 2020, Sec. VI A;
  Torquato, *Random Heterogeneous Materials*, Ch. 3).

The generators (:mod:`randmedia.generate.balls`, :mod:`randmedia.generate.rsa`, the hard-particle
Monte Carlo) and the closed forms (:mod:`randmedia.theory.overlapping`,
:mod:`randmedia.theory.hard_spheres`) all take these from here. The module imports nothing
heavy, so a generator that needs a ball volume does not depend on the descriptors' theory.
"""

from __future__ import annotations

import math

from randmedia.numerics.checks import check_dim, check_fraction, check_positive

__all__ = ["ball_volume", "poisson_intensity", "unit_ball_volume"]

#: omega_d in closed form for d = 1, 2, 3 (2, pi, 4 pi / 3); for d = 2, 3 these are the values
#: of the Gamma-function form below, bit for bit, and omega_1 is exactly 2 (the Gamma form
#: gives 2 - 2^-52)
_UNIT_BALL_VOLUME = {1: 2.0, 2: math.pi, 3: 4.0 * math.pi / 3.0}


def unit_ball_volume(dim: int) -> float:
    """omega_d = pi^(d/2) / Gamma(1 + d/2), the volume of the unit d-ball (Ma & Torquato 2020,
    Eq. 8): 2, pi, 4 pi / 3 for d = 1, 2, 3.

    Parameters
    ----------
    dim : int
        Dimension d >= 1.

    Returns
    -------
    float
        omega_d.
    """
    if dim in _UNIT_BALL_VOLUME:
        return _UNIT_BALL_VOLUME[dim]
    if int(dim) != dim or dim < 1:
        raise ValueError(f"dimension must be a whole number >= 1, got {dim!r}")
    return math.pi ** (dim / 2) / math.gamma(1 + dim / 2)


def ball_volume(radius, dim: int):
    """v1(R) = omega_d R^d, the volume of a d-ball of radius R (Ma & Torquato 2020, Eq. 8).

    Parameters
    ----------
    radius : float or array_like
        Radius R (a diameter D gives ``ball_volume(D / 2, dim)``).
    dim : int
        Dimension d >= 1.

    Returns
    -------
    float or numpy.ndarray
        v1(R), in the length unit of ``radius`` to the d; an array for an array ``radius``.
    """
    return unit_ball_volume(dim) * radius**dim


def poisson_intensity(phi2: float, radius: float, dim: int) -> float:
    """Number density rho of the Poisson centres of overlapping balls that cover the expected
    fraction phi2: rho = -ln(1 - phi2) / v1(R) = eta / v1(R).

    Parameters
    ----------
    phi2 : float
        Expected volume fraction of the balls (phase 2), in (0, 1).
    radius : float
        Ball radius R, > 0.
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        rho, centres per unit volume (length unit of ``radius``, to the -d).
    """
    check_dim(dim)
    check_fraction(phi2)
    check_positive(radius, "radius")
    return -math.log1p(-phi2) / ball_volume(radius, dim)
