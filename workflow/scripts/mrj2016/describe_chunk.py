"""Rule mrj2016_describe_chunk: one descriptor kind over one chunk of a system's samples."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import time

from randmedia.studies import mrj2016
from randmedia.io import write_dataset

params = dict(snakemake.params.items())
system, kind = snakemake.wildcards.system, snakemake.wildcards.kind
paths = list(snakemake.input.samples)
start = time.perf_counter()
configs = [mrj2016.load_configuration(path) for path in paths]
log.info("%s %s: samples %d-%d", system, kind, params["first"], params["first"] + len(configs) - 1)
dataset, used = mrj2016.describe(kind, system, configs, first=params["first"],
                                 nthreads=snakemake.threads, log=log,
                                 **params["settings"])
elapsed = time.perf_counter() - start
log.info("%d samples in %.1f s (%.2f s per sample)", len(configs), elapsed, elapsed / len(configs))
dataset.attrs["sample_files"] = " ".join(paths)
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=None, config=used)
