"""The one driver of every construction that runs for minutes and must survive a kill.

DESIGN.md, Conventions: "Long jobs report progress to their log (rate, ETA) and can be
resumed". The generators that do -- :func:`randmedia.generate.hard_particles.run.run_chain`
(Metropolis chains of hard disks and spheres), :func:`randmedia.generate.sphere_mc.run_fluid`
(Monte Carlo on the sphere), :func:`randmedia.generate.jammed.jam` (Torquato-Jiao LPs),
:func:`randmedia.generate.yeong_torquato.construct` (Yeong-Torquato annealing) and
:func:`randmedia.generate.mrj.make_packing` (inflation LPs) -- provide only their state
(arrays and scalars), their step and their key; a :class:`ResumableRun` owns the rest:

1. *Resume.* The checkpoint (:mod:`randmedia.checkpoint`: one ``.npz`` per run) is used only
   if its key -- the SHA-256 of the run's parameters and start state, the random state at the
   start included -- is the run's own; a file of another run, an unreadable one or one the
   generator cannot restore (:class:`KeyError` / :class:`ValueError` from its ``restore``)
   is ignored with a warning and the run starts afresh with its random generator untouched.
2. *Save.* At step boundaries only, at most every ``checkpoint_seconds`` (0: after every
   step), atomically (temporary file + rename: a kill never leaves half a checkpoint), with
   the random generator's state and the run's clocks (wall and CPU seconds so far, stored as
   ``elapsed`` and ``cpu``). Since a step is a deterministic function of the saved state and
   random stream, a resumed run is bit-identical to an uninterrupted one.
3. *Progress.* :meth:`ResumableRun.progress` gives a :class:`randmedia.progress.Progress`
   writing at most every ``log_seconds``: units done of the total, rate, ETA, and the step's
   own numbers.
4. *Finish.* The checkpoint is removed when the run is done, or holds the final state for a
   caller that still writes its outputs (it removes the file afterwards).

Typical use::

    run = ResumableRun(checkpoint, key, log, rng=rng, checkpoint_seconds=60.0)
    state = run.resume(restore) or fresh_state()
    progress = run.progress(total, "what", "sweeps", done=...)
    run.loop(step, finished, lambda: arrays_of(state))   # step() calls progress.step(...)
    run.finish()
"""

from __future__ import annotations

import logging
import os
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

from randmedia.checkpoint import load_checkpoint, save_checkpoint
from randmedia.progress import Progress

#: names the driver stores its clocks under in every checkpoint (a generator must not use them)
CLOCKS = ("elapsed", "cpu")


