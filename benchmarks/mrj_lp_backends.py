"""Benchmark of the LP backends on the LPs of an MRJ packing (mrj2016), all in one run.

For each size N of ``--sizes``: a Lubachevsky-Stillinger compression with the paper
config's constants (seed ``--seed``), then the first inflation LP
(:func:`randmedia.generate.inflation.inflation_step`'s LP, bound 0.005 D) and the TJ LP of
the polish (:func:`randmedia.generate.jammed.tj_step`'s LP, influence gap 0.1 D, strains
0.003) are built once and solved by every backend of ``--backends``, alternated
``--repeats`` times in one process (one HiGHS thread). Printed: CPU seconds per solve
(median over the repeats), the ratio against the first backend (the baseline, IPX +
crossover unless changed), the objective's deviation from the baseline's and the largest
row violation of each solution.

Usage: python benchmarks/mrj_lp_backends.py [--sizes 1000,2000] [--repeats 2]
       [--backends highs-ipm,highs-ipx,highs-hipo,highs-hipo-vertex]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import yaml

from randmedia.generate import inflation, packing_lp
from randmedia.generate.lubachevsky_stillinger import LSParameters, compress
from randmedia.generate.jammed import TJParameters
from randmedia.periodic import Cell, pairs_within

CONFIG = Path(__file__).resolve().parents[1] / "config" / "config.yaml"


def lps(n: int, seed: int, section: dict) -> dict:
    """The inflation and TJ LPs (cost, matrix, row lower bounds, column bounds, sense) of
    the compressed packing of ``n`` spheres."""
    positions, box, _ = compress(np.random.default_rng(seed), n, 3, LSParameters(**section["compression"]))
    cell = Cell(box)
    bound = section["inflation"]["displacement_bound"]
    i, j, sep, dist = pairs_within(cell, positions, inflation.cutoff_for(bound, 3))
    matrix = packing_lp.inflation_matrix(n, i, j, sep, dist)
    cost = np.zeros(3 * n + 1)
    cost[-1] = 1.0
    lower, upper = np.full(3 * n + 1, -bound), np.full(3 * n + 1, bound)
    lower[:3] = upper[:3] = 0.0
    lower[-1], upper[-1] = 0.0, (1 + 2 * math.sqrt(3) * bound) ** 2
    out = {"inflation": (cost, matrix, -dist / 2, lower, upper, "max")}
    polish = {k: v for k, v in section["polish"].items() if k != "backend"}
    params = TJParameters(**polish)
    i, j, sep, dist = pairs_within(cell, positions, 1 + params.influence_gap)
    matrix = packing_lp.constraint_matrix(n, i, j, sep, dist)
    cost = np.zeros(6 + 3 * n)
    cost[:3] = 1.0
    upper = np.full(6 + 3 * n, params.translation_bound(3))
    upper[:3] = params.max_normal_strain
    upper[3:6] = params.max_shear_strain
    upper[6:9] = 0.0
    out["TJ"] = (cost, matrix, np.minimum(packing_lp.gap_bound(dist, 1.0), 0.0), -upper, upper, "min")
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="1000,2000")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--backends", default="highs-ipm,highs-ipx,highs-hipo,highs-hipo-vertex")
    args = parser.parse_args()
    section = yaml.safe_load(CONFIG.read_text())["mrj2016"]["mrj"]
    backends = args.backends.split(",")
    print(f"{'LP':10} {'N':>6} {'rows':>7} {'backend':18} {'CPU s':>8} {'ratio':>7} {'obj - base':>11} {'max viol.':>10}")
    for n in map(int, args.sizes.split(",")):
        for name, (cost, matrix, rows, lower, upper, sense) in lps(n, args.seed, section).items():
            seconds = {b: [] for b in backends}
            solutions = {}
            for _ in range(args.repeats):
                for backend in backends:
                    s = packing_lp.solve(cost, matrix, rows, lower, upper, backend=backend, sense=sense)
                    seconds[backend].append(s.cpu_seconds)
                    solutions[backend] = s
            base = backends[0]
            for backend in backends:
                s = solutions[backend]
                violation = float(np.maximum(rows - matrix @ s.x, 0.0).max())
                t = float(np.median(seconds[backend]))
                print(f"{name:10} {n:6d} {matrix.shape[0]:7d} {backend:18} {t:8.2f} "
                      f"{float(np.median(seconds[base])) / t:7.2f} "
                      f"{s.objective - solutions[base].objective:11.2e} {violation:10.1e}", flush=True)


if __name__ == "__main__":
    main()
