"""Maximally random jammed (MRJ) sphere packings: fast compression, then linear programs.

Klatt & Torquato, PRE 94, 022152 (2016), analyse strictly jammed packings of N = 2000
(and 10 000) monodisperse spheres at phi = 0.6356 made by the Torquato-Jiao (TJ)
sequential-LP algorithm from dilute starts. Here the same kind of packing is made in
three stages, each a standard method (README, mrj2016 methods, for the measurements
behind the choice):

1. **Compression** (:mod:`randmedia.generate.lubachevsky_stillinger`): event-driven MD
   of growing spheres from a Poisson start, fast (growth rate ``growth_rate``) until the
   reduced pressure reaches ``slowdown_pressure``, then quasi-statically (growth rate
   proportional to 1 / pressure) until ``target_pressure``. The fast stage freezes the
   disorder: rapid compressions jam monodisperse spheres at the "lowest typical" density
   0.634-0.636 (Baranau & Tallarek, Soft Matter 10, 3826 (2014)), the density of the
   paper's TJ packings, while slower ones rearrange towards 0.64 and beyond. The slow
   stage only brings the spheres close to their jammed state (gaps ~ D / pressure).
2. **Collective jamming in the fixed cell** (:mod:`randmedia.generate.inflation`):
   iterated inflation LPs until no sphere of the backbone can move and no inflation is
   left, or at most ``max_lps`` of them (a rare packing creeps: a sliding motion the fixed
   cell does not stop, which stage 3 removes). Each step is exact (conservative
   constraints), so nothing is ever rejected.
3. **Strict jamming** (:func:`randmedia.generate.jammed.jam`): TJ LPs with a deformable
   cell (minimize Tr epsilon) and small strain bounds until the volume cannot be lowered
   to first order: the cell's d (d + 1) / 2 strain degrees of freedom are blocked too.

Starting LPs from a compressed state matters for the cost: from a dilute start the LPs
spend hundreds of steps in a slow creep near phi ~ 0.62-0.63 whose per-step gain is set
by the LP optimum itself, not by the step bounds (measured: README).

The whole construction is deterministic given the seed; a checkpoint (at the end of the
compression and at LP boundaries; :class:`randmedia.resumable.ResumableRun`) resumes it
after a kill with the same result.
"""

from __future__ import annotations

import logging
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from randmedia.checkpoint import checkpoint_key
from randmedia.config import MRJ_ROUTE_STAGES
from randmedia.generate import inflation, packing_lp
from randmedia.generate.jammed import (ConstructionError, JammedPacking, TJParameters,
                                       constants_without_cap, jam, packing_fraction,
                                       tj_lp_history, validate_packing_input)
from randmedia.generate.lubachevsky_stillinger import LSParameters, compress
from randmedia.generate.rsa import random_sequential_addition
from randmedia.theory.balls import ball_volume
from randmedia.resumable import ResumableRun

#: per-LP keys of the inflation stage kept in the packing's history
INFLATION_HISTORY = ("phi",) + inflation.STEP_RECORD_KEYS


@dataclass(frozen=True)
class DiluteTJ:
    """The paper's route: Torquato-Jiao LPs from a dilute random start, with the constants
    of the public TJ code of Atkinson, Stillinger & Torquato, PRE 88, 062208 (2013)
    (sdatkinson/TJ, ``test3d/parameters_3d.txt``): start at ``initial_phi`` (random
    sequential addition, as dilute as the code's example start), influence sphere
    ``influence_gap`` D beyond contact, translation bound ``translation_max`` D in lattice
    coordinates (Cartesian: times the cell's linear size relative to the start), every step
    accepted and its overlaps removed by rescaling (no trust region), stop when the cell
    volume changed by at most ``volume_tolerance`` of the start volume over two LPs.

    ``max_lps`` bounds the stage: after that many LPs it ends where it stands and the polish
    takes over, as the TJ code ends after ``max_iterations`` LPs and writes its packing (2000
    in its example parameters, the paper config's value at N = 10 000, where no stage ends by
    the volume rule; the N = 2000 packings were made with 5000, above all their stages,
    649-1557 LPs, so either cap gives them; docs/mrj2016.md). The packing's ``dilute_stop``
    says which rule ended the stage. The cap is not part of the stage's checkpoint key (it
    changes where the stage ends, not its LPs): a stage resumes under a changed cap unless it
    is already past it.

    Strain bounds: the code multiplies every length-like constant by the diameter of its
    unit-cell start, the strain bounds ``comp_max`` = ``shear_max`` = 0.1 included, so its
    strain bound is ``strain_max`` D / L_0 = 0.1 (phi_0 / (n v_1))^(1/d) -- 0.0073, 0.0046 and
    0.0027 for n = 500, 2000 and 10 000 at phi_0 = 0.1 (:meth:`tj_parameters`).
    """

    initial_phi: float = 0.1
    influence_gap: float = 0.2
    translation_max: float = 0.01
    strain_max: float = 0.1
    volume_tolerance: float = 1e-8
    max_lps: int = 5000
    backend: str = "highs-hipo"

    def tj_parameters(self, n: int, dim: int = 3, diameter: float = 1.0) -> TJParameters:
        """The :class:`TJParameters` of the route for ``n`` spheres (class docstring)."""
        start_side = (n * ball_volume(diameter / 2.0, dim) / self.initial_phi) ** (1.0 / dim)
        strain = self.strain_max * diameter / start_side
        return TJParameters(influence_gap=self.influence_gap, max_normal_strain=strain,
                            max_shear_strain=strain, translation_max=self.translation_max,
                            trust_region=False, volume_tolerance_start=self.volume_tolerance,
                            tolerance=1e-10, max_lps=self.max_lps, backend=self.backend)


