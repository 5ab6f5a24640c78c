"""Rule mrj2016_figure: one figure of the paper."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.plot import mrj2016  # noqa: E402
from randmedia.plot.style import save_figure  # noqa: E402

number = int(snakemake.wildcards.nn)  # noqa: F821
inputs = {name: path for name, path in snakemake.input.items() if name != "code"}  # noqa: F821
fig = mrj2016.FIGURES[number](inputs, dict(snakemake.params.settings), log)  # noqa: F821
save_figure(fig, snakemake.output.pdf)  # noqa: F821
