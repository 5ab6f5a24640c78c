"""Rule sphere2019_fig02: icosahedral and Fibonacci grids (paper Fig. 2)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.sphere_points import CAP_VARIANCE  # noqa: E402
from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.sphere2019 import fig02_regular  # noqa: E402

ico, fib = (frames_of(read_dataset(p, SPHERE_CONFIG))[0] for p in snakemake.input.configs)  # noqa: F821
d_ico, d_fib = (read_dataset(p, CAP_VARIANCE, attrs=["R", "density"])
                for p in snakemake.input.descriptors)  # noqa: F821
fig02_regular(ico, d_ico, fib, d_fib, snakemake.output.pdf)  # noqa: F821