#: the routes to a packing: "compression" (LS, inflation LPs, polish; module docstring) and
#: "dilute" (:class:`DiluteTJ`, then the same polish)
ROUTES = tuple(MRJ_ROUTE_STAGES)

#: what a polish still compacting after ``polish.max_lps`` LPs does (config key
#: ``polish.at_max_lps``): "redraw" -- fail, so :func:`make_packing_retrying` discards the start
#: and draws the next seed (rare at N = 2000: 2 of 13 starts); "end" -- end there (after one
#: vertex LP when the polish has a ``final_backend``) and keep the packing, whose jamming test
#: then decides whether it is certified (N = 10 000, where every start creeps: docs/mrj2016.md)
POLISH_AT_MAX_LPS = ("redraw", "end")


@dataclass(frozen=True)
class MRJProtocol:
    """The stages of the module docstring (``route`` "compression") or of the paper's route
    (``route`` "dilute": :class:`DiluteTJ`, then the polish) and their constants."""

    compression: LSParameters = field(default_factory=LSParameters)
    inflation: inflation.InflationParameters = field(default_factory=inflation.InflationParameters)
    polish: TJParameters = field(default_factory=lambda: TJParameters(
        influence_gap=0.1, max_normal_strain=3e-3, max_shear_strain=3e-3, tolerance=1e-10,
        max_lps=500, shrink_with_trust=True, backend="highs-ipm"))
    route: str = "dilute"
    dilute: DiluteTJ = field(default_factory=DiluteTJ)
    #: :data:`POLISH_AT_MAX_LPS`
    polish_at_max_lps: str = "redraw"

    def __post_init__(self):
        if self.route not in ROUTES:
            raise ValueError(f"MRJ route must be one of {ROUTES}, got {self.route!r}")
        if self.polish_at_max_lps not in POLISH_AT_MAX_LPS:
            raise ValueError(f"polish.at_max_lps must be one of {POLISH_AT_MAX_LPS}, got "
                             f"{self.polish_at_max_lps!r}")

    @classmethod
    def from_config(cls, section: dict) -> "MRJProtocol":
        """From the config keys ``route``, ``compression``, ``inflation``, ``dilute`` and ``polish``
        (whose ``at_max_lps``, "redraw" where absent, is :attr:`polish_at_max_lps`)."""
        polish = dict(section["polish"])
        at_max_lps = polish.pop("at_max_lps", "redraw")
        return cls(LSParameters(**section.get("compression", {})),
                   inflation.InflationParameters(**section.get("inflation", {})),
                   TJParameters(**polish, shrink_with_trust=True),
                   route=section.get("route", "dilute"),
                   dilute=DiluteTJ(**section.get("dilute", {})), polish_at_max_lps=at_max_lps)

    def polish_stage(self, positions, box, **options) -> JammedPacking:
        """The polish (:func:`randmedia.generate.jammed.jam` with :attr:`polish`) from
        ``positions`` in ``box``; at ``polish.max_lps`` it raises or ends as
        :attr:`polish_at_max_lps` says."""
        return jam(positions, box, self.polish, at_max_lps="end" if self.polish_at_max_lps == "end" else "raise",
                   **options)

    def as_dict(self) -> dict:
        """The constants of the stages the route runs (``MRJ_ROUTE_STAGES``) and the polish's;
        the route itself only for "dilute", so the compression route's checkpoints and
        attributes stay as they were."""
        stages = {stage: asdict(getattr(self, stage)) for stage in MRJ_ROUTE_STAGES[self.route]}
        route = {"route": {"name": self.route}} if self.route == "dilute" else {}
        return {**route, **stages, "polish": asdict(self.polish)}


