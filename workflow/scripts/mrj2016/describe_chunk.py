"""Rule mrj2016_describe_chunk: one descriptor kind over one chunk of a system's samples."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

import time  # noqa: E402

from randmedia.describe import sphere_samples  # noqa: E402
from randmedia.io import write_dataset  # noqa: E402
from randmedia.seeding import sample_rng, sample_seed  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
system, kind = snakemake.wildcards.system, snakemake.wildcards.kind  # noqa: F821
first = params["first"]
paths = list(snakemake.input.samples)  # noqa: F821
start = time.perf_counter()
configs = [sphere_samples.load_configuration(path) for path in paths]
indices = range(first, first + len(configs))
log.info("%s %s: samples %d-%d", system, kind, first, first + len(configs) - 1)
used = {"system": system, "kind": kind, "first": first}
if kind == "correlation":
    used.update(params["descriptors"])
    dataset = sphere_samples.correlation_samples(
        configs, r_step=params["descriptors"]["r_step"], r_max=params["descriptors"]["r_max"],
        contact_r=params["descriptors"]["contact_r"], first=first)
elif kind == "spectral":
    from randmedia.generate.spheres import bragg_peak_count

    spectral = params["spectral"]
    used.update(spectral, table_k=list(params["table_k"]))
    bragg = bragg_peak_count(system, spectral["k_max"]) if system in ("fcc", "bcc") else None
    dataset = sphere_samples.spectral_samples(
        configs, k_max=spectral["k_max"], bin_width=spectral["bin_width"], table_k=params["table_k"],
        table_width=spectral["table_bin_width"], eps=spectral["nufft_eps"],
        nthreads=snakemake.threads, first=first, bragg=bragg)  # noqa: F821
elif kind == "points":
    pores = params["pores"]
    used.update(pores, seed=params["seed"])
    rngs = [sample_rng(sample_seed(params["seed"], "mrj2016", f"{system}/points", k)) for k in indices]
    dataset = sphere_samples.points_samples(
        configs, rngs, n_matrix_points=pores["matrix_points"], bin_width=pores["bin_width"],
        d_max=pores["d_max"], first=first, covering=system != "overlapping", log=log)
else:
    windows = params["windows"]
    used.update(windows, seed=params["seed"])
    rngs = [sample_rng(sample_seed(params["seed"], "mrj2016", f"{system}/windows", k)) for k in indices]
    dataset = sphere_samples.windows_samples(
        configs, rngs, radius_step=windows["radius_step"], fR_radii=windows["fR_radii"],
        phi_B=windows["phi_B"], max_windows=windows["max_windows"], first=first)
elapsed = time.perf_counter() - start
log.info("%d samples in %.1f s (%.2f s per sample)", len(configs), elapsed, elapsed / len(configs))
dataset.attrs.update(system=system, sample_files=" ".join(paths))
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=None, config=used)  # noqa: F821
