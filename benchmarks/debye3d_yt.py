"""Benchmark of the 3D accelerated Yeong-Torquato construction (issue 13, docs/debye3d.md).

Prints, from one run on this machine (CPU time of this process, ``time.process_time``,
so that other load disturbs the ratios less than wall time would):

1. the per-trial cost of our 3D construction (O(bins) per trial from stored per-voxel
   shell counts, accepted swaps applied in batches) against the 3D ball scan (the
   ``scan=True`` baseline: every trial counts the l_c-ball around both voxels) over the
   *same* whole construction (same seed and schedule; the images are checked to be
   identical), as a ratio;
2. the 3D construction against the 2D one at a comparable number of pixels (L^2 ~ N^3)
   and the same bins (l_c, a, phi2): CPU time per trial and per accepted swap, as ratios
   3D / 2D, beside the ratio of their stencils (voxels within l_c), which an accepted swap
   pays for;
3. (``--measure N``, default 64) a whole construction at N^3 voxels, a = 4, l_c = 24
   (8a = 32 does not fit below N/2 at 64^3; l_c close to N/2 also makes the pending-flip
   cells one voxel wide), run in a child process for its peak memory: time and acceptance
   per stage, Delta S2 reached, peak RSS; then a fit of the per-stage CPU time,
   t = c_trial * trials + c_swap * accepted, and its extrapolation to 128^3, a = 4,
   l_c = 32 (the issue's must: Delta S2 <= 2e-4 over 0 < r <= l_c, <= 30 min on one core,
   <= 4 GB), with c_swap scaled by the stencil size and c_trial by the bins, the accepted
   swaps per voxel as measured;
4. (``--direct``) the 128^3, a = 4, l_c = 32 construction itself (20-40 min), in a child.
5. (``--scaling``, ~30 min) the cost against N (a = 3, l_c = 24: N = 64, 80, 96) and against
   l_c (N = 96: l_c = 16, 24, 32 with a = l_c / 8), whole constructions in children: CPU
   time, accepted swaps per voxel, the fitted cost per count increment and per trial, peak
   RSS; then the model CPU = trials c_trial + accepted c_swap, with accepted swaps per voxel
   and c_swap per stencil voxel taken from the largest run, extrapolated to 128^3 (a = 4,
   l_c = 32: compared with the workflow's measured constructions), 256^3 (a = 5, l_c = 40:
   the issue's goal, <= 3 h) and 500^3 (the paper's 2D size, their ~10^5 h).

Usage: python benchmarks/debye3d_yt.py [--side 32] [--measure 64] [--phi2 0.5] [--direct]
                                       [--scaling] [--skip-scan] [--skip-2d]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from randmedia.generate.yeong_torquato import AnnealingSchedule, _Geometry, construct  # noqa: E402
from randmedia.generate.yt_stencil import Stencil  # noqa: E402
from randmedia.theory.debye import debye_s2  # noqa: E402

CHILD = """
import functools, json, resource, sys, time
import numpy as np
from randmedia.generate.yeong_torquato import AnnealingSchedule, construct
from randmedia.theory.debye import debye_s2
n, a, lc, phi2, seed = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
target = functools.partial(debye_s2, phi2=phi2, a=a)
construct(target, phi2, (int(2 * lc) + 3,) * 3, lc, np.random.default_rng(0),
          AnnealingSchedule(trials_per_pixel=1, n_stages=2, tolerance=1.0, long_range_stages=0))  # compile: same count type
