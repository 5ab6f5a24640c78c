"""Rules debye2020_fig03 / debye2020_fig04: F_sv and F_ss of the Debye media (paper Figs. 3, 4)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.surface import SURFACE
from randmedia.io import read_dataset
from randmedia.plot import debye2020 as figures

surface = {}
for path in snakemake.input.surface:
    ds = read_dataset(path, SURFACE, attrs=["phi2"])
    surface[float(ds.attrs["phi2"])] = ds
draw = getattr(figures, snakemake.params.figure)
draw(surface, a=snakemake.params.a, pdf_path=snakemake.output.pdf)
