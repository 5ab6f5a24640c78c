"""Benchmark: exact Appendix-A correlation functions of one N ~ 2000 packing at 400 radii.

Klatt & Torquato 2016, Appendix A (randmedia.describe.packings.correlation_functions):
S2, F_sv, F_ss and the two-body parts F*_sv, F*_ss at 400 radii 0 <= r < h_w - D
of a hard-sphere packing of N = 2048 spheres at phi = 0.62 (jittered fcc) in a
periodic cube. Target: <= 0.5 s per packing (all five functions, one core).

Prints the best (and median) wall time of 7 evaluations (after one warm-up that compiles
the numba kernels), the pair count, and the largest deviation of the fast
prefix-sum evaluation from the direct pair-by-pair sum of the kernels (the
same formulas evaluated independently per pair) at 40 of the radii.

Second case, the size of the paper's liquid (Table II): N = 10 976 at phi = 0.478 (jittered
fcc), all radii 0, 0.01 D, ... < h_w - D (the paper config's grid, ~1000 radii, ~25 million
pairs). Printed: CPU seconds of the five functions, and the ratio against the pair-by-pair
sum of the three kernels over the pairs each radius needs (|rho - r| < D), timed on 10 radii
spread over the grid and scaled to all of them (the baseline measured in the same run).

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
    liquid_size()


def liquid_size():
    """N = 10 976 at phi = 0.478, every radius of the 0.01 D grid: ours against the pair sum."""
    x, box = jittered_fcc(14, (0.7405 / 0.478) ** (1 / 3), seed=2)
    r = np.arange(0.0, packings.max_radius(box) - 1e-9, 0.01)
    tic = time.process_time()
    packings.correlation_functions(x, box, r)
    ours = time.process_time() - tic
    rho = packings.pair_distances(x, box, min(r.max() + 1.0, Cell(box).half_width))
    sample = r[1:][:: max(1, (r.size - 1) // 10)][:10]
    tic = time.process_time()
    for ri in sample:
        near = rho[np.abs(rho - ri) < 1.0]
        for kernel in ("v", "h", "J"):
            packings.pair_kernel(kernel, near, ri, 0.5).sum()
    direct = (time.process_time() - tic) / sample.size * r.size
    print(f"N = {len(x)}, phi = 0.478, {r.size} radii, {rho.size} pairs within r_max + D: "
          f"{ours:.2f} CPU s; pair-by-pair sum {direct:.0f} CPU s (10 radii, scaled): "
          f"{direct / ours:.0f}x")


if __name__ == "__main__":
    main()