wall, cpu = time.perf_counter(), time.process_time()
result = construct(target, phi2, (n, n, n), lc, np.random.default_rng(seed), AnnealingSchedule(long_range_stages=0))
print(json.dumps({"delta_s2": result.delta_s2, "wall": time.perf_counter() - wall,
                  "cpu": time.process_time() - cpu, "trials": result.stats["trials"],
                  "accepted": result.stats["accepted"], "per_stage": result.stats["per_stage"],
                  "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""


def warm_up(target, phi2, dimension, cutoff, scan=False):
    """Compile (or load from numba's cache) the kernels outside the timing: a tiny
    construction with the same cutoff, hence the same shell-count type (the kernels are
    compiled per type)."""
    small = (int(2 * cutoff) + 3,) * dimension
    construct(target, phi2, small, cutoff, np.random.default_rng(0),
              AnnealingSchedule(trials_per_pixel=1, n_stages=2, tolerance=1.0, long_range_stages=0), scan=scan)


def timed(shape, phi2, a, cutoff, seed, scan, schedule=None):
    schedule = schedule or AnnealingSchedule(long_range_stages=0)
    target = lambda r: debye_s2(r, phi2, a)  # noqa: E731
    warm_up(target, phi2, len(shape), cutoff, scan)
    tic = time.process_time()
    result = construct(target, phi2, shape, cutoff, np.random.default_rng(seed), schedule, scan=scan)
    return result, time.process_time() - tic


def stencil_voxels(shape, cutoff):
    return _Geometry(shape, cutoff).stencil.offsets.shape[0]


def child_run(n, a, cutoff, phi2, seed):
    out = subprocess.run([sys.executable, "-c", CHILD, str(n), str(a), str(cutoff), str(phi2), str(seed)],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def fit_costs(per_stage):
    """Least-squares (c_trial, c_swap) of cpu_seconds = c_trial trials + c_swap accepted
    over the stages (the first, which includes the shell counts' page faults, left out)."""
    rows = per_stage[1:]
    design = np.array([[s["trials"], s["accepted"]] for s in rows], dtype=float)
    seconds = np.array([s["cpu_seconds"] for s in rows])
    (c_trial, c_swap), *_ = np.linalg.lstsq(design, seconds, rcond=None)
    return c_trial, c_swap


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--side", type=int, default=32, help="N of parts 1-2 (N^3 voxels)")
    parser.add_argument("--a", type=float, default=2.0, help="a of parts 1-2")
    parser.add_argument("--lc", type=float, default=12.0, help="l_c of parts 1-2")
    parser.add_argument("--phi2", type=float, default=0.5)
    parser.add_argument("--measure", type=int, default=64, help="N of part 3 (0: skip)")
    parser.add_argument("--measure-lc", type=float, default=24.0)
    parser.add_argument("--direct", action="store_true", help="part 4: 128^3, a = 4, l_c = 32")
    parser.add_argument("--scaling", action="store_true", help="part 5: cost against N and l_c")
    parser.add_argument("--skip-scan", action="store_true")
    parser.add_argument("--skip-2d", action="store_true")
    args = parser.parse_args()
    n, a, cutoff, phi2 = args.side, args.a, args.lc, args.phi2
    shape = (n, n, n)

    fast = None
    if not args.skip_scan:
        fast, t_fast = timed(shape, phi2, a, cutoff, 7, False)
        slow, t_slow = timed(shape, phi2, a, cutoff, 7, True)
        identical = np.array_equal(fast.image, slow.image)
        trials = fast.stats["trials"]
        print(f"1. whole 3D construction {n}^3, a={a:g}, l_c={cutoff:g}, phi2={phi2}: {trials} trials, "
              f"acceptance {fast.stats['accepted'] / trials:.4f}, Delta S2 {fast.delta_s2:.2e}, "
              f"identical images: {identical}")
        print(f"   CPU time per trial: ours {t_fast / trials * 1e6:.2f} us, ball scan "
              f"({stencil_voxels(shape, cutoff)} voxels) {t_slow / trials * 1e6:.2f} us -> ratio "
              f"scan/ours {t_slow / t_fast:.1f}x")
        if not identical:
            raise SystemExit("fast and scanning 3D constructions diverged: bug")

    if not args.skip_2d:
        if fast is None:
            fast, t_fast = timed(shape, phi2, a, cutoff, 7, False)
        side = int(round(n ** 1.5))
        flat, t_flat = timed((side, side), phi2, a, cutoff, 7, False)
        per_trial = (t_fast / fast.stats["trials"]) / (t_flat / flat.stats["trials"])
        per_swap = (t_fast / fast.stats["accepted"]) / (t_flat / flat.stats["accepted"])
        stencils = stencil_voxels(shape, cutoff) / stencil_voxels((side, side), cutoff)
        print(f"2. 3D {n}^3 against 2D {side}^2 (same a, l_c, phi2, default schedule): CPU per trial "
              f"{t_fast / fast.stats['trials'] * 1e6:.2f} vs {t_flat / flat.stats['trials'] * 1e6:.2f} us "
              f"-> 3D/2D {per_trial:.1f}x; per accepted swap {t_fast / fast.stats['accepted'] * 1e6:.1f} vs "
              f"{t_flat / flat.stats['accepted'] * 1e6:.1f} us -> {per_swap:.1f}x; stencil ratio "
              f"{stencils:.1f}x; accepted swaps per voxel {fast.stats['accepted'] / n**3:.3f} vs "
              f"{flat.stats['accepted'] / side**2:.3f}; Delta S2 {fast.delta_s2:.2e} vs {flat.delta_s2:.2e}")

    if args.measure:
        m, a_m, lc_m = args.measure, 4.0, args.measure_lc
        run = child_run(m, a_m, lc_m, phi2, 11)
        print(f"3. {m}^3, a=4, l_c={lc_m:g}, phi2={phi2}: {run['wall']:.1f} s wall, {run['cpu']:.1f} s CPU, "
              f"{run['trials']} trials ({run['accepted']} accepted), Delta S2 {run['delta_s2']:.2e}, "
              f"peak RSS {run['peak_rss_mb']:.0f} MB")
        print("   stage  acceptance  CPU s   wall s   Delta S2")
        for s in run["per_stage"]:
            print(f"   {s['stage']:5d}  {s['accepted'] / s['trials']:10.4f}  {s['cpu_seconds']:6.2f}  "
                  f"{s['seconds']:7.2f}   {s['delta_s2']:.2e}")
        c_trial, c_swap = fit_costs(run["per_stage"])
        small = stencil_voxels((m, m, m), lc_m)
        big = stencil_voxels((128, 128, 128), 32.0)
        scale = (128 / m) ** 3
        trials_big, accepted_big = run["trials"] * scale, run["accepted"] * scale
        c_trial_big, c_swap_big = c_trial * 32 / lc_m, c_swap * big / small
        predicted = trials_big * c_trial_big + accepted_big * c_swap_big
        h_big = _Geometry((128, 128, 128), 32.0).stencil.counts_bytes()
        print(f"   fit over stages 2-40: {c_trial * 1e6:.2f} us per trial + {c_swap * 1e6:.0f} us per "
              f"accepted swap ({c_swap / (2 * small) * 1e9:.2f} ns per count increment)")
        print(f"   extrapolated to 128^3, a=4, l_c=32 (stencil {big} vs {small} voxels, same accepted "
              f"swaps per voxel): {trials_big:.3g} trials x {c_trial_big * 1e6:.2f} us + "
              f"{accepted_big:.3g} accepted x {c_swap_big * 1e6:.0f} us = {predicted / 60:.1f} min CPU "
              f"(must <= 30 min); shell counts {h_big / 2**20:.0f} MiB vs "
              f"{_Geometry((m, m, m), lc_m).stencil.counts_bytes() / 2**20:.0f} MiB here (must: peak <= 4 GB; "
              f"--direct measures it)")

    if args.direct:
        run = child_run(128, 4.0, 32.0, phi2, 11)
        print(f"4. 128^3, a=4, l_c=32, phi2={phi2}: {run['wall'] / 60:.1f} min wall, {run['cpu'] / 60:.1f} min CPU, "
              f"Delta S2 {run['delta_s2']:.2e}, {run['accepted']} accepted swaps, peak RSS "
              f"{run['peak_rss_mb']:.0f} MB")

    if args.scaling:
        scaling(phi2)


def scaling(phi2, seed=11):
    """Part 5 (see the module docstring)."""
    grid = [(64, 3.0, 24.0), (80, 3.0, 24.0), (96, 3.0, 24.0), (96, 2.0, 16.0), (96, 4.0, 32.0)]
    print(f"5. cost against N and l_c, phi2={phi2}, default schedule, one seed, CPU of one core:")
    print("       N    a   l_c  stencil  CPU s  accepted/voxel  trials/voxel  ns/increment  us/trial"
          "  Delta S2  peak MB")
    rows = []
    for n, a, cutoff in grid:
        run = child_run(n, a, cutoff, phi2, seed)
        c_trial, c_swap = fit_costs(run["per_stage"])
        stencil = stencil_voxels((n, n, n), cutoff)
        rows.append(dict(n=n, a=a, lc=cutoff, stencil=stencil, run=run, c_trial=c_trial,
                         ns_per_increment=c_swap / (2 * stencil) * 1e9))
        print(f"    {n:4d} {a:4g} {cutoff:5g} {stencil:8d} {run['cpu']:6.1f}  "
              f"{run['accepted'] / n**3:14.3f}  {run['trials'] / n**3:12.1f}  "
              f"{rows[-1]['ns_per_increment']:12.2f}  {c_trial * 1e6:8.2f}  {run['delta_s2']:8.1e}  "
              f"{run['peak_rss_mb']:7.0f}")
    largest = next(row for row in rows if (row["n"], row["lc"]) == (96, 24.0))  # largest N at l_c = 24
    per_voxel_accepted = largest["run"]["accepted"] / largest["n"] ** 3
    per_voxel_trials = largest["run"]["trials"] / largest["n"] ** 3
    ns = largest["ns_per_increment"] * 1e-9
    print(f"   model from N = {largest['n']}, l_c = {largest['lc']:g}: {per_voxel_accepted:.3f} accepted "
          f"swaps and {per_voxel_trials:.0f} trials per voxel, {ns * 1e9:.2f} ns per count increment "
          f"(2 x stencil per swap), {largest['c_trial'] * 1e6:.2f} us per trial x l_c / {largest['lc']:g}")
    for n, a, cutoff, note in [(128, 4.0, 32.0, "the workflow's constructions (must <= 30 min)"),
                               (256, 5.0, 40.0, "the goal (<= 3 h, <= 12 GB)"),
                               (500, 5.0, 40.0, "the paper's 2D size; their estimate ~1e5 h")]:
        # the displacements within l_c are the same in every box wider than 2 l_c + 1, so the
        # stencil comes from a small box (building it at 500^3 would take GBs of meshgrids)
        small = Stencil((int(2 * cutoff) + 3,) * 3, cutoff)
        stencil = small.offsets.shape[0]
        counts_bytes = n**3 * small.n_columns * small.count_dtype.itemsize
        seconds = n**3 * (per_voxel_accepted * 2 * stencil * ns
                          + per_voxel_trials * largest["c_trial"] * cutoff / largest["lc"])
        print(f"   {n}^3, a={a:g}, l_c={cutoff:g} (stencil {stencil}): {seconds / 3600:.2f} h CPU predicted, "
              f"shell counts {counts_bytes / 2**30:.2f} GiB -- {note}")


if __name__ == "__main__":
    main()
