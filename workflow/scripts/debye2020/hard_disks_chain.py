"""Rule debye2020_hard_disks_chain{c}: one Markov chain of equilibrium hard disks, its
samples digitized to L x L images (pixel-centre rule) with the disk centres beside them."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import math
from pathlib import Path

import xarray as xr

from randmedia.generate import particle_config_dataset, phase_image_dataset
from randmedia.generate.disks import digitize_disks
from randmedia.generate.hard_particles.datasets import contact_histogram_dataset, sample_attrs
from randmedia.generate.hard_particles.run import run_chain
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.theory.hard_spheres import compressibility_factor

params = dict(snakemake.params.items())
chain, side, radius, phi2 = params["chain"], params["L"], params["radius"], params["phi2"]
n_disks = round(phi2 * side * side / (math.pi * radius * radius))
seed = sample_seed(params["seed"], "debye2020", f"hard_disks_phi{phi2:g}", chain)
settings = MCSettings(**params["mc"])
outputs = [Path(p) for p in snakemake.output]
checkpoint = outputs[0].with_name(f".hard_disks_chain{chain}.checkpoint.npz")
result = run_chain(n_disks, [side, side], 2.0 * radius, len(outputs), sample_rng(seed), settings,
                   checkpoint=checkpoint, checkpoint_seconds=params["checkpoint_seconds"], log=log,
                   keep_checkpoint=True)
eos_z = compressibility_factor(result.phi, 2)
for j, path in enumerate(outputs):
    k = chain * params["samples_per_chain"] + j
    sample = result.samples[j]
    image = digitize_disks(sample.positions, radius, (side, side))
    attrs = {"phi2": phi2, "radius": radius, "L": side, "sample": k, "chain": chain,
             "sample_in_chain": j, "n_disks": n_disks, "phi2_disks": result.phi,
             "phi2_digitized": float(image.mean()), "eos": "henderson",
             "eos_reduced_pressure": eos_z, **sample_attrs(result, j)}
    particles = particle_config_dataset(sample.positions, [[side, 0], [0, side]], 2.0 * radius,
                                        {}, units="pixel")
    dataset = xr.merge([phase_image_dataset(image, {}), particles,
                        contact_histogram_dataset(result, j, settings)], combine_attrs="override")
    dataset.attrs = {**particles.attrs, **attrs}
    write_dataset(dataset, path, rule=snakemake.rule, seed=seed,
                  config={**params, "sample": k})
    log.info("sample %d: reduced pressure %.4f (EOS %.4f), MSD since previous %.2f D^2, "
             "digitized phi2 %.4f", k, attrs["reduced_pressure"], eos_z,
             attrs["msd_since_previous"], attrs["phi2_digitized"])
checkpoint.unlink(missing_ok=True)  # only now: a kill while writing resumes the finished chain
