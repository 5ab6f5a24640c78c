"""Rule mrj2016_overlapping_samples: Poisson centres of overlapping spheres, one file per sample."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821 (snakemake is injected by Snakemake)

import re  # noqa: E402

from randmedia.generate import particle_config_dataset  # noqa: E402
from randmedia.generate.spheres import overlapping_intensity, overlapping_spheres  # noqa: E402
from randmedia.io import write_dataset  # noqa: E402
from randmedia.seeding import sample_rng, sample_seed  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
for path in snakemake.output:  # noqa: F821
    index = int(re.search(r"sample(\d+)\.nc$", path).group(1))
    seed = sample_seed(params["seed"], "mrj2016", "overlapping", index)
    positions, box = overlapping_spheres(sample_rng(seed), params["phi"], params["n_mean"])
    log.info("sample %d: seed %d, %d centres in a cube of side %.4f D", index, seed, len(positions),
             box[0, 0])
    dataset = particle_config_dataset(positions, box, 1.0, {
        "system": "overlapping", "phi": params["phi"], "rho": overlapping_intensity(params["phi"]),
        "n_mean": params["n_mean"], "sample": index})
    write_dataset(dataset, path, rule=snakemake.rule, seed=seed,  # noqa: F821
                  config={**params, "sample": index})
