"""Rule sphere2019_fig01: the spherical-cap window (paper Fig. 1)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.plot.sphere2019 import fig01_cap_schematic

fig01_cap_schematic(snakemake.output.pdf)
