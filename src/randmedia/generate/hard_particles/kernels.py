"""Numba kernels of the hard-particle Monte Carlo (``cache=True``) and the cell list they use.

The cell list is the member table of :mod:`randmedia.cell_list` (O(1) insertion and
removal as particles move). Overlap checks use a cell list (cells of side >= D, the 3^d
cells around the trial position), kept up to date move by move; the contact histogram
uses its own cell list (side >= D (1 + contact_range)). Positions are stored with three columns whatever d;
for d = 2 the third column is 0 and the third box length a dummy 1 with a single cell
layer, never displaced. Every random number is drawn from the numpy Generator passed in.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.cell_list import (CELL_CAPACITY, MemberTable, build_members, cell_index, insert,
                                 minimum_image, neighbour_cells, remove)
from randmedia.generate.hard_particles.settings import ChainError


@njit(cache=True)
def _overlaps(i, x, y, z, pos, box, ncell, members, count, diameter2, scratch):
    """Whether (x, y, z), the trial position of particle i (-1: none), lies closer than
    sqrt(diameter2) to another particle (nearest image; the 3^d cells around it)."""
    n = neighbour_cells(cell_index(x, y, z, box, ncell), ncell, scratch)
    for k in range(n):
        cell = scratch[k]
        for s in range(count[cell]):
            j = members[cell, s]
            if j == i:
                continue
            dx = minimum_image(pos[j, 0] - x, box[0])
            dy = minimum_image(pos[j, 1] - y, box[1])
            dz = minimum_image(pos[j, 2] - z, box[2])
            if dx * dx + dy * dy + dz * dz < diameter2:
                return True
    return False


@njit(cache=True)
def _wrap(x, length):
    x = x - length * math.floor(x / length)
    if x >= length:
        x = 0.0
    return x


@njit(cache=True)
def sweeps(pos, unwrapped, box, dim, diameter, step, n_sweeps, ncell, members, count,
            cell_of, slot_of, rng):
    """n_sweeps x N single-particle displacement trials; returns accepted moves (-1 if a
    cell overflowed, which cannot happen for non-overlapping particles).

    Parameters
    ----------
    pos : ndarray, shape (n, 3)
        Wrapped positions, updated in place (third column 0 in 2D).
    unwrapped : ndarray, shape (n, 3)
        Unwrapped positions for the MSD, updated in place (first ``dim`` columns).
    box : ndarray, shape (3,)
        Orthogonal box lengths (third a dummy 1 in 2D).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D.
    step : float
        Half width of the uniform displacement per component.
    n_sweeps : int
        Number of sweeps (N trials each).
    ncell : ndarray of int64, shape (3,)
        Cells per axis of the member table (1 along z in 2D).
    members, count, cell_of, slot_of : ndarray of int64
        Member table of :mod:`randmedia.cell_list`, updated in place.
    rng : numpy.random.Generator
        Source of every random number.

    Returns
    -------
    int
        Number of accepted moves, or -1 on a cell overflow.
    """
    n = pos.shape[0]
    diameter2 = diameter * diameter
    scratch = np.empty(27, dtype=np.int64)
    trial = np.zeros(3)
    accepted = 0
    for _ in range(n_sweeps * n):
        i = int(rng.random() * n)
        if i >= n:
            i = n - 1
        for k in range(3):
            trial[k] = 0.0
        for k in range(dim):
            trial[k] = step * (2.0 * rng.random() - 1.0)
        x = _wrap(pos[i, 0] + trial[0], box[0])
        y = _wrap(pos[i, 1] + trial[1], box[1])
        z = _wrap(pos[i, 2] + trial[2], box[2]) if dim == 3 else pos[i, 2]
        if _overlaps(i, x, y, z, pos, box, ncell, members, count, diameter2, scratch):
            continue
        accepted += 1
        pos[i, 0] = x
        pos[i, 1] = y
        pos[i, 2] = z
        for k in range(dim):
            unwrapped[i, k] += trial[k]
        new_cell = cell_index(x, y, z, box, ncell)
        if new_cell != cell_of[i]:
            remove(i, members, count, cell_of, slot_of)
            if not insert(i, new_cell, members, count, cell_of, slot_of):
                return -1
    return accepted


@njit(cache=True)
def pair_scan(pos, box, ncell, members, count, diameter, r_max, n_bins, hist):
    """Histogram pairs with D <= r < r_max into hist (n_bins equal bins); returns
    (number of overlapping pairs r < D, smallest pair distance).

    Parameters
    ----------
    pos : ndarray, shape (n, 3)
        Positions (third column 0 in 2D).
    box : ndarray, shape (3,)
        Orthogonal box lengths.
    ncell : ndarray of int64, shape (3,)
        Cells per axis; cells must be at least ``r_max`` wide.
    members, count : ndarray of int64
        Member table of :mod:`randmedia.cell_list` built for ``pos``.
    diameter : float
        Particle diameter D, the lower edge of the histogram.
    r_max : float
        Upper edge of the histogram, D (1 + contact_range).
    n_bins : int
        Number of equal bins on [D, r_max).
    hist : ndarray of int64, shape (n_bins,)
        Incremented in place.

    Returns
    -------
    tuple (int, float)
        Number of pairs with r < D, and the smallest pair distance found (inf if no pair in
        the scanned cells).
    """
    scratch = np.empty(27, dtype=np.int64)
    overlaps = 0
    r2_min = np.inf
    width = (r_max - diameter) / n_bins
    r_max2 = r_max * r_max
    for i in range(pos.shape[0]):
        n = neighbour_cells(cell_index(pos[i, 0], pos[i, 1], pos[i, 2], box, ncell), ncell,
                            scratch)
        for k in range(n):
            cell = scratch[k]
            for s in range(count[cell]):
                j = members[cell, s]
                if j <= i:
                    continue
                dx = minimum_image(pos[j, 0] - pos[i, 0], box[0])
                dy = minimum_image(pos[j, 1] - pos[i, 1], box[1])
                dz = minimum_image(pos[j, 2] - pos[i, 2], box[2])
                r2 = dx * dx + dy * dy + dz * dz
                if r2 < r2_min:
                    r2_min = r2
                if r2 >= r_max2:
                    continue
                r = math.sqrt(r2)
                if r < diameter:
                    overlaps += 1
                    continue
                b = int((r - diameter) / width)
                if b < n_bins:
                    hist[b] += 1
    return overlaps, math.sqrt(r2_min)


@njit(cache=True)
def random_sequential_addition(pos, box, dim, diameter, ncell, members, count, cell_of, slot_of,
                               max_attempts, rng):
    """Random sequential addition of pos.shape[0] particles; returns how many were placed.

    Parameters
    ----------
    pos : ndarray, shape (n, 3)
        Filled in place with the placed positions (third column 0 in 2D).
    box : ndarray, shape (3,)
        Orthogonal box lengths (third a dummy 1 in 2D).
    dim : int
        Dimension d, 2 or 3.
    diameter : float
        Particle diameter D.
    ncell : ndarray of int64, shape (3,)
        Cells per axis of the member table (1 along z in 2D).
    members, count, cell_of, slot_of : ndarray of int64
        Member table of :mod:`randmedia.cell_list`, updated in place.
    max_attempts : int
        Number of trial insertions after which it gives up.
    rng : numpy.random.Generator
        Source of every random number.

    Returns
    -------
    int
        Number of particles placed (< n if ``max_attempts`` ran out), or -1 on a cell overflow.
    """
    diameter2 = diameter * diameter
    scratch = np.empty(27, dtype=np.int64)
    count[:] = 0
    placed = 0
    attempts = 0
    while placed < pos.shape[0] and attempts < max_attempts:
        attempts += 1
        x = rng.random() * box[0]
        y = rng.random() * box[1]
        z = rng.random() * box[2] if dim == 3 else 0.0
        if _overlaps(-1, x, y, z, pos, box, ncell, members, count, diameter2, scratch):
            continue
        pos[placed, 0] = x
        pos[placed, 1] = y
        pos[placed, 2] = z
        if not insert(placed, cell_index(x, y, z, box, ncell), members, count, cell_of, slot_of):
            return -1
        placed += 1
    return placed


class CellList(MemberTable):
    """Member table (:mod:`randmedia.cell_list`) for one box size, cells of side >= ``cutoff``."""

    def __init__(self, box3: np.ndarray, dim: int, n: int, cutoff: float):
        ncell = np.ones(3, dtype=np.int64)
        for k in range(dim):
            ncell[k] = max(1, int(math.floor(box3[k] / cutoff)))
        super().__init__(ncell, n, CELL_CAPACITY[dim])

    def build(self, pos, box3):
        if not build_members(pos, box3, self.ncell, self.members, self.count, self.cell_of,
                             self.slot_of):
            raise ChainError("cell list overflow: the configuration has overlapping particles")
