"""Rule sphere2019_fig06: snapshots for alpha = 1, 3, 6 (paper Fig. 6), for Eq. (12b) as printed
(fig06) and for its second reading (fig06_alpha_cubed)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of
from randmedia.io import read_dataset
from randmedia.plot.sphere2019 import fig06_snapshots


def snapshots(paths):
    panels = {}
    for label, path in zip("abcdefgh", paths):
        ds = read_dataset(path, SPHERE_CONFIG, attrs=["R", "coupling"])
        title = rf"({label}) $\alpha = {ds.attrs['coupling']:g}$, N = {int(ds['n_points'].values[-1])}"
        panels[label] = (frames_of(ds)[-1], float(ds.attrs["R"]), title)
    return panels


inputs, outputs = snakemake.input, snakemake.output
fig06_snapshots(snapshots(inputs.configs), outputs.pdf)
fig06_snapshots(snapshots(inputs.alpha_cubed), outputs.alpha_cubed_pdf)