@dataclass
class MRJPacking(JammedPacking):
    """A strictly jammed packing and the record of all three stages."""

    compression: dict = field(default_factory=dict)   # LS: phi, pressure, collisions, seconds
    inflation_history: dict = field(default_factory=dict)
    n_inflation_lp: int = 0
    #: why the inflation stage ended (:func:`randmedia.generate.inflation.stop_reason`)
    inflation_stop: str = ""
    #: per-LP record of the dilute TJ stage (route "dilute"; jammed.jam's history keys)
    dilute_history: dict = field(default_factory=dict)
    n_dilute_lp: int = 0
    #: why the dilute stage ended: "converged" (the TJ code's volume rule) or "max_lps"
    dilute_stop: str = ""

    def construction_attrs(self) -> dict:
        attrs = {f"{stage}_{k}": v for stage, values in self.params.as_dict().items()
                 for k, v in values.items()}
        attrs.update({f"compression_final_{k}": v for k, v in self.compression.items()})
        attrs["n_inflation_lp"] = self.n_inflation_lp
        attrs["inflation_stop"] = self.inflation_stop
        attrs["n_polish_lp"] = self.n_lp - self.n_inflation_lp - self.n_dilute_lp
        attrs["polish_at_max_lps"] = self.params.polish_at_max_lps
        attrs["polish_stop"] = self.stop
        if self.params.route == "dilute":
            attrs["n_dilute_lp"] = self.n_dilute_lp
            attrs["dilute_stop"] = self.dilute_stop
        return attrs

    def lp_history(self) -> dict:
        """Per-LP record of all stages in order: stage 0 = inflation, 2 = dilute TJ,
        1 = the TJ polish."""
        h = self.inflation_history
        m = len(h.get("phi", []))
        inflation_record = {"stage": np.zeros(m, dtype=np.int8),
                            "phi": np.asarray(h.get("phi", []), dtype=float),
                            "predicted": self.positions.shape[1] * np.asarray(h.get("inflation", []), dtype=float),
                            "rows": np.asarray(h.get("rows", []), dtype=np.int64),
                            "solve_seconds": np.asarray(h.get("solve_seconds", []), dtype=float)}
        stages = (inflation_record, tj_lp_history(self.dilute_history, stage=2), super().lp_history())
        return {key: np.concatenate([record[key] for record in stages]) for key in inflation_record}


def _key(seed: int, n: int, dim: int, protocol: MRJProtocol) -> str:
    return checkpoint_key(seed=int(seed), n=int(n), dim=int(dim), protocol=protocol.as_dict())


