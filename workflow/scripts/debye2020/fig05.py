"""Rule debye2020_fig05: pore-size density and mean pore size of the Debye media (paper Fig. 5)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.pore_size import PORES
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import fig05_pore_size

pores = {}
for path in snakemake.input.pores:
    ds = read_dataset(path, PORES, attrs=["phi2"])
    pores[float(ds.attrs["phi2"])] = ds
fits = read_dataset(snakemake.input.fits)
fig05_pore_size(pores, fits, a=snakemake.params.a, pdf_path=snakemake.output.pdf)
