"""Rule sphere2019_describe: cap number variances, g2 and Eq. (4)/(5) for one system."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.sphere_points import describe_configurations
from randmedia.generate.sphere_surface import SPHERE_CONFIG
from randmedia.io import read_dataset, write_dataset
from randmedia.seeding import sample_rng, sample_seed

system = snakemake.wildcards.system
caps = dict(snakemake.params.caps)
seed = sample_seed(snakemake.params.seed, "sphere2019", f"windows_{system}", 0)
configs = read_dataset(snakemake.input.config, SPHERE_CONFIG, attrs=["R", "ensemble", "kind"])
result = describe_configurations(configs, rng=sample_rng(seed), **caps)
log.info("%s: %d frames, rho = %.4g, sigma^2/(rho s) at a = R: %.4f", system, result.attrs["n_frames"],
         result.attrs["density"], float(result["scaled_sigma2"].isel(variant=0, a=-1)))
write_dataset(result, snakemake.output[0], rule=snakemake.rule, seed=seed, config=caps)
