"""Benchmark of the MRJ packing constructions (mrj2016): LP backends and routes in one run.

Whole packings (CPU seconds of each packing's own process, which on a shared machine is
steadier than wall time; peak memory of that process), from the same seeds, for every
combination of

* route: ``compression`` (Lubachevsky-Stillinger compression, inflation LPs, TJ polish) and
  ``dilute`` (the paper's route: TJ LPs from phi = 0.1 with the TJ code's constants, then the
  polish), both with the paper config's constants (``randmedia.generate.mrj``);
* LP backends: ``A`` in every stage, or ``A/B``: ``A`` in the first stage (inflation or
  dilute), ``B`` in the polish -- e.g. ``highs-hipo/highs-ipm`` (the paper config: HiPO without
  crossover, then IPX + crossover; the baseline) and ``highs-hipo/highs-simplex`` (the polish's
  LPs by the dual simplex, each warm-started from the previous LP's basis).

Printed per packing: CPU, the ratio baseline / HiPO, LP counts of each stage, phi, the
strict-jamming test at the configured contact gap, isostatic excess, rattlers, memory.
Single LPs of larger N: ``benchmarks/mrj_lp_backends.py``.

Usage: python benchmarks/mrj_tj.py [--sizes 500,1000] [--seeds 1] [--routes compression,dilute]
       [--backends highs-hipo/highs-ipm,highs-hipo/highs-simplex]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

import yaml

CONFIG = Path(__file__).resolve().parents[1] / "config" / "config.yaml"

_CHILD = r"""
import json, resource, sys, time
n, seed, section = int(sys.argv[1]), int(sys.argv[2]), json.loads(sys.argv[3])
from randmedia.describe import jamming
from randmedia.generate.mrj import MRJProtocol, make_packing
t = time.process_time()
packing = make_packing(seed, n, MRJProtocol.from_config(section))
cpu = time.process_time() - t
a = jamming.analyse(packing.positions, packing.box, **section["contacts"])
print("RESULT " + json.dumps({
    "cpu": cpu, "phi": packing.phi, "jammed": bool(a.jammed), "excess": a.isostatic_excess,
    "rattlers": a.rattler_fraction, "first_lps": packing.n_inflation_lp + packing.n_dilute_lp,
    "polish_lps": packing.n_lp - packing.n_inflation_lp - packing.n_dilute_lp,
    "mem_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""


def run(n: int, seed: int, section: dict) -> dict:
    result = subprocess.run([sys.executable, "-c", _CHILD, str(n), str(seed), json.dumps(section)],
                            capture_output=True, text=True, check=True)
    line = [x for x in result.stdout.splitlines() if x.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT "):])


def with_backend(section: dict, route: str, backend: str) -> dict:
    """The config section with ``route`` and the backends ``A`` (every LP stage) or ``A/B``
    (``B`` in the polish)."""
    first, _, polish = backend.partition("/")
    out = json.loads(json.dumps(section))
    out["route"] = route
    for stage in ("inflation", "dilute", "polish"):
        out[stage]["backend"] = first
    out["polish"]["backend"] = polish or first
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="500,1000")
    parser.add_argument("--seeds", type=int, default=1)
    parser.add_argument("--routes", default="compression,dilute")
    parser.add_argument("--backends", default="highs-hipo/highs-ipm,highs-hipo/highs-simplex")
    args = parser.parse_args()
    section = yaml.safe_load(CONFIG.read_text())["mrj2016"]["mrj"]
    backends = args.backends.split(",")
    print(f"{'route':12} {'N':>5} {'seed':>4} {'backends':26} {'CPU s':>8} {'ratio':>6} {'LPs 1st':>7} "
          f"{'polish':>6} {'phi':>8} {'jammed':>6} {'excess':>6} {'rattl.':>6} {'MB':>6}")
    for route in args.routes.split(","):
        for n in [int(x) for x in args.sizes.split(",") if x]:
            for seed in range(1, args.seeds + 1):
                base = None
                for backend in backends:
                    r = run(n, seed, with_backend(section, route, backend))
                    base = base or r["cpu"]
                    print(f"{route:12} {n:5d} {seed:4d} {backend:26} {r['cpu']:8.1f} {base / r['cpu']:6.2f} "
                          f"{r['first_lps']:7d} {r['polish_lps']:6d} {r['phi']:8.5f} {r['jammed']!s:>6} "
                          f"{r['excess']:6d} {r['rattlers']:6.3f} {r['mem_mb']:6.0f}", flush=True)


if __name__ == "__main__":
    main()
