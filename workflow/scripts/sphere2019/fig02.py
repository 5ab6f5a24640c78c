"""Rule sphere2019_fig02: icosahedral and Fibonacci grids (paper Fig. 2)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of
from randmedia.io import read_dataset
from randmedia.plot.sphere2019 import fig02_regular

ico, fib = (frames_of(read_dataset(p, SPHERE_CONFIG))[0] for p in snakemake.input.configs)
d_ico, d_fib = (read_dataset(p, CAP_VARIANCE, attrs=["R", "density"])
                for p in snakemake.input.descriptors)
fig02_regular(ico, d_ico, fib, d_fib, snakemake.output.pdf)
