"""The Markov chain of equilibrium hard disks / spheres (NVT Monte Carlo).

Moves. Single-particle displacements: a particle chosen uniformly at random is
displaced by a vector uniform in [-step, step]^d and the move is accepted iff the
new position overlaps no other particle (Metropolis for hard cores). The proposal is
symmetric, so detailed balance holds *for a fixed step*: the step is tuned only
while the chain equilibrates (towards ``target_acceptance``, default 0.25: measured at
phi = 0.478 in 3D, targets 0.15-0.25 give the largest MSD per CPU second, 1.7 times
that of 0.45, since rejected trials are cheap) and is frozen before any production
sample is taken. The step is capped at half the box. Overlap checks use a cell
list (cells of side >= D, the 3^d cells around the trial position), kept up to date
move by move, in numba kernels (``cache=True``; :mod:`~randmedia.generate.hard_particles.kernels`).
Event-chain Monte Carlo was not
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
own contact-value pressure (:mod:`~randmedia.generate.hard_particles.contact`).

The chain works in blocks of ``block_sweeps`` sweeps whose boundaries depend only on
the chain itself; :meth:`HardParticleChain.state` / :meth:`~HardParticleChain.restore`
are its whole state (arrays, counters, random state, the samples taken so far), which
:func:`randmedia.generate.hard_particles.run.run_chain` checkpoints.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field

import numpy as np

from randmedia.generate.hard_particles.contact import contact_fit
from randmedia.generate.hard_particles.geometry import lattice_sites, packing_fraction_of
from randmedia.generate.hard_particles.kernels import (CellList, pair_scan, random_sequential_addition,
                                                      sweeps)
from randmedia.generate.hard_particles.settings import ChainError

#: packing fraction of the random-sequential-addition start (well below RSA jamming)
RSA_PHI = {2: 0.35, 3: 0.25}


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
class HardParticleChain:
    """One Markov chain; see the module docstring. Use
    :func:`randmedia.generate.hard_particles.run.run_chain`."""

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
        self.cells: CellList | None = None

    # ----------------------------------------------------------------- helpers

    def _rebuild_cells(self):
        self.cells = CellList(self.box, self.dim, self.n, self.diameter)
        self.cells.build(self.pos, self.box)

    def _run(self, n_sweeps):
        c = self.cells
        accepted = sweeps(self.pos, self.unwrapped, self.box, self.dim, self.diameter, self.step,
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
        c = CellList(self.box, self.dim, self.n, self.cutoff)
        c.build(self.pos, self.box)
        scratch_hist = np.zeros(self.settings.contact_bins, dtype=np.int64) if hist is None else hist
        overlaps, r_min = pair_scan(self.pos, self.box, c.ncell, c.members, c.count,
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
            self.cells = CellList(self.box, self.dim, self.n, self.diameter)
            c = self.cells
            placed = random_sequential_addition(self.pos, self.box, self.dim, self.diameter, c.ncell,
                                                c.members, c.count, c.cell_of, c.slot_of,
                                                1000 * self.n + 10000, self.rng)
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
        """The whole state of the chain (arrays, counters, random state, samples) by name."""
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

    def restore(self, data) -> "HardParticleChain":
        """This chain set to the arrays of :meth:`state` (KeyError / ValueError if they are
        incomplete); returns itself."""
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
        return self
