"""Rules debye2020_hard_disks_chain{c} and mrj2016_equilibrium_chain{c}: one Markov chain of
an equilibrium hard-particle system (randmedia.generate.hard_particles, d-generic NVT Monte
Carlo) and its samples, k = chain * samples_per_chain + j.

params.system selects what a sample holds:
- ``hard_disks`` (Ma & Torquato 2020, Sec. VI B): disks of radius ``radius`` pixels at area
  fraction ``phi2`` in an L x L box, each sample digitized to an L x L image (pixel-centre
  rule) with the disk centres beside it (lengths in pixels);
- ``hard_spheres`` (Klatt & Torquato 2016, the liquid at ``phi``): N spheres of D = 1 in a
  periodic cube, each sample with its global Q6 and crystal-like fraction.
Both carry the contact-value pressure measurements and the EOS value at the chain's fraction."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import math
from pathlib import Path

import numpy as np
import xarray as xr

from randmedia.describe.bond_order import crystalline_fraction, global_q6
from randmedia.generate import particle_config_dataset, phase_image_dataset
from randmedia.generate.disks import digitize_disks
from randmedia.generate.hard_particles.datasets import contact_histogram_dataset, sample_attrs
from randmedia.generate.hard_particles.geometry import cubic_box
from randmedia.generate.hard_particles.run import run_chain
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.theory.hard_spheres import DEFAULT_EOS, compressibility_factor

params = dict(snakemake.params.items())
system, chain = params["system"], params["chain"]
settings = MCSettings(**params["mc"])
outputs = [Path(p) for p in snakemake.output]
if system == "hard_disks":
    side, radius, phi2 = params["L"], params["radius"], params["phi2"]
    n_particles = round(phi2 * side * side / (math.pi * radius * radius))
    box_lengths, diameter = [side, side], 2.0 * radius
    seed = sample_seed(params["seed"], "debye2020", f"hard_disks_phi{phi2:g}", chain)
    checkpoint = outputs[0].with_name(f".hard_disks_chain{chain}.checkpoint.npz")
elif system == "hard_spheres":
    n_particles = params["n_particles"]
    box_lengths, diameter = cubic_box(n_particles, params["phi"], 3), 1.0
    seed = sample_seed(params["seed"], "mrj2016", "equilibrium", chain)
    checkpoint = outputs[0].with_name(f".equilibrium_chain{chain}.checkpoint.npz")
else:
    raise ValueError(f"params.system = {system!r}: expected 'hard_disks' or 'hard_spheres'")
box = np.diag(np.asarray(box_lengths, dtype=float))
result = run_chain(n_particles, box_lengths, diameter, len(outputs), sample_rng(seed), settings,
                   checkpoint=checkpoint, checkpoint_seconds=params["checkpoint_seconds"], log=log,
                   keep_checkpoint=True)
eos = params.get("eos") or DEFAULT_EOS[len(box_lengths)]  # debye2020 configures none
eos_z = compressibility_factor(result.phi, len(box_lengths), eos)


def disk_sample(positions, attrs):
    """The digitized image and the disk centres (pixels) of one sample, with its attributes."""
    image = digitize_disks(positions, radius, (side, side))
    attrs = {"phi2": phi2, "radius": radius, "L": side, **attrs, "n_disks": n_particles,
             "phi2_disks": result.phi, "phi2_digitized": float(image.mean())}
    particles = particle_config_dataset(positions, box, diameter, {}, units="pixel")
    return [phase_image_dataset(image, {}), particles], attrs


def sphere_sample(positions, attrs):
    """The sphere centres (D = 1) of one sample, with its bond order among its attributes."""
    attrs = {"phi": result.phi, **attrs, "global_q6": global_q6(positions, box),
             "crystalline_fraction": crystalline_fraction(positions, box)}
    return [particle_config_dataset(positions, box, diameter, {}, units="D")], attrs


for j, path in enumerate(outputs):
    k = chain * params["samples_per_chain"] + j
    positions = result.samples[j].positions
    parts, attrs = (disk_sample if system == "hard_disks" else sphere_sample)(
        positions, {"sample": k, "chain": chain, "sample_in_chain": j})
    attrs = {**attrs, "eos": eos, "eos_reduced_pressure": eos_z, **sample_attrs(result, j)}
    dataset = xr.merge(parts + [contact_histogram_dataset(result, j, settings)], combine_attrs="override")
    dataset.attrs = {**parts[-1].attrs, **attrs}
    write_dataset(dataset, path, rule=snakemake.rule, seed=seed, config={**params, "sample": k})
    log.info("sample %d: beta p / rho %.4f (EOS %.4f), MSD since previous %.2f D^2; %s", k,
             attrs["reduced_pressure"], eos_z, attrs["msd_since_previous"],
             f"digitized phi2 {attrs['phi2_digitized']:.4f}" if system == "hard_disks" else
             f"Q6 {attrs['global_q6']:.4f}, crystal-like {attrs['crystalline_fraction']:.4f}")
checkpoint.unlink(missing_ok=True)  # only now: a kill while writing resumes the finished chain
