"""Rule debye2020_overlapping_disks_image: one digitized overlapping-disk image."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821 (snakemake is injected by Snakemake)

from randmedia.generate import phase_image_dataset  # noqa: E402
from randmedia.generate.disks import overlapping_disks_image  # noqa: E402
from randmedia.io import write_dataset  # noqa: E402
from randmedia.seeding import sample_rng, sample_seed  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
index = int(snakemake.wildcards.k)  # noqa: F821
seed = sample_seed(params["seed"], "debye2020", "overlapping_disks", index)
image = overlapping_disks_image(sample_rng(seed), params["L"], params["radius"], params["phi2"])
log.info("sample %d: seed %d, realized phi2 = %.4f", index, seed, image.mean())
dataset = phase_image_dataset(
    image, {"phi2": params["phi2"], "radius": params["radius"], "L": params["L"], "sample": index}
)
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=seed,  # noqa: F821
              config={**params, "sample": index})
