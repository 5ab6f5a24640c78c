"""Rule debye3d_window_surface: F_sv, F_ss and s of one Poisson-plane system's windows by
minus-sampling on level sets tuned to the exact s (randmedia.studies.debye3d.window_surface_dataset)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.io import write_dataset
from randmedia.studies.debye3d import read_voxel_images, window_surface_dataset

params = dict(snakemake.params.system)
system = snakemake.wildcards.system
images, periodic = read_voxel_images(snakemake.input.samples)
if periodic:
    raise ValueError(f"{system}: the window estimator is for windows of non-periodic media")
surface = window_surface_dataset(images, params, snakemake.params.interface, log)
surface.attrs["system"] = system
log.info("%s: sigma = %.4f voxel gives s = %.6g in the interiors (exact %.6g)", system,
         surface.attrs["sigma"], surface.attrs["s_tuned"], surface.attrs["s_exact"])
write_dataset(surface, snakemake.output[0], rule=snakemake.rule, seed=None,
              config={**params, "interface": dict(snakemake.params.interface)})
