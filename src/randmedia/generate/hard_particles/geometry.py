"""Geometry of a hard-particle system: the box at a packing fraction, the checks that
refuse impossible or off-branch input, the lattice starts of a chain, and an exact
overlap count independent of the Monte Carlo cell list."""

from __future__ import annotations

import math

import numpy as np

from randmedia.theory.balls import ball_volume
from randmedia.theory.hard_spheres import FLUID_LIMIT


def cubic_box(n_particles: int, phi: float, dim: int, diameter: float = 1.0) -> np.ndarray:
    """Side lengths (d,) of the cube (square) holding N particles at packing fraction phi.

    Parameters
    ----------
    n_particles : int
        Number of particles N.
    phi : float
        Packing fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.
    diameter : float, optional
        Particle diameter D (default 1); lengths are in its unit.

    Returns
    -------
    ndarray, shape (d,)
        Equal side lengths L = (N v1(D/2) / phi)^(1/d).
    """
    if dim not in (2, 3):
        raise ValueError(f"dimension must be 2 or 3, got {dim}")
    if not 0.0 < phi < 1.0:
        raise ValueError(f"packing fraction must lie in (0, 1), got {phi}")
    volume = n_particles * float(ball_volume(diameter / 2.0, dim)) / phi
    return np.full(dim, volume ** (1.0 / dim))


def packing_fraction_of(n_particles: int, box_lengths, diameter: float) -> float:
    """Packing fraction N v1(D/2) / prod(box_lengths) of N particles in an orthogonal box.

    Parameters
    ----------
    n_particles : int
        Number of particles N.
    box_lengths : array_like, shape (d,)
        Box side lengths (unit of ``diameter``); d = len(box_lengths).
    diameter : float
        Particle diameter D.

    Returns
    -------
    float
        The packing fraction phi.
    """
    box_lengths = np.asarray(box_lengths, dtype=float)
    return float(n_particles * ball_volume(diameter / 2.0, len(box_lengths)) / np.prod(box_lengths))


def validate_system(n_particles: int, box_lengths, diameter: float, contact_range: float = 0.1) -> float:
    """Refuse impossible or off-branch input; returns the packing fraction.

    Parameters
    ----------
    n_particles : int
        Number of particles N (an integer >= 2).
    box_lengths : array_like, shape (d,)
        Box side lengths, d = 2 or 3; each must be >= 2 D (1 + contact_range) + D.
    diameter : float
        Particle diameter D (> 0).
    contact_range : float, optional
        Width of the contact histogram in units of D (default 0.1).

    Returns
    -------
    float
        The packing fraction phi (at most the end of the fluid branch, FLUID_LIMIT[d]).

    Raises
    ------
    ValueError
        For any of the refused inputs.
    """
    box_lengths = np.asarray(box_lengths, dtype=float)
    dim = len(box_lengths)
    if dim not in (2, 3):
        raise ValueError(f"box must have 2 or 3 side lengths (d = 2 or 3), got {box_lengths}")
    if not isinstance(n_particles, (int, np.integer)) or n_particles < 2:
        raise ValueError(f"need at least N = 2 particles, got {n_particles!r}")
    if not (np.isfinite(diameter) and diameter > 0):
        raise ValueError(f"particle diameter must be > 0, got {diameter}")
    if not np.all(np.isfinite(box_lengths)) or np.any(box_lengths <= 0):
        raise ValueError(f"box side lengths must be > 0, got {box_lengths}")
    shortest = 2.0 * diameter * (1.0 + contact_range) + diameter
    if np.any(box_lengths < shortest):
        raise ValueError(f"every box side must be >= {shortest:g} (2 D (1 + contact_range) + D, "
                         f"so the contact shell fits the minimum-image range), got {box_lengths}")
    phi = packing_fraction_of(n_particles, box_lengths, diameter)
    if phi > FLUID_LIMIT[dim]:
        raise ValueError(
            f"packing fraction {phi:.4f} of N = {n_particles} particles of diameter {diameter:g} "
            f"in box {box_lengths} is above the end of the stable fluid branch in d = {dim} "
            f"(phi <= {FLUID_LIMIT[dim]}); this generator samples the equilibrium fluid only")
    return phi


#: lattices tried for the start, least stable first (it has to melt): basis in cell units
_LATTICES = {
    2: (("square", ((0.0, 0.0),)),),
    3: (("simple cubic", ((0.0, 0.0, 0.0),)),
        ("bcc", ((0.0, 0.0, 0.0), (0.5, 0.5, 0.5))),
        ("fcc", ((0.0, 0.0, 0.0), (0.5, 0.5, 0.0), (0.5, 0.0, 0.5), (0.0, 0.5, 0.5)))),
}


def lattice_sites(n_particles: int, box_lengths, diameter: float):
    """(name, sites) of the first lattice in :data:`_LATTICES` with at least N sites in the
    box and nearest-neighbour distance >= D (cells per side n or n - 1, n = ceil((N/b)^(1/d))),
    or None when none fits (then the chain starts by RSA + compression).

    Parameters
    ----------
    n_particles : int
        Number of particles N the lattice must hold.
    box_lengths : array_like, shape (d,)
        Box side lengths (unit of ``diameter``).
    diameter : float
        Particle diameter D.

    Returns
    -------
    tuple (str, ndarray of shape (m, d)) or None
        Lattice name and its m >= N sites (Cartesian, in the box), the fitting choice with fewest sites.
    """
    box_lengths = np.asarray(box_lengths, dtype=float)
    dim = len(box_lengths)
    for name, basis in _LATTICES[dim]:
        basis = np.asarray(basis)
        n = math.ceil((n_particles / len(basis)) ** (1.0 / dim))
        candidates = []
        for cells in np.ndindex(*([2] * dim)):
            counts = np.array([n - c for c in cells])
            if np.any(counts < 1) or len(basis) * np.prod(counts) < n_particles:
                continue
            grid = np.stack(np.meshgrid(*[np.arange(c) for c in counts], indexing="ij"),
                            axis=-1).reshape(-1, dim)
            points = ((grid[:, None, :] + basis[None]).reshape(-1, dim)) * (box_lengths / counts)
            if count_overlaps(points, box_lengths, diameter * (1.0 + 1e-9)) == 0:
                candidates.append((len(points), points))
        if candidates:
            return name, min(candidates, key=lambda item: item[0])[1]
    return None


def count_overlaps(positions, box_lengths, diameter: float) -> int:
    """Exact count of pairs closer than ``diameter`` (nearest periodic images), by the
    k-d tree pair search of :mod:`randmedia.periodic` (independent of the MC cell list).

    Parameters
    ----------
    positions : array_like, shape (n, d)
        Particle centres.
    box_lengths : array_like, shape (d,)
        Side lengths of the orthogonal periodic box.
    diameter : float
        Distance below which a pair counts as overlapping; must not exceed half the box width.

    Returns
    -------
    int
        Number of pairs with centre distance < ``diameter``.
    """
    from randmedia.periodic import Cell, pairs_within

    box_lengths = np.asarray(box_lengths, dtype=float)
    cell = Cell.orthogonal(box_lengths)
    if diameter > cell.half_width:
        raise ValueError("box too small for an overlap check (D > half the box)")
    i, _, _, distance = pairs_within(cell, positions, diameter)
    return int(np.count_nonzero(distance < diameter))
