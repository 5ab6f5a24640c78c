"""Rules sphere2019_fig04, _fig05, _fig07, _fig08: curves of the fluids (paper Figs. 4, 5, 7, 8)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.sphere_points import CAP_VARIANCE  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot import sphere2019 as figures  # noqa: E402

descriptors = {}
for path in snakemake.input.descriptors:  # noqa: F821
    ds = read_dataset(path, CAP_VARIANCE, attrs=["system", "R", "density", "potential", "coupling"])
    descriptors[ds.attrs["system"]] = ds
draw = getattr(figures, snakemake.params.figure)  # noqa: F821
draw(descriptors, snakemake.output.pdf, a_min=snakemake.params.a_min)  # noqa: F821
