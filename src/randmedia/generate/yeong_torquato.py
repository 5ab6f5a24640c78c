"""Accelerated Yeong-Torquato construction of digitized two-phase media.

Ma & Torquato, PRE 102, 043310 (2020), Sec. IV. A periodic L x L image (or, beyond the
paper, an N^3 voxel image: issue 13, docs/debye3d.md) with exactly round(phi N^d)
pixels of the tracked phase is annealed towards a
target two-point function: a trial swaps one pixel of each phase (so the
volume fraction is conserved), with the Metropolis rule on the energy of
Eq. (23),

    E = sum_b [S2_b - target_b]^2 ,

summed over radial bins b = 1..n_b of width one pixel with 0 < r <= l_c
(bins are those of :class:`randmedia.numerics.radial.RadialBinning`, so the
construction targets exactly what the S2 estimator measures, sampled in *all*
directions). The target of a bin is the exact average of the target S2 over
the lattice displacements in that bin. Differences of S2 and of chi_V are
the same, so E is the chi_V energy of Eq. (23).

Acceleration. With C_b = sum_x sum_{v in b} I(x) I(x+v) and the shell counts
h_x[b] = sum_{v in b} I(x+v) kept for every pixel x, swapping p (tracked
phase -> other) with q (other -> tracked) changes

    Delta C_b = 2 (h_q[b] - h_p[b]) - 2 [|p - q| in b],

so a trial costs O(n_b); only an accepted swap pays O(l_c^2) to update h
around p and q. The straightforward alternative scans the l_c-disk around p
and q for every trial (``scan=True``; kept as the benchmark baseline and as
an independent check: both follow the same random trajectory to the
bit-identical image).

Applying an accepted swap at once would stream ~0.8 MB of h (L = 501: 25 MB of
16-bit counts, one cache line per updated pixel) through the cache per flipped
pixel. Instead the flips wait in a batch (per-stage size from the acceptance
rate, :func:`_batch_for`), bucketed by coarse cells of ~l_c/2 along each axis
(:class:`_PendingCells`); a trial adds the pending flips within l_c of its two
pixels to their stored counts (exact integers, so the trajectory is unchanged),
and a full batch is applied image row by image row, each row's counts staying
in cache. Measured at L = 501, l_c = 50 (``benchmarks/debye_yt.py``): a trial
costs ~0.7 us, an accepted swap ~13 us, the disk scan ~25 us per trial.

One implementation for 2D and 3D. The shell counts h, the stencil of
displacements 0 < |v| <= l_c with its bin columns and the batched update are
those of :mod:`randmedia.generate.yt_stencil` (:class:`~randmedia.generate.yt_stencil.Stencil`,
:func:`~randmedia.generate.yt_stencil.shell_counts`,
:func:`~randmedia.generate.yt_stencil.apply_flips_kernel`), and the trial loop
:func:`_anneal` with its lookups (pair term and pending flips through the
column table indexed by |v|^2, interface candidates with 2d face neighbours)
works on an nz x ny x nx image raveled in C order, a 2D image being one layer
(nz = 1). The 2D images are those of the former 2D-only kernels (commit e000202)
bit for bit: the trajectory depends only on the random stream, the integer
counts and the candidate-list order, which is kept (the 2D neighbours first).
The driver :func:`construct` takes L (an L x L image) or a shape (ny, nx) or
(nz, ny, nx); every scaling of the schedule uses the number of voxels N^d. The shell
counts are held in the smallest unsigned type that holds the fullest shell
(:func:`~randmedia.generate.yt_stencil.count_dtype`: uint8 in 2D up to l_c ~ 40, uint16
in 3D up to l_c ~ 72; 128^3 at l_c = 32 needs 128 MiB). Checkpoint keys of an L x L
image are those of the former 2D driver; any other shape is keyed by the shape itself,
so a 2D and a 3D checkpoint are never confused.

Phase-inversion symmetry. The kernel always tracks the minority phase
(phase 2 when phi2 <= 1/2), the initial image and every random draw depend
only on min(phi1, phi2), and the energy is that of chi_V, which both phases
share; the construction at 1 - phi2 is therefore exactly the complement of
the one at phi2 with the same seed.

Schedule (the paper fixes only the scalings, Sec. IV): total trials
``trials_per_pixel * phi1 phi2 N^d`` (N^d voxels); initial temperature
``initial_temperature * phi1 phi2 / N^d``, lowered geometrically stage by
stage to ``final_temperature_ratio`` times the initial one; the last
``refine_fraction`` of the trials draw both pixels from the interface (pixels
with a 4-neighbour of the other phase, kept in incrementally updated lists),
which removes isolated islands. If Delta S2 = mean_b |S2_b - target_b| then
exceeds the tolerance, up to ``max_extra_stages`` more refinement stages are
run at the final temperature; a construction still above tolerance raises
:class:`ConstructionError` -- it is never written as if it had converged. Each stage
logs a progress line (trials done of the schedule's, rate, ETA from the mean rate so far:
an overestimate early on, when most swaps are accepted and each pays for its update).

Long-range stages. Beyond l_c the energy says nothing, so S2 there carries the
image's own fluctuations (mean |S2 - target| over all bins 0 < r < L/2 of
~2-5 x 10^-4 at L = 501, a = 5, where the paper quotes 0.6-2 x 10^-4 without
naming the bins). ``long_range_stages`` more interface stages at the final
temperature, with the energy of Eq. (23) summed over every bin
0 < r <= ``long_range_cutoff_over_L`` L, bring it to ~10^-5 at the cost of one
shell-count table of that range (built by FFT, :func:`~randmedia.generate.yt_stencil.shell_counts`) -- the
trial cost stays O(bins). The cutoff stops short of L/2 so that the pending-flip
cells (:class:`_PendingCells`) stay a few pixels wide. No default: the paper config
runs two, the 3D study none (``long_range_stages = 0``).
"""