class ResumableRun:
    """Checkpoint loading, timed atomic saving, progress and clean-up of one long run.

    Parameters
    ----------
    checkpoint : path or None
        The run's checkpoint file; None: nothing is saved or resumed (the loop still runs).
    key : str
        :func:`randmedia.checkpoint.checkpoint_key` of everything that defines the run.
    log : logging.Logger
        Gets the warnings about unusable checkpoints and the progress lines.
    rng : numpy.random.Generator, optional
        Saved with every checkpoint and set to the saved state on resume. A generator that
        keeps the random state inside its own arrays passes None.
    checkpoint_seconds : float
        Least wall seconds between two timed saves (:meth:`save_if_due`).
    log_seconds : float
        Least wall seconds between two progress lines (:meth:`progress`).
    """

    def __init__(self, checkpoint: str | os.PathLike | None, key: str, log: logging.Logger, *,
                 rng: np.random.Generator | None = None, checkpoint_seconds: float = 60.0,
                 log_seconds: float = 10.0):
        self.path = None if checkpoint is None else Path(checkpoint)
        self.key, self.log, self.rng = key, log, rng
        self.checkpoint_seconds, self.log_seconds = checkpoint_seconds, log_seconds
        self._wall_start, self._cpu_start = time.perf_counter(), time.process_time()
        self._last_save = self._wall_start
        self.seconds_before = self.cpu_seconds_before = 0.0  # clocks of the runs before a resume

    # ------------------------------------------------------------------ clocks

    @property
    def run_seconds(self) -> float:
        """Wall seconds of this process's part of the run."""
        return time.perf_counter() - self._wall_start

    @property
    def run_cpu_seconds(self) -> float:
        """CPU seconds of this process's part of the run."""
        return time.process_time() - self._cpu_start

    @property
    def seconds(self) -> float:
        """Wall seconds of the whole run, the parts before any resume included."""
        return self.seconds_before + self.run_seconds

    @property
    def cpu_seconds(self) -> float:
        """CPU seconds of the whole run, the parts before any resume included."""
        return self.cpu_seconds_before + self.run_cpu_seconds

    # ------------------------------------------------------------------ checkpoints

    def resume(self, restore: Callable[[dict], Any] | None = None) -> Any:
        """The state saved by an earlier, killed attempt of this run, or None (rule 1).

        ``restore`` turns the checkpoint's arrays (name -> array, clocks removed) into the
        generator's state and raises KeyError or ValueError if they do not make one;
        without it the arrays are returned. On success the random generator continues the
        saved stream and the clocks continue the saved ones."""
        if self.path is None:
            return None
        before = self.rng.bit_generator.state if self.rng is not None else None
        data = load_checkpoint(self.path, self.key, self.log, self.rng)
        if data is None:
            return None
        try:
            seconds, cpu = (float(data.pop(name, 0.0)) for name in CLOCKS)
            state = data if restore is None else restore(data)
        except (KeyError, ValueError) as exc:
            self.log.warning("%s is incomplete (%s); starting afresh", self.path, exc)
            if before is not None:
                self.rng.bit_generator.state = before
            return None
        self.seconds_before, self.cpu_seconds_before = seconds, cpu
        return state

    def save(self, state: dict | Callable[[], dict]) -> None:
        """Write ``state`` (name -> array or scalar, or a callable returning it), the random
        state and the clocks atomically, now (a step boundary; nothing without a checkpoint)."""
        if self.path is None:
            return
        arrays = state() if callable(state) else state
        clash = set(CLOCKS) & set(arrays)
        if clash:
            raise ValueError(f"state names {sorted(clash)} are reserved for the run's clocks")
        save_checkpoint(self.path, self.key, {**arrays, CLOCKS[0]: self.seconds, CLOCKS[1]: self.cpu_seconds},
                        self.rng)
        self._last_save = time.perf_counter()

    def save_if_due(self, state: dict | Callable[[], dict]) -> bool:
        """:meth:`save` if ``checkpoint_seconds`` have passed since the last save (rule 2);
        call it at step boundaries only. Returns whether it saved."""
        if self.path is None or time.perf_counter() - self._last_save < self.checkpoint_seconds:
            return False
        self.save(state)
        return True

    def finish(self, final_state: dict | Callable[[], dict] | None = None) -> None:
        """The run is done: remove the checkpoint, or with ``final_state`` save that instead
        (for a caller that still writes outputs; it removes the file itself afterwards)."""
        if self.path is None:
            return
        if final_state is not None:
            self.save(final_state)
        else:
            self.path.unlink(missing_ok=True)

    # ------------------------------------------------------------------ the loop

    def loop(self, step: Callable[[], None], finished: Callable[[], bool],
             state: dict | Callable[[], dict]) -> None:
        """``step()`` until ``finished()``, with :meth:`save_if_due` after every step.

        ``finished`` is called once before each step (it may log why the run ends, or raise
        if it cannot); ``state`` returns what a checkpoint holds (:meth:`save`).

        Parameters
        ----------
        step : callable
            Advances the run by one step.
        finished : callable
            Returns True when the run is done.
        state : dict or callable
            Checkpoint contents, or a function returning them.
        """
        while not finished():
            step()
            self.save_if_due(state)

    def progress(self, total: int | None, what: str, unit: str, done: int = 0) -> Progress:
        """A progress log of this run (rule 3): ``done`` units were done before this process,
        ``total`` (None: unknown) in all; a line at most every ``log_seconds``.

        Parameters
        ----------
        total : int or None
            Units of the whole run (None: unknown).
        what : str
            Start of each log line.
        unit : str
            Name of a unit.
        done : int, optional
            Units done before this process (default 0).

        Returns
        -------
        Progress
            The progress log, writing to this run's logger.
        """
        return Progress(total, what, self.log, unit=unit, start=done, every=self.log_seconds)
