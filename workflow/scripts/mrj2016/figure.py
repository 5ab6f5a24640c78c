"""Rules mrj2016_fig01 ... mrj2016_fig13: the figure
randmedia.plot.mrj2016.FIGURES[params.figure], saved as PDF and PNG."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.plot import mrj2016
from randmedia.plot.rule import draw_rule_figure

draw_rule_figure(mrj2016.FIGURES, snakemake, log)
