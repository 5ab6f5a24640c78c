"""Benchmark of the hard-particle NVT Monte Carlo (randmedia.generate.hard_particles).

Prints, from one run on this machine (CPU time of this process, so other load on the
machine matters less than for wall time):

1. trial moves per CPU second and mean squared displacement (MSD, D^2) per CPU second
   for d = 2 (hard disks, phi = 0.3) and d = 3 (hard spheres, phi = 0.478), each at the
   default target acceptance 0.25 and at the baseline 0.45 (a common textbook choice),
   with the ratio -- the reason for the default;
2. the cost of one contact-histogram scan in sweeps (sets ``measure_every``);
3. for d = 3: the sweeps per unit MSD at N = 4000 and the projected CPU time of the
   mrj2016 paper config (100 samples of N = 10 000, MSD >= 1 D^2 apart, 4 chains) --
   the number that decided against building event-chain Monte Carlo.

Usage: python benchmarks/hard_spheres_mc.py [--n3 4000] [--n2 2000] [--sweeps3 3000]
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import yaml  # noqa: E402

from randmedia.generate.hard_particles.chain import HardParticleChain  # noqa: E402
from randmedia.generate.hard_particles.geometry import cubic_box  # noqa: E402
from randmedia.generate.hard_particles.settings import MCSettings  # noqa: E402


#: the chain constants of the paper config's hard-sphere liquid (mrj2016.equilibrium.mc)
_MC = yaml.safe_load((Path(__file__).resolve().parents[1] / "config" / "config.yaml").read_text())["mrj2016"]["equilibrium"]["mc"]


def equilibrated_chain(n, phi, dim, seed=0):
    chain = HardParticleChain(n, cubic_box(n, phi, dim), 1.0, 1, MCSettings(**_MC),
                              np.random.default_rng(seed))
    chain.start()
    chain._run(1)  # compile / load the kernels outside any timing
    chain._scan()
    for _ in range(30):  # melt the lattice start a little before measuring
        chain._tune(chain._run(10))
    return chain


def measure(chain, target, sweeps):
    """Tune to ``target`` acceptance, then time ``sweeps`` sweeps at the frozen step."""
    chain.settings = MCSettings(**{**_MC, "target_acceptance": target})
    for _ in range(20):
        chain._tune(chain._run(10))
    chain._mark()
    tic = time.process_time()
    acceptance = chain._run(sweeps)
    cpu = time.process_time() - tic
    return {"step": chain.step, "acceptance": acceptance, "moves_per_s": sweeps * chain.n / cpu,
            "msd_per_sweep": chain.msd() / sweeps, "msd_per_cpu_s": chain.msd() / cpu}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n2", type=int, default=2000)
    parser.add_argument("--n3", type=int, default=4000)
    parser.add_argument("--sweeps2", type=int, default=300)
    parser.add_argument("--sweeps3", type=int, default=3000)
    args = parser.parse_args()
    for dim, n, phi, sweeps in ((2, args.n2, 0.3, args.sweeps2), (3, args.n3, 0.478, args.sweeps3)):
        chain = equilibrated_chain(n, phi, dim)
        tic = time.process_time()
        chain._run(20)
        sweep_cpu = (time.process_time() - tic) / 20
        tic = time.process_time()
        for _ in range(10):
            chain._scan()
        scan_cpu = (time.process_time() - tic) / 10
        state = (chain.pos.copy(), chain.unwrapped.copy(), chain.step)
        results = {}
        for target in (0.25, 0.45):
            chain.pos[:], chain.unwrapped[:], chain.step = state[0], state[1], state[2]
            chain._rebuild_cells()
            results[target] = measure(chain, target, sweeps)
        print(f"d = {dim}, N = {n}, phi = {phi}: contact scan = {scan_cpu / sweep_cpu:.2f} sweeps")
        for target, r in results.items():
            print(f"  target acceptance {target}: step {r['step']:.3f} D, acceptance "
                  f"{r['acceptance']:.3f}, {r['moves_per_s'] / 1e6:.2f} M moves/CPU s, "
                  f"MSD {r['msd_per_sweep']:.3e} D^2/sweep, {r['msd_per_cpu_s']:.3e} D^2/CPU s")
        ratio = results[0.25]["msd_per_cpu_s"] / results[0.45]["msd_per_cpu_s"]
        print(f"  MSD per CPU second, default 0.25 / baseline 0.45: {ratio:.2f}x")
        if dim == 3:
            r = results[0.25]
            sweeps_per_d2 = 1.0 / r["msd_per_sweep"]
            # paper config: 4 chains x (4 D^2 equilibration + 1.25 D^2 calibration
            # + 25 samples x 1.25 D^2), contact scans every 10 sweeps
            d2_total = 4 * (4.0 + 1.25 + 25 * 1.25)
            moves = d2_total * sweeps_per_d2 * 10000
            cpu = moves / r["moves_per_s"] * (1 + scan_cpu / sweep_cpu / 10)
            print(f"  sweeps per D^2 of MSD: {sweeps_per_d2:.0f} (short-time part included; "
                  f"over longer windows a little more)")
            print(f"  projected mrj2016 paper config (100 x N = 10 000): {cpu / 60:.0f} CPU min, "
                  f"{cpu / 120:.0f} min on 2 cores")


if __name__ == "__main__":
    main()
