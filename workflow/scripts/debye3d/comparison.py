"""Rule debye3d_comparison: every system's descriptors against exact values, the issue's goals
and Ma & Torquato's 3D conjectures (randmedia.compare.debye3d); comparison.csv and notes."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import xarray as xr

from randmedia.compare import comparison_frame, notes_frame
from randmedia.compare.debye3d import s2_rows
from randmedia.io import write_csv

k_sigma = snakemake.params.k_sigma
rows = []
for path in snakemake.input.s2:
    ds = xr.load_dataset(path)
    rows += s2_rows(str(ds.attrs["system"]), ds, k_sigma)
frame = comparison_frame(rows)
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
for _, row in frame[~frame["passed"]].iterrows():
    log.info("not passed: %s [%s]: exact/goal %.5g, ours %.5g +- %.2g (tolerance %.2g)", row["quantity"],
             row["key"], row["published"], row["ours"], row["ours_sem"], row["tolerance"])
write_csv(frame, snakemake.output.comparison)
write_csv(notes_frame(rows), snakemake.output.notes)
