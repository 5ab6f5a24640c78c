"""Rule sphere2019_fig06: snapshots for alpha = 1, 3, 6 (paper Fig. 6)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.sphere2019 import fig06_snapshots  # noqa: E402

snapshots = {}
for label, path in zip("abcdefgh", snakemake.input.configs):  # noqa: F821
    ds = read_dataset(path, SPHERE_CONFIG, attrs=["R", "coupling"])
    title = rf"({label}) $\alpha = {ds.attrs['coupling']:g}$, N = {int(ds['n_points'].values[-1])}"
    snapshots[label] = (frames_of(ds)[-1], float(ds.attrs["R"]), title)
fig06_snapshots(snapshots, snakemake.output.pdf)  # noqa: F821
