"""Equilibrium hard disks (d = 2) and hard spheres (d = 3) by NVT Monte Carlo.

One d-generic implementation serves Ma & Torquato 2020, Sec. VI B (hard disks at
phi2 = 0.3 on the stable fluid branch) and Klatt & Torquato 2016 (the hard-sphere
liquid at phi = 0.478). N identical particles of diameter D in a periodic
orthogonal box; the equilibrium (Gibbs) measure is uniform over non-overlapping
configurations.

Moves. Single-particle displacements: a particle chosen uniformly at random is
displaced by a vector uniform in [-step, step]^d and the move is accepted iff the
new position overlaps no other particle (Metropolis for hard cores). The proposal is
symmetric, so detailed balance holds *for a fixed step*: the step is tuned only
while the chain equilibrates (towards ``target_acceptance``, default 0.25: measured at
phi = 0.478 in 3D, targets 0.15-0.25 give the largest MSD per CPU second, 1.7 times
that of 0.45, since rejected trials are cheap) and is frozen before any production
sample is taken. The step is capped at half the box. Overlap checks use a cell
list (cells of side >= D, the 3^d cells around the trial position), kept up to date
move by move, in numba kernels (``cache=True``). Event-chain Monte Carlo was not
built: measured on this machine, the Metropolis chain makes the paper's 100
decorrelated N = 10 000 liquid configurations in about 32 CPU minutes, well within
the time budget (docs/hard_particles.md; ``benchmarks/hard_spheres_mc.py``).

Chain. (1) Start: a lattice at the target density with random vacancies -- the first
of square (2D) / simple cubic, bcc, fcc (3D) whose sites fit N particles without
overlap, the least stable first, since it has to melt -- or, when none fits (small N
at high phi), random sequential addition (RSA) at ``min(phi, RSA_PHI[d])`` (far below
the RSA jamming limits 0.547 in 2D and 0.384 in 3D) followed by Monte Carlo
compression: after every block of sweeps the box is shrunk affinely by as much as the
closest pair allows, until it reaches the target size (slow for large N: the closest
gap shrinks like 1/N). (2) Equilibration at the target density, with step tuning,
until the mean squared displacement (MSD, unwrapped coordinates) since the target was
reached is at least ``equilibration_msd`` D^2 and at least ``min_equilibration_sweeps``
sweeps were made -- every particle has then moved
several diameters, so no memory of the start remains. (3) The step is frozen; the
number of sweeps the frozen chain needs for an MSD of ``sample_msd`` D^2 is measured
once and, times ``interval_safety``, fixed as the sampling interval. (4) Production:
one sample every interval; if a sample's MSD since the previous one is still below
``sample_msd`` (never seen so far), the chain runs on block by block until it is not.
Every sample records its MSD since the previous sample, sweeps, acceptance and its
own contact-value pressure.

Pressure from the contact value. During equilibration's last part and production,
every ``measure_every`` sweeps the pairs at distances D <= r < D (1 + contact_range)
are histogrammed (``contact_bins`` bins). With g(r) a polynomial of degree
``contact_order`` in x = r - D, the expected count in bin b is linear in its
coefficients, n_b = N (N - 1) / (2 V) * n_measurements * sum_k c_k int_b x^k s1(D + x) dx
(s1 = surface of the d-sphere), so a least-squares fit to the raw counts has no
binning bias; g(D+) = c_0 and beta p / rho = 1 + 2^(d-1) phi g(D+) (virial theorem).
The (N - 1) makes the normalization exact for fixed N. Defaults: a cubic over
0.1 D in 20 bins. Measured on one long N = 500 chain at phi = 0.478 (3D): cubic fits
over 0.05, 0.1 and 0.15 D and a quadratic over 0.05 D agree within 0.15 %, while a
quadratic over 0.1 D is 0.5 % low and a linear one 5 % low (g falls steeply from
contact). The histogram uses its own cell list (side >= D (1 + contact_range)).

Reproducibility. All randomness comes from the numpy Generator passed in; the chain
works in blocks of ``block_sweeps`` sweeps whose boundaries depend only on the chain
itself, and a checkpoint (every ``checkpoint_seconds`` at a block boundary; arrays,
counters, random state and the samples taken so far) resumes the bit-identical chain
after a kill.
"""

