"""Accelerated Yeong-Torquato construction of digitized two-phase media.

Ma & Torquato, PRE 102, 043310 (2020), Sec. IV. A periodic L x L image with
exactly round(phi N^2) pixels of the tracked phase is annealed towards a
target two-point function: a trial swaps one pixel of each phase (so the
volume fraction is conserved), with the Metropolis rule on the energy of
Eq. (23),

    E = sum_b [S2_b - target_b]^2 ,

summed over radial bins b = 1..n_b of width one pixel with 0 < r <= l_c
(bins are those of :class:`randmedia.describe.two_phase.RadialBinning`, so the
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
int16 counts, one cache line per updated pixel) through the cache per flipped
pixel. Instead the flips wait in a batch (per-stage size from the acceptance
rate, :func:`_batch_for`), bucketed by coarse cells of ~l_c/2; a trial adds the
pending flips within l_c of its two pixels to their stored counts (exact
integers, so the trajectory is unchanged), and a full batch is applied image
row by image row (:func:`_apply_flips`), each row's counts staying in cache.
Measured at L = 501, l_c = 50 (``benchmarks/debye_yt.py``): a trial costs
~0.7 us, an accepted swap ~13 us, the disk scan ~25 us per trial.

Phase-inversion symmetry. The kernel always tracks the minority phase
(phase 2 when phi2 <= 1/2), the initial image and every random draw depend
only on min(phi1, phi2), and the energy is that of chi_V, which both phases
share; the construction at 1 - phi2 is therefore exactly the complement of
the one at phi2 with the same seed.

Schedule (the paper fixes only the scalings, Sec. IV): total trials
``trials_per_pixel * phi1 phi2 N^2``; initial temperature
``initial_temperature * phi1 phi2 / N^2``, lowered geometrically stage by
stage to ``final_temperature_ratio`` times the initial one; the last
``refine_fraction`` of the trials draw both pixels from the interface (pixels
with a 4-neighbour of the other phase, kept in incrementally updated lists),
which removes isolated islands. If Delta S2 = mean_b |S2_b - target_b| then
exceeds the tolerance, up to ``max_extra_stages`` more refinement stages are
run at the final temperature; a construction still above tolerance raises
:class:`ConstructionError` -- it is never written as if it had converged.

Long-range stages. Beyond l_c the energy says nothing, so S2 there carries the
image's own fluctuations (mean |S2 - target| over all bins 0 < r < L/2 of
~2-5 x 10^-4 at L = 501, a = 5, where the paper quotes 0.6-2 x 10^-4 without
naming the bins). ``long_range_stages`` more interface stages at the final
temperature, with the energy of Eq. (23) summed over every bin
0 < r <= ``long_range_cutoff_over_L`` L, bring it to ~10^-5 at the cost of one
shell-count table of that range (built by FFT, :func:`_shell_counts`) -- the
trial cost stays O(bins). The cutoff stops short of L/2 so that the pending-flip
cells (:class:`_PendingCells`) stay a few pixels wide. Off by default
(``long_range_stages = 0``); the paper config runs two.
"""

from __future__ import annotations

import logging
import math
import os
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
from numba import njit

from randmedia.describe.two_phase import RadialBinning, periodic_autocorrelation
from randmedia.checkpoint import array_digest, checkpoint_key, load_checkpoint, save_checkpoint
from randmedia.generate import refuse_invalid

_NEIGHBOURS = np.array([[-1, 0], [1, 0], [0, -1], [0, 1]], dtype=np.int64)


class ConstructionError(RuntimeError):
    """The construction did not reach the required Delta S2."""


@dataclass(frozen=True)
class AnnealingSchedule:
    """Constants of the annealing schedule (see the module docstring)."""

    trials_per_pixel: float = 40.0
    initial_temperature: float = 0.005
    final_temperature_ratio: float = 1e-3
    n_stages: int = 40
    refine_fraction: float = 0.1
    tolerance: float = 2e-4
    max_extra_stages: int = 40
    long_range_stages: int = 0
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


@njit(cache=True, inline="always")
def _shifted(x, side, di, dj):
    """Index of pixel x shifted by (di, dj) on the periodic side x side lattice (|d| < side)."""
    i = x // side + di
    j = x % side + dj
    if i < 0:
        i += side
    elif i >= side:
        i -= side
    if j < 0:
        j += side
    elif j >= side:
        j -= side
    return i * side + j


