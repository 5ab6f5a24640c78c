"""Equations of state of equilibrium hard disks (d = 2) and hard spheres (d = 3).

Notation: diameter D, number density rho, packing fraction phi = rho v1(D/2) with
v1(r) the volume of a d-ball of radius r (:func:`randmedia.theory.balls.ball_volume`);
compressibility factor Z = beta p / rho. Exact for any non-overlapping balls: the specific
surface s = d phi / R (:func:`specific_surface`; Ma & Torquato 2020, Eq. 40 in 2D).

Compressibility factors (``eos=`` names):

d = 3
  * ``"carnahan_starling"``: Z = (1 + phi + phi^2 - phi^3) / (1 - phi)^3
    (Carnahan & Starling, J. Chem. Phys. 51, 635 (1969)). Its virial coefficients
    B_n = n^2 + n - 2 (in units of v1^(n-1)) are within 2 % of the exact B4-B11; it
    lies 0.25 % below the converged virial series at phi = 0.3 and, at phi = 0.478,
    0.08 +- 0.04 % below our N = 10 000 Monte Carlo (docs/hard_particles.md).
  * ``"kolafa"``: Z = (1 + phi + phi^2 - (2/3)(phi^3 + phi^4)) / (1 - phi)^3, J. Kolafa's
    equation as given by Boublik & Nezbeda, Collect. Czech. Chem. Commun. 51, 2301
    (1986). Its virial coefficients 18.33, 28.33, 40.0, 53.33, 68.33 reproduce the exact
    B4-B8 (18.365, 28.224, 39.815, 53.344, 68.538) to 0.5 %; within 0.02 % of the
    converged virial series for phi <= 0.3 and 0.1 % above Carnahan-Starling at
    phi = 0.478 (0.02 +- 0.04 % above our Monte Carlo). The default in d = 3. The later fit of
    Kolafa, Labik & Malijevsky, PCCP 6, 2335 (2004), to high-precision MD data is not
    reproduced here: its coefficients could not be checked against the source offline.
d = 2
  * ``"henderson"``: Z = (1 + phi^2 / 8) / (1 - phi)^2 (Henderson, Mol. Phys. 30, 971
    (1975)); virial coefficients 3.125, 4.25, 5.375 against the exact 3.128, 4.258,
    5.337; within 0.03 % of the converged virial series for phi <= 0.3 (0.09 % at
    phi = 0.35); its higher coefficients are too large (B10: 11.0 against 10.2), so it
    overestimates Z near freezing (measured against our Monte Carlo in docs/hard_particles.md). The
    default in d = 2.
  * ``"santos"``: Z = 1 / (1 - 2 phi + (2 phi_cp - 1) phi^2 / phi_cp^2), phi_cp = pi / (2 sqrt 3)
    (Santos, Lopez de Haro & Santos Yuste, J. Chem. Phys. 103, 4622 (1995)); built for
    the high-density end, 0.9 % low at phi = 0.3 (its B3 is 3.01 instead of 3.128).
any d
  * ``"virial"``: the virial series with the known exact/high-precision coefficients
    (d = 2: B2..B10, Clisby & McCoy, J. Stat. Phys. 122, 15 (2006); d = 3: B2..B11,
    Clisby & McCoy 2006, Schultz & Kofke, PRE 90, 023301 (2014)). Converged to
    better than 1e-3 relative for phi <= 0.35 (d = 2) and phi <= 0.3 (d = 3) only; used
    to check the closed forms, refused above those densities.

Derived quantities, for any of the above:

  * contact value of the pair correlation function, from the virial theorem
    beta p / rho = 1 + 2^(d-1) phi g(D+):  g(D+) = (Z - 1) / (2^(d-1) phi);
  * structure factor at k = 0 (Klatt & Torquato 2016, Eq. 32; the dashed line of their
    Fig. 6): S(0) = rho k_B T kappa_T = [d(beta p)/d rho]^(-1) = [d(phi Z)/d phi]^(-1),
    and the spectral density chi_V(0) = phi v1(D/2) S(0) (their Eq. 14 at k = 0).

Phase limits used to refuse input off the stable fluid branch: FLUID_LIMIT (d = 3:
0.492, the freezing density of Fernandez et al., PRL 108, 165701 (2012); Hoover & Ree
1968 give 0.494; d = 2: 0.700, where liquid-hexatic coexistence starts, Bernard &
Krauth, PRL 107, 155704 (2011)) and CLOSE_PACKING (pi / (2 sqrt 3), pi / (3 sqrt 2)).
"""

from __future__ import annotations

import math

import numpy as np

from randmedia.numerics.checks import check_dim, check_fraction, check_positive
from randmedia.theory.balls import ball_volume

