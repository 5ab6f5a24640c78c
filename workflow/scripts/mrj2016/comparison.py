"""Rule mrj2016_comparison: comparison.csv and comparison_notes.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.compare import mrj2016  # noqa: E402
from randmedia.io import write_csv  # noqa: E402

inputs = {name: path for name, path in snakemake.input.items()  # noqa: F821
          if name not in ("code", "tables", "references")}
frame, notes = mrj2016.comparison(inputs, list(snakemake.input.tables), dict(snakemake.params.items()))  # noqa: F821
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output.comparison)  # noqa: F821
write_csv(notes, snakemake.output.notes)  # noqa: F821