from __future__ import annotations

import json
import logging
import math
import os
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np
from numba import njit

from randmedia.checkpoint import checkpoint_key, load_checkpoint, save_checkpoint
from randmedia.generate import refuse_invalid
from randmedia.theory.hard_spheres import FLUID_LIMIT, ball_volume

#: packing fraction of the random-sequential-addition start (well below RSA jamming)
RSA_PHI = {2: 0.35, 3: 0.25}
_CELL_CAPACITY = {2: 16, 3: 64}


class ChainError(RuntimeError):
    """The chain could not be started or did not behave (overlap, stalled compression)."""


@dataclass(frozen=True)
class MCSettings:
    """Constants of a chain (module docstring); MSDs in units of D^2."""

    target_acceptance: float = 0.25
    equilibration_msd: float = 4.0
    min_equilibration_sweeps: int = 200
    sample_msd: float = 1.0
    interval_safety: float = 1.25
    block_sweeps: int = 10
    measure_every: int = 5
    contact_range: float = 0.1
    contact_bins: int = 20
    contact_order: int = 3

    def __post_init__(self):
        checks = {
            "target_acceptance": 0.0 < self.target_acceptance < 1.0,
            "equilibration_msd": self.equilibration_msd >= 0.0,
            "min_equilibration_sweeps": self.min_equilibration_sweeps >= 0,
            "sample_msd": self.sample_msd > 0.0,
            "interval_safety": self.interval_safety >= 1.0,
            "block_sweeps": self.block_sweeps >= 1,
            "measure_every": self.measure_every >= 1,
            "contact_range": 0.0 < self.contact_range <= 0.5,
            "contact_bins": self.contact_bins >= self.contact_order + 2,
            "contact_order": 0 <= self.contact_order <= 4,
        }
        refuse_invalid("Monte Carlo settings", checks, self)