@njit(cache=True, boundscheck=False)
def _apply_flips(h, side, flips, signs, n_flips, run_di, run_lo, run_hi, run_dj0, run_address):
    """Add signs[k] to h[x, column] of every pixel x within l_c of flips[k], for k < n_flips.

    The stencil is stored as runs of consecutive columns dj in one stencil row di
    (offsets in row-major order), so the pixels a run touches are consecutive in
    memory. Flips are sorted by image row (counting sort) and applied image row by
    image row: the shell counts of one image row (side x n_bins int16, ~50 kB at paper
    size) stay in cache while every flip whose stencil crosses that row updates it.
    Applied one flip at a time, each flip would stream ~0.8 MB of h through the
    cache; batched, h streams through once per batch.
    """
    n_columns = h.shape[1]
    flat = h.reshape(-1)
    first = np.zeros(side + 1, dtype=np.int64)  # flips of image row r: order[first[r]:first[r+1]]
    for k in range(n_flips):
        first[flips[k] // side + 1] += 1
    for r in range(side):
        first[r + 1] += first[r]
    order = np.empty(n_flips, dtype=np.int64)
    fill = first[:side].copy()
    for k in range(n_flips):
        row = flips[k] // side
        order[fill[row]] = k
        fill[row] += 1
    for r in range(side):
        row_base = r * side
        for run in range(run_di.shape[0]):
            i0 = r - run_di[run]  # image row of the flips whose stencil run lands on row r
            if i0 < 0:
                i0 += side
            elif i0 >= side:
                i0 -= side
            lo = run_lo[run]
            hi = run_hi[run]
            for e in range(first[i0], first[i0 + 1]):
                k = order[e]
                sign = signs[k]
                j_first = flips[k] - i0 * side + run_dj0[run]  # image column of the run's start
                # pixels of the run inside the row: u in [start, stop); the rest wraps around
                start = lo + max(0, -j_first)
                stop = min(hi, lo + side - j_first)
                base = (row_base + j_first) * n_columns
                for u in range(start, stop):
                    flat[base + run_address[u]] += sign
                for u in range(lo, start):  # wrapped on the left
                    flat[base + side * n_columns + run_address[u]] += sign
                for u in range(stop, hi):  # wrapped on the right
                    flat[base - side * n_columns + run_address[u]] += sign


def _stencil_runs(offsets: np.ndarray, column: np.ndarray, n_columns: int):
    """(run_di, run_lo, run_hi, run_dj0, run_address): maximal runs of consecutive dj in one
    stencil row of the row-major sorted ``offsets`` (the origin splits row 0 into two
    runs), and for every stencil entry u its offset in the flattened shell counts from the
    run's first pixel: column[u] + (u - run_lo) * n_columns."""
    breaks = np.flatnonzero((np.diff(offsets[:, 0]) != 0) | (np.diff(offsets[:, 1]) != 1)) + 1
    lo = np.concatenate([[0], breaks]).astype(np.int64)
    hi = np.concatenate([breaks, [len(offsets)]]).astype(np.int64)
    run_start = np.repeat(lo, hi - lo)
    address = column + (np.arange(len(offsets)) - run_start) * n_columns
    return (np.ascontiguousarray(offsets[lo, 0]), lo, hi, np.ascontiguousarray(offsets[lo, 1]),
            address.astype(np.int64))


def _shell_counts(image, side, offsets, column, n_columns):
    """h[x, c] = number of tracked pixels at displacements of bin c+1 from pixel x, counted
    from scratch: per bin, the periodic correlation of the image with the bin's shell of
    displacements by FFT (exact after rounding: counts < 2^15, FFT error ~1e-10). Equal
    to applying every tracked pixel as a +1 flip with :func:`_apply_flips` (tested), and
    ~3x faster for shells out to L/2."""
    import scipy.fft

    h = np.empty((side * side, n_columns), dtype=np.int16)
    spectrum = scipy.fft.rfft2(np.asarray(image, dtype=np.float64).reshape(side, side))
    shell = np.zeros((side, side))
    rows, cols = offsets[:, 0] % side, offsets[:, 1] % side
    order = np.argsort(column, kind="stable")
    starts = np.searchsorted(column[order], np.arange(n_columns + 1))
    for c in range(n_columns):
        members = order[starts[c]:starts[c + 1]]
        shell[rows[members], cols[members]] = 1.0
        # sum_v shell(v) I(x + v) = IFFT(FFT(I) conj(FFT(shell))); the shell is symmetric
        counts = scipy.fft.irfft2(spectrum * np.conj(scipy.fft.rfft2(shell)), s=(side, side))
        h[:, c] = np.rint(counts).reshape(-1)
        shell[rows[members], cols[members]] = 0.0
    return h


@njit(cache=True)
def _scan_counts(image, side, x, offsets, column, out):
    """out[c] = tracked pixels at displacements of bin c+1 from x, by scanning the disk."""
    out[:] = 0
    for k in range(offsets.shape[0]):
        out[column[k]] += image[_shifted(x, side, offsets[k, 0], offsets[k, 1])]


@njit(cache=True)
def _pair_column(p, q, side, cutoff, column_table):
    """Bin column of the minimal-image displacement q - p, or -1 beyond the cutoff."""
    di = q // side - p // side
    dj = q % side - p % side
    if di > side // 2:
        di -= side
    elif di < -(side // 2):
        di += side
    if dj > side // 2:
        dj -= side
    elif dj < -(side // 2):
        dj += side
    if abs(di) > cutoff or abs(dj) > cutoff:
        return -1
    return column_table[di + cutoff, dj + cutoff]


@njit(cache=True)
def _is_candidate(image, side, x, interface_only):
    """Can x be drawn? Every pixel, or in interface mode only those with a 4-neighbour
    of the other phase."""
    if not interface_only:
        return True
    for n in range(4):
        if image[_shifted(x, side, _NEIGHBOURS[n, 0], _NEIGHBOURS[n, 1])] != image[x]:
            return True
    return False


@njit(cache=True)
def _list_add_if_candidate(image, side, x, interface_only, members, sizes, slot):
    if _is_candidate(image, side, x, interface_only):
        ph = image[x]
        members[ph, sizes[ph]] = x
        slot[x] = sizes[ph]
        sizes[ph] += 1


@njit(cache=True)
def _build_lists(image, side, interface_only, members, sizes, slot):
    """members[phase, :sizes[phase]] = candidate pixels of each phase; slot = position or -1."""
    sizes[0] = 0
    sizes[1] = 0
    slot[:] = -1
    for x in range(side * side):
        _list_add_if_candidate(image, side, x, interface_only, members, sizes, slot)


@njit(cache=True)
def _list_remove(members, sizes, slot, ph, x):
    s = slot[x]
    last = members[ph, sizes[ph] - 1]
    members[ph, s] = last
    slot[last] = s
    sizes[ph] -= 1
    slot[x] = -1


@njit(cache=True)
def _refresh(image, side, x, old_phase, interface_only, members, sizes, slot):
    if slot[x] >= 0:
        _list_remove(members, sizes, slot, old_phase, x)
    _list_add_if_candidate(image, side, x, interface_only, members, sizes, slot)


class _PendingCells:
    """Coarse cells for looking up pending flips near a pixel, per image axis.

    Pixel row (or column) i lies in cell ``cell_of[i]`` (cells of ``width`` pixels, the
    last one wider). ``near[i, :n_near[i]]`` are the cells meeting the window
    [i - l_c, i + l_c] (periodic, each once); ``gap[i, a]`` is the distance from i to
    the nearest pixel of cell ``near[i, a]`` in that window (cells farther than l_c in
    both axes together are skipped) and ``shift[i, a]`` (0 or +-L) turns a row index in
    that cell into its periodic image nearest to i.
    """

    def __init__(self, side: int, cutoff: int, width: int):
        self.width = max(1, int(width))
        self.count = max(1, side // self.width)
        cell_of = np.minimum(np.arange(side) // self.width, self.count - 1)
        window = np.arange(-cutoff, cutoff + 1)
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
def _counts_now(h, x, side, cutoff, padded_table, cells, bucket_i, bucket_j, bucket_sign,
                bucket_size, out):
    """out[1:] = current shell counts of pixel x: the stored h[x] plus the pending (not
    yet applied) flips within l_c, read from the buckets of the coarse cells near x.

    Branch-free inner loop: displacements are clamped to +-(l_c + 1), where
    ``padded_table`` holds column -1, and a flip lands in out[column + 1], so flips
    beyond l_c (or at the pixel itself) only add to the discarded out[0].
    """
    n_cells, cell_of, near, gap, shift, n_near = cells
    for c in range(h.shape[1]):
        out[c + 1] = h[x, c]
    i = x // side
    j = x - i * side
    reach = cutoff * cutoff
    edge = cutoff + 1
    width = 2 * edge + 1
    for a in range(n_near[i]):
        dy = gap[i, a]
        row = near[i, a] * n_cells
        origin_i = shift[i, a] - i + edge
        for b in range(n_near[j]):
            cell = row + near[j, b]
            size = bucket_size[cell]
            if size == 0:
                continue
            dx = gap[j, b]
            if dy * dy + dx * dx > reach:
                continue
            origin_j = shift[j, b] - j + edge
            for e in range(size):
                di = min(max(bucket_i[cell, e] + origin_i, 0), 2 * edge)
                dj = min(max(bucket_j[cell, e] + origin_j, 0), 2 * edge)
                out[padded_table[di * width + dj] + 1] += bucket_sign[cell, e]


@njit(cache=True)
def _anneal(image, h, diff, norm, offsets, column, column_table, cutoff, side, n_trials,
            temperature, interface_only, scan, rng, runs, cells, batch):
    """Run ``n_trials`` Metropolis swap trials in place; returns the number accepted.

    Accepted swaps are not applied to the shell counts h at once: up to ``batch``
    flips wait in a list bucketed by coarse cells, trials add the pending flips
    within l_c to the stored counts (exact integers, so the trajectory is the same as
    with immediate updates), and full batches are applied by :func:`_apply_flips`.
    h is up to date when the function returns.
    """
    n_columns = diff.shape[0]
    members = np.empty((2, side * side), dtype=np.int32)
    sizes = np.zeros(2, dtype=np.int64)
    slot = np.empty(side * side, dtype=np.int32)
    _build_lists(image, side, interface_only, members, sizes, slot)
    hp = np.empty(n_columns + 1, dtype=np.int64)  # hp[c + 1]: count of column c; hp[0] unused
    hq = np.empty(n_columns + 1, dtype=np.int64)
    run_di, run_lo, run_hi, run_dj0, run_address = runs
    n_cells, cell_of = cells[0], cells[1]
    edge = cutoff + 1
    padded_table = np.full((2 * edge + 1) * (2 * edge + 1), -1, dtype=np.int64)
    for a in range(2 * cutoff + 1):
        for b in range(2 * cutoff + 1):
            padded_table[(a + 1) * (2 * edge + 1) + b + 1] = column_table[a, b]
    # pending flips: in order of acceptance (applied by _apply_flips) and, for the
    # lookups, copied into per-cell buckets; a full bucket triggers an early flush
    pending = np.empty(batch, dtype=np.int64)
    signs = np.empty(batch, dtype=np.int16)
    capacity = max(16, 4 * batch // (n_cells * n_cells))
    bucket_i = np.empty((n_cells * n_cells, capacity), dtype=np.int32)
    bucket_j = np.empty((n_cells * n_cells, capacity), dtype=np.int32)
    bucket_sign = np.empty((n_cells * n_cells, capacity), dtype=np.int8)
    bucket_size = np.zeros(n_cells * n_cells, dtype=np.int64)
    n_pending = 0
    accepted = 0
    beta = 1.0 / temperature if temperature > 0 else np.inf
    for _ in range(n_trials):
        if sizes[0] == 0 or sizes[1] == 0:
            break
        p = members[1, int(rng.random() * sizes[1])]
        q = members[0, int(rng.random() * sizes[0])]
        if scan:
            _scan_counts(image, side, p, offsets, column, hp[1:])
            _scan_counts(image, side, q, offsets, column, hq[1:])
        elif n_pending == 0:
            for c in range(n_columns):
                hp[c + 1] = h[p, c]
                hq[c + 1] = h[q, c]
        else:
            _counts_now(h, p, side, cutoff, padded_table, cells, bucket_i, bucket_j, bucket_sign,
                        bucket_size, hp)
            _counts_now(h, q, side, cutoff, padded_table, cells, bucket_i, bucket_j, bucket_sign,
                        bucket_size, hq)
        # Delta C_b = 2 (h_q[b] - h_p[b]) - 2 [|p - q| in b]: fold the pair term into h_q
        pair = _pair_column(p, q, side, cutoff, column_table)
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
            cell_p = cell_of[p // side] * n_cells + cell_of[p % side]
            cell_q = cell_of[q // side] * n_cells + cell_of[q % side]
            if (n_pending + 2 > batch or bucket_size[cell_p] + 2 > capacity
                    or bucket_size[cell_q] + 2 > capacity):
                _apply_flips(h, side, pending, signs, n_pending, run_di, run_lo, run_hi, run_dj0,
                             run_address)
                n_pending = 0
                bucket_size[:] = 0
            for x, sign, cell in ((p, -1, cell_p), (q, 1, cell_q)):
                pending[n_pending] = x
                signs[n_pending] = sign
                n_pending += 1
                e = bucket_size[cell]
                bucket_i[cell, e] = x // side
                bucket_j[cell, e] = x % side
                bucket_sign[cell, e] = sign
                bucket_size[cell] = e + 1
        # p left the tracked phase (1 -> 0), q joined it (0 -> 1)
        _refresh(image, side, p, 1, interface_only, members, sizes, slot)
        _refresh(image, side, q, 0, interface_only, members, sizes, slot)
        if interface_only:
            for x in (p, q):
                for n in range(4):
                    y = _shifted(x, side, _NEIGHBOURS[n, 0], _NEIGHBOURS[n, 1])
                    if y != p and y != q:
                        _refresh(image, side, y, image[y], interface_only, members, sizes, slot)
    if not scan:
        _apply_flips(h, side, pending, signs, n_pending, run_di, run_lo, run_hi, run_dj0,
                     run_address)
    return accepted


# --------------------------------------------------------------------------- driver


class _Geometry:
    """Bins, displacement stencil and normalization for an L x L image and cutoff l_c."""

    def __init__(self, side: int, cutoff: float):
        self.side = side
        self.binning = RadialBinning.build((side, side), cutoff)
        vectors = self.binning.displacements()
        keep = self.binning.bin_of > 0
        # row-major order of the stencil: an accepted swap then walks h almost sequentially
        order = np.lexsort((vectors[keep][:, 1], vectors[keep][:, 0]))
        self.offsets = np.ascontiguousarray(vectors[keep][order], dtype=np.int64)
        self.column = np.ascontiguousarray((self.binning.bin_of[keep] - 1)[order], dtype=np.int64)
        self.n_columns = int(self.binning.counts.size - 1)
        self.cutoff = int(math.floor(cutoff))
        table = np.full((2 * self.cutoff + 1, 2 * self.cutoff + 1), -1, dtype=np.int64)
        table[self.offsets[:, 0] + self.cutoff, self.offsets[:, 1] + self.cutoff] = self.column
        self.column_table = table
        self.runs = _stencil_runs(self.offsets, self.column, self.n_columns)
        # pending-flip lookup cells about l_c / 2 wide: the cells met by a pixel's
        # l_c-disk cover about twice the disk's area (3 x 3 cells of width l_c: ~3x)
        # (no wider than the part of the ring outside a pixel's window, so that no cell is
        # met at both ends of it: matters only for l_c close to L/2)
        width = min((self.cutoff + 1) // 2, side - 2 * self.cutoff - 1)
        self.cells = _PendingCells(side, self.cutoff, width).arrays()
        # S2_b = C_b / (N^2 n_b)
        self.norm = 1.0 / (side * side * self.binning.counts[1:].astype(float))

    def s2(self, image_flat: np.ndarray, counts: np.ndarray | None = None) -> np.ndarray:
        """S2 of the tracked phase per bin (0..n_b), exactly, from the shell counts
        (recounted from the image unless ``counts`` are given)."""
        if counts is None:
            counts = _shell_counts(image_flat, self.side, self.offsets, self.column,
                                   self.n_columns)
        pair_sums = (counts[image_flat == 1].astype(np.int64)).sum(axis=0)
        return np.concatenate([[image_flat.mean()], pair_sums * self.norm])


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


def _validate(phi2: float, side: int, cutoff: float) -> None:
    if not 0.0 < phi2 < 1.0:
        raise ValueError(f"phi2 must lie in (0, 1), got {phi2}")
    if not isinstance(side, (int, np.integer)) or side < 4:
        raise ValueError(f"L must be an integer >= 4 pixels (the image is L x L), got {side!r}")
    if not 1.0 <= cutoff < side / 2:
        raise ValueError(f"cutoff l_c must satisfy 1 <= l_c < L/2 = {side / 2:g}, got {cutoff}")


def tracked_target(target_s2: Callable, phi2: float, binning: RadialBinning) -> tuple[float, np.ndarray]:
    """(phi of the tracked minority phase, its target S2 per bin as the exact bin average).

    ``target_s2`` is S2 of phase 2; for the minority phase 1 the target is
    phi1^2 + chi_V(r) with chi_V = S2^(2) - phi2^2.
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
    side: int,
    cutoff: float,
    rng: np.random.Generator,
    schedule: AnnealingSchedule = AnnealingSchedule(),
    *,
    checkpoint: str | os.PathLike | None = None,
    checkpoint_seconds: float = 30.0,
    log: logging.Logger | None = None,
    scan: bool = False,
    batch: int = 4096,
) -> Construction:
    """Construct an L x L periodic image (1 = phase 2) with S2 of phase 2 close to ``target_s2``.

    ``checkpoint``: file to save the state to (image + random state, at stage
    boundaries, at most every ``checkpoint_seconds``) and to resume from if it
    exists and belongs to the same construction; it is removed on success.
    ``scan``: use the straightforward per-trial disk scan (benchmark baseline).
    ``batch``: pixel flips (two per accepted swap) collected before they are applied
    to the shell counts; a performance knob only -- any value gives the same image.
    """
    if not isinstance(batch, (int, np.integer)) or batch < 2:
        raise ValueError(f"batch must be an integer >= 2, got {batch!r}")
    _validate(phi2, side, cutoff)
    log = log or logging.getLogger(__name__)
    geometry = _Geometry(side, cutoff)
    phi, target = tracked_target(target_s2, phi2, geometry.binning)
    n_pixels = side * side
    n_tracked = int(round(phi * n_pixels))
    if n_tracked == 0:
        raise ValueError(f"phi2 = {phi2} leaves no pixel of the minority phase on {side}^2 pixels")
    weight = phi * (1.0 - phi)
    total_trials = int(schedule.trials_per_pixel * weight * n_pixels)
    t_initial = schedule.initial_temperature * weight / n_pixels
    n_refine = int(round(schedule.refine_fraction * schedule.n_stages))
    n_cool = schedule.n_stages - n_refine
    trials_per_stage = max(1, total_trials // schedule.n_stages)

    def temperature(stage: int) -> float:
        k = min(stage, n_cool - 1)
        return t_initial * schedule.final_temperature_ratio ** (k / max(1, n_cool - 1))

    key = _checkpoint_key(phi2, side, cutoff, target, schedule, rng, scan)
    stage, long_range_done, image = 0, 0, None
    if checkpoint is not None:
        stage, long_range_done, image = _load_checkpoint(checkpoint, key, rng, log)
    if image is None:
        image = np.zeros(n_pixels, dtype=np.uint8)
        image[rng.permutation(n_pixels)[:n_tracked]] = 1

    h = (_shell_counts(image, side, geometry.offsets, geometry.column, geometry.n_columns)
         if not scan else np.zeros((1, geometry.n_columns), dtype=np.int16))
    diff = geometry.s2(image, None if scan else h)[1:] - target[1:]
    started, last_save = time.perf_counter(), time.perf_counter()
    trials_done = accepted_total = 0
    last_stage = schedule.n_stages + schedule.max_extra_stages
    delta_s2 = float(np.mean(np.abs(diff)))
    stage_batch = batch
    while stage < last_stage and long_range_done == 0:  # (resumed in a long-range stage: done)
        if stage >= schedule.n_stages and delta_s2 <= schedule.tolerance:
            break
        tic = time.perf_counter()
        accepted = _anneal(image, h, diff, geometry.norm, geometry.offsets, geometry.column,
                           geometry.column_table, geometry.cutoff, side, trials_per_stage,
                           temperature(stage), stage >= n_cool, scan, rng, geometry.runs,
                           geometry.cells, stage_batch)
        stage += 1
        elapsed = time.perf_counter() - tic
        trials_done += trials_per_stage
        accepted_total += accepted
        stage_batch = _batch_for(accepted / trials_per_stage, batch)
        delta_s2 = float(np.mean(np.abs(diff)))
        remaining = max(0, schedule.n_stages - stage) * elapsed
        log.info("stage %d/%d T=%.3g: %.3g trials/s, acceptance %.4f, E=%.4g, dS2=%.3g, ETA %.0f s",
                 stage, schedule.n_stages, temperature(stage - 1), trials_per_stage / elapsed,
                 accepted / trials_per_stage, float(np.sum(diff**2)), delta_s2, remaining)
        if checkpoint is not None and time.perf_counter() - last_save >= checkpoint_seconds:
            _save_checkpoint(checkpoint, key, stage, 0, image, rng)
            last_save = time.perf_counter()

    long_range_accepted = 0
    if long_range_done < schedule.long_range_stages and (delta_s2 <= schedule.tolerance
                                                         or long_range_done > 0):
        del h
        far = _Geometry(side, math.floor(schedule.long_range_cutoff_over_L * side))
        _, far_target = tracked_target(target_s2, phi2, far.binning)
        tic = time.perf_counter()
        h = (_shell_counts(image, side, far.offsets, far.column, far.n_columns)
             if not scan else np.zeros((1, far.n_columns), dtype=np.int16))
        far_diff = far.s2(image, None if scan else h)[1:] - far_target[1:]
        log.info("long-range stages: bins 0 < r <= %d, shell counts in %.1f s, dS2 = %.3g",
                 far.cutoff, time.perf_counter() - tic, float(np.mean(np.abs(far_diff))))
        while long_range_done < schedule.long_range_stages:
            tic = time.perf_counter()
            accepted = _anneal(image, h, far_diff, far.norm, far.offsets, far.column,
                               far.column_table, far.cutoff, side, trials_per_stage,
                               temperature(n_cool - 1), True, scan, rng, far.runs, far.cells,
                               stage_batch)
            long_range_done += 1
            trials_done += trials_per_stage
            long_range_accepted += accepted
            stage_batch = _batch_for(accepted / trials_per_stage, batch)
            log.info("long-range stage %d/%d: %.3g trials/s, acceptance %.4f, dS2 (r <= %d) = %.3g",
                     long_range_done, schedule.long_range_stages,
                     trials_per_stage / (time.perf_counter() - tic), accepted / trials_per_stage,
                     far.cutoff, float(np.mean(np.abs(far_diff))))
            if checkpoint is not None and time.perf_counter() - last_save >= checkpoint_seconds:
                _save_checkpoint(checkpoint, key, stage, long_range_done, image, rng)
                last_save = time.perf_counter()
        accepted_total += long_range_accepted

    # final S2 from the FFT estimator: independent of the incremental bookkeeping
    s2_tracked = geometry.binning.average(periodic_autocorrelation(image.reshape(side, side)))
    delta_s2 = float(np.mean(np.abs(s2_tracked[1:] - target[1:])))
    seconds = time.perf_counter() - started
    stats = {"trials": trials_done, "accepted": accepted_total, "stages": stage,
             "long_range_stages": long_range_done, "long_range_accepted": long_range_accepted,
             "seconds": seconds, "schedule": asdict(schedule)}
    if delta_s2 > schedule.tolerance:
        raise ConstructionError(
            f"construction did not converge: Delta S2 = {delta_s2:.3g} > tolerance "
            f"{schedule.tolerance:g} after {stage} stages (phi2 = {phi2}, L = {side}, l_c = {cutoff})"
        )
    if checkpoint is not None:
        Path(checkpoint).unlink(missing_ok=True)
    tracked_is_phase2 = phi2 <= 0.5
    phase2 = image if tracked_is_phase2 else 1 - image
    s2_phase2 = s2_tracked if tracked_is_phase2 else _complement_s2(s2_tracked, phi)
    target_phase2 = target if tracked_is_phase2 else _complement_s2(target, phi)
    return Construction(
        image=phase2.reshape(side, side).astype(np.uint8),
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


def _checkpoint_key(phi2, side, cutoff, target, schedule, rng, scan) -> str:
    """Identifies a construction: parameters, target and the random state it started from."""
    return checkpoint_key(phi2=phi2, L=side, lc=cutoff, schedule=asdict(schedule), scan=scan,
                          target=array_digest(target), rng=rng.bit_generator.state)


def _save_checkpoint(path, key, stage, long_range_done, image, rng) -> None:
    save_checkpoint(path, key, {"stage": stage, "long_range_done": long_range_done, "image": image}, rng)


def _load_checkpoint(path, key, rng, log):
    data = load_checkpoint(path, key, log, rng)
    if data is None:
        return 0, 0, None
    stage, long_range_done, image = int(data["stage"]), int(data["long_range_done"]), data["image"]
    log.info("resumed from %s at stage %d (+ %d long-range stages)", path, stage, long_range_done)
    return stage, long_range_done, image
