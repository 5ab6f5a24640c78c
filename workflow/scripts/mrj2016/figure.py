"""Rule mrj2016_figure: one figure of the paper."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.plot import mrj2016
from randmedia.plot.style import save_figure

number = int(snakemake.wildcards.nn)
inputs = {name: path for name, path in snakemake.input.items() if name != "code"}
fig = mrj2016.FIGURES[number](inputs, dict(snakemake.params.settings), log)
save_figure(fig, snakemake.output.pdf)
