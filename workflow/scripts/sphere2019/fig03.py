"""Rule sphere2019_fig03: Poisson and uniform points (paper Fig. 3)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.sphere_points import CAP_VARIANCE  # noqa: E402
from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.sphere2019 import fig03_uncorrelated  # noqa: E402

poisson, uniform = (frames_of(read_dataset(p, SPHERE_CONFIG))[0] for p in snakemake.input.configs)  # noqa: F821
d_poisson, d_uniform = (read_dataset(p, CAP_VARIANCE, attrs=["R", "density"])
                        for p in snakemake.input.descriptors)  # noqa: F821
fig03_uncorrelated(poisson, uniform, d_uniform, d_poisson, snakemake.output.pdf)  # noqa: F821
