"""Rule debye2020_fig02: S2 of the constructions against the targets (paper Fig. 2)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.two_phase import TWO_POINT
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import fig02_s2

s2 = {}
for path in snakemake.input.s2:
    ds = read_dataset(path, TWO_POINT, attrs=["phi2", "a"])
    s2[float(ds.attrs["phi2"])] = ds
fig02_s2(s2, lc=snakemake.params.lc, pdf_path=snakemake.output.pdf)
