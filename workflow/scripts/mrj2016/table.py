"""Rule mrj2016_table: one table of the paper with our values."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import mrj2016
from randmedia.io import write_csv

number = int(snakemake.wildcards.n)
inputs = {name: path for name, path in snakemake.input.items() if name != "code"}
frame = mrj2016.TABLES[number](inputs, dict(snakemake.params.items()))
log.info("table %d: %d rows", number, len(frame))
write_csv(frame, snakemake.output[0])
