"""Rules sphere2019_fig01 ... sphere2019_fig08: the figure
randmedia.plot.sphere2019.FIGURES[params.figure], saved as PDF and PNG."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.plot import sphere2019
from randmedia.plot.rule import draw_rule_figure

draw_rule_figure(sphere2019.FIGURES, snakemake, log)
