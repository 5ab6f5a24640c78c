"""Rule debye3d_window_pores: F(delta), P(delta) and <delta> of one Poisson-plane system's windows
by the reduced-sample estimator on the level set of its window surface functions
(randmedia.studies.debye3d.window_pores_dataset)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import xarray as xr

from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.studies.debye3d import read_voxel_images, window_pores_dataset

params = dict(snakemake.params.system)
system = snakemake.wildcards.system
images, periodic = read_voxel_images(snakemake.input.samples)
if periodic:
    raise ValueError(f"{system}: the window estimator is for windows of non-periodic media")
level_set = xr.open_dataset(snakemake.input.surface).attrs
seed = sample_seed(snakemake.params.seed, "debye3d", f"window_pores_{system}", 0)
pores = window_pores_dataset(images, params, snakemake.params.interface, level_set, sample_rng(seed), log)
pores.attrs["system"] = system
log.info("%s: <delta> = %.3f voxel (up to delta = %.2f, F there %.3g) over %d windows", system,
         float(pores["mean_delta_samples"].mean()), float(pores["delta"][-1]), pores.attrs["F_at_delta_max"],
         images.shape[0])
write_dataset(pores, snakemake.output[0], rule=snakemake.rule, seed=seed,
              config={**params, "interface": dict(snakemake.params.interface)})
