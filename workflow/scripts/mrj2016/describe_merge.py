"""Rule mrj2016_describe: one descriptor kind of one system, merged over its chunks (or computed
directly from the samples when they form a single chunk)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import time

from randmedia.studies import mrj2016
from randmedia.io import read_dataset, write_dataset

params = dict(snakemake.params.items())
system, kind = snakemake.wildcards.system, snakemake.wildcards.kind
settings = params["settings"]  # this kind's config values only
used = {"system": system, "kind": kind, **settings}
if "samples" in snakemake.input.keys():
    start = time.perf_counter()
    configs = [mrj2016.load_configuration(path) for path in snakemake.input.samples]
    chunk, used_chunk = mrj2016.describe(kind, system, configs, first=0,
                                         nthreads=snakemake.threads, log=log,
                                         **settings)
    chunks = [chunk]
    used.update(used_chunk)
    log.info("%d samples described in %.1f s", len(configs), time.perf_counter() - start)
else:
    chunks = [read_dataset(path, attrs=["kind"]) for path in snakemake.input.chunks]
dataset = mrj2016.summarize(chunks, kind, spectral=settings.get("spectral"),
                            windows=settings.get("windows"))
log.info("%s %s: %d samples merged", system, kind, dataset.sizes["sample"])
dataset.attrs["system"] = system
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=None, config=used)
