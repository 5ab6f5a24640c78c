"""Rule mrj2016_comparison: comparison.csv and comparison_notes.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.compare import COLUMNS, mrj2016, read_reference  # noqa: E402
from randmedia.io import write_csv  # noqa: E402

inputs = {name: path for name, path in snakemake.input.items()  # noqa: F821
          if name not in ("code", "tables", "references", "equilibrium_validation")}
# equilibrium hard-sphere liquid: contact-value pressure against the EOS, decorrelation
liquid_checks = read_reference(snakemake.input.equilibrium_validation, COLUMNS)  # noqa: F821
frame, notes = mrj2016.comparison(inputs, list(snakemake.input.tables),  # noqa: F821
                                  dict(snakemake.params.items()), checked_rows=liquid_checks)  # noqa: F821
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output.comparison)  # noqa: F821
write_csv(notes, snakemake.output.notes)  # noqa: F821