def make_packing(seed: int, n: int, protocol: MRJProtocol = MRJProtocol(), *, dim: int = 3,
                 checkpoint: str | os.PathLike | None = None, checkpoint_seconds: float = 120.0,
                 log: logging.Logger | None = None, log_seconds: float = 15.0,
                 threads: int = 1) -> MRJPacking:
    """One strictly jammed packing of ``n`` spheres (D = 1) from ``seed`` (module docstring).

    Parameters
    ----------
    seed : int
        Seeds the compression's random start; the rest is deterministic.
    n : int
        Spheres.
    protocol : MRJProtocol
        Constants of the three stages.
    dim : int
        2 or 3.
    checkpoint : path, optional
        File the state is saved to after the compression and then at LP boundaries (at most
        every ``checkpoint_seconds``), and resumed from if it belongs to the same seed, size
        and protocol; removed on success (the polish stage keeps its own file beside it while
        it runs). Saving and resuming are :class:`randmedia.resumable.ResumableRun`'s.
    log, log_seconds
        Progress of the inflation LPs at most every ``log_seconds`` (and the polish's).
    threads : int
        HiGHS threads.

    Returns
    -------
    MRJPacking
        The packing and the record of all three stages.

    Raises
    ------
    ConstructionError
        If the polish does not converge within ``protocol.polish.max_lps``
        (:func:`randmedia.generate.jammed.jam`) and ``protocol.polish_at_max_lps`` is
        "redraw" (with "end" the packing is returned, its ``stop`` "max_lps"); inflation LPs that do not converge within
        ``protocol.inflation.max_lps``, and a dilute stage after ``protocol.dilute.max_lps``
        LPs, hand over to the polish instead.
    """
    log = log or logging.getLogger(__name__)
    validate_packing_input(n, 0.5, dim)
    packing_lp.check_backends(protocol.polish.backend, *([protocol.polish.final_backend] if protocol.polish.final_backend else []),
                              protocol.dilute.backend if protocol.route == "dilute" else protocol.inflation.backend)
    if protocol.route == "dilute":
        return _make_packing_dilute(seed, n, protocol, dim=dim, checkpoint=checkpoint,
                                    checkpoint_seconds=checkpoint_seconds, log=log,
                                    log_seconds=log_seconds, threads=threads)
    params = protocol.inflation
    run = ResumableRun(checkpoint, _key(seed, n, dim, protocol), log,
                       checkpoint_seconds=checkpoint_seconds, log_seconds=log_seconds)
    state = run.resume(_restore)
    if state is not None:
        positions, box, history, compression = state
        log.info("resumed from %s after the compression and %d inflation LPs", checkpoint,
                 len(history["phi"]))
    else:
        history = {name: [] for name in INFLATION_HISTORY}
        positions, box, info = compress(np.random.default_rng(seed), n, dim, protocol.compression,
                                        log=log, log_seconds=log_seconds)
        compression = {name: float(info[name]) for name in
                       ("phi", "pressure", "events", "collisions", "seconds")}
        log.info("compression: phi = %.5f at reduced pressure %.3g after %.3g collisions "
                 "(%.1f s)", compression["phi"], compression["pressure"],
                 compression["collisions"], compression["seconds"])

    def arrays() -> dict:
        return {"positions": positions, "box": box,
                **{f"ls_{name}": value for name, value in compression.items()},
                **{f"history_{name}": np.asarray(values, dtype=float) for name, values in history.items()}}

    if state is None:
        run.save(arrays)
    reason = inflation.stop_reason(history["inflation"], history["phi"], params)
    progress = run.progress(None, "inflation", "LPs", done=len(history["phi"]))

    def finished() -> bool:
        return reason is not None

    def step() -> None:
        nonlocal positions, box, reason
        bound = params.bound(history["inflation"][-1]) if history["phi"] else params.displacement_bound
        positions, box, record = inflation.inflation_step(positions, box, bound,
                                                          backend=params.backend, threads=threads)
        record["phi"] = packing_fraction(positions, box)
        if record["fallback"]:
            log.warning("inflation LP %d: %s", len(history["phi"]) + 1, record["fallback"])
        for name in INFLATION_HISTORY:
            history[name].append(record[name])
        reason = inflation.stop_reason(history["inflation"], history["phi"], params)
        progress.step(1, force=reason is not None, detail=lambda: (
            f"phi = {record['phi']:.7f}, sqrt(Gamma) - 1 = {record['inflation']:.3g} (realized "
            f"{record['realized']:.3g}), bound {bound:.3g}, {record['rows']} rows, {record['n_backbone']} "
            f"backbone spheres ({record['backbone_at_bound']} components at the bound), solve "
            f"{record['solve_seconds']:.2f} s (build {record['build_seconds']:.2f} s)"))

    run.loop(step, finished, arrays)
    log.info("inflation stage ended after %d LPs: %s%s", len(history["phi"]), reason,
             "" if reason != "max_lps" else
             f" (still inflating: last sqrt(Gamma) - 1 = {history['inflation'][-1]:.3g}, phi = "
             f"{history['phi'][-1]:.7f}); the polish takes over")
    run.save(arrays)  # a kill in the polish resumes after the inflation
    polish_checkpoint = _polish_checkpoint(checkpoint)
    packing = _nested_stage(run, lambda: protocol.polish_stage(
        positions, box, checkpoint=polish_checkpoint,
        checkpoint_seconds=checkpoint_seconds, log=log, log_seconds=log_seconds, threads=threads))
    seconds, cpu_seconds = run.seconds, run.cpu_seconds
    run.finish()
    n_inflation = len(history["phi"])
    log.info("polished (the jamming test follows) after %d inflation and %d TJ LPs in %.1f s (%.1f s CPU): "
             "phi = %.6f", n_inflation, packing.n_lp, seconds, cpu_seconds, packing.phi)
    return MRJPacking(positions=packing.positions, box=packing.box, diameter=1.0,
                      n_lp=n_inflation + packing.n_lp, seconds=seconds, cpu_seconds=cpu_seconds,
                      lp_seconds=float(np.sum(history["solve_seconds"])) + packing.lp_seconds,
                      history=packing.history, params=protocol, stop=packing.stop, compression=compression,
                      inflation_history={k: np.asarray(v) for k, v in history.items()},
                      n_inflation_lp=n_inflation, inflation_stop=reason)


