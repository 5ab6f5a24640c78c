"""Rules debye2020_fig06 / debye2020_fig07: lineal path and chord-length density figures."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.chords import CHORDS
from randmedia.io import read_dataset
from randmedia.plot import debye2020 as figures

chords = {}
for path in snakemake.input.chords:
    ds = read_dataset(path, CHORDS, attrs=["phi2"])
    chords[float(ds.attrs["phi2"])] = ds
fits = read_dataset(snakemake.input.fits)
draw = getattr(figures, snakemake.params.figure)
draw(chords, fits, a=snakemake.params.a, pdf_path=snakemake.output.pdf)
