"""Rule mrj2016_describe: one descriptor kind of one system, merged over its chunks (or computed
directly from the samples when they form a single chunk)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

import time  # noqa: E402

from randmedia.describe import sphere_samples  # noqa: E402
from randmedia.io import read_dataset, write_dataset  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
system, kind = snakemake.wildcards.system, snakemake.wildcards.kind  # noqa: F821
settings = params["settings"]  # this kind's config values only
used = {"system": system, "kind": kind, **settings}
if "samples" in snakemake.input.keys():  # noqa: F821
    start = time.perf_counter()
    configs = [sphere_samples.load_configuration(path) for path in snakemake.input.samples]  # noqa: F821
    chunk, used_chunk = sphere_samples.describe(kind, system, configs, first=0,
                                                nthreads=snakemake.threads, log=log,  # noqa: F821
                                                **settings)
    chunks = [chunk]
    used.update(used_chunk)
    log.info("%d samples described in %.1f s", len(configs), time.perf_counter() - start)
else:
    chunks = [read_dataset(path, attrs=["kind"]) for path in snakemake.input.chunks]  # noqa: F821
dataset = sphere_samples.summarize(chunks, kind, spectral=settings.get("spectral"),
                                   windows=settings.get("windows"))
log.info("%s %s: %d samples merged", system, kind, dataset.sizes["sample"])
dataset.attrs["system"] = system
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=None, config=used)  # noqa: F821
