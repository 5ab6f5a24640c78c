"""Benchmark of the Torquato-Jiao construction of MRJ packings (mrj2016).

Prints, from one run on this machine (CPU seconds of this process, which on a shared
machine is a steadier measure than wall time; both are printed):

1. LP backends on the *same* TJ LP (a packing compressed to phi ~ 0.6, where the
   slow final creep starts): HiGHS interior point + crossover (``highs-ipm``, the
   default), interior point alone, dual simplex (highspy) and scipy's linprog,
   as ratios to ``highs-ipm``; and one whole small packing with ``highs-ipm``
   against ``highs-simplex`` (different LP vertices, so different trajectories);
2. the cost of one such LP against N (N = 250 ... ``--max-n``), a power-law fit and
   its extrapolation to N = 10 000;
3. with ``--paper``: one whole N = 2000 packing (time per packing, per LP, LP count).

Usage: python benchmarks/mrj_tj.py [--max-n 1000] [--paper]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from randmedia.generate import jammed, packing_lp
from randmedia.generate.rsa import random_sequential_addition
from randmedia.periodic import Cell, pairs_within

PARAMS = jammed.TJParameters()


def compressed(n, phi_stop=0.6, seed=1):
    """A TJ packing stopped at phi >= phi_stop (the start of the slow final creep)."""
    positions, box = random_sequential_addition(np.random.default_rng(seed), n, 0.25)
    phi = 0.0
    while phi < phi_stop:
        positions, box, _ = jammed.tj_step(positions, box, PARAMS)
        phi = jammed.packing_fraction(positions, box)
    return positions, box


def tj_lp(positions, box):
    n, dim = positions.shape
    i, j, separation, distance = pairs_within(Cell(box), positions, 1 + PARAMS.influence_gap)
    matrix = packing_lp.constraint_matrix(n, i, j, separation, distance)
    ns = packing_lp.n_strain(dim)
    cost = np.zeros(matrix.shape[1])
    cost[:dim] = 1.0
    upper = np.full(matrix.shape[1], PARAMS.translation_bound(dim))
    upper[:ns] = PARAMS.max_normal_strain
    upper[ns:ns + dim] = 0.0
    return cost, matrix, packing_lp.gap_bound(distance, 1.0), -upper, upper


def timed(function, *args, **kwargs):
    wall, cpu = time.perf_counter(), time.process_time()
    result = function(*args, **kwargs)
    return result, time.perf_counter() - wall, time.process_time() - cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-n", type=int, default=1000)
    parser.add_argument("--paper", action="store_true")
    args = parser.parse_args()

    print("1. LP backends on one TJ LP (N = 500, phi ~ 0.6)")
    lp = tj_lp(*compressed(500))
    base = None
    for backend in packing_lp.BACKENDS:
        solution, wall, cpu = timed(packing_lp.solve, *lp, backend=backend)
        base = base or cpu
        print(f"   {backend:14s} cpu {cpu:7.2f} s (wall {wall:7.2f} s), objective "
              f"{solution.objective:.10f}, ratio to highs-ipm {cpu / base:6.1f}x")
    start, box = random_sequential_addition(np.random.default_rng(2), 250, 0.25)
    whole = {}
    for backend in ("highs-ipm", "highs-simplex"):
        packing, wall, cpu = timed(jammed.jam, start, box,
                                   jammed.TJParameters(backend=backend))
        whole[backend] = cpu
        print(f"   whole N = 250 packing, {backend}: cpu {cpu:.1f} s (wall {wall:.1f} s), "
              f"{packing.n_lp} LPs, phi = {packing.phi:.4f}")
    print(f"   -> simplex / ipm per packing: {whole['highs-simplex'] / whole['highs-ipm']:.1f}x")

    print("2. one TJ LP (highs-ipm) against N, phi ~ 0.6")
    sizes = [n for n in (250, 500, 1000, 2000, 4000) if n <= args.max_n]
    costs = []
    for n in sizes:
        lp = tj_lp(*compressed(n))
        _, wall, cpu = timed(packing_lp.solve, *lp, backend="highs-ipm")
        costs.append(cpu)
        print(f"   N = {n:5d}: {lp[1].shape[0]:6d} rows, cpu {cpu:7.2f} s (wall {wall:7.2f} s)")
    if len(sizes) >= 2:
        slope, intercept = np.polyfit(np.log(sizes), np.log(costs), 1)
        for n in (2000, 10000):
            print(f"   power law cpu ~ N^{slope:.2f}: N = {n} -> {np.exp(intercept) * n**slope:.0f} s "
                  "per LP")

    if args.paper:
        print("3. one paper-size packing, N = 2000")
        start, box = random_sequential_addition(np.random.default_rng(3), 2000, 0.25)
        packing, wall, cpu = timed(jammed.jam, start, box, PARAMS)
        print(f"   phi = {packing.phi:.5f}, {packing.n_lp} LPs, cpu {cpu:.0f} s (wall {wall:.0f} s), "
              f"{cpu / packing.n_lp:.1f} s per LP")


if __name__ == "__main__":
    main()
