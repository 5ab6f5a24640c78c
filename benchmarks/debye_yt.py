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
   phi2 = 0.3) to Delta S2 <= 2e-4 on one core;
3. with ``--against REV``: this checkout's construction against the one of git revision
   REV (its ``generate/yeong_torquato.py`` loaded into a temporary module; the rest of
   the package is this checkout's), same seeds, repeats interleaved (old, new, old,
   ...), CPU time per trial with and without the paper config's two long-range stages;
   prints the median per-trial costs, the median of the per-pair ratios new/old and
   their range, and checks that both give the same image.

Usage: python benchmarks/debye_yt.py [--side 501] [--skip-paper] [--skip-scan]
                                     [--against REV] [--repeats 5]
The ratio is measured at the paper size by default (the baseline takes about a
minute); ``--side 201`` is quicker.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from randmedia.generate import yeong_torquato  # noqa: E402
from randmedia.generate.yeong_torquato import AnnealingSchedule  # noqa: E402
from randmedia.theory.debye import debye_s2  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
MODULE = "src/randmedia/generate/yeong_torquato.py"


def timed_construction(side, phi2, a, cutoff, seed, scan, schedule, clock=time.process_time,
                       module=yeong_torquato):
    target = lambda r: debye_s2(r, phi2, a)  # noqa: E731
    module.construct(target, phi2, 32, 8.0, np.random.default_rng(0), AnnealingSchedule(
        trials_per_pixel=1, n_stages=2, tolerance=1.0, long_range_stages=1),
        scan=scan)  # compile outside the timing
    tic = clock()
    result = module.construct(target, phi2, side, cutoff, np.random.default_rng(seed),
                              module.AnnealingSchedule(**schedule.__dict__), scan=scan)
    return result, clock() - tic


def module_at(revision: str, directory: Path):
    """yeong_torquato.py of git ``revision`` as a module (name yt_<revision>)."""
    source = subprocess.run(["git", "show", f"{revision}:{MODULE}"], cwd=REPO, check=True,
                            capture_output=True, text=True).stdout
    name = "yt_" + "".join(c if c.isalnum() else "_" for c in revision)
    path = directory / f"{name}.py"
    path.write_text(source)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def compare_with_revision(revision, side, phi2, a, cutoff, repeats):
    """Part 3: per-trial CPU time of this checkout against ``revision``, interleaved."""
    with tempfile.TemporaryDirectory() as tmp:
        old = module_at(revision, Path(tmp))
        for long_range in (0, 2):
            schedule = AnnealingSchedule(long_range_stages=long_range)
            times = {"old": [], "new": []}
            for k in range(repeats):
                seed = 100 + k
                pair = {}
                for label, module in (("old", old), ("new", yeong_torquato)):
                    pair[label] = timed_construction(side, phi2, a, cutoff, seed, False, schedule,
                                                     module=module)
                    times[label].append(pair[label][1] / pair[label][0].stats["trials"])
                if not np.array_equal(pair["old"][0].image, pair["new"][0].image):
                    raise SystemExit(f"{revision} and this checkout diverged (seed {seed}): bug")
            ratios = np.array(times["new"]) / np.array(times["old"])
            print(f"  L={side}, l_c={cutoff:g}, phi2={phi2}, long-range stages {long_range}, "
                  f"{repeats} seeds: CPU us per trial {revision} {np.median(times['old']) * 1e6:.3f}, "
                  f"this checkout {np.median(times['new']) * 1e6:.3f}; ratio new/old median "
                  f"{np.median(ratios):.3f} (range {ratios.min():.3f}-{ratios.max():.3f}); "
                  f"images identical")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--side", type=int, default=501)
    parser.add_argument("--skip-paper", action="store_true")
    parser.add_argument("--skip-scan", action="store_true", help="leave out part 1")
    parser.add_argument("--against", metavar="REV", help="part 3: compare with git revision REV")
    parser.add_argument("--repeats", type=int, default=5, help="seeds per schedule in part 3")
    args = parser.parse_args()
    schedule = AnnealingSchedule(long_range_stages=0)  # the construction these timings measure
    phi2, a, cutoff = 0.3, 5.0, 50.0

    if not args.skip_scan:
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

    if args.against:
        print(f"this checkout against {args.against} (CPU time, interleaved repeats):")
        compare_with_revision(args.against, args.side, phi2, a, cutoff, args.repeats)

    if not args.skip_paper:
        paper, t_paper = timed_construction(501, phi2, a, cutoff, 11, False, schedule,
                                            clock=time.perf_counter)
        peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        print(f"paper-size sample L=501, a=5, l_c=50, phi2=0.3: {t_paper:.1f} s wall on one core "
              f"(goal <= 60 s), Delta S2 = {paper.delta_s2:.2e}, peak RSS {peak_mb:.0f} MB")


if __name__ == "__main__":
    main()
