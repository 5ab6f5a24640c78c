"""Rule sphere2019_pattern: one point pattern on the sphere (Secs. III-IV, Appendix)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import math

from randmedia.generate import sphere_surface as patterns
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed

system = snakemake.wildcards.system
p = dict(snakemake.params.patterns)
seed = None
if system == "icosahedral":
    n = 40 * p["icosahedral_resolution"] * (p["icosahedral_resolution"] - 1) + 12
    radius = math.sqrt(n / (4 * math.pi * p["density"]))
    frames = [patterns.icosahedral_grid(p["icosahedral_resolution"], radius)]
    attrs = {"pattern": "Tegmark icosahedral pixelization", "resolution": p["icosahedral_resolution"]}
elif system == "fibonacci":
    radius = math.sqrt(p["fibonacci_points"] / (4 * math.pi * p["density"]))
    frames = [patterns.fibonacci_grid(p["fibonacci_points"], radius)]
    attrs = {"pattern": "Swinbank-Purser Fibonacci grid"}
else:
    seed = sample_seed(snakemake.params.seed, "sphere2019", system, 0)
    rng = sample_rng(seed)
    radius = p["uncorrelated_R"]
    if system == "uniform":
        n = int(round(p["uncorrelated_points"]))
        frames = [patterns.uniform_points(n, radius, rng) for _ in range(p["uncorrelated_configs"])]
        attrs = {"pattern": "uniform (canonical)"}
    else:
        frames = [patterns.poisson_points(p["uncorrelated_points"], radius, rng,
                                          n_theta=p["poisson_n_theta"], n_phi=p["poisson_n_phi"])
                  for _ in range(p["uncorrelated_configs"])]
        attrs = {"pattern": "Poisson (grand canonical)", "intensity_mean_points": p["uncorrelated_points"]}
attrs.update(kind="pattern", system=system,
             ensemble="grand_canonical" if system == "poisson" else "canonical")
log.info("%s: %d frame(s), mean %.1f points, R = %.4g", system, len(frames),
         sum(len(f) for f in frames) / len(frames), radius)
write_dataset(patterns.points_dataset(frames, radius, attrs), snakemake.output[0],
              rule=snakemake.rule, seed=seed, config=p)
