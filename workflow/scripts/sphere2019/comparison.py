"""Rule sphere2019_comparison: results/sphere2019/comparison.csv (a row per Table I entry) and
comparison_notes.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import pandas as pd

from randmedia.compare.sphere2019 import comparison
from randmedia.io import write_csv

params = dict(snakemake.params.items())
frame, notes = comparison(pd.read_csv(snakemake.input.table), k_sigma=params["k_sigma"],
                          rounding_margin=params["rounding_margin"])
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output.comparison)
write_csv(notes, snakemake.output.notes)
