"""Rule debye2020_overlapping_disks_s2: S2 of the void phase over all images."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import numpy as np

from randmedia.describe.two_phase import two_point_function
from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset, write_dataset

params = dict(snakemake.params.items())
images = np.stack([read_dataset(path, PHASE_IMAGE)["phase"].values
                   for path in snakemake.input.samples])
log.info("read %d images of shape %s", images.shape[0], images.shape[1:])
s2 = two_point_function(images, phase=0, r_max=params["r_max"])
write_dataset(s2, snakemake.output[0], rule=snakemake.rule, seed=None,
              config=params)
