"""Steinhardt bond-orientational order of 3D particle configurations in any periodic cell.

Definitions (Steinhardt, Nelson & Ronchetti, PRB 28, 784 (1983); ten Wolde,
Ruiz-Montero & Frenkel, J. Chem. Phys. 104, 9932 (1996)). Two particles are
*neighbours* ("bonded") when their nearest periodic separation is shorter than
the cutoff r_c (found by :func:`randmedia.periodic.pairs_within`, exact in
triclinic cells). With Y_lm the orthonormal spherical harmonics and r_hat the
bond direction:

* global order: Q_lm = (1 / N_b) sum over all N_b bonds of Y_lm(r_hat),
  Q_l = sqrt(4 pi / (2l + 1) sum_m |Q_lm|^2). A bond and its reverse give the
  same Y_lm for even l, so each bond is counted once.
* local order: q_lm(i) = (1 / N_b(i)) sum over the neighbours j of i of Y_lm(r_hat_ij),
  q_l(i) = sqrt(4 pi / (2l + 1) sum_m |q_lm(i)|^2).
* crystal-like particles (ten Wolde et al.): the normalized overlap
  d_l(i, j) = sum_m q_lm(i) q_lm(j)^* / (|q_l(i)| |q_l(j)|) of two neighbours is
  "connected" when d_6 > ``bond_threshold``; a particle is crystal-like when it has
  at least ``min_connections`` connected neighbours.

Reference values (l = 6): perfect fcc with its 12 nearest neighbours Q6 = 0.57452;
perfect bcc with its 8 + 6 first- and second-shell neighbours Q6 = 0.51069; hcp
0.48476; an uncorrelated set of bond directions gives Q6 ~ N_b^(-1/2) (each
Q_6m is a mean of N_b terms with <|Y_6m|^2> = 1/(4 pi)), i.e.
Q6 ~ (2 / (N z))^(1/2) for N particles with z neighbours each.

Defaults (the papers are silent; this is the standard practice for hard spheres):
``cutoff = 1.4 * diameter``. It lies between the first (D) and second (sqrt(2) D)
shells of fcc at contact, between the second (2 D / sqrt(3)) and third
(sqrt(8/3) D) shells of bcc at contact, and near the first minimum of g(r) of the
dense hard-sphere liquid (about 1.4-1.5 D at phi ~ 0.45-0.5). The crystal-like
criterion uses d_6 > 0.7 and at least 7 connections (the hard-sphere nucleation
convention, e.g. Auer & Frenkel, Nature 409, 1020 (2001); Filion et al.,
J. Chem. Phys. 133, 244115 (2010)): every particle of a perfect fcc, hcp or bcc
crystal is crystal-like and a liquid at phi = 0.478 has a fraction of order 1e-3.

Spherical harmonics are evaluated for m = 0..l only: q_{l,-m} = (-1)^m conj(q_lm),
so sum_{m=-l..l} a_m b_m^* = a_0 b_0 + 2 Re sum_{m>0} a_m b_m^*.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import lpmv

from randmedia.periodic import Cell, pairs_within

#: default cutoff in units of the diameter (see the module docstring)
DEFAULT_CUTOFF_OVER_D = 1.4
#: ten Wolde connection threshold on the normalized q6 . q6 overlap
DEFAULT_BOND_THRESHOLD = 0.7
#: connected neighbours a crystal-like particle needs
DEFAULT_MIN_CONNECTIONS = 7


def _cell(box) -> Cell:
    cell = box if isinstance(box, Cell) else Cell(np.asarray(box, dtype=float))
    if cell.dim != 3:
        raise ValueError(f"bond-orientational order needs a 3D cell, got dimension {cell.dim}")
    return cell


def spherical_harmonics(l: int, vectors: np.ndarray) -> np.ndarray:
    """Y_lm(r_hat) for m = 0..l of each vector, shape (n, l + 1), complex (Condon-Shortley phase)."""
    vectors = np.asarray(vectors, dtype=float).reshape(-1, 3)
    norm = np.linalg.norm(vectors, axis=1)
    if np.any(norm == 0):
        raise ValueError("zero-length bond vector (two particles at the same position)")
    cos_theta = np.clip(vectors[:, 2] / norm, -1.0, 1.0)
    phi = np.arctan2(vectors[:, 1], vectors[:, 0])
    out = np.empty((len(vectors), l + 1), dtype=complex)
    for m in range(l + 1):
        factor = math.sqrt((2 * l + 1) / (4 * math.pi) * math.factorial(l - m) / math.factorial(l + m))
        out[:, m] = factor * lpmv(m, l, cos_theta) * np.exp(1j * m * phi)
    return out


def _bonds(positions, cell: Cell, cutoff: float):
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 2 or positions.shape[1] != 3:
        raise ValueError(f"positions must have shape (n, 3), got {positions.shape}")
    if not cutoff > 0:
        raise ValueError(f"cutoff must be > 0, got {cutoff}")
    if cutoff > cell.half_width:
        raise ValueError(f"cutoff {cutoff:g} exceeds half the smallest width of the cell "
                         f"({cell.half_width:g}); neighbours would not be unique")
    i, j, separation, _ = pairs_within(cell, positions, cutoff)
    return i, j, separation


def _resolve_cutoff(cutoff, diameter):
    if not diameter > 0:
        raise ValueError(f"diameter must be > 0, got {diameter}")
    return DEFAULT_CUTOFF_OVER_D * diameter if cutoff is None else float(cutoff)


def _invariant(qlm: np.ndarray, l: int) -> np.ndarray:
    """sqrt(4 pi / (2l+1) sum_{m=-l..l} |q_lm|^2) from the m >= 0 components (last axis)."""
    power = np.abs(qlm[..., 0]) ** 2 + 2.0 * np.sum(np.abs(qlm[..., 1:]) ** 2, axis=-1)
    return np.sqrt(4.0 * math.pi / (2 * l + 1) * power)


def global_ql(positions, box, cutoff=None, *, l: int = 6, diameter: float = 1.0) -> float:
    """Global Steinhardt Q_l over every bond shorter than ``cutoff`` (default 1.4 * diameter).

    Returns NaN when there is no bond at all.

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Particle centres, in the units of ``box``.
    box : array_like, shape (3, 3), or Cell
        Periodic cell; columns (``box[:, k]``) are the lattice vectors (any periodic cell).
    cutoff : float, optional
        Bond length cutoff r_c; None: 1.4 x ``diameter``. Must not exceed half the cell's
        smallest width.
    l : int, optional
        Degree l of the spherical harmonics.
    diameter : float, optional
        Particle diameter D (units of ``box``); sets the default cutoff.

    Returns
    -------
    float
        Q_l of all bonds.
    """
    cell = _cell(box)
    cutoff = _resolve_cutoff(cutoff, diameter)
    _, _, separation = _bonds(positions, cell, cutoff)
    if len(separation) == 0:
        return float("nan")
    qlm = spherical_harmonics(l, separation).mean(axis=0)
    return float(_invariant(qlm, l))


def global_q6(positions, box, cutoff=None, *, diameter: float = 1.0) -> float:
    """Global Q6 (fcc 0.5745, bcc 0.5107, isotropic liquid ~ (N z / 2)^(-1/2)).

    ``positions`` (n, 3) in the units of ``box`` (columns = lattice vectors, any periodic
    cell); ``cutoff`` defaults to 1.4 * ``diameter`` and must not exceed half the cell's
    smallest width.

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Particle centres, in the units of ``box``.
    box : array_like, shape (3, 3), or Cell
        Periodic cell; columns (``box[:, k]``) are the lattice vectors (any periodic cell).
    cutoff : float, optional
        Bond length cutoff r_c; None: 1.4 x ``diameter``. Must not exceed half the cell's
        smallest width.
    diameter : float, optional
        Particle diameter D (units of ``box``); sets the default cutoff.

    Returns
    -------
    float
        Q_6 of all bonds (NaN without bonds).
    """
    return global_ql(positions, box, cutoff, l=6, diameter=diameter)


def local_qlm(positions, box, cutoff=None, *, l: int = 6, diameter: float = 1.0):
    """Per-particle q_lm (m = 0..l), the neighbour count, and the bond list.

    Returns (qlm, n_neighbours, i, j): qlm has shape (n, l + 1), zero for particles
    without neighbours; (i, j) are the bonded pairs (i < j).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Particle centres, in the units of ``box``.
    box : array_like, shape (3, 3), or Cell
        Periodic cell; columns (``box[:, k]``) are the lattice vectors (any periodic cell).
    cutoff : float, optional
        Bond length cutoff r_c; None: 1.4 x ``diameter``. Must not exceed half the cell's
        smallest width.
    l : int, optional
        Degree l of the spherical harmonics.
    diameter : float, optional
        Particle diameter D (units of ``box``); sets the default cutoff.

    Returns
    -------
    qlm : ndarray of complex, shape (n, l + 1)
        q_lm(i) for m = 0..l.
    n_neighbours : ndarray of int, shape (n,)
        Neighbours of each particle.
    i, j : ndarray of int, shape (n_bonds,)
        The bonded pairs, i < j.
    """
    cell = _cell(box)
    cutoff = _resolve_cutoff(cutoff, diameter)
    positions = np.asarray(positions, dtype=float)
    i, j, separation = _bonds(positions, cell, cutoff)
    n = len(positions)
    ylm = spherical_harmonics(l, separation) if len(separation) else np.zeros((0, l + 1), complex)
    sums = np.zeros((n, l + 1), dtype=complex)
    # bond i -> j has direction +r_hat, j -> i has -r_hat: Y_lm(-r) = (-1)^l Y_lm(r)
    sign = 1.0 if l % 2 == 0 else -1.0
    for m in range(l + 1):
        sums[:, m] = (np.bincount(i, weights=ylm[:, m].real, minlength=n)
                      + sign * np.bincount(j, weights=ylm[:, m].real, minlength=n)
                      + 1j * (np.bincount(i, weights=ylm[:, m].imag, minlength=n)
                              + sign * np.bincount(j, weights=ylm[:, m].imag, minlength=n)))
    count = np.bincount(i, minlength=n) + np.bincount(j, minlength=n)
    qlm = np.divide(sums, count[:, None], out=np.zeros_like(sums), where=count[:, None] > 0)
    return qlm, count, i, j


def local_q6(positions, box, cutoff=None, *, diameter: float = 1.0) -> np.ndarray:
    """Per-particle q6(i) (NaN for a particle without neighbours).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Particle centres, in the units of ``box``.
    box : array_like, shape (3, 3), or Cell
        Periodic cell; columns (``box[:, k]``) are the lattice vectors (any periodic cell).
    cutoff : float, optional
        Bond length cutoff r_c; None: 1.4 x ``diameter``. Must not exceed half the cell's
        smallest width.
    diameter : float, optional
        Particle diameter D (units of ``box``); sets the default cutoff.

    Returns
    -------
    ndarray, shape (n,)
        q6(i) per particle.
    """
    qlm, count, _, _ = local_qlm(positions, box, cutoff, l=6, diameter=diameter)
    q = _invariant(qlm, 6)
    q[count == 0] = np.nan
    return q


def crystal_like(positions, box, cutoff=None, *, diameter: float = 1.0,
                 bond_threshold: float = DEFAULT_BOND_THRESHOLD,
                 min_connections: int = DEFAULT_MIN_CONNECTIONS) -> np.ndarray:
    """Boolean mask of crystal-like particles (ten Wolde q6 . q6 criterion, module docstring).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Particle centres, in the units of ``box``.
    box : array_like, shape (3, 3), or Cell
        Periodic cell; columns (``box[:, k]``) are the lattice vectors (any periodic cell).
    cutoff : float, optional
        Bond length cutoff r_c; None: 1.4 x ``diameter``. Must not exceed half the cell's
        smallest width.
    diameter : float, optional
        Particle diameter D (units of ``box``); sets the default cutoff.
    bond_threshold : float, optional
        A neighbour pair is connected when d_6 > this value (in [-1, 1]).
    min_connections : int, optional
        Connected neighbours a crystal-like particle needs (>= 1).

    Returns
    -------
    ndarray of bool, shape (n,)
        True for crystal-like particles.
    """
    if not -1.0 <= bond_threshold <= 1.0:
        raise ValueError(f"bond_threshold must lie in [-1, 1], got {bond_threshold}")
    if min_connections < 1:
        raise ValueError(f"min_connections must be >= 1, got {min_connections}")
    qlm, count, i, j = local_qlm(positions, box, cutoff, l=6, diameter=diameter)
    n = len(count)
    norm = np.sqrt(np.abs(qlm[:, 0]) ** 2 + 2.0 * np.sum(np.abs(qlm[:, 1:]) ** 2, axis=1))
    if len(i) == 0:
        return np.zeros(n, dtype=bool)
    dot = (qlm[i, 0] * np.conj(qlm[j, 0])).real + 2.0 * np.sum(
        (qlm[i, 1:] * np.conj(qlm[j, 1:])).real, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        d6 = dot / (norm[i] * norm[j])
    connected = d6 > bond_threshold
    connections = (np.bincount(i[connected], minlength=n) + np.bincount(j[connected], minlength=n))
    return connections >= min_connections


def crystalline_fraction(positions, box, cutoff=None, *, diameter: float = 1.0,
                         bond_threshold: float = DEFAULT_BOND_THRESHOLD,
                         min_connections: int = DEFAULT_MIN_CONNECTIONS) -> float:
    """Fraction of crystal-like particles (1 for perfect fcc/hcp/bcc, ~1e-3 for the liquid).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Particle centres, in the units of ``box``.
    box : array_like, shape (3, 3), or Cell
        Periodic cell; columns (``box[:, k]``) are the lattice vectors (any periodic cell).
    cutoff : float, optional
        Bond length cutoff r_c; None: 1.4 x ``diameter``. Must not exceed half the cell's
        smallest width.
    diameter : float, optional
        Particle diameter D (units of ``box``); sets the default cutoff.
    bond_threshold : float, optional
        A neighbour pair is connected when d_6 > this value (in [-1, 1]).
    min_connections : int, optional
        Connected neighbours a crystal-like particle needs (>= 1).

    Returns
    -------
    float
        Fraction of crystal-like particles (NaN for no particles).
    """
    mask = crystal_like(positions, box, cutoff, diameter=diameter, bond_threshold=bond_threshold,
                        min_connections=min_connections)
    return float(mask.mean()) if len(mask) else float("nan")


# --------------------------------------------------------------------------- lattices


def cubic_lattice(kind: str, cells: int, nearest_distance: float = 1.0):
    """Positions and box of an fcc, bcc or sc lattice of ``cells``^3 cubic unit cells,
    scaled so that nearest neighbours are ``nearest_distance`` apart (validation cases).

    Parameters
    ----------
    kind : {"fcc", "bcc", "sc"}
        Lattice.
    cells : int
        Cubic unit cells per edge (>= 1).
    nearest_distance : float, optional
        Nearest-neighbour distance.

    Returns
    -------
    positions : ndarray, shape (n_basis * cells^3, 3)
        Lattice sites (n_basis = 4, 2, 1 for fcc, bcc, sc).
    box : ndarray, shape (3, 3)
        Cubic periodic cell, diagonal = cells x lattice constant.
    """
    basis = {
        "sc": [[0, 0, 0]],
        "bcc": [[0, 0, 0], [0.5, 0.5, 0.5]],
        "fcc": [[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]],
    }
    nearest_in_cell = {"sc": 1.0, "bcc": math.sqrt(3) / 2, "fcc": math.sqrt(0.5)}
    if kind not in basis:
        raise ValueError(f"kind must be one of {sorted(basis)}, got {kind!r}")
    if cells < 1:
        raise ValueError(f"cells must be >= 1, got {cells}")
    a = nearest_distance / nearest_in_cell[kind]
    grid = np.stack(np.meshgrid(*[np.arange(cells)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    positions = (grid[:, None, :] + np.asarray(basis[kind], dtype=float)[None]).reshape(-1, 3) * a
    return positions, np.eye(3) * a * cells
