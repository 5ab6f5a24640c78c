"""Benchmark: window counts for the number variance, 30 radii x 20 000 windows (Sec. VI B).

Ours (randmedia.describe.points.window_counts): one pass over the centres near
each window counts N(R) for all radii at once (periodic cell list, numba, one
core). Baseline: scipy's cKDTree.query_ball_point(..., return_length=True) on a
periodic tree, once per radius (workers=1). Same N = 2048 packing (jittered
fcc, phi = 0.62), same 20 000 window centres, 30 radii up to h_w; the counts
are checked to be identical. Target: ours >= 10x faster. Also timed: the
paper's throws rule (phi_B = 0.8 nested windows), which is what the workflow runs.

Usage: python benchmarks/mrj_number_variance.py
"""

from __future__ import annotations

import os
import time

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

from _mrj_common import jittered_fcc  # noqa: E402
from randmedia.describe import points  # noqa: E402
from randmedia.periodic import Cell  # noqa: E402


def main():
    x, box = jittered_fcc(8, 1.065, seed=2)
    cell = Cell(box)
    side = box[0, 0]
    radii = np.linspace(0.2, cell.half_width, 30)
    rng = np.random.default_rng(3)
    centres = cell.random_points(rng, 20_000)
    full = np.full(len(radii), len(centres))
    points.window_counts(x, box, centres[:100], radii, np.full(len(radii), 100))  # compile
    ours = []
    for _ in range(3):
        tic = time.perf_counter()
        counts = points.window_counts(x, box, centres, radii, full)
        ours.append(time.perf_counter() - tic)
    tree = cKDTree(cell.wrap(x), boxsize=side)
    tic = time.perf_counter()
    baseline = np.stack([tree.query_ball_point(centres, R, return_length=True, workers=1) for R in radii], axis=1)
    t_base = time.perf_counter() - tic
    if not np.array_equal(baseline, counts):
        raise SystemExit("counts differ from the cKDTree baseline")
    throws = points.throws_per_radius(cell.volume, radii, 0.8, 20_000)
    tic = time.perf_counter()
    points.window_counts(x, box, centres, radii, throws)
    t_rule = time.perf_counter() - tic
    t_ours = float(np.median(ours))
    ratio = t_base / t_ours
    print(f"N = {len(x)}, box side {side:.3f} D, radii 0.2 .. {cell.half_width:.3f} D (30), 20 000 windows each")
    print(f"ours (all radii per window, one pass): {t_ours:.3f} s; cKDTree per radius: {t_base:.3f} s; "
          f"ratio {ratio:.1f}x -- target >= 10x: {'PASS' if ratio >= 10 else 'FAIL'}")
    print(f"counts identical to the baseline; with the phi_B = 0.8 throws rule ({throws.sum()} windows "
          f"in all): {t_rule:.3f} s")


if __name__ == "__main__":
    main()
