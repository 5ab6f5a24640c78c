"""Rule mrj2016_jammed_packing: one strictly jammed MRJ packing (randmedia.generate.mrj)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import logging
from pathlib import Path

from randmedia.describe import bond_order
from randmedia.generate.jammed import packing_dataset
from randmedia.generate.mrj import MAX_ATTEMPTS, MRJProtocol, make_packing_retrying
from randmedia.io import write_dataset
from randmedia.kept_configurations import CheckpointKeeper, keep, kept_path, matching_kept, unfinished_dir
from randmedia.seeding import sample_seed
from randmedia.studies.jammed_certificate import certified

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
    # the test, and the repair of a polish stopped at a degenerate vertex (unloaded contacts)
    packing, analysis, repair = certified(packing, protocol.polish, params["contacts"], log=log)
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
        "bond_order_cutoff": cutoff, "attempt": attempt, **repair.attrs()})
    write_dataset(dataset, output, rule=snakemake.rule, seed=seed, config=config)
    if kept:
        # certified packings beside the record, the others (counted, not replaced) beside them
        path = kept[0] if analysis.jammed else kept[1]
        keep(output, path)
        log.log(logging.INFO if analysis.jammed else logging.WARNING, "kept a copy in %s%s", path,
                "" if analysis.jammed else " (not strictly jammed at the %g D contact gap)"
                % params["contacts"]["gap_tolerance"])


# the copies kept beside the record (randmedia.kept_configurations): certified packings under
# keep_dir, the others in its uncertified folder; one is taken back when it was made from the
# same seed and configuration, whichever attempt made it
kept = [kept_path(params["keep_dir"], system, index, certified=certified) for certified in (True, False)] \
    if params["keep_dir"] else []
found = next((path for path in kept if any(matching_kept(path, seed, config) for seed in seeds)), None)
if found is not None:
    keep(found, output)
    log.info("taken from the kept copy %s (same seed and configuration): not regenerated", found)
elif kept:
    # its checkpoints kept beside the record while it runs, so that an unfinished packing
    # resumes on another machine (taken back first when this machine has none)
    with CheckpointKeeper(output, unfinished_dir(params["keep_dir"], system),
                          seconds=params["checkpoint_seconds"], log=log):
        make()
else:
    make()

