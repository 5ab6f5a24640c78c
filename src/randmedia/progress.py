"""Progress of a job's loop over samples or images, for its log: done / total, rate, ETA."""

from __future__ import annotations

import time


class Progress:
    """Log '<what>: k/n <unit>, rate, ETA' after each :meth:`step` (nothing without a logger).

    Used by every per-sample loop that can run longer than a minute (describe jobs), so that
    a job's log (results/{paper}/logs/...) tells how far it is and when it will end."""

    def __init__(self, total: int, what: str, log=None, unit: str = "samples"):
        self.total, self.what, self.log, self.unit = total, what, log, unit
        self.done = 0
        self.start = time.monotonic()

    def step(self) -> None:
        self.done += 1
        if self.log is None:
            return
        elapsed = time.monotonic() - self.start
        rate = self.done / elapsed if elapsed > 0 else float("inf")
        self.log.info("%s: %d/%d %s, %.3g %s/s, ETA %.0f s", self.what, self.done, self.total, self.unit,
                      rate, self.unit, (self.total - self.done) / rate)
