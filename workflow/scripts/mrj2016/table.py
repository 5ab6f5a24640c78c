"""Rule mrj2016_table: one table of the paper with our values."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.compare import mrj2016  # noqa: E402
from randmedia.io import write_csv  # noqa: E402

number = int(snakemake.wildcards.n)  # noqa: F821
inputs = {name: path for name, path in snakemake.input.items() if name != "code"}  # noqa: F821
frame = mrj2016.TABLES[number](inputs, dict(snakemake.params.items()))  # noqa: F821
log.info("table %d: %d rows", number, len(frame))
write_csv(frame, snakemake.output[0])  # noqa: F821
