"""Rules debye3d_figure_{name}: the figure randmedia.plot.debye3d.FIGURES[params.figure], PDF and PNG."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.plot import debye3d
from randmedia.plot.rule import draw_rule_figure

draw_rule_figure(debye3d.FIGURES, snakemake, log)
