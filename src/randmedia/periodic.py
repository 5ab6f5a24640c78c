"""Periodic simulation cells of any shape (orthogonal or triclinic), in 2D and 3D.

A cell is given by the matrix ``box`` whose *columns* are its lattice vectors
(the file contract of particle configurations: variable ``box`` with dims
(``xyz``, ``vec``)). A point x has fractional coordinates f = box^-1 x; the
cell is the set 0 <= f < 1 and the periodic images of x are x + box n for
integer vectors n.

Distances. The *half width* h_w of a cell is half the smallest distance
between two opposite faces, h_w = min_k 1 / (2 |b_k|) with b_k the rows of
box^-1 (the reciprocal vectors without the 2 pi). A ball of radius h_w fits in
the cell, so for a cutoff r_c <= h_w every point has at most one periodic
image of another point within r_c, and that image is the nearest one: this is
the range where minimum-image quantities are unique (e.g. the r < h_w - D of
Klatt & Torquato 2016, Eq. A8, where h_w is what the paper calls "half of the
minimum width").

:func:`pairs_within` lists every pair closer than r_c <= h_w with its
separation vector, using a k-d tree on the points padded by their images
within r_c of the cell (exact for triclinic cells, unlike a tree with a
periodic ``boxsize``, which only knows orthogonal boxes). It is called from Python
once per configuration or LP, where one vectorized tree query beats the numba cell
lists of :mod:`randmedia.cell_list` (those serve the move-by-move kernels).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree


@dataclass(frozen=True)
class Cell:
    """A periodic cell; ``box[:, k]`` is the k-th lattice vector."""

    box: np.ndarray

    def __post_init__(self):
        box = np.array(self.box, dtype=float)
        if box.ndim != 2 or box.shape[0] != box.shape[1] or box.shape[0] not in (2, 3):
            raise ValueError(f"box must be a 2x2 or 3x3 matrix of lattice vectors, got shape {box.shape}")
        if not np.all(np.isfinite(box)) or abs(np.linalg.det(box)) <= 0:
            raise ValueError("box lattice vectors must be finite and linearly independent")
        if np.linalg.det(box) < 0:
            raise ValueError("box lattice vectors must form a right-handed set (det > 0)")
        object.__setattr__(self, "box", box)

    @classmethod
    def cubic(cls, side: float, dim: int = 3) -> "Cell":
        """An orthogonal cell with all sides ``side``."""
        if side <= 0:
            raise ValueError(f"side must be > 0, got {side}")
        return cls(np.eye(dim) * float(side))

    @classmethod
    def orthogonal(cls, sides) -> "Cell":
        sides = np.asarray(sides, dtype=float)
        if np.any(sides <= 0):
            raise ValueError(f"sides must be > 0, got {sides}")
        return cls(np.diag(sides))

    @property
    def dim(self) -> int:
        return self.box.shape[0]

    @property
    def volume(self) -> float:
        return float(np.linalg.det(self.box))

    @property
    def inverse(self) -> np.ndarray:
        return np.linalg.inv(self.box)

    @property
    def face_distances(self) -> np.ndarray:
        """Distance between the two faces opposite lattice vector k, for each k."""
        return 1.0 / np.linalg.norm(self.inverse, axis=1)

    @property
    def half_width(self) -> float:
        """h_w: half the smallest distance between opposite faces (radius of the inscribed ball)."""
        return float(self.face_distances.min() / 2.0)

    def fractional(self, positions) -> np.ndarray:
        return np.asarray(positions, dtype=float) @ self.inverse.T

    def cartesian(self, fractional) -> np.ndarray:
        return np.asarray(fractional, dtype=float) @ self.box.T

    def wrap(self, positions) -> np.ndarray:
        """Positions mapped into the cell (fractional coordinates in [0, 1))."""
        f = self.fractional(positions)
        f -= np.floor(f)
        f[f >= 1.0] = 0.0  # -tiny wraps to exactly 1.0 in floating point
        return self.cartesian(f)

    def minimum_image(self, separations) -> np.ndarray:
        """The shortest periodic image of each separation vector (exact in any cell).

        Rounding the fractional separation gives the nearest image only in
        orthogonal cells; the candidates around it (all 3^d neighbours) are
        checked so the result is exact for triclinic cells too.
        """
        d = np.atleast_2d(np.asarray(separations, dtype=float))
        f = d @ self.inverse.T
        f -= np.rint(f)
        base = f @ self.box.T
        best = base.copy()
        best_norm = np.einsum("ij,ij->i", base, base)
        for shift in itertools.product((-1, 0, 1), repeat=self.dim):
            if not any(shift):
                continue
            candidate = base + self.box @ np.array(shift, dtype=float)
            norm = np.einsum("ij,ij->i", candidate, candidate)
            closer = norm < best_norm
            best[closer] = candidate[closer]
            best_norm[closer] = norm[closer]
        return best.reshape(np.shape(separations))

    def random_points(self, rng: np.random.Generator, n: int) -> np.ndarray:
        """``n`` points uniform in the cell."""
        return self.cartesian(rng.random((int(n), self.dim)))


def padded_images(cell: Cell, positions: np.ndarray, cutoff: float):
    """The points inside the cell plus every periodic image within ``cutoff`` of the cell.

    Returns (points, index): ``points[m]`` is an image of ``positions[index[m]]``; the
    first len(positions) rows are the wrapped positions themselves.

    Parameters
    ----------
    cell : Cell
        The periodic cell.
    positions : ndarray, shape (n, d)
        Cartesian points.
    cutoff : float
        Padding thickness; at most the smallest face distance of the cell.

    Returns
    -------
    points : ndarray, shape (m, d)
        Wrapped points, then their images in the padding layer.
    index : ndarray of int, shape (m,)
        Row of ``positions`` each point is an image of.
    """
    wrapped = cell.wrap(positions)
    f = cell.fractional(wrapped)
    pad = cutoff / cell.face_distances  # fractional thickness of the padding layer per axis
    if np.any(pad > 1.0):
        raise ValueError(f"cutoff {cutoff:g} exceeds a face distance of the cell "
                         f"{cell.face_distances.min():g}")
    points, index = [wrapped], [np.arange(len(wrapped))]
    for shift in itertools.product((-1, 0, 1), repeat=cell.dim):
        if not any(shift):
            continue
        shifted = f + np.array(shift, dtype=float)
        keep = np.all((shifted >= -pad) & (shifted < 1.0 + pad), axis=1)
        if keep.any():
            points.append(cell.cartesian(shifted[keep]))
            index.append(np.flatnonzero(keep))
    return np.concatenate(points), np.concatenate(index)


def pairs_within(cell: Cell, positions, cutoff: float):
    """Every pair i < j whose nearest periodic separation is shorter than ``cutoff``.

    Requires ``cutoff <= cell.half_width`` (then the nearest image is the only one
    within the cutoff). Returns (i, j, separation, distance): ``separation[m]`` is
    the vector from particle i[m] to the nearest image of particle j[m].

    Parameters
    ----------
    cell : Cell
        The periodic cell.
    positions : array_like, shape (n, d)
        Cartesian points.
    cutoff : float
        Pair cutoff, in (0, cell.half_width].

    Returns
    -------
    i, j : ndarray of int64, shape (m,)
        Pair indices, i < j, sorted by (i, j).
    separation : ndarray, shape (m, d)
        Nearest-image vector from i to j.
    distance : ndarray, shape (m,)
        Its length.
    """
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 2 or positions.shape[1] != cell.dim:
        raise ValueError(f"positions must have shape (n, {cell.dim}), got {positions.shape}")
    if not 0 < cutoff <= cell.half_width * (1 + 1e-12):
        raise ValueError(f"cutoff must lie in (0, h_w = {cell.half_width:g}], got {cutoff:g}")
    points, index = padded_images(cell, positions, cutoff)
    n = len(positions)
    neighbours = cKDTree(points[:n]).sparse_distance_matrix(
        cKDTree(points), cutoff, output_type="ndarray")
    i, m = neighbours["i"].astype(np.int64), neighbours["j"].astype(np.int64)
    j = index[m]
    # (i, nearest image of j) is found from i's side and (j, nearest image of i) from
    # j's side; for cutoff <= h_w nothing else lies within the cutoff. Keep i < j.
    keep = i < j
    i, j, m = i[keep], j[keep], m[keep]
    order = np.lexsort((j, i))
    i, j, m = i[order], j[order], m[order]
    separation = points[m] - points[i]
    return i, j, separation, np.linalg.norm(separation, axis=1)


def min_pair_distance(cell: Cell, positions, cutoff: float) -> float:
    """Smallest nearest-image centre distance among the pairs closer than ``cutoff``
    (:func:`pairs_within`, so ``cutoff <= cell.half_width``); inf if no pair is that close.

    Parameters
    ----------
    cell : Cell
        The periodic cell.
    positions : array_like, shape (n, d)
        Cartesian points.
    cutoff : float
        Pair cutoff, in (0, cell.half_width].

    Returns
    -------
    float
        The smallest pair distance below ``cutoff``, or inf.
    """
    _, _, _, distance = pairs_within(cell, positions, cutoff)
    return float(distance.min()) if distance.size else np.inf
