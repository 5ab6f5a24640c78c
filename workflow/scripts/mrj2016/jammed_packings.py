"""Rule mrj2016_packings: per-packing summary of the MRJ packings, mean and SEM per system."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.jamming import PACKING_ATTRS, summary_table
from randmedia.io import read_dataset, write_csv

records = []
for path in snakemake.input.samples:
    dataset = read_dataset(path, attrs=PACKING_ATTRS)
    records.append({"file": str(path), **{key: dataset.attrs[key] for key in PACKING_ATTRS}})
table = summary_table(records)
for _, row in table[table["sample"].isin(["mean", "sem"])].iterrows():
    log.info("%s %s: phi %.5f, z %.4f, rattlers %.4f, Q6 %.4f", row["system"], row["sample"],
             row["phi"], row["z_mean_nonrattlers"], row["rattler_fraction"], row["Q6"])
write_csv(table, snakemake.output[0])
