"""Rule debye2020_fig05: pore-size density and mean pore size of the Debye media (paper Fig. 5)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.pore_size import PORES  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.debye2020 import fig05_pore_size  # noqa: E402

pores = {}
for path in snakemake.input.pores:  # noqa: F821
    ds = read_dataset(path, PORES, attrs=["phi2"])
    pores[float(ds.attrs["phi2"])] = ds
fits = read_dataset(snakemake.input.fits)  # noqa: F821
fig05_pore_size(pores, fits, a=snakemake.params.a, pdf_path=snakemake.output.pdf)  # noqa: F821