#: packing fraction at which the stable fluid branch ends (freezing / liquid-hexatic)
FLUID_LIMIT = {2: 0.700, 3: 0.492}
#: densest packing (triangular lattice, fcc)
CLOSE_PACKING = {2: math.pi / (2.0 * math.sqrt(3.0)), 3: math.pi / (3.0 * math.sqrt(2.0))}
#: default equation of state per dimension
DEFAULT_EOS = {2: "henderson", 3: "kolafa"}

#: virial coefficients B_n / v1(D/2)^(n-1), n = 2, 3, ... (Z = 1 + sum_n b_n phi^(n-1))
VIRIAL_COEFFICIENTS = {
    # hard disks: B_n / B_2^(n-1) = 1, 0.782004, 0.5322318, 0.33355604, 0.1988425,
    # 0.11486728, 0.0649930, 0.0362193, 0.0199537 (Clisby & McCoy 2006) times 2^(n-1)
    2: (2.0, 3.128017752, 4.257854, 5.336897, 6.362960, 7.351506, 8.319104, 9.272141, 10.216294),
    # hard spheres: 4, 10, 18.3647684, 28.224512, 39.81507, 53.3444, 68.538, 85.813,
    # 105.78, 127.9
    3: (4.0, 10.0, 18.3647684, 28.224512, 39.81507, 53.3444, 68.538, 85.813, 105.78, 127.9),
}
#: densities up to which the truncated virial series is converged to ~1e-3
VIRIAL_RANGE = {2: 0.35, 3: 0.30}

_EOS_BY_DIM = {2: ("henderson", "santos", "virial"), 3: ("carnahan_starling", "kolafa", "virial")}


def number_density(phi: float, diameter: float, dim: int) -> float:
    """rho = phi / v1(D/2).

    Parameters
    ----------
    phi : float
        Packing fraction.
    diameter : float
        Particle diameter D, > 0.
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        rho, in units of 1/length^d (length of ``diameter``).
    """
    check_dim(dim)
    check_positive(diameter, "diameter")
    return float(phi / ball_volume(diameter / 2.0, dim))


def packing_fraction(rho: float, diameter: float, dim: int) -> float:
    """phi = rho v1(D/2).

    Parameters
    ----------
    rho : float
        Number density (1/length^d).
    diameter : float
        Particle diameter D (same length unit).
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        Packing fraction phi.
    """
    check_dim(dim)
    return float(rho * ball_volume(diameter / 2.0, dim))


def specific_surface(radius: float, phi: float, dim: int) -> float:
    """s = d phi / R of non-overlapping d-balls (exact: surface d v1(R) / R per ball), Eq. (40)
    of Ma & Torquato 2020 in 2D (s = 2 phi2 / R).

    Parameters
    ----------
    radius : float
        Particle radius R, > 0.
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    float
        s (1/length of ``radius``).
    """
    check_dim(dim)
    check_fraction(phi, "packing fraction")
    check_positive(radius, "radius")
    return dim * phi / radius


def _check_eos(phi, dim: int, eos: str) -> np.ndarray:
    """phi as an array, checked against the fluid range of the equation of state ``eos``."""
    check_dim(dim)
    if eos not in _EOS_BY_DIM[dim]:
        raise ValueError(f"unknown equation of state {eos!r} for d = {dim}; "
                         f"choose one of {_EOS_BY_DIM[dim]}")
    phi = np.asarray(phi, dtype=float)
    if np.any(phi < 0) or np.any(phi >= CLOSE_PACKING[dim]):
        raise ValueError(f"packing fraction must lie in [0, {CLOSE_PACKING[dim]:.4f}) (close "
                         f"packing in d = {dim}), got {phi}")
    if eos == "virial" and np.any(phi > VIRIAL_RANGE[dim]):
        raise ValueError(f"the truncated virial series is not converged above phi = "
                         f"{VIRIAL_RANGE[dim]} in d = {dim}, got {phi}")
    return phi


def compressibility_factor(phi, dim: int, eos: str | None = None):
    """Z = beta p / rho of the equilibrium hard-disk/-sphere fluid (module docstring).

    Parameters
    ----------
    phi : float or array_like
        Packing fraction(s), in [0, close packing); for ``"virial"`` at most :data:`VIRIAL_RANGE`.
    dim : int
        Dimension d, 2 or 3.
    eos : str or None
        Equation of state (module docstring); None selects :data:`DEFAULT_EOS` of ``dim``.

    Returns
    -------
    float or numpy.ndarray
        Z, a float for scalar ``phi``, else an array of the shape of ``phi``.
    """
    eos = eos or DEFAULT_EOS.get(dim, "")
    phi = _check_eos(phi, dim, eos)
    if eos == "carnahan_starling":
        z = (1 + phi + phi**2 - phi**3) / (1 - phi) ** 3
    elif eos == "kolafa":
        z = (1 + phi + phi**2 - (2.0 / 3.0) * (phi**3 + phi**4)) / (1 - phi) ** 3
    elif eos == "henderson":
        z = (1 + phi**2 / 8.0) / (1 - phi) ** 2
    elif eos == "santos":
        cp = CLOSE_PACKING[2]
        z = 1.0 / (1 - 2 * phi + (2 * cp - 1) * phi**2 / cp**2)
    else:  # virial
        z = np.ones_like(phi)
        for k, b in enumerate(VIRIAL_COEFFICIENTS[dim]):
            z = z + b * phi ** (k + 1)
    return z if z.ndim else float(z)


