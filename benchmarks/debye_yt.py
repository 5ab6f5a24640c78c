"""Benchmark of the accelerated Yeong-Torquato construction (debye2020, Sec. IV).

Prints, from one run on this machine:

1. the average per-trial cost of our construction (O(bins) per trial from stored
   per-pixel shell counts; accepted swaps update the counts in batches, O(l_c^2) per
   swap) against the straightforward one that scans the l_c-disk around both pixels
   for every trial, over the *same* whole construction (same seed, schedule and
   trajectory -- the two images are checked to be identical), as a ratio. CPU time of
   this process is used (``time.process_time``), so other load on the machine
   disturbs the ratio less than wall time would;
2. wall time and peak memory of one paper-size sample (L = 501, a = 5, l_c = 50,
   phi2 = 0.3) to Delta S2 <= 2e-4 on one core.

Usage: python benchmarks/debye_yt.py [--side 501] [--skip-paper]
The ratio is measured at the paper size by default (the baseline takes about a
minute); ``--side 201`` is quicker.
"""

from __future__ import annotations

import argparse
import os
import resource
import time

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from randmedia.generate.yeong_torquato import AnnealingSchedule, construct  # noqa: E402
from randmedia.theory.debye import debye_s2  # noqa: E402


def timed_construction(side, phi2, a, cutoff, seed, scan, schedule, clock=time.process_time):
    target = lambda r: debye_s2(r, phi2, a)  # noqa: E731
    construct(target, phi2, 32, 8.0, np.random.default_rng(0), AnnealingSchedule(
        trials_per_pixel=1, n_stages=2, tolerance=1.0), scan=scan)  # compile outside the timing
    tic = clock()
    result = construct(target, phi2, side, cutoff, np.random.default_rng(seed), schedule, scan=scan)
    return result, clock() - tic


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--side", type=int, default=501)
    parser.add_argument("--skip-paper", action="store_true")
    args = parser.parse_args()
    schedule = AnnealingSchedule()
    phi2, a, cutoff = 0.3, 5.0, 50.0

    fast, t_fast = timed_construction(args.side, phi2, a, cutoff, 7, False, schedule)
    slow, t_slow = timed_construction(args.side, phi2, a, cutoff, 7, True, schedule)
    identical = np.array_equal(fast.image, slow.image)
    trials = fast.stats["trials"]
    acceptance = fast.stats["accepted"] / trials
    print(f"whole construction L={args.side}, l_c={cutoff:g}, phi2={phi2}: {trials} trials, "
          f"acceptance {acceptance:.4f}, identical images: {identical}")
    print(f"  CPU time per trial: ours {t_fast / trials * 1e6:.2f} us, disk scan "
          f"{t_slow / trials * 1e6:.2f} us  -> ratio {t_slow / t_fast:.1f}x (goal >= 20x)")
    if not identical:
        raise SystemExit("fast and scanning constructions diverged: bug")

    if not args.skip_paper:
        paper, t_paper = timed_construction(501, phi2, a, cutoff, 11, False, schedule,
                                            clock=time.perf_counter)
        peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        print(f"paper-size sample L=501, a=5, l_c=50, phi2=0.3: {t_paper:.1f} s wall on one core "
              f"(goal <= 60 s), Delta S2 = {paper.delta_s2:.2e}, peak RSS {peak_mb:.0f} MB")


if __name__ == "__main__":
    main()
