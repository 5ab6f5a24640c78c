"""Rules sphere2019_fig04, _fig05, _fig07, _fig08: curves of the fluids (paper Figs. 4, 5, 7, 8);
Figs. 5, 7, 8 also for the second reading of Eq. (12b) (input alpha_cubed -> figNN_alpha_cubed)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.io import read_dataset
from randmedia.plot import sphere2019 as figures


def descriptors(paths):
    by_system = {}
    for path in paths:
        ds = read_dataset(path, CAP_VARIANCE, attrs=["system", "R", "density", "potential", "coupling"])
        by_system[ds.attrs["system"]] = ds
    return by_system


inputs, outputs = snakemake.input, snakemake.output
draw = getattr(figures, snakemake.params.figure)
draw(descriptors(inputs.descriptors), outputs.pdf, a_min=snakemake.params.a_min)
if "alpha_cubed_pdf" in outputs.keys():
    draw(descriptors(inputs.alpha_cubed), outputs.alpha_cubed_pdf, a_min=snakemake.params.a_min)
