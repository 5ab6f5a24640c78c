"""Rule mrj2016_comparison: comparison.csv and comparison_notes.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import COLUMNS, mrj2016, read_reference
from randmedia.io import write_csv

inputs = {name: path for name, path in snakemake.input.items()
          if name not in ("code", "tables", "references", "equilibrium_validation")}
# equilibrium hard-sphere liquid: contact-value pressure against the EOS, decorrelation
liquid_checks = read_reference(snakemake.input.equilibrium_validation, COLUMNS)
frame, notes = mrj2016.comparison(inputs, list(snakemake.input.tables),
                                  dict(snakemake.params.items()), checked_rows=liquid_checks)
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output.comparison)
write_csv(notes, snakemake.output.notes)