def _make_packing_dilute(seed: int, n: int, protocol: MRJProtocol, *, dim: int, checkpoint,
                         checkpoint_seconds: float, log: logging.Logger, log_seconds: float,
                         threads: int) -> MRJPacking:
    """Route "dilute" of :func:`make_packing`: random sequential addition at
    ``protocol.dilute.initial_phi`` from ``seed``, TJ LPs with the constants of
    :class:`DiluteTJ`, then the polish (the same as the compression route's), which certifies
    the packing strictly jammed at the LP's precision. A checkpoint is saved after the dilute
    stage, so a kill in the polish does not repeat it."""
    # the state saved here is the dilute stage's result: it depends on that stage alone (the
    # polish resumes from its own checkpoint), and on its cap max_lps only through its LP count
    # (checked below), so the cap is not part of the key, as in jam's
    key = checkpoint_key(seed=int(seed), n=int(n), dim=int(dim), dilute=constants_without_cap(protocol.dilute))
    run = ResumableRun(checkpoint, key, log, checkpoint_seconds=checkpoint_seconds, log_seconds=log_seconds)
    state = run.resume(lambda data: (data["positions"], data["box"],
                                     {k[len("history_"):]: v for k, v in data.items() if k.startswith("history_")},
                                     str(data["stop"]) if "stop" in data else "converged"))
    if state is not None:
        positions, box, history, stop = state
        lps, cap = len(history["phi"]), protocol.dilute.max_lps
        # what a fresh run under this cap makes: a stage that converged within it, or one that
        # the same cap ended
        if lps > cap or (stop == "max_lps" and lps != cap):
            raise ValueError(
                f"checkpoint {checkpoint} holds a dilute stage that ended ({stop}) after {lps} LPs, "
                f"which dilute.max_lps = {cap} would not give: set the cap it ran with, or remove "
                "the file to start afresh")
        log.info("resumed from %s after the dilute TJ stage (%d LPs)", checkpoint, len(history["phi"]))
    else:
        start, start_box = random_sequential_addition(np.random.default_rng(seed), n,
                                                      protocol.dilute.initial_phi, dim)
        stage_checkpoint = None if checkpoint is None else \
            Path(checkpoint).with_name(Path(checkpoint).stem + ".dilute.npz")
        stage = _nested_stage(run, lambda: jam(
            start, start_box, protocol.dilute.tj_parameters(n, dim), checkpoint=stage_checkpoint,
            checkpoint_seconds=checkpoint_seconds, log=log, log_seconds=log_seconds, threads=threads,
            at_max_lps="end"))
        positions, box, history, stop = stage.positions, stage.box, stage.history, stage.stop
        log.info("dilute TJ stage: phi = %.6f after %d LPs (%.1f s CPU)%s", stage.phi, stage.n_lp,
                 stage.cpu_seconds, "" if stop == "converged" else
                 "; max_lps reached before the volume rule: the polish takes over")
        run.save({"positions": positions, "box": box, "stop": np.asarray(stop),
                  **{f"history_{k}": np.asarray(v) for k, v in history.items()}})
    packing = _nested_stage(run, lambda: protocol.polish_stage(
        positions, box, checkpoint=_polish_checkpoint(checkpoint),
        checkpoint_seconds=checkpoint_seconds, log=log, log_seconds=log_seconds, threads=threads))
    seconds, cpu_seconds = run.seconds, run.cpu_seconds
    run.finish()
    n_dilute = len(history["phi"])
    log.info("polished (the jamming test follows) after %d dilute TJ and %d polish LPs in %.1f s (%.1f s CPU): phi = %.6f",
             n_dilute, packing.n_lp, seconds, cpu_seconds, packing.phi)
    return MRJPacking(positions=packing.positions, box=packing.box, diameter=1.0,
                      n_lp=n_dilute + packing.n_lp, seconds=seconds, cpu_seconds=cpu_seconds,
                      lp_seconds=float(np.sum(history["seconds"])) + packing.lp_seconds,
                      history=packing.history, params=protocol, stop=packing.stop,
                      compression={"phi": protocol.dilute.initial_phi},
                      dilute_history={k: np.asarray(v) for k, v in history.items()},
                      n_dilute_lp=n_dilute, dilute_stop=stop)


