"""Rule mrj2016_overlapping_samples: Poisson centres of overlapping spheres, one file per sample."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import re

from randmedia.generate import particle_config_dataset
from randmedia.generate.spheres import overlapping_spheres
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.theory.balls import poisson_intensity

params = dict(snakemake.params.items())
for path in snakemake.output:
    index = int(re.search(r"sample(\d+)\.nc$", path).group(1))
    seed = sample_seed(params["seed"], "mrj2016", "overlapping", index)
    positions, box = overlapping_spheres(sample_rng(seed), params["phi"], params["n_mean"])
    log.info("sample %d: seed %d, %d centres in a cube of side %.4f D", index, seed, len(positions),
             box[0, 0])
    dataset = particle_config_dataset(positions, box, 1.0, {
        "system": "overlapping", "phi": params["phi"], "rho": poisson_intensity(params["phi"], 0.5, 3),
        "n_mean": params["n_mean"], "sample": index})
    write_dataset(dataset, path, rule=snakemake.rule, seed=seed,
                  config={**params, "sample": index})