from __future__ import annotations

import functools
import logging
import math
import os
import time
from dataclasses import asdict, dataclass, field
from typing import Callable

import numpy as np
from numba import njit

from randmedia.checkpoint import array_digest, checkpoint_key
from randmedia.generate import refuse_invalid
from randmedia.generate.yt_stencil import Stencil, apply_flips_kernel, shell_counts
from randmedia.numerics.radial import RadialBinning, periodic_autocorrelation
from randmedia.resumable import ResumableRun

# face neighbours (dz, dy, dx) of the interface test: the 2D four first, in the order the
# 2D construction always used (candidate-list order, hence trajectories, unchanged), then z
_NEIGHBOURS = np.array([[0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1], [-1, 0, 0], [1, 0, 0]],
                       dtype=np.int64)


class ConstructionError(RuntimeError):
    """The construction did not reach the required Delta S2."""


@dataclass(frozen=True, kw_only=True)
class AnnealingSchedule:
    """Constants of the annealing schedule (see the module docstring).

    The defaults are those of the config sections ``debye2020.media.schedule`` and
    ``debye3d.media.schedule`` (schema ``workflow/schemas/yt_schedule.schema.yaml``);
    ``long_range_stages``, which the two set differently, has none (tests/test_defaults.py)."""

    trials_per_pixel: float = 40.0
    initial_temperature: float = 0.005
    final_temperature_ratio: float = 1e-3
    n_stages: int = 40
    refine_fraction: float = 0.1
    tolerance: float = 2e-4
    max_extra_stages: int = 40
    long_range_stages: int
    long_range_cutoff_over_L: float = 0.49

    def __post_init__(self):
        checks = {
            "trials_per_pixel": self.trials_per_pixel > 0,
            "initial_temperature": self.initial_temperature >= 0,
            "final_temperature_ratio": 0 < self.final_temperature_ratio <= 1,
            "n_stages": self.n_stages >= 2,
            "refine_fraction": 0 <= self.refine_fraction < 1,
            "tolerance": self.tolerance > 0,
            "max_extra_stages": self.max_extra_stages >= 0,
            "long_range_stages": isinstance(self.long_range_stages, int) and self.long_range_stages >= 0,
            "long_range_cutoff_over_L": 0 < self.long_range_cutoff_over_L < 0.5,
        }
        refuse_invalid("annealing schedule values", checks, self)


@dataclass
class Construction:
    """A finished construction: the image (1 = phase 2) and how it got there."""

    image: np.ndarray
    delta_s2: float
    energy: float
    s2: np.ndarray  # S2 of phase 2 per bin, bins 0..n_b
    target: np.ndarray  # target S2 of phase 2 per bin
    r: np.ndarray  # mean distance per bin
    stats: dict = field(default_factory=dict)


# --------------------------------------------------------------------------- kernels
# Voxel x of an nz x ny x nx image is raveled in C order; a 2D image is one layer (nz = 1).


@njit(cache=True, inline="always")
def _coordinates(x, shape):
    """(z, y, x) of the raveled voxel index x."""
    nz, ny, nx = shape
    if nz == 1:  # 2D: no division for the layer
        z = 0
        rest = x
    else:
        z = x // (ny * nx)
        rest = x - z * (ny * nx)
    y = rest // nx
    return z, y, rest - y * nx


@njit(cache=True, inline="always")
def _wrap(i, n):
    """Coordinate i (-n <= i < 2n) on a periodic axis of n voxels."""
    if i < 0:
        return i + n
    if i >= n:
        return i - n
    return i


@njit(cache=True, inline="always")
def _shifted(z, y, x, dz, dy, dx, shape):
    """Raveled index of voxel (z, y, x) shifted by (dz, dy, dx) periodically (|d| < n per axis)."""
    nz, ny, nx = shape
    return (_wrap(z + dz, nz) * ny + _wrap(y + dy, ny)) * nx + _wrap(x + dx, nx)


