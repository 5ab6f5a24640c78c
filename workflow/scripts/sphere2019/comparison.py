"""Rule sphere2019_comparison: results/sphere2019/comparison.csv (a row per Table I entry)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

import pandas as pd  # noqa: E402

from randmedia.compare.sphere2019 import comparison  # noqa: E402
from randmedia.io import write_csv  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
frame = comparison(pd.read_csv(snakemake.input.table), k_sigma=params["k_sigma"],  # noqa: F821
                   rounding_margin=params["rounding_margin"])
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output[0])  # noqa: F821
