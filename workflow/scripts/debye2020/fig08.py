"""Rule debye2020_fig08: representative images of the particle-dispersion models (paper Fig. 8)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import fig08_models

images = {}
for title, path in zip(snakemake.params.titles, snakemake.input.samples):
    ds = read_dataset(path, PHASE_IMAGE, attrs=["phi2"])
    images[rf"{title}, $\phi_2 = {float(ds.attrs['phi2']):g}$"] = ds["phase"].values
fig08_models(images, pdf_path=snakemake.output.pdf)
