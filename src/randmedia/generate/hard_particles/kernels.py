"""Numba kernels of the hard-particle Monte Carlo (``cache=True``) and the cell list they use.

Overlap checks use a cell list (cells of side >= D, the 3^d cells around the trial
position), kept up to date move by move; the contact histogram uses its own cell list
(side >= D (1 + contact_range)). Positions are stored with three columns whatever d;
for d = 2 the third column is 0 and the third box length a dummy 1 with a single cell
layer, never displaced. Every random number is drawn from the numpy Generator passed in.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.generate.hard_particles.settings import ChainError

_CELL_CAPACITY = {2: 16, 3: 64}


@njit(cache=True)
def _cell_index(x, y, z, box, ncell):
    cx = int(x / box[0] * ncell[0])
    cy = int(y / box[1] * ncell[1])
    cz = int(z / box[2] * ncell[2])
    if cx >= ncell[0]:
        cx = ncell[0] - 1
    if cy >= ncell[1]:
        cy = ncell[1] - 1
    if cz >= ncell[2]:
        cz = ncell[2] - 1
    return (cx * ncell[1] + cy) * ncell[2] + cz


@njit(cache=True)
def _build_cells(pos, box, ncell, members, count, cell_of, slot_of):
    count[:] = 0
    for i in range(pos.shape[0]):
        c = _cell_index(pos[i, 0], pos[i, 1], pos[i, 2], box, ncell)
        if count[c] >= members.shape[1]:
            return False
        members[c, count[c]] = i
        cell_of[i] = c
        slot_of[i] = count[c]
        count[c] += 1
    return True


@njit(cache=True)
def _neighbour_cells(c, ncell, out):
    """Distinct cells around c (itself included); returns how many were written to out."""
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
def _min_image(d, length):
    """Nearest periodic image of a coordinate difference |d| < length (both points in the box)."""
    half = 0.5 * length
    if d > half:
        return d - length
    if d < -half:
        return d + length
    return d


@njit(cache=True)
def _overlaps(i, x, y, z, pos, box, ncell, members, count, diameter2, scratch):
    c = _cell_index(x, y, z, box, ncell)
    n = _neighbour_cells(c, ncell, scratch)
    for k in range(n):
        cell = scratch[k]
        for s in range(count[cell]):
            j = members[cell, s]
            if j == i:
                continue
            dx = _min_image(pos[j, 0] - x, box[0])
            dy = _min_image(pos[j, 1] - y, box[1])
            dz = _min_image(pos[j, 2] - z, box[2])
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
    cell overflowed, which cannot happen for non-overlapping particles)."""
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
        new_cell = _cell_index(x, y, z, box, ncell)
        old_cell = cell_of[i]
        if new_cell != old_cell:
            # remove from the old cell (move its last member into the hole), add to the new
            last = members[old_cell, count[old_cell] - 1]
            members[old_cell, slot_of[i]] = last
            slot_of[last] = slot_of[i]
            count[old_cell] -= 1
            if count[new_cell] >= members.shape[1]:
                return -1
            members[new_cell, count[new_cell]] = i
            slot_of[i] = count[new_cell]
            count[new_cell] += 1
            cell_of[i] = new_cell
    return accepted


@njit(cache=True)
def pair_scan(pos, box, ncell, members, count, diameter, r_max, n_bins, hist):
    """Histogram pairs with D <= r < r_max into hist (n_bins equal bins); returns
    (number of overlapping pairs r < D, smallest pair distance)."""
    scratch = np.empty(27, dtype=np.int64)
    overlaps = 0
    r2_min = np.inf
    width = (r_max - diameter) / n_bins
    r_max2 = r_max * r_max
    for i in range(pos.shape[0]):
        n = _neighbour_cells(_cell_index(pos[i, 0], pos[i, 1], pos[i, 2], box, ncell), ncell,
                             scratch)
        for k in range(n):
            cell = scratch[k]
            for s in range(count[cell]):
                j = members[cell, s]
                if j <= i:
                    continue
                dx = _min_image(pos[j, 0] - pos[i, 0], box[0])
                dy = _min_image(pos[j, 1] - pos[i, 1], box[1])
                dz = _min_image(pos[j, 2] - pos[i, 2], box[2])
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
    """Random sequential addition of pos.shape[0] particles; returns how many were placed."""
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
        c = _cell_index(x, y, z, box, ncell)
        if count[c] >= members.shape[1]:
            return -1
        members[c, count[c]] = placed
        cell_of[placed] = c
        slot_of[placed] = count[c]
        count[c] += 1
        placed += 1
    return placed


class CellList:
    """Cell-list arrays for one box size (cells of side >= ``cutoff``)."""

    def __init__(self, box3: np.ndarray, dim: int, n: int, cutoff: float):
        self.ncell = np.ones(3, dtype=np.int64)
        for k in range(dim):
            self.ncell[k] = max(1, int(math.floor(box3[k] / cutoff)))
        total = int(np.prod(self.ncell))
        capacity = n if total == 1 else min(n, _CELL_CAPACITY[dim])
        self.members = np.zeros((total, capacity), dtype=np.int64)
        self.count = np.zeros(total, dtype=np.int64)
        self.cell_of = np.zeros(n, dtype=np.int64)
        self.slot_of = np.zeros(n, dtype=np.int64)

    def build(self, pos, box3):
        if not _build_cells(pos, box3, self.ncell, self.members, self.count, self.cell_of,
                            self.slot_of):
            raise ChainError("cell list overflow: the configuration has overlapping particles")