#: seeds tried per sample by :func:`make_packing_retrying` (the first and two redraws)
MAX_ATTEMPTS = 3


def _nested_stage(run: ResumableRun, stage: Callable[[], JammedPacking]) -> JammedPacking:
    """``stage()``, a :func:`jam` with its own checkpoint inside ``run``: a stage resumed from
    that checkpoint ran partly in earlier processes, whose clocks (kept in the stage's
    checkpoint, returned in its ``seconds`` / ``cpu_seconds``) are added to ``run``'s, so the
    packing's totals count every process, not only the last one."""
    wall, cpu = time.perf_counter(), time.process_time()
    result = stage()
    run.seconds_before += max(result.seconds - (time.perf_counter() - wall), 0.0)
    run.cpu_seconds_before += max(result.cpu_seconds - (time.process_time() - cpu), 0.0)
    return result


def attempt_checkpoint(checkpoint: str | os.PathLike | None, attempt: int) -> Path | None:
    """Checkpoint file of attempt ``attempt``: ``checkpoint`` itself for the first, then
    ``.name.attempt{j}.npz`` beside it (so a redraw never resumes a discarded attempt)."""
    if checkpoint is None:
        return None
    path = Path(checkpoint)
    return path if attempt == 0 else path.with_name(f"{path.stem}.attempt{attempt}{path.suffix}")


def _polish_checkpoint(checkpoint: str | os.PathLike | None) -> Path | None:
    """Checkpoint file of the polish stage beside ``checkpoint`` (that of the compression and
    inflation stages)."""
    return None if checkpoint is None else Path(checkpoint).with_name(Path(checkpoint).stem + ".polish.npz")


def make_packing_retrying(seeds: Sequence[int], n: int, protocol: MRJProtocol = MRJProtocol(), *,
                          checkpoint: str | os.PathLike | None = None, log: logging.Logger | None = None,
                          **options) -> tuple[MRJPacking, int]:
    """:func:`make_packing` from ``seeds[0]``; with ``protocol.polish_at_max_lps`` "redraw" (the
    default) a packing whose polish does not converge within
    ``protocol.polish.max_lps`` (it keeps sliding: the volume still falls, in bursts, after
    hundreds of TJ LPs -- one of the ten paper-config N = 2000 starts, docs/mrj2016.md) is
    discarded and the sample made again from the next seed. An ensemble of packings that jam
    is what the paper analyses; discarding the rare creeping start is the usual practice of
    packing generators (the discarded fraction is a selection the log and
    ``packings.csv``'s attempt column make visible). Each attempt checkpoints to its own file
    (:func:`attempt_checkpoint`), so a killed run resumes the attempt it was in (a discarded
    attempt fails again at once from its checkpoint); once a packing is made, the checkpoints
    of the discarded attempts are removed. Every attempt is deterministic, hence so is the
    result.

    Returns
    -------
    (MRJPacking, int)
        The packing and the index of the attempt that made it.

    Raises
    ------
    ConstructionError
        If the polish of every seed fails.
    """
    log = log or logging.getLogger(__name__)
    if len(seeds) == 0:
        raise ValueError("make_packing_retrying needs at least one seed")
    for attempt, seed in enumerate(seeds):
        try:
            packing = make_packing(seed, n, protocol, checkpoint=attempt_checkpoint(checkpoint, attempt),
                                   log=log, **options)
        except ConstructionError as error:
            if attempt == len(seeds) - 1:
                raise
            log.warning("attempt %d (seed %d) discarded: %s; the sample is made again from the next seed",
                        attempt, seed, error)
            continue
        if checkpoint is not None:
            for discarded in range(attempt):
                stages = attempt_checkpoint(checkpoint, discarded)
                for path in (stages, _polish_checkpoint(stages)):
                    path.unlink(missing_ok=True)
        return packing, attempt
    raise AssertionError("unreachable")


def _restore(data: dict):
    """(positions, box, inflation history, compression record) from a checkpoint's arrays."""
    history = {name: data[f"history_{name}"].tolist() for name in INFLATION_HISTORY}
    compression = {name[len("ls_"):]: float(data[name]) for name in data if name.startswith("ls_")}
    return data["positions"], data["box"], history, compression