# --------------------------------------------------------------------------- numba kernels
# Positions are stored with three columns whatever d; for d = 2 the third column is 0
# and the third box length a dummy 1 with a single cell layer, never displaced.


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
def _sweeps(pos, unwrapped, box, dim, diameter, step, n_sweeps, ncell, members, count,
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
def _pair_scan(pos, box, ncell, members, count, diameter, r_max, n_bins, hist):
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
def _rsa(pos, box, dim, diameter, ncell, members, count, cell_of, slot_of, max_attempts, rng):
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


# --------------------------------------------------------------------------- geometry helpers


def cubic_box(n_particles: int, phi: float, dim: int, diameter: float = 1.0) -> np.ndarray:
    """Side lengths (d,) of the cube (square) holding N particles at packing fraction phi."""
    if dim not in (2, 3):
        raise ValueError(f"dimension must be 2 or 3, got {dim}")
    if not 0.0 < phi < 1.0:
        raise ValueError(f"packing fraction must lie in (0, 1), got {phi}")
    volume = n_particles * float(ball_volume(diameter / 2.0, dim)) / phi
    return np.full(dim, volume ** (1.0 / dim))


def packing_fraction_of(n_particles: int, box_lengths, diameter: float) -> float:
    box_lengths = np.asarray(box_lengths, dtype=float)
    return float(n_particles * ball_volume(diameter / 2.0, len(box_lengths)) / np.prod(box_lengths))


def validate_system(n_particles: int, box_lengths, diameter: float, contact_range: float = 0.1) -> float:
    """Refuse impossible or off-branch input; returns the packing fraction."""
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
    or None when none fits (then the chain starts by RSA + compression)."""
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


# --------------------------------------------------------------------------- the chain


@dataclass
class Sample:
    """One production configuration and its diagnostics."""

    positions: np.ndarray        # (N, d), wrapped into [0, L)
    diagnostics: dict = field(default_factory=dict)
    contact_histogram: np.ndarray | None = None   # pair counts since the previous sample


@dataclass
class ChainResult:
    box_lengths: np.ndarray
    diameter: float
    phi: float
    samples: list
    equilibration: dict
    contact: dict                # pooled histogram fit over the whole production


class _Cells:
    """Cell-list arrays for one box size."""

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


class HardParticleChain:
    """One Markov chain; see the module docstring. Use :func:`run_chain`."""

    STAGES = ("compress", "equilibrate", "calibrate", "produce", "done")

    def __init__(self, n_particles, box_lengths, diameter, n_samples, settings, rng,
                 start="auto"):
        if start not in ("auto", "lattice", "rsa"):
            raise ValueError(f"start must be 'auto', 'lattice' or 'rsa', got {start!r}")
        self.start_kind = start
        self.settings = settings
        self.dim = len(box_lengths)
        self.n = int(n_particles)
        self.diameter = float(diameter)
        self.n_samples = int(n_samples)
        self.target = np.ones(3)
        self.target[: self.dim] = box_lengths
        self.phi = packing_fraction_of(self.n, box_lengths, diameter)
        self.rng = rng
        self.cutoff = self.diameter * (1.0 + settings.contact_range)
        # state (everything below is checkpointed)
        self.stage = 0
        self.box = self.target.copy()
        self.pos = np.zeros((self.n, 3))
        self.unwrapped = np.zeros((self.n, 3))
        self.reference = np.zeros((self.n, 3))      # unwrapped positions at the last mark
        self.step = 0.2 * self.diameter
        self.counters = {"sweeps": 0, "compress_sweeps": 0, "equilibrate_sweeps": 0,
                         "calibrate_sweeps": 0, "produce_sweeps": 0, "trials": 0, "accepted": 0,
                         "window_sweeps": 0, "window_trials": 0, "window_accepted": 0,
                         "window_measurements": 0, "interval": 0, "extended_samples": 0}
        self.window_hist = np.zeros(settings.contact_bins, dtype=np.int64)
        self.total_hist = np.zeros(settings.contact_bins, dtype=np.int64)
        self.total_measurements = 0
        self.equilibration: dict = {}
        self.start_method = ""
        self.samples: list[Sample] = []
        self.cells: _Cells | None = None

    # ----------------------------------------------------------------- helpers

    def _rebuild_cells(self):
        self.cells = _Cells(self.box, self.dim, self.n, self.diameter)
        self.cells.build(self.pos, self.box)

    def _run(self, n_sweeps):
        c = self.cells
        accepted = _sweeps(self.pos, self.unwrapped, self.box, self.dim, self.diameter, self.step,
                           n_sweeps, c.ncell, c.members, c.count, c.cell_of, c.slot_of, self.rng)
        if accepted < 0:
            raise ChainError("cell list overflow during moves (overlapping particles)")
        trials = n_sweeps * self.n
        for key, value in (("sweeps", n_sweeps), ("trials", trials), ("accepted", accepted),
                           ("window_sweeps", n_sweeps), ("window_trials", trials),
                           ("window_accepted", accepted)):
            self.counters[key] += value
        self.counters[f"{self.STAGES[self.stage]}_sweeps"] += n_sweeps
        return accepted / trials

    def _scan(self, hist=None):
        """Contact histogram (into ``hist``) and overlap check, on a cell list of side
        >= D (1 + contact_range) built for the purpose; returns the smallest distance."""
        c = _Cells(self.box, self.dim, self.n, self.cutoff)
        c.build(self.pos, self.box)
        scratch_hist = np.zeros(self.settings.contact_bins, dtype=np.int64) if hist is None else hist
        overlaps, r_min = _pair_scan(self.pos, self.box, c.ncell, c.members, c.count,
                                     self.diameter, self.cutoff, self.settings.contact_bins,
                                     scratch_hist)
        if overlaps:
            raise ChainError(f"{overlaps} overlapping pairs found (smallest distance {r_min:.6g} "
                             f"< D = {self.diameter:g})")
        return r_min

    def _block(self, measure: bool):
        """block_sweeps sweeps, measuring the contact histogram every measure_every sweeps."""
        s = self.settings
        done, accepted = 0, 0.0
        while done < s.block_sweeps:
            chunk = s.block_sweeps - done
            if measure:
                to_measure = s.measure_every - (self.counters["sweeps"] % s.measure_every)
                chunk = min(chunk, to_measure)
            accepted += self._run(chunk) * chunk
            done += chunk
            if measure and self.counters["sweeps"] % s.measure_every == 0:
                self._scan(self.window_hist)
                self.counters["window_measurements"] += 1
        return accepted / s.block_sweeps

    def msd(self) -> float:
        """Mean squared displacement since the last mark, in D^2."""
        d = self.unwrapped - self.reference
        return float(np.mean(np.sum(d * d, axis=1)) / self.diameter**2)

    def _mark(self):
        self.reference = self.unwrapped.copy()

    def _reset_window(self):
        for key in ("window_sweeps", "window_trials", "window_accepted", "window_measurements"):
            self.counters[key] = 0
        self.window_hist[:] = 0

    def _tune(self, acceptance):
        s = self.settings
        factor = min(1.5, max(0.5, acceptance / s.target_acceptance)) if acceptance > 0 else 0.5
        self.step = min(self.step * factor, 0.5 * float(self.target[: self.dim].min()))

    # ----------------------------------------------------------------- stages

    def start(self):
        """A lattice at the target density (random vacancies) if one fits, else RSA at
        min(phi, RSA_PHI) in a correspondingly larger box followed by compression."""
        sites = (None if self.start_kind == "rsa"
                 else lattice_sites(self.n, self.target[: self.dim], self.diameter))
        if sites is None and self.start_kind == "lattice":
            raise ChainError(f"no lattice start fits N = {self.n} particles at phi = {self.phi:.4f}")
        if sites is not None:
            kind, points = sites
            chosen = np.sort(self.rng.permutation(len(points))[: self.n])
            self.box = self.target.copy()
            self.pos[:, : self.dim] = points[chosen]
            self.start_method = f"{kind} lattice, {len(points) - self.n} random vacancies"
            self._rebuild_cells()
        else:
            start_phi = min(self.phi, RSA_PHI[self.dim])
            scale = (self.phi / start_phi) ** (1.0 / self.dim)
            self.box = self.target.copy()
            self.box[: self.dim] *= scale
            self.cells = _Cells(self.box, self.dim, self.n, self.diameter)
            c = self.cells
            placed = _rsa(self.pos, self.box, self.dim, self.diameter, c.ncell, c.members,
                          c.count, c.cell_of, c.slot_of, 1000 * self.n + 10000, self.rng)
            if placed != self.n:
                raise ChainError(f"random sequential addition placed only {placed} of {self.n} "
                                 f"particles at phi = {start_phi:.3f}")
            self.start_method = f"random sequential addition at phi = {start_phi:.3f} + compression"
        self.unwrapped = self.pos.copy()
        self._mark()
        self.step = 0.2 * self.diameter

    def advance(self):
        """One unit of work of the current stage (a block, or one compression step)."""
        s = self.settings
        stage = self.STAGES[self.stage]
        if stage == "compress":
            if np.allclose(self.box, self.target, rtol=0, atol=0):
                self.stage = 1
                self._mark()
                self._reset_window()
                return
            acceptance = self._block(measure=False)
            self._tune(acceptance)
            r_min = self._scan()
            # shrink affinely as far as the closest pair allows (a hair less, so that
            # rounding can never create an overlap), but not below the target box
            factor = max(float((self.target[: self.dim] / self.box[: self.dim]).max()),
                         self.diameter * (1.0 + 1e-9) / r_min)
            if factor < 1.0:
                new_box = self.target.copy()
                new_box[: self.dim] = np.maximum(self.box[: self.dim] * factor,
                                                 self.target[: self.dim])
                ratio = new_box / self.box
                self.pos *= ratio
                self.unwrapped *= ratio
                self.reference *= ratio
                self.box = new_box
                self._rebuild_cells()
            if self.counters["compress_sweeps"] > 200000:
                raise ChainError("compression stalled (is phi on the fluid branch?)")
        elif stage == "equilibrate":
            # measure the contact histogram over the second half of equilibration too
            measure = self.msd() >= 0.5 * s.equilibration_msd
            acceptance = self._block(measure=measure)
            self._tune(acceptance)
            if (self.msd() >= s.equilibration_msd
                    and self.counters["equilibrate_sweeps"] >= s.min_equilibration_sweeps):
                window = self._window_summary()
                self.equilibration = {
                    "start": self.start_method,
                    "equilibration_sweeps": self.counters["equilibrate_sweeps"],
                    "compression_sweeps": self.counters["compress_sweeps"],
                    "equilibration_msd": self.msd(),
                    "step": self.step,
                    "equilibration_acceptance_last_block": acceptance,
                    "equilibration_contact_value": window["contact_value"],
                    "equilibration_reduced_pressure": window["reduced_pressure"],
                }
                self.stage = 2
                self._mark()
                self._reset_window()
        elif stage == "calibrate":
            self._block(measure=False)
            if self.msd() >= s.sample_msd:
                sweeps = self.counters["calibrate_sweeps"]
                blocks = math.ceil(s.interval_safety * sweeps / s.block_sweeps)
                self.counters["interval"] = blocks * s.block_sweeps
                self.equilibration.update({
                    "calibration_sweeps": sweeps, "calibration_msd": self.msd(),
                    "acceptance": self.counters["window_accepted"] / self.counters["window_trials"],
                    "sample_interval_sweeps": self.counters["interval"]})
                self.stage = 3
                self._mark()
                self._reset_window()
        elif stage == "produce":
            self._block(measure=True)
            if (self.counters["window_sweeps"] >= self.counters["interval"]
                    and self.msd() >= s.sample_msd):
                if self.counters["window_sweeps"] > self.counters["interval"]:
                    self.counters["extended_samples"] += 1
                self._take_sample()
                if len(self.samples) >= self.n_samples:
                    self.stage = 4

    def _window_summary(self) -> dict:
        fit = contact_fit(self.window_hist, self.counters["window_measurements"], self.n,
                          self.box[: self.dim], self.diameter, self.settings)
        return fit

    def _take_sample(self):
        fit = self._window_summary()
        self.total_hist += self.window_hist
        self.total_measurements += self.counters["window_measurements"]
        diagnostics = {
            "sweeps_since_previous": self.counters["window_sweeps"],
            "msd_since_previous": self.msd(),
            "acceptance": self.counters["window_accepted"] / self.counters["window_trials"],
            "contact_value": fit["contact_value"],
            "reduced_pressure": fit["reduced_pressure"],
            "contact_measurements": self.counters["window_measurements"],
            "total_sweeps": self.counters["sweeps"],
        }
        self.samples.append(Sample(self.pos[:, : self.dim].copy(), diagnostics,
                                   self.window_hist.copy()))
        self._mark()
        self._reset_window()

    # ----------------------------------------------------------------- checkpoints

    def state(self) -> dict:
        return {
            "stage": self.stage, "box": self.box, "pos": self.pos, "unwrapped": self.unwrapped,
            "reference": self.reference, "step": self.step, "window_hist": self.window_hist,
            "total_hist": self.total_hist, "total_measurements": self.total_measurements,
            "counters": json.dumps(self.counters), "equilibration": json.dumps(self.equilibration),
            "start_method": self.start_method,
            "sample_positions": (np.stack([s.positions for s in self.samples])
                                 if self.samples else np.zeros((0, self.n, self.dim))),
            "sample_diagnostics": json.dumps([s.diagnostics for s in self.samples]),
            "sample_histograms": (np.stack([s.contact_histogram for s in self.samples])
                                  if self.samples else np.zeros((0, len(self.window_hist)), np.int64)),
            "rng_state": json.dumps(self.rng.bit_generator.state, default=int),
        }

    def restore(self, data) -> None:
        self.stage = int(data["stage"])
        self.box = data["box"].copy()
        self.pos = data["pos"].copy()
        self.unwrapped = data["unwrapped"].copy()
        self.reference = data["reference"].copy()
        self.step = float(data["step"])
        self.window_hist = data["window_hist"].copy()
        self.total_hist = data["total_hist"].copy()
        self.total_measurements = int(data["total_measurements"])
        self.counters = json.loads(str(data["counters"]))
        self.equilibration = json.loads(str(data["equilibration"]))
        self.start_method = str(data["start_method"])
        diagnostics = json.loads(str(data["sample_diagnostics"]))
        self.samples = [Sample(p.copy(), d, h.copy()) for p, d, h in
                        zip(data["sample_positions"], diagnostics, data["sample_histograms"])]
        self.rng.bit_generator.state = json.loads(str(data["rng_state"]))
        self._rebuild_cells()


def contact_fit(hist, n_measurements, n_particles, box_lengths, diameter, settings) -> dict:
    """g(D+) and beta p / rho from a histogram of pair distances in [D, D (1 + range))
    accumulated over ``n_measurements`` configurations (module docstring)."""
    hist = np.asarray(hist, dtype=float)
    box_lengths = np.asarray(box_lengths, dtype=float)
    dim = len(box_lengths)
    phi = packing_fraction_of(n_particles, box_lengths, diameter)
    if n_measurements <= 0 or hist.sum() == 0:
        return {"contact_value": float("nan"), "reduced_pressure": float("nan"),
                "contact_value_se_fit": float("nan"),
                "coefficients": np.full(settings.contact_order + 1, np.nan)}
    order = settings.contact_order
    edges = diameter + np.linspace(0.0, settings.contact_range * diameter, len(hist) + 1)
    pair_density = n_particles * (n_particles - 1) / (2.0 * np.prod(box_lengths)) * n_measurements
    # design matrix: pair_density * int_bin x^k s1(D + x) dx, s1(r) = d v1(1) r^(d-1)
    surface = dim * float(ball_volume(1.0, dim))
    nodes, weights = np.polynomial.legendre.leggauss(8)
    design = np.zeros((len(hist), order + 1))
    for b in range(len(hist)):
        lo, hi = edges[b], edges[b + 1]
        r = 0.5 * (hi - lo) * nodes + 0.5 * (hi + lo)
        w = 0.5 * (hi - lo) * weights
        for k in range(order + 1):
            design[b, k] = pair_density * np.sum(w * ((r - diameter) / diameter) ** k
                                                  * surface * r ** (dim - 1))
    # Weighted least squares with weights fixed by the geometry (the expected count of an
    # ideal gas in each bin), never by the observed counts: data-dependent Poisson
    # weights bias sparse histograms low (bins that fluctuate down get more weight);
    # measured: -3 % on per-sample fits of 240 hard disks. The estimate is linear in the
    # counts, hence unbiased, and per-sample estimates can be averaged.
    sigma = np.sqrt(design[:, 0])
    a = design / sigma[:, None]
    coefficients, *_ = np.linalg.lstsq(a, hist / sigma, rcond=None)
    # Poisson covariance of the counts (the fitted ones) through the linear estimator
    estimator = np.linalg.pinv(a) / sigma[None, :]
    covariance = estimator @ np.diag(np.maximum(design @ coefficients, 1.0)) @ estimator.T
    g0 = float(coefficients[0])
    return {"contact_value": g0,
            "reduced_pressure": float(1.0 + 2.0 ** (dim - 1) * phi * g0),
            # Poisson-count error of the fit (correlated MC counts: a lower bound; the
            # production error bar is the SEM over decorrelated samples)
            "contact_value_se_fit": float(math.sqrt(covariance[0, 0])),
            "coefficients": coefficients}


def _checkpoint_key(n, box_lengths, diameter, n_samples, settings, rng, start) -> str:
    return checkpoint_key(n=n, box=np.asarray(box_lengths).tolist(), diameter=diameter, start=start,
                          n_samples=n_samples, settings=asdict(settings), rng=rng.bit_generator.state)


def _save(path, key, chain: HardParticleChain) -> None:
    save_checkpoint(path, key, chain.state())


def _load(path, key, chain: HardParticleChain, log) -> bool:
    data = load_checkpoint(path, key, log)
    if data is None:
        return False
    try:
        chain.restore(data)
    except (KeyError, ValueError) as exc:
        log.warning("%s is incomplete (%s); starting afresh", path, exc)
        return False
    log.info("resumed from %s: stage %s, %d sweeps, %d samples", path,
             chain.STAGES[chain.stage], chain.counters["sweeps"], len(chain.samples))
    return True


def run_chain(n_particles: int, box_lengths, diameter: float, n_samples: int,
              rng: np.random.Generator, settings: MCSettings = MCSettings(), *,
              checkpoint: str | os.PathLike | None = None, checkpoint_seconds: float = 60.0,
              log: logging.Logger | None = None, log_seconds: float = 10.0,
              start: str = "auto", keep_checkpoint: bool = False) -> ChainResult:
    """Run one chain to ``n_samples`` production samples (module docstring).

    ``box_lengths`` (d,) of the periodic orthogonal box, d = 2 or 3, in the units of
    ``diameter``. ``checkpoint``: file to save the chain state to (at block boundaries,
    at most every ``checkpoint_seconds``) and to resume from if it belongs to the same
    chain; removed when the chain finishes unless ``keep_checkpoint`` (then the final
    state is saved, so that a caller killed while writing its outputs resumes at once;
    the caller removes it afterwards). The returned samples are the same whether or
    not the chain was interrupted and resumed.
    """
    log = log or logging.getLogger(__name__)
    validate_system(n_particles, box_lengths, diameter, settings.contact_range)
    if n_samples < 1:
        raise ValueError(f"n_samples must be >= 1, got {n_samples}")
    box_lengths = np.asarray(box_lengths, dtype=float)
    key = _checkpoint_key(int(n_particles), box_lengths, float(diameter), int(n_samples),
                          settings, rng, start)
    chain = HardParticleChain(n_particles, box_lengths, diameter, n_samples, settings, rng, start)
    if checkpoint is None or not _load(checkpoint, key, chain, log):
        chain.start()
        log.info("start: N = %d, d = %d, phi = %.4f, box %s: %s", chain.n, chain.dim,
                 chain.phi, box_lengths, chain.start_method)
    started = last_save = last_log = time.perf_counter()
    cpu_started = time.process_time()
    sweeps_at_start = chain.counters["sweeps"]
    while chain.stage < 4:
        chain.advance()
        now = time.perf_counter()
        if checkpoint is not None and now - last_save >= checkpoint_seconds:
            _save(checkpoint, key, chain)
            last_save = now
        if now - last_log >= log_seconds:
            _log_progress(log, chain, now - started, time.process_time() - cpu_started,
                          chain.counters["sweeps"] - sweeps_at_start)
            last_log = now
    _log_progress(log, chain, time.perf_counter() - started, time.process_time() - cpu_started,
                  chain.counters["sweeps"] - sweeps_at_start)
    for index, sample in enumerate(chain.samples):  # exact check, independent of the cell lists
        overlaps = count_overlaps(sample.positions, box_lengths, diameter)
        if overlaps:
            raise ChainError(f"sample {index} has {overlaps} overlapping pairs")
    pooled = contact_fit(chain.total_hist, chain.total_measurements, chain.n, box_lengths,
                         chain.diameter, settings)
    pooled["measurements"] = chain.total_measurements
    pooled["histogram"] = chain.total_hist.copy()
    chain.equilibration.update({"total_sweeps": chain.counters["sweeps"],
                                "extended_samples": chain.counters["extended_samples"],
                                "overall_acceptance": chain.counters["accepted"]
                                / max(1, chain.counters["trials"])})
    if checkpoint is not None:
        if keep_checkpoint:
            _save(checkpoint, key, chain)
        else:
            Path(checkpoint).unlink(missing_ok=True)
    return ChainResult(box_lengths=box_lengths, diameter=float(diameter), phi=chain.phi,
                       samples=chain.samples, equilibration=chain.equilibration, contact=pooled)


def _log_progress(log, chain: HardParticleChain, seconds: float, cpu_seconds: float,
                  sweeps: int) -> None:
    """Progress line: sweeps, rate (wall and per CPU second), acceptance, step, MSD, ETA."""
    rate = sweeps / seconds if seconds > 0 else float("nan")
    cpu_rate = sweeps * chain.n / cpu_seconds if cpu_seconds > 0 else float("nan")
    stage = chain.STAGES[min(chain.stage, 4)]
    eta = ""
    if stage == "produce" and rate > 0 and chain.counters["interval"]:
        remaining = (chain.n_samples - len(chain.samples)) * chain.counters["interval"] \
            - chain.counters["window_sweeps"]
        eta = f", ETA {max(0.0, remaining / rate):.0f} s"
    if chain.counters["window_trials"]:
        acceptance = chain.counters["window_accepted"] / chain.counters["window_trials"]
    else:
        acceptance = chain.counters["accepted"] / max(1, chain.counters["trials"])
    log.info("%s: %d sweeps (%.3g sweeps/s, %.3g moves per CPU s), acceptance %.3f, step "
             "%.4g D, MSD %.3g D^2, samples %d/%d%s", stage, chain.counters["sweeps"], rate,
             cpu_rate, acceptance, chain.step / chain.diameter, chain.msd(),
             len(chain.samples), chain.n_samples, eta)


def count_overlaps(positions, box_lengths, diameter: float) -> int:
    """Exact count of pairs closer than ``diameter`` (nearest periodic images), by the
    k-d tree pair search of :mod:`randmedia.periodic` (independent of the MC cell list)."""
    from randmedia.periodic import Cell, pairs_within

    box_lengths = np.asarray(box_lengths, dtype=float)
    cell = Cell.orthogonal(box_lengths)
    if diameter > cell.half_width:
        raise ValueError("box too small for an overlap check (D > half the box)")
    i, _, _, distance = pairs_within(cell, positions, diameter)
    return int(np.count_nonzero(distance < diameter))


# --------------------------------------------------------------------------- sample files


def sample_attrs(result: ChainResult, index: int) -> dict:
    """The diagnostics of sample ``index`` of a chain, as flat netCDF attributes: its own
    (MSD since the previous sample in D^2, sweeps, acceptance, contact value, reduced
    pressure) and the chain's (start, equilibration, frozen step, sampling interval)."""
    sample = result.samples[index]
    attrs = {key: sample.diagnostics[key] for key in (
        "msd_since_previous", "sweeps_since_previous", "acceptance", "contact_value",
        "reduced_pressure", "contact_measurements", "total_sweeps")}
    eq = result.equilibration
    attrs.update({
        "start": eq["start"],
        "equilibration_sweeps": eq["equilibration_sweeps"],
        "compression_sweeps": eq["compression_sweeps"],
        "equilibration_msd": eq["equilibration_msd"],
        "step_over_diameter": eq["step"] / result.diameter,
        "sample_interval_sweeps": eq["sample_interval_sweeps"],
        "chain_acceptance": eq["acceptance"],
        "n_particles": len(sample.positions),
        "phi_particles": result.phi,
    })
    return {key: (int(v) if isinstance(v, (bool, np.bool_)) else v) for key, v in attrs.items()}


def contact_histogram_dataset(result: ChainResult, index: int, settings: MCSettings):
    """The pair counts near contact accumulated since the previous sample (re-fittable)."""
    import xarray as xr

    edges = 1.0 + np.linspace(0.0, settings.contact_range, settings.contact_bins + 1)
    return xr.Dataset(
        {"contact_pairs": (("contact_bin",), result.samples[index].contact_histogram.astype(np.int64),
                           {"units": "1", "long_name": "pair counts with r in the bin, summed over "
                            "the contact measurements since the previous sample (attr "
                            "contact_measurements)"})},
        coords={"contact_r_lower": (("contact_bin",), edges[:-1],
                                    {"units": "D", "long_name": "lower bin edge r / D"}),
                "contact_r_upper": (("contact_bin",), edges[1:],
                                    {"units": "D", "long_name": "upper bin edge r / D"})},
    )
