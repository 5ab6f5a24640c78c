"""Rule mrj2016_lattice_samples: fcc or bcc lattice of touching spheres, randomly translated copies."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import re

from randmedia.generate import particle_config_dataset
from randmedia.generate.spheres import lattice_covering_radius, lattice_packing_fraction, lattice_spheres
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed

params = dict(snakemake.params.items())
lattice = snakemake.wildcards.lattice
for path in snakemake.output:
    index = int(re.search(r"sample(\d+)\.nc$", path).group(1))
    seed = sample_seed(params["seed"], "mrj2016", lattice, index)
    positions, box = lattice_spheres(lattice, params["n_cells"], rng=sample_rng(seed))
    log.info("%s sample %d: %d spheres, phi = %.4f", lattice, index, len(positions),
             lattice_packing_fraction(lattice))
    dataset = particle_config_dataset(positions, box, 1.0, {
        "system": lattice, "phi": lattice_packing_fraction(lattice), "n_cells": params["n_cells"],
        "covering_radius": lattice_covering_radius(lattice), "sample": index})
    write_dataset(dataset, path, rule=snakemake.rule, seed=seed,
                  config={**params, "lattice": lattice, "sample": index})
