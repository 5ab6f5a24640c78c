"""Progress of a job's loop over samples, images, sweeps or LPs, for its log: done / total, rate, ETA."""

from __future__ import annotations

import time
from typing import Callable


class Progress:
    """Log '<what>: k/n <unit>, rate, ETA' after a :meth:`step` (nothing without a logger).

    Used by every per-sample loop that can run longer than a minute (describe jobs), so that
    a job's log (results/{paper}/logs/...) tells how far it is and when it will end; and by
    every resumable construction through :meth:`randmedia.resumable.ResumableRun.progress`
    (Yeong-Torquato: unit trials, one step per stage; Monte Carlo: sweeps; Torquato-Jiao and
    inflation: LPs), with the step's own numbers as ``detail``.

    Parameters
    ----------
    total : int or None
        Units of the whole job; None while unknown (the line then has no '/n' and no ETA).
    what : str
        Start of each line.
    log : logging.Logger, optional
        Where the lines go; without one, :meth:`step` only counts.
    unit : str
        Name of a unit in the line.
    start : int
        Units already done before this run (a resumed job); the rate counts only this run's.
    every : float
        Least seconds between two lines (0: a line after every step); a forced step always logs.
    """

    def __init__(self, total: int | None, what: str, log=None, unit: str = "samples", start: int = 0,
                 every: float = 0.0):
        self.total, self.what, self.log, self.unit, self.every = total, what, log, unit, every
        self.done = self.start_done = start
        self.start = self.last_line = time.monotonic()

    def step(self, count: int = 1, detail: str | Callable[[], str] = "", *, total: int | None = None,
             force: bool = False) -> None:
        """``count`` more units done; ``detail`` (or what it returns, called only when a line
        is written) is appended to the line after '; '. ``total`` replaces the total (a new
        estimate); ``force`` logs even within ``every`` seconds.

        Parameters
        ----------
        count : int, optional
            Units done in this step (default 1).
        detail : str or callable, optional
            Text for the end of the line, or a function returning it.
        total : int, optional
            New total of units (None: keep it).
        force : bool, optional
            Log regardless of ``every`` (default False).
        """
        self.done += count
        if total is not None:
            self.total = total
        if self.log is None:
            return
        now = time.monotonic()
        if not force and now - self.last_line < self.every:
            return
        self.last_line = now
        if callable(detail):
            detail = detail()
        elapsed = now - self.start
        rate = (self.done - self.start_done) / elapsed if elapsed > 0 else float("inf")
        if self.total is None:
            self.log.info("%s: %d %s, %.3g %s/s%s", self.what, self.done, self.unit, rate, self.unit,
                          f"; {detail}" if detail else "")
            return
        remaining = max(0, self.total - self.done)
        eta = remaining / rate if rate > 0 else (0.0 if remaining == 0 else float("inf"))
        self.log.info("%s: %d/%d %s, %.3g %s/s, ETA %.0f s%s", self.what, self.done, self.total, self.unit,
                      rate, self.unit, eta, f"; {detail}" if detail else "")
