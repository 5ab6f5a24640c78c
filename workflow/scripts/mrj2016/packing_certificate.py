"""Rule mrj2016_packing_certificate: the contact-gap ladder of one MRJ packing.

The strict-jamming test (randmedia.describe.jamming.analyse, with the system's configured
contact options) at the configured gap tolerance, then at 10x, 100x, ... up to 1e-4 D until it
passes (randmedia.describe.jamming_resolution.gap_ladder): one row per rung tried. The first
rung repeats the test the packing rule stored as the packing's ``jammed`` attribute (same code
and options, so the same outcome; a difference is logged as an error). One job per packing:
at N = 10 000 an uncertified packing's ladder costs ~40 CPU min (two cone LPs and rank checks on
~30 000 contacts), which then runs beside the other packings' jobs instead of inside the
summary table's. The ladder of a kept packing is kept beside it with the key it was computed
from (randmedia.kept_certificates) and taken back when the packing, the contact options and the
code that computes the ladder are the same, so a new machine rebuilds the record without
recomputing it.
"""
from randmedia.jobs import start_job

log = start_job(snakemake)

import pandas as pd

from randmedia.describe.jamming_resolution import LADDER_COLUMNS, certified_from_ladder, gap_ladder
from randmedia.io import read_dataset, write_csv
from randmedia.kept_certificates import (certificate_key, keep_ladder, kept_certificate_path, kept_ladder,
                                         ladder_sources)

contacts = dict(snakemake.params.contacts)
dataset = read_dataset(snakemake.input.packing, attrs=("diameter", "jammed"))
positions, box, diameter = dataset["position"].values, dataset["box"].values, float(dataset.attrs["diameter"])
stored_jammed = bool(dataset.attrs["jammed"])
# kept beside the kept packing (randmedia.kept_certificates)
keep_dir = snakemake.params.keep_dir
kept = kept_certificate_path(keep_dir, snakemake.wildcards.system, int(snakemake.wildcards.k),
                             certified=stored_jammed) if keep_dir else None
key = certificate_key(positions, box, diameter, contacts, ladder_sources())
rows = kept_ladder(kept, key) if kept else None
if rows is not None:
    log.info("ladder taken from the kept certificate %s (same packing, contact options and code): "
             "not recomputed", kept)
else:
    rows = gap_ladder(positions, box, diameter, **contacts)
    if kept:
        keep_ladder(kept, key, rows)
for row in rows:
    log.info("gap tolerance %g D: %d pairs, backbone %d spheres, isostatic excess %s, min Tr eps %s, "
             "min force / mean %s, rank ratio %s: jammed %s (%.1f CPU s)", row["gap_tolerance"],
             row["n_pairs"], row["n_backbone"], row["isostatic_excess"], row["min_trace"],
             row["min_force_ratio"], row["rank_ratio"], row["jammed"], row["cpu_seconds"])
if rows[0]["jammed"] != stored_jammed:
    log.error("%s: the test at %g D gives jammed %s, the packing's stored attribute %s",
              snakemake.input.packing, contacts["gap_tolerance"], rows[0]["jammed"], stored_jammed)
log.info("certified gap tolerance: %g D", certified_from_ladder(rows))
write_csv(pd.DataFrame(rows, columns=list(LADDER_COLUMNS)), snakemake.output[0])
