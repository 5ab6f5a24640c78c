"""Rule sphere2019_table1: Table I and the Monte Carlo run summary."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import read_reference
from randmedia.compare.sphere2019 import REFERENCE_COLUMNS, run_summary, table1
from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.io import read_dataset, write_csv

inputs = snakemake.input
reference = read_reference(inputs.reference, REFERENCE_COLUMNS)
table = table1(reference, read_dataset(inputs.fits))
log.info("\n%s", table[["system", "published_delta", "delta", "delta_err", "delta_three_origins"]])
descriptors = {}
for path in inputs.descriptors:
    ds = read_dataset(path, CAP_VARIANCE, attrs=["system"])
    descriptors[ds.attrs["system"]] = ds
write_csv(table, snakemake.output.table)
write_csv(run_summary(descriptors), snakemake.output.runs)