@njit(cache=True, inline="always")
def _minimal(d, n):
    """Minimal periodic image of a coordinate difference d (|d| < n) on an axis of n voxels."""
    if d > n // 2:
        return d - n
    if d < -(n // 2):
        return d + n
    return d


@njit(cache=True)
def _scan_counts(image, z, y, x, shape, offsets, column, out):
    """out[c] = tracked voxels at displacements of bin c+1 from (z, y, x), by scanning the
    l_c-ball (the benchmark baseline)."""
    out[:] = 0
    for k in range(offsets.shape[0]):
        out[column[k]] += image[_shifted(z, y, x, offsets[k, 0], offsets[k, 1], offsets[k, 2], shape)]


@njit(cache=True, inline="always")
def _pair_column(p_at, q_at, shape, column_of_d2):
    """Bin column of the minimal-image displacement q - p (coordinates p_at, q_at), or -1
    beyond l_c (``column_of_d2`` of :class:`~randmedia.generate.yt_stencil.Stencil`)."""
    dz = _minimal(q_at[0] - p_at[0], shape[0])
    dy = _minimal(q_at[1] - p_at[1], shape[1])
    dx = _minimal(q_at[2] - p_at[2], shape[2])
    return column_of_d2[min(dz * dz + dy * dy + dx * dx, column_of_d2.shape[0] - 1)]


@njit(cache=True, inline="always")
def _neighbour(at, n, shape):
    """Raveled index of face neighbour n (a row of ``_NEIGHBOURS``) of the voxel at ``at``."""
    return _shifted(at[0], at[1], at[2], _NEIGHBOURS[n, 0], _NEIGHBOURS[n, 1], _NEIGHBOURS[n, 2],
                    shape)


@njit(cache=True)
def _is_candidate(image, x, shape, interface_only):
    """Can x be drawn? Every voxel, or in interface mode only those with a face neighbour
    of the other phase (2d neighbours)."""
    if not interface_only:
        return True
    at = _coordinates(x, shape)
    for n in range(4 if shape[0] == 1 else 6):
        if image[_neighbour(at, n, shape)] != image[x]:
            return True
    return False


@njit(cache=True)
def _list_add_if_candidate(image, x, shape, interface_only, members, sizes, slot):
    if _is_candidate(image, x, shape, interface_only):
        ph = image[x]
        members[ph, sizes[ph]] = x
        slot[x] = sizes[ph]
        sizes[ph] += 1


@njit(cache=True)
def _build_lists(image, shape, interface_only, members, sizes, slot):
    """members[phase, :sizes[phase]] = candidate voxels of each phase; slot = position or -1."""
    sizes[0] = 0
    sizes[1] = 0
    slot[:] = -1
    for x in range(image.shape[0]):
        _list_add_if_candidate(image, x, shape, interface_only, members, sizes, slot)


@njit(cache=True)
def _list_remove(members, sizes, slot, ph, x):
    s = slot[x]
    last = members[ph, sizes[ph] - 1]
    members[ph, s] = last
    slot[last] = s
    sizes[ph] -= 1
    slot[x] = -1


@njit(cache=True)
def _refresh(image, x, shape, old_phase, interface_only, members, sizes, slot):
    if slot[x] >= 0:
        _list_remove(members, sizes, slot, old_phase, x)
    _list_add_if_candidate(image, x, shape, interface_only, members, sizes, slot)


class _PendingCells:
    """Coarse cells along one image axis of ``side`` voxels, for looking up pending flips
    near a voxel (one per axis; an axis of one voxel, z of a 2D image, has one cell).

    Coordinate i lies in cell ``cell_of[i]`` (``count`` cells of equal width to within one
    voxel, at most ``width``: a cell no wider than the part of the ring outside a window
    is never met at both ends of it, while a wider last cell could be, e.g. at L = 110,
    l_c = 50). ``near[i, :n_near[i]]`` are the cells meeting the window [i - l_c, i + l_c]
    (periodic, each once); ``gap[i, a]`` is the distance from i to the nearest coordinate
    of cell ``near[i, a]`` in that window (cells farther than l_c over all axes together
    are skipped) and ``shift[i, a]`` (0 or +-side) turns a coordinate in that cell into
    its periodic image nearest to i.
    """

    def __init__(self, side: int, cutoff: int, width: int):
        self.width = max(1, int(width))
        self.count = -(-side // self.width)
        cell_of = np.arange(side) * self.count // side
        window = np.arange(-cutoff, cutoff + 1) if side > 1 else np.zeros(1, dtype=np.int64)
        near = np.full((side, self.count), -1, dtype=np.int64)
        gap = np.zeros((side, self.count), dtype=np.int64)
        shift = np.zeros((side, self.count), dtype=np.int64)
        n_near = np.zeros(side, dtype=np.int64)
        for i in range(side):
            unwrapped = i + window
            cells = cell_of[unwrapped % side]
            for cell in np.unique(cells):
                mine = cells == cell
                shifts = np.unique(unwrapped[mine] - unwrapped[mine] % side)
                if shifts.size != 1:
                    raise AssertionError("a cell straddles the periodic boundary")
                near[i, n_near[i]] = cell
                gap[i, n_near[i]] = np.abs(window[mine]).min()
                shift[i, n_near[i]] = shifts[0]
                n_near[i] += 1
        self.cell_of = cell_of.astype(np.int64)
        self.near, self.gap, self.shift, self.n_near = near, gap, shift, n_near

    def arrays(self):
        return self.count, self.cell_of, self.near, self.gap, self.shift, self.n_near


@njit(cache=True, inline="always")
def _cell_of(at, cells):
    """Pending-flip cell of the voxel at coordinates ``at`` (``cells``: one
    :meth:`_PendingCells.arrays` per axis)."""
    return (cells[0][1][at[0]] * cells[1][0] + cells[1][1][at[1]]) * cells[2][0] + cells[2][1][at[2]]


@njit(cache=True, inline="always")
def _counts_now(h, x, at, reach, column_of_d2, cells, bucket_z, bucket_y, bucket_x, bucket_sign,
                bucket_size, out):
    """out[1:] = current shell counts of voxel x (coordinates ``at``): the stored h[x] plus
    the pending (not yet applied) flips within l_c, read from the buckets of the coarse
    cells near x.

    Branch-free inner loop: the squared displacement is clamped to the sentinel entry
    of ``column_of_d2`` (column -1), and a flip lands in out[column + 1], so flips
    beyond l_c (or at the voxel itself, column -1 too) only add to the discarded out[0].
    """
    near_z, gap_z, shift_z, n_near_z = cells[0][2], cells[0][3], cells[0][4], cells[0][5]
    n_y, near_y, gap_y, shift_y, n_near_y = cells[1][0], cells[1][2], cells[1][3], cells[1][4], cells[1][5]
    n_x, near_x, gap_x, shift_x, n_near_x = cells[2][0], cells[2][2], cells[2][3], cells[2][4], cells[2][5]
    for c in range(h.shape[1]):
        out[c + 1] = h[x, c]
    z, y, xx = at
    limit = column_of_d2.shape[0] - 1
    for a in range(n_near_z[z]):
        gz2 = gap_z[z, a] * gap_z[z, a]
        layer = near_z[z, a] * n_y
        origin_z = shift_z[z, a] - z
        for b in range(n_near_y[y]):
            gy2 = gz2 + gap_y[y, b] * gap_y[y, b]
            if gy2 > reach:
                continue
            row = (layer + near_y[y, b]) * n_x
            origin_y = shift_y[y, b] - y
            for c in range(n_near_x[xx]):
                cell = row + near_x[xx, c]
                size = bucket_size[cell]
                if size == 0:
                    continue
                if gy2 + gap_x[xx, c] * gap_x[xx, c] > reach:
                    continue
                origin_x = shift_x[xx, c] - xx
                for e in range(size):
                    dz = bucket_z[cell, e] + origin_z
                    dy = bucket_y[cell, e] + origin_y
                    dx = bucket_x[cell, e] + origin_x
                    out[column_of_d2[min(dz * dz + dy * dy + dx * dx, limit)] + 1] += bucket_sign[cell, e]


@njit(cache=True)
def _anneal(image, h, diff, n_trials, temperature, interface_only, scan, rng, batch, norm, shape,
            offsets, column, column_of_d2, flip_arrays, cells):
    """Run ``n_trials`` Metropolis swap trials on the energy of Eq. (23) in place; returns
    the number accepted. The arguments after ``batch`` are :meth:`_Geometry.kernel_args`.

    Accepted swaps are not applied to the shell counts h at once: up to ``batch``
    flips wait in a list bucketed by coarse cells, trials add the pending flips
    within l_c to the stored counts (exact integers, so the trajectory is the same as
    with immediate updates), and full batches are applied by
    :func:`~randmedia.generate.yt_stencil.apply_flips_kernel`. h is up to date when the
    function returns.
    """
    n_columns = diff.shape[0]
    n_voxels = image.shape[0]
    members = np.empty((2, n_voxels), dtype=np.int32)
    sizes = np.zeros(2, dtype=np.int64)
    slot = np.empty(n_voxels, dtype=np.int32)
    _build_lists(image, shape, interface_only, members, sizes, slot)
    hp = np.empty(n_columns + 1, dtype=np.int64)  # hp[c + 1]: count of column c; hp[0] unused
    hq = np.empty(n_columns + 1, dtype=np.int64)
    nz, ny, nx = shape
    cutoff, reach_y, run_first, run_count, run_lo, run_hi, run_dx0, run_address = flip_arrays
    reach = cutoff * cutoff
    n_cells = cells[0][0] * cells[1][0] * cells[2][0]
    # pending flips: in order of acceptance (applied by apply_flips_kernel) and, for the
    # lookups, copied into per-cell buckets; a full bucket triggers an early flush
    pending = np.empty(batch, dtype=np.int64)
    signs = np.empty(batch, dtype=np.int16)
    capacity = max(16, 4 * batch // n_cells)
    bucket_z = np.empty((n_cells, capacity), dtype=np.int32)
    bucket_y = np.empty((n_cells, capacity), dtype=np.int32)
    bucket_x = np.empty((n_cells, capacity), dtype=np.int32)
    bucket_sign = np.empty((n_cells, capacity), dtype=np.int8)
    bucket_size = np.zeros(n_cells, dtype=np.int64)
    n_pending = 0
    accepted = 0
    beta = 1.0 / temperature if temperature > 0 else np.inf
    for _ in range(n_trials):
        if sizes[0] == 0 or sizes[1] == 0:
            break
        p = members[1, int(rng.random() * sizes[1])]
        q = members[0, int(rng.random() * sizes[0])]
        p_at = _coordinates(p, shape)
        q_at = _coordinates(q, shape)
        if scan:
            _scan_counts(image, p_at[0], p_at[1], p_at[2], shape, offsets, column, hp[1:])
            _scan_counts(image, q_at[0], q_at[1], q_at[2], shape, offsets, column, hq[1:])
        elif n_pending == 0:
            for c in range(n_columns):
                hp[c + 1] = h[p, c]
                hq[c + 1] = h[q, c]
        else:
            _counts_now(h, p, p_at, reach, column_of_d2, cells, bucket_z, bucket_y, bucket_x,
                        bucket_sign, bucket_size, hp)
            _counts_now(h, q, q_at, reach, column_of_d2, cells, bucket_z, bucket_y, bucket_x,
                        bucket_sign, bucket_size, hq)
        # Delta C_b = 2 (h_q[b] - h_p[b]) - 2 [|p - q| in b]: fold the pair term into h_q
        pair = _pair_column(p_at, q_at, shape, column_of_d2)
        if pair >= 0:
            hq[pair + 1] -= 1
        d_energy = 0.0
        for c in range(n_columns):
            d = 2 * (hq[c + 1] - hp[c + 1]) * norm[c]
            d_energy += d * (2.0 * diff[c] + d)
        if d_energy > 0.0:
            if beta == np.inf or rng.random() >= math.exp(-d_energy * beta):
                continue
        accepted += 1
        for c in range(n_columns):
            diff[c] += 2 * (hq[c + 1] - hp[c + 1]) * norm[c]
        image[p] = 0
        image[q] = 1
        if not scan:
            cell_p = _cell_of(p_at, cells)
            cell_q = _cell_of(q_at, cells)
            if (n_pending + 2 > batch or bucket_size[cell_p] + 2 > capacity
                    or bucket_size[cell_q] + 2 > capacity):
                apply_flips_kernel(h, nz, ny, nx, pending, signs, n_pending, cutoff, reach_y,
                                   run_first, run_count, run_lo, run_hi, run_dx0, run_address)
                n_pending = 0
                bucket_size[:] = 0
            for x, at, sign, cell in ((p, p_at, -1, cell_p), (q, q_at, 1, cell_q)):
                pending[n_pending] = x
                signs[n_pending] = sign
                n_pending += 1
                e = bucket_size[cell]
                bucket_z[cell, e] = at[0]
                bucket_y[cell, e] = at[1]
                bucket_x[cell, e] = at[2]
                bucket_sign[cell, e] = sign
                bucket_size[cell] = e + 1
        # p left the tracked phase (1 -> 0), q joined it (0 -> 1)
        _refresh(image, p, shape, 1, interface_only, members, sizes, slot)
        _refresh(image, q, shape, 0, interface_only, members, sizes, slot)
        if interface_only:
            for at in (p_at, q_at):
                for n in range(4 if nz == 1 else 6):
                    nb = _neighbour(at, n, shape)
                    if nb != p and nb != q:
                        _refresh(image, nb, shape, image[nb], interface_only, members, sizes, slot)
    if not scan:
        apply_flips_kernel(h, nz, ny, nx, pending, signs, n_pending, cutoff, reach_y, run_first,
                           run_count, run_lo, run_hi, run_dx0, run_address)
    return accepted


# --------------------------------------------------------------------------- driver


class _Geometry:
    """Stencil, bins, pending-flip cells and normalization for an image of ``shape``
    (L x L, or nz x ny x nx) and cutoff l_c."""

    def __init__(self, shape, cutoff: float):
        self.stencil = Stencil(shape, cutoff)
        self.shape = self.stencil.shape
        self.binning = self.stencil.binning
        self.n_columns = self.stencil.n_columns
        self.cutoff = self.stencil.cutoff
        # pending-flip lookup cells about l_c / 2 wide along each axis: in 2D the cells met
        # by a pixel's l_c-disk cover about twice the disk's area (3 x 3 cells of width l_c:
        # ~3x); no wider than the part of the ring outside a voxel's window, so that no cell
        # is met at both ends of it (matters only for l_c close to L/2, where the cells get
        # narrow and many: keep L >= 2.5 l_c + 1 for speed, in 3D especially)
        per_length = {n: _PendingCells(n, self.cutoff,
                                       min((self.cutoff + 1) // 2, n - 2 * self.cutoff - 1)).arrays()
                      for n in set(self.stencil.shape3)}
        self.cells = tuple(per_length[n] for n in self.stencil.shape3)
        # S2_b = C_b / (N^d n_b)
        self.norm = 1.0 / (int(np.prod(self.shape)) * self.binning.counts[1:].astype(float))

    def kernel_args(self) -> tuple:
        """The arguments of :func:`_anneal` after ``batch``."""
        s = self.stencil
        return (self.norm, s.shape3, s.offsets, s.column, s.column_of_d2, s.kernel_arrays(),
                self.cells)

    def shell_counts(self, image_flat: np.ndarray, scan: bool = False) -> np.ndarray:
        """Shell counts h of every voxel (:func:`~randmedia.generate.yt_stencil.shell_counts`),
        or with ``scan`` a placeholder (the disk-scan baseline keeps none)."""
        if scan:
            return np.zeros((1, self.n_columns), dtype=self.stencil.count_dtype)
        return shell_counts(image_flat.reshape(self.shape), self.stencil)

    def s2(self, image_flat: np.ndarray, counts: np.ndarray | None = None) -> np.ndarray:
        """S2 of the tracked phase per bin (0..n_b), exactly, from the shell counts
        (recounted from the image unless ``counts`` are given). Summed in chunks of voxels
        (exact integers), so that no int64 copy of the tracked voxels' counts is made
        (268 MB at 128^3, l_c = 32, twice the counts themselves)."""
        if counts is None:
            counts = self.shell_counts(image_flat)
        pair_sums = np.zeros(self.n_columns, dtype=np.int64)
        chunk = 1 << 16
        for start in range(0, image_flat.size, chunk):
            mine = image_flat[start:start + chunk] == 1
            pair_sums += counts[start:start + chunk][mine].sum(axis=0, dtype=np.int64)
        return np.concatenate([[image_flat.mean()], pair_sums * self.norm])

    def describe(self) -> str:
        """One log line: bins, stencil, count type and memory, pending-flip cells."""
        cells = "x".join(str(c[0]) for c in self.cells[3 - len(self.shape):])
        return (f"{self.n_columns} bins 0 < r <= {self.cutoff}, stencil {self.stencil.offsets.shape[0]} "
                f"voxels, fullest shell {self.stencil.largest_shell} -> {self.stencil.count_dtype} "
                f"shell counts {self.stencil.counts_bytes() / 2**20:.0f} MiB, pending-flip cells {cells}")


def _batch_for(acceptance: float, largest: int) -> int:
    """Pending flips per batch for a stage, from the last stage's acceptance rate.

    A trial pays for looking up the pending flips near its two pixels (cost ~ batch)
    and an accepted swap for its share of a batch update (cost ~ a + b / batch), so the
    cheapest batch grows like sqrt(acceptance): 4096 flips at 40 % acceptance, 256 at
    0.3 % (measured at L = 501, l_c = 50). Performance only: the trajectory is the same
    for every batch size.
    """
    best = 6500.0 * math.sqrt(max(acceptance, 1e-12))
    return int(min(largest, max(256, 2 ** round(math.log2(best)))))


def image_shape(side) -> tuple[int, ...]:
    """The image shape of ``side``: an integer L (an L x L image, as in the paper) or a
    shape (ny, nx) or (nz, ny, nx) of integers >= 4; ValueError otherwise."""
    def integer(n):
        return isinstance(n, (int, np.integer)) and not isinstance(n, (bool, np.bool_))

    if integer(side):
        if side < 4:
            raise ValueError(f"L must be an integer >= 4 pixels (the image is L x L), got {side!r}")
        return (int(side), int(side))
    if isinstance(side, (tuple, list, np.ndarray)):
        shape = tuple(side)
        if len(shape) in (2, 3) and all(integer(n) and n >= 4 for n in shape):
            return tuple(int(n) for n in shape)
        raise ValueError(f"the image shape must be (ny, nx) or (nz, ny, nx), 2 or 3 integers "
                         f">= 4 voxels, got {side!r}")
    raise ValueError(f"L must be an integer >= 4 pixels (the image is L x L), or the image "
                     f"shape (ny, nx) or (nz, ny, nx), got {side!r}")


def _validate(phi2: float, shape: tuple[int, ...], cutoff: float) -> None:
    if not 0.0 < phi2 < 1.0:
        raise ValueError(f"phi2 must lie in (0, 1), got {phi2}")
    shortest = min(shape)
    if not 1.0 <= cutoff < shortest / 2:
        raise ValueError(f"cutoff l_c must satisfy 1 <= l_c < L/2 = {shortest / 2:g} "
                         f"(L the shortest side of the {'x'.join(map(str, shape))} image), got {cutoff}")


def tracked_target(target_s2: Callable, phi2: float, binning: RadialBinning) -> tuple[float, np.ndarray]:
    """(phi of the tracked minority phase, its target S2 per bin as the exact bin average).

    ``target_s2`` is S2 of phase 2; for the minority phase 1 the target is
    phi1^2 + chi_V(r) with chi_V = S2^(2) - phi2^2.

    Parameters
    ----------
    target_s2 : callable
        r (ndarray, pixels) -> S2 of phase 2 at r; S2(0) must equal ``phi2``.
    phi2 : float
        Volume fraction of phase 2.
    binning : RadialBinning
        Radial bins of the estimator (width one pixel).

    Returns
    -------
    phi : float
        Volume fraction of the tracked phase, min(phi2, 1 - phi2).
    target : ndarray, shape (n_bins,)
        phi^2 + bin average of chi_V, one entry per bin of ``binning``.
    """
    at_zero = float(target_s2(np.array([0.0]))[0])
    if not math.isclose(at_zero, phi2, rel_tol=1e-6, abs_tol=1e-9):
        raise ValueError(f"target S2(0) = {at_zero:g} must equal phi2 = {phi2:g}")
    phi = min(phi2, 1.0 - phi2)

    def chi(r):
        return np.asarray(target_s2(r), dtype=float) - phi2 * phi2

    return phi, phi * phi + binning.average_of(chi)


def construct(
    target_s2: Callable[[np.ndarray], np.ndarray],
    phi2: float,
    side,
    cutoff: float,
    rng: np.random.Generator,
    schedule: AnnealingSchedule,
    *,
    checkpoint: str | os.PathLike | None = None,
    checkpoint_seconds: float = 30.0,
    log: logging.Logger | None = None,
    scan: bool = False,
    batch: int = 4096,
) -> Construction:
    """Construct a periodic image (1 = phase 2) with S2 of phase 2 close to ``target_s2``.

    Parameters
    ----------
    target_s2 : callable
        S2 of phase 2 as a function of r (pixels); S2(0) must equal ``phi2``.
    phi2 : float
        Volume fraction of phase 2, in (0, 1).
    side : int or tuple
        L for an L x L image (the paper's 2D media), or the image shape (ny, nx) or
        (nz, ny, nx) -- e.g. (N, N, N) for 3D media (:func:`image_shape`). Every count of the
        schedule scales with the number of voxels N^d (trials, temperature), so a 2D
        construction is the same whichever way its shape is given, and bit-identical to the
        former 2D-only driver.
    cutoff : float
        l_c: the energy sums the bins 0 < r <= l_c.
    rng : numpy.random.Generator
        The construction's only source of randomness.
    schedule : AnnealingSchedule
        Trials, temperatures, refinement, tolerance, extra and long-range stages.
    checkpoint : path, optional
        File to save the state to (image + random state, at stage boundaries, at most every
        ``checkpoint_seconds``) and to resume from if it exists and belongs to the same
        construction (same parameters, shape and dimension included, and start state); removed
        on success. Saving, resuming and the per-stage progress lines are
        :class:`randmedia.resumable.ResumableRun`'s.
    log : logging.Logger, optional
        Gets a progress line per stage.
    scan : bool
        Use the straightforward per-trial disk scan (benchmark baseline).
    batch : int
        Voxel flips (two per accepted swap) collected before they are applied to the shell
        counts; a performance knob only -- any value gives the same image.

    Returns
    -------
    Construction
        The image, its Delta S2, energy, S2 and target per bin, and the run's statistics
        (``stats``: trials, accepted swaps and per-stage records of this process's stages).

    Raises
    ------
    ConstructionError
        If Delta S2 still exceeds ``schedule.tolerance`` after the extra stages.
    """
    if not isinstance(batch, (int, np.integer)) or batch < 2:
        raise ValueError(f"batch must be an integer >= 2, got {batch!r}")
    shape = image_shape(side)
    _validate(phi2, shape, cutoff)
    log = log or logging.getLogger(__name__)
    geometry = _Geometry(shape, cutoff)
    phi, target = tracked_target(target_s2, phi2, geometry.binning)
    n_pixels = int(np.prod(shape))
    n_tracked = int(round(phi * n_pixels))
    name = "x".join(map(str, shape))
    if n_tracked == 0:
        raise ValueError(f"phi2 = {phi2} leaves no voxel of the minority phase on {name} voxels")
    weight = phi * (1.0 - phi)
    total_trials = int(schedule.trials_per_pixel * weight * n_pixels)
    t_initial = schedule.initial_temperature * weight / n_pixels
    n_refine = int(round(schedule.refine_fraction * schedule.n_stages))
    n_cool = schedule.n_stages - n_refine
    trials_per_stage = max(1, total_trials // schedule.n_stages)

    def temperature(stage: int) -> float:
        k = min(stage, n_cool - 1)
        return t_initial * schedule.final_temperature_ratio ** (k / max(1, n_cool - 1))

    key = _checkpoint_key(phi2, shape, cutoff, target, schedule, rng, scan)
    run = ResumableRun(checkpoint, key, log, rng=rng, checkpoint_seconds=checkpoint_seconds, log_seconds=0.0)
    resumed = run.resume(functools.partial(_restore, n_voxels=n_pixels))
    # the stats count the whole construction, the parts before a resume included
    accepted_total = long_range_accepted = 0
    if resumed is not None:
        stage, long_range_done, image, accepted_before = resumed
        log.info("resumed from %s at stage %d (+ %d long-range stages)", checkpoint, stage, long_range_done)
        if accepted_before is None:
            log.warning("%s predates the saved swap counts: 'accepted' counts only the swaps "
                        "after this resume", checkpoint)
        else:
            accepted_total, long_range_accepted = accepted_before
    else:
        stage, long_range_done = 0, 0
        image = np.zeros(n_pixels, dtype=np.uint8)
        image[rng.permutation(n_pixels)[:n_tracked]] = 1

    log.info("YT construction %s, phi2 = %g, %s; %d stages of %d trials", name, phi2,
             geometry.describe(), schedule.n_stages, trials_per_stage)
    h = geometry.shell_counts(image, scan)
    diff = geometry.s2(image, None if scan else h)[1:] - target[1:]
    trials_done = (stage + long_range_done) * trials_per_stage
    last_stage = schedule.n_stages + schedule.max_extra_stages
    delta_s2 = float(np.mean(np.abs(diff)))
    stage_batch = batch
    # one line per stage (the driver's log_seconds = 0)
    progress = run.progress(schedule.n_stages * trials_per_stage, f"YT {name}", "trials",
                            done=min(stage, schedule.n_stages) * trials_per_stage)
    per_stage = []  # this process's stages: trials, accepted, wall and CPU seconds, Delta S2

    def saved() -> dict:
        return {"stage": stage, "long_range_done": long_range_done, "image": image,
                "accepted": accepted_total, "long_range_accepted": long_range_accepted}

    def annealed() -> bool:
        # (resumed in a long-range stage: done)
        return (stage >= last_stage or long_range_done > 0
                or (stage >= schedule.n_stages and delta_s2 <= schedule.tolerance))

    def anneal_stage() -> None:
        nonlocal stage, trials_done, accepted_total, stage_batch, delta_s2
        tic, cpu = time.perf_counter(), time.process_time()
        accepted = _anneal(image, h, diff, trials_per_stage, temperature(stage), stage >= n_cool,
                           scan, rng, stage_batch, *geometry.kernel_args())
        stage += 1
        elapsed = time.perf_counter() - tic
        per_stage.append({"stage": stage, "trials": trials_per_stage, "accepted": int(accepted),
                          "seconds": elapsed, "cpu_seconds": time.process_time() - cpu,
                          "delta_s2": float(np.mean(np.abs(diff)))})
        trials_done += trials_per_stage
        accepted_total += accepted
        stage_batch = _batch_for(accepted / trials_per_stage, batch)
        delta_s2 = float(np.mean(np.abs(diff)))
        progress.step(trials_per_stage, detail=(
            f"stage {stage}/{schedule.n_stages} T={temperature(stage - 1):.3g}: {elapsed:.3g} s, "
            f"{trials_per_stage / elapsed:.3g} trials/s, acceptance {accepted / trials_per_stage:.4f}, "
            f"E={float(np.sum(diff**2)):.4g}, dS2={delta_s2:.3g}"))

    run.loop(anneal_stage, annealed, saved)

    if long_range_done < schedule.long_range_stages and (delta_s2 <= schedule.tolerance
                                                         or long_range_done > 0):
        h = None  # (frees the shell counts before the long-range table is built)
        far = _Geometry(shape, math.floor(schedule.long_range_cutoff_over_L * min(shape)))
        _, far_target = tracked_target(target_s2, phi2, far.binning)
        tic = time.perf_counter()
        far_h = far.shell_counts(image, scan)
        far_diff = far.s2(image, None if scan else far_h)[1:] - far_target[1:]
        log.info("long-range stages: bins 0 < r <= %d, shell counts in %.1f s, dS2 = %.3g",
                 far.cutoff, time.perf_counter() - tic, float(np.mean(np.abs(far_diff))))

        def long_range_stage() -> None:
            nonlocal long_range_done, trials_done, long_range_accepted, stage_batch
            tic = time.perf_counter()
            accepted = _anneal(image, far_h, far_diff, trials_per_stage, temperature(n_cool - 1), True,
                               scan, rng, stage_batch, *far.kernel_args())
            long_range_done += 1
            trials_done += trials_per_stage
            long_range_accepted += accepted
            stage_batch = _batch_for(accepted / trials_per_stage, batch)
            log.info("long-range stage %d/%d: %.3g trials/s, acceptance %.4f, dS2 (r <= %d) = %.3g",
                     long_range_done, schedule.long_range_stages,
                     trials_per_stage / (time.perf_counter() - tic), accepted / trials_per_stage,
                     far.cutoff, float(np.mean(np.abs(far_diff))))

        run.loop(long_range_stage, lambda: long_range_done >= schedule.long_range_stages, saved)
        far_h = None
    accepted_total += long_range_accepted  # (saved apart: the checkpoints hold both counts)
    h = None  # (frees the shell counts before the FFT)

    # final S2 from the FFT estimator: independent of the incremental bookkeeping
    s2_tracked = geometry.binning.average(periodic_autocorrelation(image.reshape(shape)))
    delta_s2 = float(np.mean(np.abs(s2_tracked[1:] - target[1:])))
    stats = {"trials": trials_done, "accepted": accepted_total, "stages": stage,
             "long_range_stages": long_range_done, "long_range_accepted": long_range_accepted,
             "seconds": run.seconds, "cpu_seconds": run.cpu_seconds, "schedule": asdict(schedule),
             "per_stage": per_stage}
    if delta_s2 > schedule.tolerance:
        raise ConstructionError(
            f"construction did not converge: Delta S2 = {delta_s2:.3g} > tolerance "
            f"{schedule.tolerance:g} after {stage} stages (phi2 = {phi2}, {name} voxels, l_c = {cutoff})"
        )
    run.finish()
    tracked_is_phase2 = phi2 <= 0.5
    phase2 = image if tracked_is_phase2 else 1 - image
    # the measured S2 complements with the image's own fraction (s2_tracked[0]; round(phi N^d)
    # voxels, not exactly phi), the target with the nominal one
    s2_phase2 = s2_tracked if tracked_is_phase2 else _complement_s2(s2_tracked, s2_tracked[0])
    target_phase2 = target if tracked_is_phase2 else _complement_s2(target, phi)
    return Construction(
        image=phase2.reshape(shape).astype(np.uint8),
        delta_s2=delta_s2,
        energy=float(np.sum((s2_tracked[1:] - target[1:]) ** 2)),
        s2=s2_phase2,
        target=target_phase2,
        r=geometry.binning.r_mean,
        stats=stats,
    )


def _complement_s2(s2_tracked: np.ndarray, phi: float) -> np.ndarray:
    """S2 of the other phase: S2' = 1 - 2 phi + S2 for r > 0; S2'(0) = 1 - phi."""
    other = 1.0 - 2.0 * phi + s2_tracked
    other[0] = 1.0 - phi
    return other


# --------------------------------------------------------------------------- checkpoints


def _checkpoint_key(phi2, shape, cutoff, target, schedule, rng, scan) -> str:
    """Identifies a construction: parameters, target and the random state it started from.

    An L x L image keeps the key of the former 2D-only driver (``L``), so its checkpoints
    stay valid; any other shape (3D, or a non-square 2D image) is named by its whole shape,
    so that a checkpoint of one dimension is never taken for one of another."""
    if len(shape) == 2 and shape[0] == shape[1]:
        where = {"L": shape[0]}
    else:
        where = {"shape": list(shape), "dimension": len(shape)}
    return checkpoint_key(phi2=phi2, **where, lc=cutoff, schedule=asdict(schedule), scan=scan,
                          target=array_digest(target), rng=rng.bit_generator.state)


def _restore(data: dict, n_voxels: int):
    """(stage, long-range stages done, image, (accepted swaps, of which long-range) or None
    for a checkpoint written before the counts were saved) from a checkpoint's arrays;
    ValueError if the image is not one of ``n_voxels`` uint8 voxels (the key names the
    shape: a bug guard)."""
    stage, long_range_done, image = int(data["stage"]), int(data["long_range_done"]), data["image"]
    if image.shape != (n_voxels,) or image.dtype != np.uint8:
        raise ValueError(f"an image of {image.dtype} {image.shape}, not {n_voxels} voxels")
    accepted = ((int(data["accepted"]), int(data["long_range_accepted"]))
                if "accepted" in data else None)
    return stage, long_range_done, image, accepted
