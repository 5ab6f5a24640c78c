"""Rule mrj2016_jammed_packing: one strictly jammed packing by the Torquato-Jiao algorithm."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from pathlib import Path  # noqa: E402

from randmedia.describe import bond_order, jamming  # noqa: E402
from randmedia.generate.jammed import TJParameters, jam, packing_dataset  # noqa: E402
from randmedia.generate.rsa import random_sequential_addition  # noqa: E402
from randmedia.generate.soft_spheres import compress  # noqa: E402
from randmedia.io import write_dataset  # noqa: E402
from randmedia.seeding import sample_rng, sample_seed  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
system = snakemake.wildcards.system  # noqa: F821
index = int(snakemake.wildcards.k)  # noqa: F821
seed = sample_seed(params["seed"], "mrj2016", system, index)
output = Path(snakemake.output[0])  # noqa: F821

start, box = random_sequential_addition(sample_rng(seed), params["n_particles"],
                                        params["initial_phi"])
precompress_phi = params["precompress_phi"]
if precompress_phi is not None:
    start, box, soft = compress(start, box, precompress_phi)
    log.info("soft-sphere compression to phi = %g: %d FIRE steps, energy %.3g; %g after "
             "removing the overlaps", precompress_phi, soft["steps"], soft["energy"],
             start.shape[0] * 3.141592653589793 / 6 / abs(box[0, 0] * box[1, 1] * box[2, 2]))
packing = jam(start, box, TJParameters(**params["tj"]),
              checkpoint=output.with_name(f".{output.stem}.checkpoint.npz"),
              checkpoint_seconds=params["checkpoint_seconds"], log=log,
              threads=snakemake.threads)  # noqa: F821
analysis = jamming.analyse(packing.positions, packing.box, packing.diameter, **params["contacts"])
cutoff = params["bond_order_cutoff"] * packing.diameter
q6 = bond_order.global_q6(packing.positions, packing.box, cutoff, diameter=packing.diameter)
crystal = bond_order.crystalline_fraction(packing.positions, packing.box, cutoff,
                                          diameter=packing.diameter)
log.info("phi = %.6f, %d LPs, %.1f s; backbone %d spheres, %d contacts (isostatic excess %d), "
         "z = %.4f, rattlers %.4f, jammed %s; Q6 = %.4f, crystal-like %.4f", packing.phi,
         packing.n_lp, packing.seconds, analysis.n_backbone, analysis.n_backbone_contacts,
         analysis.isostatic_excess, analysis.z_mean_backbone, analysis.rattler_fraction,
         analysis.jammed, q6, crystal)
dataset = packing_dataset(packing, analysis, {
    "system": system, "sample": index, "Q6": q6, "crystal_fraction": crystal,
    "bond_order_cutoff": cutoff, "initial_phi": params["initial_phi"],
    "precompress_phi": float("nan") if precompress_phi is None else precompress_phi,
})
write_dataset(dataset, output, rule=snakemake.rule, seed=seed,  # noqa: F821
              config={**params, "system": system, "sample": index})
