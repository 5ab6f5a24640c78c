"""Rule debye2020_overlapping_disks_image: one digitized overlapping-disk image."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.generate import phase_image_dataset
from randmedia.generate.disks import overlapping_disks_image
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed

params = dict(snakemake.params.items())
index = int(snakemake.wildcards.k)
seed = sample_seed(params["seed"], "debye2020", "overlapping_disks", index)
image = overlapping_disks_image(sample_rng(seed), params["L"], params["radius"], params["phi2"])
log.info("sample %d: seed %d, realized phi2 = %.4f", index, seed, image.mean())
dataset = phase_image_dataset(
    image, {"phi2": params["phi2"], "radius": params["radius"], "L": params["L"], "sample": index}
)
write_dataset(dataset, snakemake.output[0], rule=snakemake.rule, seed=seed,
              config={**params, "sample": index})
