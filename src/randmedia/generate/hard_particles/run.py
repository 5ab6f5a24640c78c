"""Running one hard-particle chain to its samples: :func:`run_chain`, resumable after a kill.

Reproducibility. All randomness comes from the numpy Generator passed in; the chain
works in blocks of ``block_sweeps`` sweeps whose boundaries depend only on the chain
itself, and a checkpoint (every ``checkpoint_seconds`` at a block boundary; arrays,
counters, random state and the samples taken so far) resumes the bit-identical chain
after a kill. Progress (sweeps, rates, acceptance, step, MSD, ETA) goes to the log
every ``log_seconds``; every sample is checked for overlaps independently of the
Monte Carlo cell lists before it is returned.
"""

from __future__ import annotations

import logging
import os
import time
from dataclasses import asdict
from pathlib import Path

import numpy as np

from randmedia.checkpoint import checkpoint_key, load_checkpoint, save_checkpoint
from randmedia.generate.hard_particles.chain import ChainResult, HardParticleChain
from randmedia.generate.hard_particles.contact import contact_fit
from randmedia.generate.hard_particles.geometry import count_overlaps, validate_system
from randmedia.generate.hard_particles.settings import ChainError, MCSettings


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
    """Run one chain to ``n_samples`` production samples (:mod:`~randmedia.generate.hard_particles.chain`).

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
