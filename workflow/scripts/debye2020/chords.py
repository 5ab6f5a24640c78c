"""Rules debye2020_media_chords / debye2020_overlapping_disks_chords: L(z) and p(z) of the void phase."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import numpy as np

from randmedia.describe.chords import lineal_path_and_chords
from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset, write_dataset
from randmedia.seeding import sample_rng, sample_seed

params = dict(snakemake.params.items())
images = np.stack([read_dataset(path, PHASE_IMAGE)["phase"].values
                   for path in snakemake.input.samples])
sampling = dict(params["chords"])
z_max = sampling.pop("z_max_over_length") * params["length"]
seed = sample_seed(params["seed"], "debye2020", params["system"], 0)
chords = lineal_path_and_chords(images, 0, sample_rng(seed), z_max=z_max, **sampling)
chords.attrs.update({"phi2": params["phi2"], "length_scale": params["length"],
                     "system": params["system"]})
log.info("%s: mean chord %.2f px over %d images", params["system"],
         chords["mean_chord_samples"].values.mean(), images.shape[0])
write_dataset(chords, snakemake.output[0], rule=snakemake.rule, seed=seed, config=params)
