"""Rule sphere2019_fig03: Poisson and uniform points (paper Fig. 3)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of
from randmedia.io import read_dataset
from randmedia.plot.sphere2019 import fig03_uncorrelated

poisson, uniform = (frames_of(read_dataset(p, SPHERE_CONFIG))[0] for p in snakemake.input.configs)
d_poisson, d_uniform = (read_dataset(p, CAP_VARIANCE, attrs=["R", "density"])
                        for p in snakemake.input.descriptors)
fig03_uncorrelated(poisson, uniform, d_uniform, d_poisson, snakemake.output.pdf)
