"""Rule debye2020_fig01: representative constructions at each phi2 (paper Fig. 1)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import fig01_media

images = {}
for path in snakemake.input.samples:
    ds = read_dataset(path, PHASE_IMAGE, attrs=["phi2"])
    images[float(ds.attrs["phi2"])] = ds["phase"].values
fig01_media(images, a=snakemake.params.a, pdf_path=snakemake.output.pdf)
