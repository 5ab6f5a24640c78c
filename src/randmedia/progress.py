"""Progress of a job's loop over samples or images, for its log: done / total, rate, ETA."""

from __future__ import annotations

import time


class Progress:
    """Log '<what>: k/n <unit>, rate, ETA' after each :meth:`step` (nothing without a logger).

    Used by every per-sample loop that can run longer than a minute (describe jobs), so that
    a job's log (results/{paper}/logs/...) tells how far it is and when it will end; and by
    the Yeong-Torquato construction (unit: trials, one step per stage, with the stage's
    numbers as ``detail``). ``start``: units already done before this run (a resumed job);
    the rate counts only this run's units."""

    def __init__(self, total: int, what: str, log=None, unit: str = "samples", start: int = 0):
        self.total, self.what, self.log, self.unit = total, what, log, unit
        self.done = self.start_done = start
        self.start = time.monotonic()

    def step(self, count: int = 1, detail: str = "") -> None:
        """``count`` more units done; ``detail`` is appended to the line after '; '."""
        self.done += count
        if self.log is None:
            return
        elapsed = time.monotonic() - self.start
        rate = (self.done - self.start_done) / elapsed if elapsed > 0 else float("inf")
        eta = max(0, self.total - self.done) / rate if rate > 0 else float("inf")
        self.log.info("%s: %d/%d %s, %.3g %s/s, ETA %.0f s%s", self.what, self.done, self.total, self.unit,
                      rate, self.unit, eta, f"; {detail}" if detail else "")
