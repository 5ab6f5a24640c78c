"""Rules debye2020_fig01 ... debye2020_fig12 and the validation figures
debye2020_overlapping_disks_figure, debye2020_overlapping_disks_level_set_figure: the figure
randmedia.plot.debye2020.FIGURES[params.figure], saved as PDF and PNG."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.plot import debye2020
from randmedia.plot.rule import draw_rule_figure

draw_rule_figure(debye2020.FIGURES, snakemake, log)
