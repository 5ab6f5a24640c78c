"""Exact descriptors of Poisson-plane (d = 3) and Poisson-line (d = 2) tessellations with
independently coloured cells (:mod:`randmedia.generate.poisson_planes`): the medium with
exactly the Debye S2 = phi2^2 + phi1 phi2 e^(-r/a) (Ma & Torquato 2020, Eq. 21), void =
phase 1 (probability phi1 per cell).

Ingredients (all from the generator's docstring): the planes cross a line as a Poisson
process of rate 1/a; cells are convex, so two points lie in the same cell iff no plane
crosses the segment between them, probability e = e^(-r/a); distinct cells have independent
colours; the plane area per volume is S_V = 1 / (a kappa_d) (kappa_3 = 1/2, kappa_2 = 2/pi);
a plane piece is interface iff the two cells it separates differ (probability 2 phi1 phi2),
so s = 2 phi1 phi2 S_V (4 phi1 phi2 / a in 3D) -- these exact plane formulas are in
:mod:`randmedia.theory.plane_process`. By Slivnyak's theorem the planes other than the one
through a typical interface point are again the Poisson process.

* **F_sv** (Eq. 11). Take x on the interface, on plane P0 between a void cell A and a solid
  cell B. For an isotropic displacement r, x + r lies on A's side of P0 with probability 1/2;
  it stays in A iff no other plane crosses [x, x + r] (probability e), it can never be in B
  from A's side nor in A from B's side (convex cells), and in any other cell it is void with
  probability phi1. So

      F_sv(r) = s [phi1 + (1/2 - phi1) e^(-r/a)],

  s/2 at r = 0 and s phi1 at r -> inf, in any d. Against the conjecture Eq. (44) (and its 2D
  counterpart Eq. 24), s (phi1 + phi2 e) / (1 + e), the difference is
  s (phi2 - 1/2) e (1 - e) / (1 + e): the two agree only at phi2 = 1/2 -- the Debye S2 alone
  does not fix F_sv.

* **F_ss** (Eq. 15), pairs of interface points at distance r, isotropically averaged:
  (i) both on P0: the density of P0 at distance r from a point of it is
  rho_same(r) = 1/(2r) (3D; 1/(pi r) in 2D), and x + r is interface iff its two cells differ:
  A and B again if no plane crosses the segment (e), else two new cells (2 phi1 phi2);
  (ii) x + r on another plane P1 (density S_V): the cell on x's side of P1 is A or B (1/2 each,
  probability e) or a new cell, the cell beyond P1 is always new, so P1 is interface there
  with probability (phi1 + phi2)/2 = 1/2, or 2 phi1 phi2. Hence

      F_ss(r) = s { rho_same(r) [e + 2 phi1 phi2 (1 - e)] + S_V [e/2 + 2 phi1 phi2 (1 - e)] }
              = s^2 + (s/(2r)) [e + 2 phi1 phi2 (1 - e)] + (4 phi1 phi2 (phi2 - phi1)^2 / a^2) e   (3D).

  The same-plane term s rho_same(r) 2 phi1 phi2 (1 - e) decays only as 1/r: infinite flat
  interfaces correlate at every distance. The conjecture Eq. (45) has the s/(2r) e term of
  (i) but no 1/r tail.

* **L(z)** = phi1 e^(-phi2 z / a) (a segment in the void crosses n planes into void cells
  only: sum_n P(n) phi1^n) and the void chord-length density **p(z)** = (phi2 / a)
  e^(-phi2 z / a) (a void run ends at a crossing into a solid cell), mean chord a / phi2 =
  4 phi1 / s (3D, Eq. 20) -- the exponential forms Sec. VII expects for Debye media.

Checked by Monte Carlo on the continuum tessellation (tests/test_poisson_planes_theory.py).
"""

from __future__ import annotations

import math

import numpy as np

from randmedia.numerics.checks import check_fraction, check_positive
from randmedia.theory.plane_process import plane_area_density, specific_surface


def same_plane_density(r, dim: int) -> np.ndarray:
    """rho_same(r): the isotropic average of the density of a hyperplane at distance r from one
    of its points, 1/(2r) in 3D and 1/(pi r) in 2D (area of the (d-2)-sphere of radius r in the
    plane over the area of the (d-1)-sphere)."""
    r = np.asarray(r, dtype=float)
    if dim == 3:
        return 1.0 / (2.0 * r)
    if dim == 2:
        return 1.0 / (math.pi * r)
    raise ValueError(f"dim must be 2 or 3, got {dim!r}")


def surface_void(r, phi2: float, a: float, dim: int = 3) -> np.ndarray:
    """F_sv(r) = s [phi1 + (1/2 - phi1) e^(-r/a)] (module docstring), 1/length.

    Parameters
    ----------
    r : float or array_like
        Distances (unit of ``a``).
    phi2 : float
        Probability that a cell is phase 2, in (0, 1).
    a : float
        Correlation length (> 0).
    dim : int, optional
        2 (Poisson lines) or 3 (Poisson planes).

    Returns
    -------
    numpy.ndarray
    """
    check_fraction(phi2)
    check_positive(a, "a")
    decay = np.exp(-np.asarray(r, dtype=float) / a)
    phi1 = 1.0 - phi2
    return specific_surface(a, phi2, dim) * (phi1 + (0.5 - phi1) * decay)


def surface_surface(r, phi2: float, a: float, dim: int = 3) -> np.ndarray:
    """F_ss(r) = s {rho_same(r) [e + 2 phi1 phi2 (1 - e)] + S_V [e/2 + 2 phi1 phi2 (1 - e)]},
    e = e^(-r/a) (module docstring), 1/length^2; diverges as s rho_same(r) at r -> 0.

    Parameters
    ----------
    r : float or array_like
        Distances (unit of ``a``), > 0.
    phi2 : float
        Probability that a cell is phase 2, in (0, 1).
    a : float
        Correlation length (> 0).
    dim : int, optional
        2 (Poisson lines) or 3 (Poisson planes).

    Returns
    -------
    numpy.ndarray
    """
    check_fraction(phi2)
    check_positive(a, "a")
    r = np.asarray(r, dtype=float)
    decay = np.exp(-r / a)
    mixed = 2.0 * phi2 * (1.0 - phi2)
    with np.errstate(divide="ignore"):
        same = same_plane_density(r, dim) * (decay + mixed * (1.0 - decay))
    other = plane_area_density(a, dim) * (0.5 * decay + mixed * (1.0 - decay))
    return specific_surface(a, phi2, dim) * (same + other)


def lineal_path_void(z, phi2: float, a: float) -> np.ndarray:
    """L(z) of the void: phi1 e^(-phi2 z / a) (any d)."""
    check_fraction(phi2)
    check_positive(a, "a")
    return (1.0 - phi2) * np.exp(-phi2 * np.asarray(z, dtype=float) / a)


def chord_density_void(z, phi2: float, a: float) -> np.ndarray:
    """p(z) of the void chords: (phi2 / a) e^(-phi2 z / a) (any d), 1/length."""
    check_fraction(phi2)
    check_positive(a, "a")
    return phi2 / a * np.exp(-phi2 * np.asarray(z, dtype=float) / a)


def chord_bin_average(low, high, phi2: float, a: float) -> np.ndarray:
    """p(z) averaged over the chord-length bin [low, high]: the exact value of a histogram bin."""
    check_fraction(phi2)
    check_positive(a, "a")
    low, high = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
    return (np.exp(-phi2 * low / a) - np.exp(-phi2 * high / a)) / (high - low)
