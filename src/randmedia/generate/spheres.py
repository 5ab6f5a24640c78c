"""Sphere configurations with known answers: overlapping spheres and the fcc / bcc lattices.

Systems of Klatt & Torquato, PRE 94, 022152 (2016), in units of the sphere
diameter D (= 1 in the files; contract PARTICLE_CONFIG):

* ``overlapping``: the Boolean model -- centres form a Poisson point process of
  intensity rho in a periodic cubic box; the spheres (diameter D) may overlap
  and cover the volume fraction phi = 1 - exp(-rho pi D^3 / 6) (Sec. III A;
  rho from :func:`randmedia.theory.balls.poisson_intensity`).
  The number of centres in a box of volume V is Poisson distributed with mean
  rho V (not fixed), so that every window statistic of the periodic sample is
  exactly that of the infinite Poisson process as long as the window fits in
  the cell (e.g. the number variance rho v(R), Sec. VI B).
* ``fcc`` / ``bcc``: perfect lattices of touching spheres (nearest-neighbour
  distance D, Sec. V A), n_cells^3 conventional cubic cells (4 or 2 sites
  each), phi = pi / (3 sqrt 2) = 0.7405 and pi sqrt(3) / 8 = 0.6802. Each
  sample is the same lattice rigidly translated by a random vector, so that
  Monte Carlo estimators (pore sizes, windows) see independent samples while
  the structure is exact.
"""

from __future__ import annotations

import math

import numpy as np

from randmedia.theory.balls import ball_volume, poisson_intensity

#: sites of the conventional cubic cell (fractions of the cubic lattice constant a)
LATTICE_BASIS = {
    "fcc": np.array([[0.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.5, 0.0, 0.5], [0.0, 0.5, 0.5]]),
    "bcc": np.array([[0.0, 0.0, 0.0], [0.5, 0.5, 0.5]]),
}
#: nearest-neighbour distance in units of the cubic lattice constant a
NEAREST_NEIGHBOUR = {"fcc": 1.0 / math.sqrt(2.0), "bcc": math.sqrt(3.0) / 2.0}
#: covering radius (largest distance of a point of space to the nearest site) in units of a:
#: fcc octahedral hole at (a/2, 0, 0); bcc "deep hole" at (a/2, a/4, 0) (Torquato, PRE 82, 056109)
COVERING_RADIUS = {"fcc": 0.5, "bcc": math.sqrt(5.0) / 4.0}


def overlapping_box_side(phi: float, n_mean: float, diameter: float = 1.0) -> float:
    """Side of the cubic box holding on average ``n_mean`` centres at intensity rho(phi).

    Parameters
    ----------
    phi : float
        Covered volume fraction of the Boolean model, in (0, 1).
    n_mean : float
        Mean number of centres in the box (> 0).
    diameter : float, optional
        Sphere diameter D (default 1); lengths are in its unit.

    Returns
    -------
    float
        Box side L = (n_mean / rho)^(1/3), rho = -ln(1 - phi) / v1(D/2).
    """
    if n_mean <= 0:
        raise ValueError(f"n_mean must be > 0, got {n_mean}")
    return (n_mean / poisson_intensity(phi, diameter / 2.0, 3)) ** (1.0 / 3.0)


