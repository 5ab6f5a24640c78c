"""What every rule script does first: threads, logging.

``start_job(snakemake)`` caps numba's thread pool at the rule's ``threads``
(``NUMBA_NUM_THREADS`` before numba is imported, ``numba.set_num_threads``
after) and returns a logger writing to the rule's log file (and stderr).
"""

from __future__ import annotations

import logging
import os
import sys


def set_threads(threads: int) -> None:
    threads = max(1, int(threads))
    os.environ["NUMBA_NUM_THREADS"] = str(threads)
    if "numba" in sys.modules:
        import numba

        numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))


def start_job(snakemake) -> logging.Logger:
    """Configure threads and logging for a Snakemake ``script:`` job."""
    set_threads(snakemake.threads)
    logger = logging.getLogger(f"randmedia.{snakemake.rule}")
    logger.setLevel(logging.INFO)
    logger.handlers.clear()
    formatter = logging.Formatter("%(asctime)s %(name)s %(levelname)s %(message)s")
    handlers = [logging.StreamHandler(sys.stderr)]
    if snakemake.log:
        handlers.append(logging.FileHandler(str(snakemake.log[0]), mode="w"))
    for handler in handlers:
        handler.setFormatter(formatter)
        logger.addHandler(handler)
    logger.info("rule %s, threads %d, wildcards %s", snakemake.rule, snakemake.threads,
                dict(snakemake.wildcards))
    return logger
