"""Rule debye2020_overlapping_disks_level_set_figure: level-set F_sv, F_ss, F, P of overlapping
disks against the exact Eqs. (35)-(37)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.pore_size import PORES
from randmedia.describe.surface import SURFACE
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import overlapping_disks_level_set

params = dict(snakemake.params.items())
overlapping_disks_level_set(read_dataset(snakemake.input.surface, SURFACE, attrs=["sigma"]),
                            read_dataset(snakemake.input.pores, PORES),
                            radius=params["radius"], phi2=params["phi2"],
                            pdf_path=snakemake.output.pdf)
