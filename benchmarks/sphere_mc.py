"""Benchmark of the canonical Monte Carlo on the sphere (sphere2019, Sec. V).

Prints, from one run on this machine (one core, NUMBA_NUM_THREADS=1):

1. pair evaluations per second of the O(N) energy change of a move at the paper's
   largest system (R = 15, rho = 0.5, N = 1414), for every potential, measured over
   whole sweeps of ``run_fluid`` (moves, Metropolis test, cap counts included), against
   a baseline measured in the same run: the same moves with the energy change computed
   by numpy (vectorized over the other particles, a Python loop over moves). Goal:
   >= 2e8 pair evaluations/s.
2. the time of the full paper-config Monte Carlo (all fluids of config/config.yaml):
   every system is run for a measured fraction of its sweeps (about ``--seconds`` of
   work each), the time per sweep is extrapolated to the configured equilibration +
   production sweeps, and the systems are scheduled longest-first on 2 cores.
   Goal: <= 30 min on 2 cores. The printout says it is an extrapolation.

Usage: python benchmarks/sphere_mc.py [--seconds 2] [--config config/config.yaml]
"""

from __future__ import annotations

import argparse
import heapq
import math
import os
import time
from pathlib import Path

os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import yaml  # noqa: E402

from randmedia.generate.sphere_mc import MCSchedule, Potential, particle_number, run_fluid  # noqa: E402
from randmedia.generate.sphere_surface import uniform_points  # noqa: E402
from randmedia.theory.sphere_caps import cap_grid, cos_thresholds  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


def kernel_rate(potential: Potential, radius: float, density: float, sweeps: int) -> float:
    """Pair evaluations per second of run_fluid (2 (N - 1) per trial move)."""
    thresholds = cos_thresholds(cap_grid(radius, 60), radius)
    schedule = MCSchedule(equilibration_sweeps=max(1, sweeps // 4), production_sweeps=sweeps,
                          frame_interval=sweeps, count_interval=1)
    run = run_fluid(potential, radius, density, 5.2, schedule, np.random.default_rng(1), thresholds)
    return run.stats["pair_evaluations"] / run.stats["seconds"]


def numpy_baseline_rate(potential: Potential, radius: float, density: float, moves: int) -> float:
    """The same trial moves with a numpy energy change per move (Python loop over moves)."""
    rng = np.random.default_rng(2)
    n = particle_number(radius, density)
    x = uniform_points(n, radius, rng)
    step, beta = 0.7, 1 / 5.2
    tic = time.perf_counter()
    for _ in range(moves):
        i = rng.integers(n)
        p = x[i] / radius
        helper = np.array([0.0, 0.0, 1.0]) if abs(p[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
        e1 = np.cross(helper, p)
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(p, e1)
        omega, angle = 2 * np.pi * rng.random(), step * math.sqrt(rng.random()) / radius
        new = radius * (math.cos(angle) * p + math.sin(angle) * (math.cos(omega) * e1 + math.sin(omega) * e2))
        others = np.delete(x, i, axis=0)
        d_energy = (potential.pair_energy(np.linalg.norm(others - new, axis=1), radius).sum()
                    - potential.pair_energy(np.linalg.norm(others - x[i], axis=1), radius).sum())
        if d_energy <= 0 or rng.random() < math.exp(-beta * d_energy):
            x[i] = new
    return moves * 2 * (n - 1) / (time.perf_counter() - tic)


def paper_time(config_path: Path, seconds: float) -> None:
    with open(config_path) as handle:
        fluids = yaml.safe_load(handle)["sphere2019"]["fluids"]
    estimates, measured_fraction = {}, []
    for name, system in fluids["systems"].items():
        run = fluids["runs"][system["run"]]
        radius = float(system["R"])
        n = particle_number(radius, fluids["density"])
        total_sweeps = run["equilibration_sweeps"] + run["production_sweeps"]
        # a measured piece of about `seconds` of work at ~5e8 pair evaluations/s
        sweeps = int(min(total_sweeps, max(200, seconds * 5e8 / (2 * n * n))))
        production = max(2, sweeps - sweeps // 5)
        schedule = MCSchedule(equilibration_sweeps=max(1, sweeps // 5), production_sweeps=production,
                              frame_interval=min(run["frame_interval"], production),
                              count_interval=min(run["count_interval"], max(1, production // 2)))
        thresholds = cos_thresholds(cap_grid(radius, 60), radius)
        result = run_fluid(Potential(system["potential"], float(system["coupling"])), radius,
                           fluids["density"], fluids["temperature"], schedule,
                           np.random.default_rng(3), thresholds)
        done = schedule.equilibration_sweeps + schedule.production_sweeps
        estimates[name] = result.stats["seconds"] / done * total_sweeps
        measured_fraction.append(done / total_sweeps)
        print(f"  {name:14s} N = {n:5d}: {done:7d} of {total_sweeps:7d} sweeps in "
              f"{result.stats['seconds']:6.2f} s -> {estimates[name]:7.0f} s on one core")
    cores = [0.0, 0.0]
    for seconds_needed in sorted(estimates.values(), reverse=True):  # longest first
        heapq.heapreplace(cores, cores[0] + seconds_needed)  # onto the core free first
    total = sum(estimates.values())
    print(f"paper-config Monte Carlo, all {len(estimates)} systems: {total / 60:.1f} min of one core, "
          f"{max(cores) / 60:.1f} min on 2 cores (goal <= 30 min) -- EXTRAPOLATED from a measured "
          f"{100 * min(measured_fraction):.2g}-{100 * max(measured_fraction):.2g} % of each run")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=2.0, help="work measured per system")
    parser.add_argument("--config", type=Path, default=REPO / "config" / "config.yaml")
    args = parser.parse_args()
    radius, density = 15.0, 0.5
    n = particle_number(radius, density)
    kernel_rate(Potential("lj", 0.0), 3.0, density, 20)  # compile outside the timings
    print(f"energy change of a move, R = {radius:g}, N = {n} (one core):")
    for name in ("lj", "udd", "uddpar", "udc", "ucc"):
        potential = Potential(name, 1.0)
        ours = kernel_rate(potential, radius, density, 100)
        baseline = numpy_baseline_rate(potential, radius, density, 3000)
        print(f"  {name:7s} ours {ours:9.3g} pair evaluations/s, numpy baseline {baseline:9.3g}/s "
              f"-> ratio {ours / baseline:5.1f}x (goal >= 2e8/s: {'met' if ours >= 2e8 else 'NOT met'})")
    paper_time(args.config, args.seconds)


if __name__ == "__main__":
    main()
