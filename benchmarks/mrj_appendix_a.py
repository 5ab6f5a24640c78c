"""Benchmark: exact Appendix-A correlation functions of one N ~ 2000 packing at 400 radii.

Klatt & Torquato 2016, Appendix A (randmedia.describe.packings.correlation_functions):
S2, F_sv, F_ss and the two-body parts F*_sv, F*_ss at 400 radii 0 <= r < h_w - D
of a hard-sphere packing of N = 2048 spheres at phi = 0.62 (jittered fcc) in a
periodic cube. Target: <= 0.5 s per packing (all five functions, one core).

Prints the best (and median) wall time of 7 evaluations (after one warm-up that compiles
the numba kernels), the pair count, and the largest deviation of the fast
prefix-sum evaluation from the direct pair-by-pair sum of the kernels (the
same formulas evaluated independently per pair) at 40 of the radii.

Usage: python benchmarks/mrj_appendix_a.py
"""

from __future__ import annotations

import os
import time

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from _mrj_common import jittered_fcc  # noqa: E402
from randmedia.describe import packings  # noqa: E402
from randmedia.periodic import Cell  # noqa: E402


def main():
    x, box = jittered_fcc(8, 1.065, seed=1)
    cell = Cell(box)
    r = np.linspace(0.0, packings.max_radius(box) - 1e-9, 400)
    packings.correlation_functions(x, box, r)  # warm-up: numba compilation
    times = []
    for _ in range(7):
        tic = time.perf_counter()
        result = packings.correlation_functions(x, box, r)
        times.append(time.perf_counter() - tic)
    rho = packings.pair_distances(x, box, min(r.max() + 1.0, cell.half_width))
    sums = packings.PairSums(rho, 0.5)
    worst = 0.0
    for ri in r[1::10]:
        for kernel in ("v", "h", "J"):
            fast = float(sums(kernel, [ri])[0])
            direct = 2 * ri * packings.pair_kernel(kernel, rho, ri, 0.5).sum()
            scale = max(abs(direct), 1e-300)
            worst = max(worst, abs(fast - direct) / scale)
    median, best = float(np.median(times)), min(times)
    print(f"N = {len(x)}, phi = {result['phi']:.4f}, box side {box[0, 0]:.3f} D, h_w - D = "
          f"{packings.max_radius(box):.3f} D, {rho.size} pairs within r_max + D")
    print(f"Appendix A (S2, F_sv, F_ss, F*_sv, F*_ss) at 400 radii: best of 7 {best:.3f} s "
          f"(median {median:.3f} s) -- target <= 0.5 s: {'PASS' if best <= 0.5 else 'FAIL'}")
    print(f"fast vs direct pair sum, 40 radii x 3 kernels: max relative deviation {worst:.2e}")


if __name__ == "__main__":
    main()
