"""Periodic cell lists: the shared building blocks of the particle neighbour searches.

A periodic box is cut into n_0 x n_1 x n_2 cells of equal *fractional* width. A
point with fractional coordinate f in [0, 1) along an axis lies in cell
min(int(f n), n - 1) (the clip catches f n rounding up to n); cells are numbered
flat = (c_0 n_1 + c_1) n_2 + c_2. Two-dimensional systems use n_2 = 1 and a third
coordinate 0 (box length 1), so every kernel here is written once for d = 2 and 3.

Storages (both filled by cell index, both numba-compatible arrays):

* **member table** (:class:`MemberTable`, :func:`insert`, :func:`remove`,
  :func:`build_members`): ``members[cell, slot]`` with ``count[cell]`` and, per
  particle, ``cell_of`` and ``slot_of``; O(1) insertion and removal, for
  configurations that change particle by particle (the hard-particle Monte Carlo
  and its random sequential addition). Orthogonal boxes, positions in [0, L).
* **sorted cells** (:class:`SortedCells`): the points of a fixed set ordered by
  cell, with ``start[flat] .. start[flat + 1]`` the points of a cell (compressed
  rows, neighbours in memory); for many queries against one set, in any
  triclinic cell, with fractional cells.

Walks:

* :func:`neighbour_cells` -- the distinct cells among the 3^d around a cell (the
  cell itself included). With cells at least as wide as the cutoff r_c and a box
  of at least 2 r_c (minimum image unique), every neighbour within r_c of a point
  lies in them; along an axis with fewer than 3 cells the images coincide and are
  listed once.
* :func:`periodic_cell` + :func:`image_cell` -- for walks that go several cells
  (and periodic images) away from the query cell: an unwrapped cell index is split
  into a lattice shift and the stored cell, and the shift becomes a Cartesian
  offset (any triclinic box; the query is given in Cartesian coordinates).
* :func:`minimum_image` -- nearest image of a coordinate difference along an
  orthogonal axis.

Sites with a different structure (see their docstrings): the event-driven
Lubachevsky-Stillinger compression keeps its doubly linked cell lists (cell
crossings are events there, the cell of a sphere is tracked, not computed);
:mod:`randmedia.generate.rsa` keeps its insertion-only head/next lists on (n, d)
points (d-generic, no capacity; the member table measured 1.2-1.8x slower there);
:func:`randmedia.periodic.pairs_within` keeps a k-d tree on padded images (all
pairs of a triclinic cell in one vectorized call, outside numba loops).

The index arithmetic is written out in :func:`cell_index` and :func:`neighbour_cells`
and the helpers kernels call per point are ``inline="always"``: a numba call with array
arguments per trial move costs up to ~40% in the Monte Carlo sweeps (measured).
Numba caches a kernel by its own source file only: after editing this module,
clear the numba cache (``.cache/numba`` of the workflow, ``__pycache__``) so that
the kernels importing it are recompiled.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.periodic import Cell

#: member-table capacity per cell: generous for non-overlapping particles in cells about
#: one diameter wide (a square of side 2 D holds at most 9 disks' centres)
CELL_CAPACITY = {2: 16, 3: 64}


# --------------------------------------------------------------------------- cell indices


@njit(cache=True)
def cell_coordinate(f, n):
    """Cell index along an axis of n cells of a fractional coordinate f in [0, 1]."""
    return min(int(f * n), n - 1)


@njit(cache=True, inline="always")
def flat_index(c0, c1, c2, ncell):
    """Flat number of cell (c0, c1, c2) in a grid of ncell[0] x ncell[1] x ncell[2] cells.

    Parameters
    ----------
    c0, c1, c2 : int
        Cell index along each axis.
    ncell : ndarray of int64, shape (3,)
        Cells per axis.

    Returns
    -------
    int
        (c0 ncell[1] + c1) ncell[2] + c2.
    """
    return (c0 * ncell[1] + c1) * ncell[2] + c2


@njit(cache=True, inline="always")
def cell_triple(flat, ncell):
    """Inverse of :func:`flat_index`: the (c0, c1, c2) of a flat cell number."""
    c2 = flat % ncell[2]
    c1 = (flat // ncell[2]) % ncell[1]
    c0 = flat // (ncell[1] * ncell[2])
    return c0, c1, c2


@njit(cache=True)
def cell_index(x, y, z, box, ncell):
    """Flat cell of the point (x, y, z) in [0, box[k]) of an orthogonal box with lengths box.

    Parameters
    ----------
    x, y, z : float
        Point coordinates (z = 0 in 2D).
    box : ndarray, shape (3,)
        Box lengths (third 1 in 2D).
    ncell : ndarray of int64, shape (3,)
        Cells per axis.

    Returns
    -------
    int
        The flat cell number.
    """
    cx = min(int(x / box[0] * ncell[0]), ncell[0] - 1)
    cy = min(int(y / box[1] * ncell[1]), ncell[1] - 1)
    cz = min(int(z / box[2] * ncell[2]), ncell[2] - 1)
    return (cx * ncell[1] + cy) * ncell[2] + cz


@njit(cache=True, inline="always")
def periodic_cell(a, n):
    """(periodic shift, wrapped index) of the unwrapped cell index a along an axis of n cells."""
    shift = math.floor(a / n)
    return shift, a - shift * n


@njit(cache=True, inline="always")
def image_cell(box, s0, s1, s2, w0, w1, w2, ncell, qc):
    """Flat index of the stored cell (w0, w1, w2) and the Cartesian offset (lattice shift
    box @ s minus the query qc) that turns its stored points into displacements from qc.

    Parameters
    ----------
    box : (3, 3) array, columns the lattice vectors.
    s0, s1, s2 : lattice shift of the image (from :func:`periodic_cell`).
    w0, w1, w2 : wrapped cell index (from :func:`periodic_cell`).
    ncell : cells per axis.
    qc : Cartesian query point (3,).

    Returns
    -------
    (flat, sh0, sh1, sh2): the displacement of stored point p is cart[p] + sh.
    """
    flat = flat_index(w0, w1, w2, ncell)
    sh0 = box[0, 0] * s0 + box[0, 1] * s1 + box[0, 2] * s2 - qc[0]
    sh1 = box[1, 0] * s0 + box[1, 1] * s1 + box[1, 2] * s2 - qc[1]
    sh2 = box[2, 0] * s0 + box[2, 1] * s1 + box[2, 2] * s2 - qc[2]
    return flat, sh0, sh1, sh2


@njit(cache=True)
def neighbour_cells(c, ncell, out):
    """Distinct cells among the 3^d around flat cell c (itself included) into out (>= 27
    entries); returns how many. Along an axis of 1 or 2 cells the images coincide and
    each cell is listed once; order: offsets -1, 0, 1 per axis, first axis slowest.

    Parameters
    ----------
    c : int
        Flat cell number.
    ncell : ndarray of int64, shape (3,)
        Cells per axis.
    out : ndarray of int64, shape (>= 27,)
        Receives the flat cell numbers.

    Returns
    -------
    int
        Number of cells written to ``out``.
    """
    cz = c % ncell[2]
    cy = (c // ncell[2]) % ncell[1]
    cx = c // (ncell[1] * ncell[2])
    n = 0
    for dx in range(-1, 2):
        if ncell[0] < 3 and (dx == -1 or (ncell[0] == 1 and dx == 1)):
            continue
        x = (cx + dx) % ncell[0]
        for dy in range(-1, 2):
            if ncell[1] < 3 and (dy == -1 or (ncell[1] == 1 and dy == 1)):
                continue
            y = (cy + dy) % ncell[1]
            for dz in range(-1, 2):
                if ncell[2] < 3 and (dz == -1 or (ncell[2] == 1 and dz == 1)):
                    continue
                z = (cz + dz) % ncell[2]
                out[n] = (x * ncell[1] + y) * ncell[2] + z
                n += 1
    return n


@njit(cache=True)
def minimum_image(d, length):
    """Nearest periodic image of a coordinate difference |d| < length (both points in the box)."""
    half = 0.5 * length
    if d > half:
        return d - length
    if d < -half:
        return d + length
    return d


# --------------------------------------------------------------------------- member table


@njit(cache=True, inline="always")
def insert(i, c, members, count, cell_of, slot_of):
    """Add particle i to flat cell c; returns False (and changes nothing) if c is full.

    Parameters
    ----------
    i : int
        Particle index.
    c : int
        Flat cell number.
    members : ndarray of int64, shape (n_cells, capacity)
        Particle indices per cell.
    count : ndarray of int64, shape (n_cells,)
        Members per cell.
    cell_of, slot_of : ndarray of int64, shape (n,)
        Cell and slot of each particle (all four arrays updated in place).

    Returns
    -------
    bool
        True if inserted.
    """
    if count[c] >= members.shape[1]:
        return False
    members[c, count[c]] = i
    cell_of[i] = c
    slot_of[i] = count[c]
    count[c] += 1
    return True


@njit(cache=True, inline="always")
def remove(i, members, count, cell_of, slot_of):
    """Take particle i out of its cell (the cell's last member moves into the hole).

    Parameters
    ----------
    i : int
        Particle index.
    members : ndarray of int64, shape (n_cells, capacity)
        Particle indices per cell.
    count : ndarray of int64, shape (n_cells,)
        Members per cell.
    cell_of, slot_of : ndarray of int64, shape (n,)
        Cell and slot of each particle (all four arrays updated in place).
    """
    c = cell_of[i]
    last = members[c, count[c] - 1]
    members[c, slot_of[i]] = last
    slot_of[last] = slot_of[i]
    count[c] -= 1


@njit(cache=True)
def build_members(pos, box, ncell, members, count, cell_of, slot_of):
    """Fill the member table with all rows of pos (orthogonal box lengths box); returns
    False if a cell overflows.

    Parameters
    ----------
    pos : ndarray, shape (n, 3)
        Positions in [0, box[k]) (third column 0 in 2D).
    box : ndarray, shape (3,)
        Orthogonal box lengths.
    ncell : ndarray of int64, shape (3,)
        Cells per axis.
    members : ndarray of int64, shape (n_cells, capacity)
        Particle indices per cell.
    count : ndarray of int64, shape (n_cells,)
        Members per cell.
    cell_of, slot_of : ndarray of int64, shape (n,)
        Cell and slot of each particle (all four arrays filled in place).

    Returns
    -------
    bool
        False if a cell overflowed (the table is then incomplete).
    """
    count[:] = 0
    for i in range(pos.shape[0]):
        if not insert(i, cell_index(pos[i, 0], pos[i, 1], pos[i, 2], box, ncell), members, count,
                      cell_of, slot_of):
            return False
    return True


class MemberTable:
    """Member-table arrays (``members``, ``count``, ``cell_of``, ``slot_of``) for ``n``
    particles in ``ncell`` cells; ``capacity`` per cell (``n`` for a single cell)."""

    def __init__(self, ncell, n: int, capacity: int):
        self.ncell = np.asarray(ncell, dtype=np.int64)
        total = int(np.prod(self.ncell))
        capacity = n if total == 1 else min(n, capacity)
        self.members = np.zeros((total, capacity), dtype=np.int64)
        self.count = np.zeros(total, dtype=np.int64)
        self.cell_of = np.zeros(n, dtype=np.int64)
        self.slot_of = np.zeros(n, dtype=np.int64)


# --------------------------------------------------------------------------- sorted cells


class SortedCells:
    """The points of a fixed 3D set sorted into n_c[0] x n_c[1] x n_c[2] fractional cells of
    a periodic (possibly triclinic) cell, about ``target_per_cell`` points per cell.

    Attributes: ``frac`` / ``cart`` (wrapped fractional / Cartesian coordinates in cell
    order), ``start`` (points of flat cell c are rows start[c]:start[c + 1]), ``n_cells``,
    ``box``, ``cell_width`` (Cartesian width of a cell across each pair of faces).
    """

    def __init__(self, positions, box, target_per_cell: float = 2.0):
        self.cell = Cell(box)
        positions = np.asarray(positions, dtype=float)
        if self.cell.dim != 3 or positions.ndim != 2 or positions.shape[1] != 3:
            raise ValueError("a cell list needs 3D positions (n, 3) and a 3x3 box")
        if len(positions) == 0:
            raise ValueError("no centres given")
        frac = self.cell.fractional(positions)
        frac -= np.floor(frac)
        frac[frac >= 1.0] = 0.0
        faces = self.cell.face_distances
        spacing = (self.cell.volume * target_per_cell / len(positions)) ** (1.0 / 3.0)
        self.n_cells = np.maximum(1, np.floor(faces / spacing)).astype(np.int64)
        index = np.floor(frac * self.n_cells).astype(np.int64)
        index = np.minimum(index, self.n_cells - 1)
        flat = (index[:, 0] * self.n_cells[1] + index[:, 1]) * self.n_cells[2] + index[:, 2]
        order = np.argsort(flat, kind="stable")
        self.frac = np.ascontiguousarray(frac[order])
        self.cart = np.ascontiguousarray(self.frac @ self.cell.box.T)
        counts = np.bincount(flat, minlength=int(np.prod(self.n_cells)))
        self.start = np.concatenate(([0], np.cumsum(counts))).astype(np.int64)
        self.box = np.ascontiguousarray(self.cell.box)
        self.cell_width = faces / self.n_cells

    def query_fractional(self, points) -> np.ndarray:
        """Fractional coordinates of query points, wrapped into [0, 1)."""
        frac = self.cell.fractional(np.asarray(points, dtype=float))
        frac -= np.floor(frac)
        frac[frac >= 1.0] = 0.0
        return np.ascontiguousarray(frac)


__all__ = [
    "CELL_CAPACITY", "cell_coordinate", "flat_index", "cell_triple", "cell_index", "periodic_cell",
    "image_cell", "neighbour_cells", "minimum_image", "insert", "remove", "build_members",
    "MemberTable", "SortedCells",
]
