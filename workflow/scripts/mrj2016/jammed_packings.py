"""Rule mrj2016_packings: per-packing summary of the MRJ packings, mean and SEM per system.

Besides the attributes the packing rule stored, each row has ``certified_gap_tolerance``:
the smallest contact gap tolerance (configured value x 10^m, up to 1e-4 D) at which the
packing passes the strict-jamming test, from the packing's certificate file (rule
mrj2016_packing_certificate, randmedia.describe.jamming_resolution), and
``cpu_seconds``, the CPU its construction took (the packing's attribute: a kept packing's is
that of the run that made it). Only the per-system mean and SEM of the summary columns are
added (randmedia.describe.jamming.summary_table).
"""
from randmedia.jobs import start_job

log = start_job(snakemake)

import pandas as pd

from randmedia.describe.jamming import PACKING_ATTRS, summary_table
from randmedia.describe.jamming_resolution import certified_from_ladder
from randmedia.io import read_dataset, write_csv

records = []
for path, certificate in zip(snakemake.input.samples, snakemake.input.certificates, strict=True):
    dataset = read_dataset(path, attrs=PACKING_ATTRS + ("cpu_seconds",))
    certified = certified_from_ladder(pd.read_csv(certificate).to_dict("records"))
    log.info("%s: jammed at the configured gap tolerance: %d; certified from %g", path,
             dataset.attrs["jammed"], certified)
    # attempt: which seed made it (0 = the sample's own; packings made before redraws existed lack it)
    records.append({"file": str(path), **{key: dataset.attrs[key] for key in PACKING_ATTRS},
                    "cpu_seconds": float(dataset.attrs["cpu_seconds"]),
                    "attempt": int(dataset.attrs.get("attempt", 0)), "certified_gap_tolerance": certified,
                    # the route that made it (randmedia.generate.mrj.ROUTES) and its polish LPs
                    "route": dataset.attrs.get("route_name", "compression"),
                    "n_polish_lp": int(dataset.attrs.get("n_polish_lp", -1)),
                    # why the dilute stage ended: "converged" (the TJ code's volume rule) or
                    # "max_lps" (handed to the polish); packings made before 2026-12-06 lack it,
                    # and their dilute stages could only converge
                    "dilute_stop": dataset.attrs.get(
                        "dilute_stop", "converged" if dataset.attrs.get("route_name") == "dilute" else ""),
                    # why the polish ended: "converged" or "max_lps" (polish.at_max_lps "end": then
                    # tested, not repaired); packings made before 2026-12-06 lack it, and their
                    # polish could only converge (or the start was redrawn)
                    "polish_stop": dataset.attrs.get("polish_stop", "converged")})
table = summary_table(records)
for _, row in table[table["sample"].isin(["mean", "sem"])].iterrows():
    log.info("%s %s: phi %.5f, z %.4f, rattlers %.4f, Q6 %.4f", row["system"], row["sample"],
             row["phi"], row["z_mean_nonrattlers"], row["rattler_fraction"], row["Q6"])
write_csv(table, snakemake.output[0])
