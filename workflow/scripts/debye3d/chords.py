"""Rule debye3d_chords: L(z) and p(z) of the void of one periodic system's 3D images."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import numpy as np
import xarray as xr

from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.studies.debye3d import chords_dataset, read_voxel_images

params = dict(snakemake.params.system)
system = snakemake.wildcards.system
images, _ = read_voxel_images(snakemake.input.samples)
seed = sample_seed(snakemake.params.seed, "debye3d", f"chords_{system}", 0)
level_set = None
if snakemake.input.surface:  # chords on the surface functions' tuned level set
    level_set = xr.open_dataset(snakemake.input.surface[0]).attrs
chords = chords_dataset(images, params, snakemake.params.chords, sample_rng(seed), level_set)
chords.attrs["system"] = system
log.info("%s: sigma = %.4f voxel (%s): mean chord %.3f voxel (4 phi1 / s = %.3f) over %d images",
         system, chords.attrs["sigma"], chords.attrs["level_set_model"],
         float(np.mean(chords["mean_chord_samples"].values)),
         4 * (1 - params["phi2"]) / chords.attrs["s_exact"], images.shape[0])
write_dataset(chords, snakemake.output[0], rule=snakemake.rule, seed=seed,
              config={**params, "chords": dict(snakemake.params.chords)})
