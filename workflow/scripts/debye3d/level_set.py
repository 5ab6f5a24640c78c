"""Rule debye3d_level_set: F_sv, F_ss, s, wrapping and pore sizes of one periodic system's
3D images on level sets tuned to the exact s (randmedia.studies.debye3d.level_set_datasets)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import numpy as np

from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.studies.debye3d import level_set_datasets, read_voxel_images

params = dict(snakemake.params.system)
system = snakemake.wildcards.system
images, _ = read_voxel_images(snakemake.input.samples)
seed = sample_seed(snakemake.params.seed, "debye3d", f"pores_{system}", 0)
surface, pores = level_set_datasets(images, params, snakemake.params.interface, sample_rng(seed), log)
for ds in (surface, pores):
    ds.attrs["system"] = system
log.info("%s: sigma = %.4f voxel gives s = %.6g (exact %.6g); <delta> = %.4g voxel", system,
         surface.attrs["sigma"], surface.attrs["s_tuned"], surface.attrs["s_exact"],
         float(np.mean(pores["mean_delta_samples"].values)))
config = {**params, "interface": dict(snakemake.params.interface)}
write_dataset(surface, snakemake.output.surface, rule=snakemake.rule, seed=None, config=config)
write_dataset(pores, snakemake.output.pores, rule=snakemake.rule, seed=seed, config=config)
