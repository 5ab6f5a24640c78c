"""Rule mrj2016_equilibrium_chain{c}: one Markov chain of the equilibrium hard-sphere
liquid (D = 1, periodic cube); every sample with its diagnostics and bond order."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from pathlib import Path

import numpy as np
import xarray as xr

from randmedia.describe.bond_order import crystalline_fraction, global_q6
from randmedia.generate import particle_config_dataset
from randmedia.generate.hard_particles.datasets import contact_histogram_dataset, sample_attrs
from randmedia.generate.hard_particles.geometry import cubic_box
from randmedia.generate.hard_particles.run import run_chain
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.theory.hard_spheres import compressibility_factor

params = dict(snakemake.params.items())
chain, n, phi = params["chain"], params["n_particles"], params["phi"]
seed = sample_seed(params["seed"], "mrj2016", "equilibrium", chain)
settings = MCSettings(**params["mc"])
outputs = [Path(p) for p in snakemake.output]
checkpoint = outputs[0].with_name(f".equilibrium_chain{chain}.checkpoint.npz")
box_lengths = cubic_box(n, phi, 3)
result = run_chain(n, box_lengths, 1.0, len(outputs), sample_rng(seed), settings,
                   checkpoint=checkpoint, checkpoint_seconds=params["checkpoint_seconds"], log=log,
                   keep_checkpoint=True)
box = np.diag(box_lengths)
eos_z = compressibility_factor(result.phi, 3, params["eos"])
for j, path in enumerate(outputs):
    k = chain * params["samples_per_chain"] + j
    positions = result.samples[j].positions
    attrs = {"phi": result.phi, "sample": k, "chain": chain, "sample_in_chain": j,
             "eos": params["eos"], "eos_reduced_pressure": eos_z,
             "global_q6": global_q6(positions, box), "crystalline_fraction":
             crystalline_fraction(positions, box), **sample_attrs(result, j)}
    particles = particle_config_dataset(positions, box, 1.0, {}, units="D")
    dataset = xr.merge([particles, contact_histogram_dataset(result, j, settings)],
                       combine_attrs="override")
    dataset.attrs = {**particles.attrs, **attrs}
    write_dataset(dataset, path, rule=snakemake.rule, seed=seed,
                  config={**params, "sample": k})
    log.info("sample %d: beta p / rho %.4f (EOS %.4f), Q6 %.4f, crystal-like %.4f, "
             "MSD since previous %.2f D^2", k, attrs["reduced_pressure"], eos_z,
             attrs["global_q6"], attrs["crystalline_fraction"], attrs["msd_since_previous"])
checkpoint.unlink(missing_ok=True)  # only now: a kill while writing resumes the finished chain
