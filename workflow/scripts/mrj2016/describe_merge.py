"""Rule mrj2016_describe: merge the chunks of one descriptor kind of one system."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe import sphere_samples  # noqa: E402
from randmedia.io import read_dataset, write_dataset  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
system, kind = snakemake.wildcards.system, snakemake.wildcards.kind  # noqa: F821
chunks = [read_dataset(path, attrs=["kind"]) for path in snakemake.input.chunks]  # noqa: F821
dataset = sphere_samples.summarize(chunks, kind, spectral=params["spectral"], windows=params["windows"])
log.info("%s %s: %d samples merged", system, kind, dataset.sizes["sample"])
dataset.attrs["system"] = system
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=None,  # noqa: F821
              config={"system": system, "kind": kind, **params})
