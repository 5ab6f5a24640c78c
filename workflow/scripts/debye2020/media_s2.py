"""Rule debye2020_media_s2: S2 of the constructed media at one phi2, with Delta S2 per sample."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import functools

import numpy as np

from randmedia.describe.two_phase import s2_discrepancy, two_point_function
from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset, write_dataset
from randmedia.theory.debye import debye_s2

params = dict(snakemake.params.items())
images = np.stack([read_dataset(path, PHASE_IMAGE, attrs=["delta_S2"])["phase"].values
                   for path in snakemake.input.samples])
target = functools.partial(debye_s2, phi2=params["phi2"], a=params["a"])
r_full = params["L"] // 2 - 1
s2 = two_point_function(images, phase=1, r_max=r_full)
s2["S2_target"] = ("r", target(s2["r"].values),
                   {"units": "1", "long_name": "target S2 of phase 2, Eq. (21), at the bin label"})
shape = images.shape[1:]
within = s2_discrepancy(two_point_function(images, phase=1, r_max=params["lc"]), target, shape)
full = s2_discrepancy(s2, target, shape)
s2["delta_S2"] = ("sample", within, {"units": "1", "long_name":
                  "mean |S2 - target| over bins 0 < r <= l_c (the constructed range)"})
s2["delta_S2_full"] = ("sample", full, {"units": "1", "long_name":
                       "mean |S2 - target| over all bins 0 < r < L/2"})
s2.attrs.update({"phi2": params["phi2"], "a": params["a"], "lc": params["lc"], "L": params["L"]})
log.info("phi2 = %g: Delta S2 (r <= l_c) max %.3g, (r < L/2) mean %.3g", params["phi2"],
         within.max(), full.mean())
write_dataset(s2, snakemake.output[0], rule=snakemake.rule, seed=None, config=params)
