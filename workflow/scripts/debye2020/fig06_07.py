"""Rules debye2020_fig06 / debye2020_fig07: lineal path and chord-length density figures."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.chords import CHORDS  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot import debye2020 as figures  # noqa: E402

chords = {}
for path in snakemake.input.chords:  # noqa: F821
    ds = read_dataset(path, CHORDS, attrs=["phi2"])
    chords[float(ds.attrs["phi2"])] = ds
fits = read_dataset(snakemake.input.fits)  # noqa: F821
draw = getattr(figures, snakemake.params.figure)  # noqa: F821
draw(chords, fits, a=snakemake.params.a, pdf_path=snakemake.output.pdf)  # noqa: F821