def overlapping_spheres(rng: np.random.Generator, phi: float, n_mean: float,
                        diameter: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Poisson centres in a periodic cube: (positions (n, 3), box 3x3), n ~ Poisson(n_mean).

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the Poisson count and the uniform positions.
    phi : float
        Covered volume fraction, in (0, 1).
    n_mean : float
        Mean number of centres (> 0).
    diameter : float, optional
        Sphere diameter D (default 1).

    Returns
    -------
    positions : ndarray, shape (n, 3)
        Centres in [0, L)^3, in units of D.
    box : ndarray, shape (3, 3)
        L I.
    """
    side = overlapping_box_side(phi, n_mean, diameter)
    count = int(rng.poisson(n_mean))
    return rng.uniform(0.0, side, size=(count, 3)), np.eye(3) * side


def lattice_constant(lattice: str, diameter: float = 1.0) -> float:
    """Cubic lattice constant a at which nearest neighbours touch (distance D)."""
    if lattice not in LATTICE_BASIS:
        raise ValueError(f"lattice must be one of {sorted(LATTICE_BASIS)}, got {lattice!r}")
    return diameter / NEAREST_NEIGHBOUR[lattice]


def lattice_packing_fraction(lattice: str) -> float:
    """phi of touching spheres: fcc pi/(3 sqrt 2), bcc pi sqrt(3)/8."""
    a = lattice_constant(lattice)
    return len(LATTICE_BASIS[lattice]) * ball_volume(0.5, 3) / a**3


def lattice_covering_radius(lattice: str, diameter: float = 1.0) -> float:
    """Exact covering radius of the lattice of touching spheres, in units of D."""
    return COVERING_RADIUS[lattice] * lattice_constant(lattice, diameter)


def lattice_spheres(lattice: str, n_cells: int, diameter: float = 1.0,
                    rng: np.random.Generator | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Touching spheres on an fcc or bcc lattice in a periodic cube of n_cells^3 cubic cells.

    With ``rng`` the whole lattice is translated by a uniform random vector
    (the sample's only randomness); positions are returned unwrapped.

    Parameters
    ----------
    lattice : str
        "fcc" or "bcc".
    n_cells : int
        Conventional cubic cells per box side (>= 1).
    diameter : float, optional
        Sphere diameter D = nearest-neighbour distance (default 1).
    rng : numpy.random.Generator, optional
        Source of the random translation; None for none.

    Returns
    -------
    positions : ndarray, shape (4 n_cells^3 or 2 n_cells^3, 3)
        Sites (unwrapped), in the unit of D.
    box : ndarray, shape (3, 3)
        n_cells a I, a the cubic lattice constant.
    """
    if int(n_cells) != n_cells or n_cells < 1:
        raise ValueError(f"n_cells must be a positive integer, got {n_cells}")
    n_cells = int(n_cells)
    a = lattice_constant(lattice, diameter)
    grid = np.stack(np.meshgrid(*(np.arange(n_cells),) * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    sites = (grid[:, None, :] + LATTICE_BASIS[lattice][None, :, :]).reshape(-1, 3) * a
    if rng is not None:
        sites = sites + rng.uniform(0.0, a, size=3)
    return sites, np.eye(3) * (n_cells * a)


def bragg_peak_count(lattice: str, k_max: float, diameter: float = 1.0) -> int:
    """Reciprocal-lattice vectors G != 0 of the lattice with |G| <= k_max, counted once per +-G.

    G = (2 pi / a)(h, k, l) with the structure-factor rule of the conventional
    cell: fcc h, k, l all even or all odd; bcc h + k + l even. These are the
    wavevectors where S(k) = N (Bragg peaks); S = 0 at every other allowed k.

    Parameters
    ----------
    lattice : str
        "fcc" or "bcc".
    k_max : float
        Largest wavenumber |G|, in 1 / (unit of ``diameter``).
    diameter : float, optional
        Sphere diameter D = nearest-neighbour distance (default 1).

    Returns
    -------
    int
        Number of pairs +-G with 0 < |G| <= k_max.
    """
    a = lattice_constant(lattice, diameter)
    m = int(math.floor(k_max * a / (2 * math.pi))) + 1
    h = np.arange(-m, m + 1)
    hkl = np.stack(np.meshgrid(h, h, h, indexing="ij"), axis=-1).reshape(-1, 3)
    if lattice == "fcc":
        parity = hkl % 2
        allowed = np.all(parity == parity[:, :1], axis=1)
    else:
        allowed = hkl.sum(axis=1) % 2 == 0
    norm = 2 * math.pi / a * np.linalg.norm(hkl, axis=1)
    inside = allowed & (norm > 0) & (norm <= k_max * (1 + 1e-12))
    return int(inside.sum()) // 2
