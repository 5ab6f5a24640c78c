"""Rule debye2020_fig08: representative images of the particle-dispersion models (paper Fig. 8)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.generate import PHASE_IMAGE  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.debye2020 import fig08_models  # noqa: E402

images = {}
for title, path in zip(snakemake.params.titles, snakemake.input.samples):  # noqa: F821
    ds = read_dataset(path, PHASE_IMAGE, attrs=["phi2"])
    images[rf"{title}, $\phi_2 = {float(ds.attrs['phi2']):g}$"] = ds["phase"].values
fig08_models(images, pdf_path=snakemake.output.pdf)  # noqa: F821
