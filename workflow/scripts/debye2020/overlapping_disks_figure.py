"""Rule debye2020_overlapping_disks_figure: S2 of overlapping disks vs exact."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.two_phase import TWO_POINT
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import overlapping_disks_s2

params = dict(snakemake.params.items())
s2 = read_dataset(snakemake.input.s2, TWO_POINT, attrs=["r_max", "bin_width"])
overlapping_disks_s2(s2, radius=params["radius"], phi2=params["phi2"],
                     compare_r_max=params["compare_r_max"], pdf_path=snakemake.output.pdf)
