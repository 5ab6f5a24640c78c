"""Benchmark of the MRJ packing constructions (mrj2016), old and new route in one run.

Prints, from one run on this machine (CPU seconds of each packing's own process, which
on a shared machine is steadier than wall time; peak memory of that process):

1. the previous route -- Torquato-Jiao LPs from a random-sequential-addition start at
   phi = 0.25 (``randmedia.generate.jammed.jam``, its defaults) -- and the current one --
   Lubachevsky-Stillinger compression, inflation LPs, TJ polish
   (``randmedia.generate.mrj.make_packing``, the paper config's protocol) -- from the
   same seeds at the sizes of ``--old-sizes``: CPU per packing, the ratio old / new, LP
   counts, phi and the jamming test;
2. the current route against N (``--sizes``): compression seconds, LP counts and the
   cost per LP of each stage, total CPU, memory, and the log-log slope of the cost per
   inflation LP against N.

Usage: python benchmarks/mrj_tj.py [--sizes 500,1000,2000] [--old-sizes 500] [--seeds 1]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import yaml

CONFIG = Path(__file__).resolve().parents[1] / "config" / "config.yaml"

_CHILD = r"""
import json, resource, sys, time
import numpy as np
route, n, seed, section = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), json.loads(sys.argv[4])
from randmedia.describe import jamming
t = time.process_time()
if route == "old":
    from randmedia.generate.jammed import jam
    from randmedia.generate.rsa import random_sequential_addition
    start, box = random_sequential_addition(np.random.default_rng(seed), n, 0.25)
    packing = jam(start, box)
    out = {"lps": packing.n_lp}
else:
    from randmedia.generate.mrj import MRJProtocol, make_packing
    packing = make_packing(seed, n, MRJProtocol.from_config(section))
    h = packing.inflation_history
    polish = packing.n_lp - packing.n_inflation_lp
    out = {"lps": packing.n_lp, "compression_s": packing.compression["seconds"],
           "inflation_lps": packing.n_inflation_lp,
           "inflation_s_per_lp": float(np.mean(h["solve_seconds"] + h["build_seconds"])),
           "polish_lps": polish,
           "polish_s_per_lp": float(np.sum(packing.history["seconds"])) / max(polish, 1)}
cpu = time.process_time() - t
a = jamming.analyse(packing.positions, packing.box)
out.update(cpu=cpu, phi=packing.phi, jammed=bool(a.jammed), excess=a.isostatic_excess,
           rattlers=a.rattler_fraction,
           mem_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
print("RESULT " + json.dumps(out))
"""


def run(route: str, n: int, seed: int, section: dict) -> dict:
    result = subprocess.run([sys.executable, "-c", _CHILD, route, str(n), str(seed),
                             json.dumps(section)], capture_output=True, text=True, check=True)
    line = [x for x in result.stdout.splitlines() if x.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT "):])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="500,1000,2000")
    parser.add_argument("--old-sizes", default="500")
    parser.add_argument("--seeds", type=int, default=1)
    args = parser.parse_args()
    with open(CONFIG) as handle:
        section = yaml.safe_load(handle)["mrj2016"]["mrj"]
    section = {k: section[k] for k in ("compression", "inflation", "polish")}

    print("1. previous route (TJ from RSA) against the current one, same seeds")
    for n in [int(x) for x in args.old_sizes.split(",") if x]:
        for seed in range(1, args.seeds + 1):
            old, new = run("old", n, seed, section), run("new", n, seed, section)
            print(f"   N = {n:5d} seed {seed}: old {old['cpu']:7.1f} s CPU, {old['lps']:4d} LPs, "
                  f"phi {old['phi']:.4f}, jammed {old['jammed']} | new {new['cpu']:6.1f} s, "
                  f"{new['lps']:3d} LPs, phi {new['phi']:.4f}, jammed {new['jammed']} | "
                  f"old / new = {old['cpu'] / new['cpu']:.1f}x")

    print("2. current route against N")
    print("       N  compress  infl LPs  s/LP  polish LPs  s/LP   total CPU   phi    jammed  "
          "excess  rattlers  memory")
    sizes, per_lp = [], []
    for n in [int(x) for x in args.sizes.split(",") if x]:
        for seed in range(1, args.seeds + 1):
            r = run("new", n, seed, section)
            sizes.append(n)
            per_lp.append(r["inflation_s_per_lp"])
            print(f"   {n:5d}  {r['compression_s']:7.1f}s  {r['inflation_lps']:8d}  "
                  f"{r['inflation_s_per_lp']:5.2f}  {r['polish_lps']:10d}  {r['polish_s_per_lp']:5.2f}  "
                  f"{r['cpu']:9.1f}s  {r['phi']:.4f}  {r['jammed']!s:6s}  {r['excess']:6d}  "
                  f"{r['rattlers']:.4f}  {r['mem_mb']:6.0f} MB", flush=True)
    if len(set(sizes)) >= 2:
        slope = np.polyfit(np.log(sizes), np.log(per_lp), 1)[0]
        print(f"   cost per inflation LP ~ N^{slope:.2f}")


if __name__ == "__main__":
    main()
