"""Rule debye2020_level_set: F_sv, F_ss, s, Euler characteristic, wrapping and pore sizes of
one system's images on Ma-Torquato level sets whose Gaussian width is tuned to the exact s."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import numpy as np

from randmedia.describe.pore_size import pore_size_functions
from randmedia.describe.surface import surface_functions, tune_sigma
from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset, write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.theory.debye_formulas import model_specific_surface

params = dict(snakemake.params.items())
datasets = [read_dataset(path, PHASE_IMAGE) for path in snakemake.input.samples]
images = np.stack([ds["phase"].values for ds in datasets])
target = dict(params["target"])
if target["model"] == "hard_disks":  # radius (pixels) and the disks' exact phi2 come with the images
    attrs = datasets[0].attrs
    target.update(radius=float(attrs["radius"]), phi2=float(attrs.get("phi2_disks", attrs["phi2"])))
length = target["a"] if target["model"] == "debye" else target["radius"]
s_target = model_specific_surface(**target)
iface = params["interface"]
n_tune = min(iface["n_tune"], images.shape[0])
sigma, s_tuned = tune_sigma(images[:n_tune], s_target, supersample=iface["supersample"],
                            model=iface["model"], bracket=tuple(iface["sigma_bracket"]), log=log)
log.info("%s: sigma = %.4f px gives s = %.6g (exact %.6g) on %d samples", params["system"], sigma,
         s_tuned, s_target, n_tune)
common = dict(sigma=sigma, supersample=iface["supersample"], model=iface["model"])
surface = surface_functions(images, r_max=iface["r_max_over_length"] * length,
                            bin_width=iface["bin_width"], bin_weighting=iface["bin_weighting"],
                            log=log, **common)
seed = sample_seed(params["seed"], "debye2020", f"pores_{params['system']}", 0)
pores = pore_size_functions(images, sample_rng(seed), delta_max=iface["delta_max_over_length"] * length,
                            delta_bin=iface["delta_bin"], k_candidates=iface["k_candidates"], log=log,
                            **common)
attrs = {"system": params["system"], "model": target["model"], "phi2": target["phi2"],
         "length_scale": length, "s_exact": s_target, "s_tuned": s_tuned, "n_tune": n_tune,
         "image_side": images.shape[-1]}
for ds in (surface, pores):
    ds.attrs.update(attrs)
log.info("%s: s = %.6g +- %.2g, <delta> = %.4g px", params["system"], surface["s_samples"].values.mean(),
         surface["s_samples"].values.std(ddof=1) / np.sqrt(images.shape[0]),
         pores["mean_delta_samples"].values.mean())
write_dataset(surface, snakemake.output.surface, rule=snakemake.rule, seed=None, config=params)
write_dataset(pores, snakemake.output.pores, rule=snakemake.rule, seed=seed, config=params)
