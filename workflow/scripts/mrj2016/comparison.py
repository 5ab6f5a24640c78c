"""Rule mrj2016_comparison: comparison.csv and comparison_notes.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

import pandas as pd  # noqa: E402

from randmedia.compare import COLUMNS, comparison_frame, mrj2016, read_reference  # noqa: E402
from randmedia.io import write_csv  # noqa: E402

inputs = {name: path for name, path in snakemake.input.items()  # noqa: F821
          if name not in ("code", "tables", "references", "equilibrium_validation")}
frame, notes = mrj2016.comparison(inputs, list(snakemake.input.tables), dict(snakemake.params.items()))  # noqa: F821
# equilibrium hard-sphere liquid: contact-value pressure against the EOS, Q6, decorrelation
validation = read_reference(snakemake.input.equilibrium_validation, COLUMNS)  # noqa: F821
frame = comparison_frame(pd.concat([frame, validation[list(COLUMNS)]]).to_dict("records"))
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output.comparison)  # noqa: F821
write_csv(notes, snakemake.output.notes)  # noqa: F821
