"""Rule mrj2016_jammed_packing: one strictly jammed MRJ packing (randmedia.generate.mrj)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from pathlib import Path

from randmedia.describe import bond_order, jamming
from randmedia.generate.jammed import packing_dataset
from randmedia.generate.mrj import MAX_ATTEMPTS, MRJProtocol, make_packing_retrying
from randmedia.io import write_dataset
from randmedia.kept_configurations import keep, kept_path, matching_kept
from randmedia.seeding import sample_seed

params = dict(snakemake.params.items())
system = snakemake.wildcards.system
index = int(snakemake.wildcards.k)
# the sample's seed, then redraws for a packing whose polish creeps past max_lps (make_packing_retrying)
seeds = [sample_seed(params["seed"], "mrj2016", system if j == 0 else f"{system} attempt {j}", index)
         for j in range(MAX_ATTEMPTS)]
output = Path(snakemake.output[0])
config = {**params, "system": system, "sample": index}


def make():
    """Generate the packing, analyse it, write it and keep a copy."""
    protocol = MRJProtocol.from_config(params)
    packing, attempt = make_packing_retrying(seeds, params["n_particles"], protocol,
                                             checkpoint=output.with_name(f".{output.stem}.checkpoint.npz"),
                                             checkpoint_seconds=params["checkpoint_seconds"], log=log)  # one HiGHS
    # thread: the LP solutions, hence the packings, are then the same whatever the core count
    seed = seeds[attempt]
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
        "bond_order_cutoff": cutoff, "attempt": attempt})
    write_dataset(dataset, output, rule=snakemake.rule, seed=seed, config=config)
    if kept is not None and analysis.jammed:
        keep(output, kept)
        log.info("kept a copy in %s", kept)
    elif kept is not None:  # the record keeps certified packings only (tests/test_kept_packings.py)
        log.warning("not kept: the packing did not pass the strict-jamming test at the %g D contact gap",
                    params["contacts"]["gap_tolerance"])


# the copy kept beside the record (randmedia.kept_configurations): taken back when it was made
# from the same seed and configuration, whichever attempt made it
kept = kept_path(params["keep_dir"], system, index) if params["keep_dir"] else None
if kept is not None and any(matching_kept(kept, seed, config) for seed in seeds):
    keep(kept, output)
    log.info("taken from the kept copy %s (same seed and configuration): not regenerated", kept)
else:
    make()

