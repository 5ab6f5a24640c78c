"""Rule debye2020_overlapping_disks_level_set_figure: level-set F_sv, F_ss, F, P of overlapping
disks against the exact Eqs. (35)-(37)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.pore_size import PORES  # noqa: E402
from randmedia.describe.surface import SURFACE  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.debye2020 import overlapping_disks_level_set  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
overlapping_disks_level_set(read_dataset(snakemake.input.surface, SURFACE, attrs=["sigma"]),  # noqa: F821
                            read_dataset(snakemake.input.pores, PORES),  # noqa: F821
                            radius=params["radius"], phi2=params["phi2"],
                            pdf_path=snakemake.output.pdf)  # noqa: F821
