"""The certificate of a jammed packing, and its repair at a degenerate vertex.

Every MRJ packing is tested for strict jamming by the LP test of
:func:`randmedia.describe.jamming.analyse` at the configured contact gap. An isostatic
packing can fail that test only because one or two backbone contacts bear no load: the
polish (:func:`randmedia.generate.jammed.jam`) stopped at a degenerate vertex, one contact
short of rigid, where the motion that opens the unloaded contact and lowers the volume is
blocked by a near pair 10^-9 - 10^-8 D away and each LP gains less than the polish's
tolerance (docs/mrj2016.md). :func:`certified` then takes the test's own cone motion as far
as the first pair it closes (:func:`randmedia.generate.jammed.leave_vertex`), polishes again
with the same constants and tests again, for at most ``max_rounds`` rounds. The packing
fraction changes by ~10^-6; the new network is closed by the polish like any other. A
packing still uncertified after the rounds is returned as it is, counted as such.

A packing whose polish ended at its ``max_lps`` still compacting (``stop`` "max_lps", the
``polish.at_max_lps`` "end" of :mod:`randmedia.generate.mrj`) is tested but not repaired: the
repair's premise, a converged polish one unloaded contact short of rigid, does not hold, and
polishing it again would only go on with the creep its polish was ended in.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, replace

import numpy as np

from randmedia.describe import jamming
from randmedia.generate.jammed import JammedPacking, TJParameters, jam, leave_vertex

#: rounds of leave-vertex + polish: a bound, not a tuned constant. Measured at N = 2000 (paper
#: config): four packings certified after one round, sample 9 after four (its first three steps
#: s = 2e-9 - 1e-5 led back to a degenerate vertex); a round costs 15-40 CPU s there
MAX_REPAIR_ROUNDS = 10


@dataclass(frozen=True)
class Repair:
    """What the repair did: rounds, their steps s (units of the LP's |x| <= 1), polish LPs and
    CPU seconds (0, (), 0, 0.0 for a packing certified at once)."""

    rounds: int = 0
    steps: tuple[float, ...] = ()
    lps: int = 0
    cpu_seconds: float = 0.0

    def attrs(self) -> dict:
        """The packing file's attributes of the repair."""
        return {"repair_rounds": self.rounds, "repair_lps": self.lps,
                "repair_cpu_seconds": self.cpu_seconds,
                "repair_steps": np.asarray(self.steps, dtype=float)}


def certified(packing: JammedPacking, polish: TJParameters, contacts: dict, *,
              max_rounds: int = MAX_REPAIR_ROUNDS, log: logging.Logger | None = None,
              threads: int = 1):
    """Test ``packing`` and repair it at a degenerate vertex (module docstring).

    Parameters
    ----------
    packing : JammedPacking
        A polished packing (any subclass: the result is the same class, its positions, cell,
        LP count, times and polish history extended by the repair's LPs); one ended at
        ``max_lps`` (``stop``) is only tested (module docstring).
    polish : TJParameters
        The polish constants (the repair polishes with these).
    contacts : dict
        Keyword arguments of :func:`randmedia.describe.jamming.analyse` (``gap_tolerance``,
        ``rank_tolerance``, ``force_tolerance``).
    max_rounds : int, optional
        Bound on the rounds.
    log : logging.Logger, optional
        Progress.
    threads : int, optional
        HiGHS threads.

    Returns
    -------
    packing : JammedPacking
        The packing, repaired or not.
    analysis : randmedia.describe.jamming.JammingAnalysis
        Its test.
    repair : Repair
        What the repair did.
    """
    log = log or logging.getLogger(__name__)
    analysis = jamming.analyse(packing.positions, packing.box, packing.diameter, **contacts)
    if packing.stop == "max_lps":
        log.warning("the polish ended at max_lps still compacting: tested (jammed %s), not repaired",
                    analysis.jammed)
        return packing, analysis, Repair()
    steps, lps, cpu = [], 0, 0.0
    while not analysis.jammed and len(steps) < max_rounds and analysis.motion is not None:
        tic, wall = time.process_time(), time.perf_counter()
        strain, displacement = analysis.motion
        positions, box, step = leave_vertex(packing.positions, packing.box, strain, displacement,
                                            packing.diameter, contact_gap=contacts.get("gap_tolerance", 1e-9))
        polished = jam(positions, box, polish, diameter=packing.diameter, log=log, threads=threads)
        steps.append(step)
        lps += polished.n_lp
        round_cpu = time.process_time() - tic
        cpu += round_cpu
        history = {key: list(packing.history.get(key, [])) + list(values)
                   for key, values in polished.history.items()}
        packing = replace(packing, positions=polished.positions, box=polished.box,
                          n_lp=packing.n_lp + polished.n_lp,
                          seconds=packing.seconds + time.perf_counter() - wall,
                          cpu_seconds=packing.cpu_seconds + round_cpu,
                          lp_seconds=packing.lp_seconds + polished.lp_seconds, history=history)
        analysis = jamming.analyse(packing.positions, packing.box, packing.diameter, **contacts)
        log.info("repair round %d: left the vertex by s = %.3g along the cone (min Tr eps was "
                 "negative or a backbone contact unloaded), %d polish LPs, phi = %.7f: jammed %s",
                 len(steps), step, polished.n_lp, packing.phi, analysis.jammed)
    return packing, analysis, Repair(len(steps), tuple(steps), lps, cpu)
