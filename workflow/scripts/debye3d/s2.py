"""Rule debye3d_s2: S2 of the void phase of a system's samples against its exact S2 (Debye,
Eq. 21, for the constructions and the Poisson planes; overlapping spheres, Eq. 32 in 3D);
Delta S2 per sample over 0 < r <= l_c for the constructions. Periodic estimator for the
periodic media, the window estimator for the Poisson-plane windows (docs/debye3d.md)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.io import write_dataset
from randmedia.studies.debye3d import read_voxel_images, s2_dataset

params = dict(snakemake.params.system)
images, periodic = read_voxel_images(snakemake.input.samples)
s2 = s2_dataset(images, periodic, params)
s2.attrs["system"] = snakemake.wildcards.system
log.info("%s: S2 over %d samples out to r = %g voxels; max |S2 - exact| / SEM = %.2f",
         snakemake.wildcards.system, images.shape[0], float(s2["r"][-1]),
         float(abs((s2["S2"] - s2["S2_exact"]) / s2["S2_sem"])[1:].max()))
write_dataset(s2, snakemake.output[0], rule=snakemake.rule, seed=None, config=params)