def contact_value(phi, dim: int, eos: str | None = None):
    """g(D+) = (Z - 1) / (2^(d-1) phi) (virial theorem); 1 at phi = 0.

    Parameters
    ----------
    phi : float or array_like
        Packing fraction(s), in [0, close packing).
    dim : int
        Dimension d, 2 or 3.
    eos : str or None
        Equation of state; None selects :data:`DEFAULT_EOS` of ``dim``.

    Returns
    -------
    float or numpy.ndarray
        g(D+), a float for scalar ``phi``, else an array of the shape of ``phi``.
    """
    eos = eos or DEFAULT_EOS.get(dim, "")
    phi = _check_eos(phi, dim, eos)
    z = np.asarray(compressibility_factor(phi, dim, eos))
    with np.errstate(invalid="ignore", divide="ignore"):
        g = np.where(phi > 0, (z - 1.0) / (2.0 ** (dim - 1) * np.where(phi > 0, phi, 1.0)), 1.0)
    return g if g.ndim else float(g)


def reduced_pressure_from_contact(phi, contact, dim: int):
    """beta p / rho = 1 + 2^(d-1) phi g(D+) (the inverse of :func:`contact_value`).

    Parameters
    ----------
    phi : float or array_like
        Packing fraction(s).
    contact : float or array_like
        Contact value(s) g(D+), broadcast against ``phi``.
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    numpy.ndarray
        beta p / rho (a 0-d array for scalar input).
    """
    check_dim(dim)
    return 1.0 + 2.0 ** (dim - 1) * np.asarray(phi, float) * np.asarray(contact, float)


def structure_factor_zero(phi, dim: int, eos: str | None = None):
    """S(0) = [d(phi Z)/d phi]^(-1) (Klatt & Torquato 2016, Eq. 32), by a second-order
    finite difference with step 1e-5 (central; one-sided three-point next to phi = 0),
    error ~1e-10 for these smooth closed forms.

    Parameters
    ----------
    phi : float or array_like
        Packing fraction(s), in [0, close packing).
    dim : int
        Dimension d, 2 or 3.
    eos : str or None
        Equation of state; None selects :data:`DEFAULT_EOS` of ``dim``.

    Returns
    -------
    float or numpy.ndarray
        S(0), a float for scalar ``phi``, else an array of the shape of ``phi``.
    """
    eos = eos or DEFAULT_EOS.get(dim, "")
    phi = _check_eos(phi, dim, eos)
    h = 1e-5

    def f(x):
        return x * np.asarray(compressibility_factor(x, dim, eos))

    central = phi >= h
    x = np.where(central, phi, h)  # placeholder where the one-sided formula applies
    derivative = np.where(
        central,
        (f(x + h) - f(np.maximum(x - h, 0.0))) / (2 * h),
        (-3 * f(phi) + 4 * f(phi + h) - f(phi + 2 * h)) / (2 * h),
    )
    s0 = 1.0 / derivative
    return s0 if np.ndim(s0) else float(s0)


def spectral_density_zero(phi, dim: int, diameter: float = 1.0, eos: str | None = None):
    """chi_V(k = 0) = rho |m(0)|^2 S(0) = phi v1(D/2) S(0) of the hard-particle packing
    (Klatt & Torquato 2016, Eq. 14 at k = 0, with m(0) = v1(D/2) the particle volume): the
    dashed line of the liquid in their Fig. 6, in units of D^d when diameter = 1.

    Parameters
    ----------
    phi : float or array_like
        Packing fraction(s), in [0, close packing).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D; default 1, i.e. the result in units of D^d.
    eos : str or None
        Equation of state; None selects :data:`DEFAULT_EOS` of ``dim``.

    Returns
    -------
    float or numpy.ndarray
        chi_V(0) in units of length^d, shape of ``phi``.
    """
    s0 = structure_factor_zero(phi, dim, eos)
    return np.asarray(phi) * float(ball_volume(diameter / 2.0, dim)) * s0
