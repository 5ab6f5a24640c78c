"""Running one hard-particle chain to its samples: :func:`run_chain`, resumable after a kill.

Reproducibility. All randomness comes from the numpy Generator passed in; the chain
works in blocks of ``block_sweeps`` sweeps whose boundaries depend only on the chain
itself, and a checkpoint (every ``checkpoint_seconds`` at a block boundary; arrays,
counters, random state and the samples taken so far) resumes the bit-identical chain
after a kill. Progress (sweeps, rates, acceptance, step, MSD, ETA) goes to the log
every ``log_seconds``. Checkpoints and progress are those of the common driver
:class:`randmedia.resumable.ResumableRun`; every sample is checked for overlaps independently of the
Monte Carlo cell lists before it is returned.
"""

from __future__ import annotations

import logging
import os
from dataclasses import asdict

import numpy as np

from randmedia.checkpoint import checkpoint_key
from randmedia.generate.hard_particles.chain import ChainResult, HardParticleChain
from randmedia.generate.hard_particles.contact import contact_fit
from randmedia.generate.hard_particles.geometry import count_overlaps, validate_system
from randmedia.generate.hard_particles.settings import ChainError, MCSettings
from randmedia.resumable import ResumableRun


def _checkpoint_key(n, box_lengths, diameter, n_samples, settings, rng, start) -> str:
    return checkpoint_key(n=n, box=np.asarray(box_lengths).tolist(), diameter=diameter, start=start,
                          n_samples=n_samples, settings=asdict(settings), rng=rng.bit_generator.state)


def run_chain(n_particles: int, box_lengths, diameter: float, n_samples: int,
              rng: np.random.Generator, settings: MCSettings, *,
              checkpoint: str | os.PathLike | None = None, checkpoint_seconds: float = 60.0,
              log: logging.Logger | None = None, log_seconds: float = 10.0,
              start: str = "auto", keep_checkpoint: bool = False) -> ChainResult:
    """Run one chain to ``n_samples`` production samples (:mod:`~randmedia.generate.hard_particles.chain`).

    Parameters
    ----------
    n_particles : int
        N.
    box_lengths : array (d,)
        Sides of the periodic orthogonal box, d = 2 or 3, in the units of ``diameter``.
    diameter : float
        D.
    n_samples : int
        Production samples to take.
    rng : numpy.random.Generator
        The chain's only source of randomness.
    settings : MCSettings
        Step tuning, equilibration and sampling criteria, block size, contact histogram.
    checkpoint : path, optional
        File to save the chain state to (at block boundaries, at most every
        ``checkpoint_seconds``) and to resume from if it belongs to the same chain; removed
        when the chain finishes unless ``keep_checkpoint`` (then the final state is saved, so
        that a caller killed while writing its outputs resumes at once; the caller removes it
        afterwards). Saving, resuming and the progress lines are
        :class:`randmedia.resumable.ResumableRun`'s.
    log, log_seconds
        Progress lines (sweeps, rate, moves per CPU second, acceptance, step, MSD, samples,
        ETA once producing) at most every ``log_seconds``.
    start : str
        'auto', 'lattice' or 'rsa' (:meth:`HardParticleChain.start`).

    Returns
    -------
    ChainResult
        The samples (checked for overlaps), the equilibration record and the pooled contact
        fit; the same whether or not the chain was interrupted and resumed.
    """
    log = log or logging.getLogger(__name__)
    validate_system(n_particles, box_lengths, diameter, settings.contact_range)
    if n_samples < 1:
        raise ValueError(f"n_samples must be >= 1, got {n_samples}")
    box_lengths = np.asarray(box_lengths, dtype=float)
    key = _checkpoint_key(int(n_particles), box_lengths, float(diameter), int(n_samples),
                          settings, rng, start)
    run = ResumableRun(checkpoint, key, log, checkpoint_seconds=checkpoint_seconds, log_seconds=log_seconds)
    # the chain keeps its random state among its own arrays (HardParticleChain.state)
    chain = run.resume(HardParticleChain(n_particles, box_lengths, diameter, n_samples, settings, rng,
                                         start).restore)
    if chain is not None:
        log.info("resumed from %s: stage %s, %d sweeps, %d samples", checkpoint,
                 chain.STAGES[chain.stage], chain.counters["sweeps"], len(chain.samples))
    else:  # (a fresh chain: a failed restore may have left parts of a checkpoint behind)
        chain = HardParticleChain(n_particles, box_lengths, diameter, n_samples, settings, rng, start)
        chain.start()
        log.info("start: N = %d, d = %d, phi = %.4f, box %s: %s", chain.n, chain.dim,
                 chain.phi, box_lengths, chain.start_method)
    progress = run.progress(None, f"chain N = {chain.n}", "sweeps", done=chain.counters["sweeps"])

    def advance() -> None:
        before = chain.counters["sweeps"]
        chain.advance()
        _report(progress, chain, chain.counters["sweeps"] - before, run.run_cpu_seconds)

    run.loop(advance, lambda: chain.stage >= 4, chain.state)
    _report(progress, chain, 0, run.run_cpu_seconds, force=True)
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
    run.finish(chain.state if keep_checkpoint else None)
    return ChainResult(box_lengths=box_lengths, diameter=float(diameter), phi=chain.phi,
                       samples=chain.samples, equilibration=chain.equilibration, contact=pooled)


def _report(progress, chain: HardParticleChain, sweeps: int, cpu_seconds: float,
            force: bool = False) -> None:
    """Progress line after ``sweeps`` more sweeps: stage, moves per CPU second of this
    process, acceptance, step, MSD, samples; once producing, the total (hence ETA) is the
    sweeps done plus those the remaining samples need at the sampling interval."""
    stage = chain.STAGES[min(chain.stage, 4)]
    total = None
    if stage == "produce" and chain.counters["interval"]:
        remaining = (chain.n_samples - len(chain.samples)) * chain.counters["interval"] \
            - chain.counters["window_sweeps"]
        total = chain.counters["sweeps"] + max(0, remaining)
    elif stage == "done":
        total = chain.counters["sweeps"]

    def detail() -> str:
        if chain.counters["window_trials"]:
            acceptance = chain.counters["window_accepted"] / chain.counters["window_trials"]
        else:
            acceptance = chain.counters["accepted"] / max(1, chain.counters["trials"])
        moves = (progress.done - progress.start_done) * chain.n
        cpu_rate = moves / cpu_seconds if cpu_seconds > 0 else float("nan")
        return (f"{stage}, {cpu_rate:.3g} moves per CPU s, acceptance {acceptance:.3f}, step "
                f"{chain.step / chain.diameter:.4g} D, MSD {chain.msd():.3g} D^2, samples "
                f"{len(chain.samples)}/{chain.n_samples}")

    progress.step(sweeps, detail, total=total, force=force)
