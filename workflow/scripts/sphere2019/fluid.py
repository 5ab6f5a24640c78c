"""Rule sphere2019_fluid: canonical Monte Carlo of one fluid on the sphere (Sec. V)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from pathlib import Path

from randmedia.theory.sphere_caps import cap_grid, cos_thresholds
from randmedia.generate.sphere_mc import MCSchedule, Potential, run_fluid
from randmedia.generate.sphere_surface import points_dataset
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed

params = dict(snakemake.params.items())
system = snakemake.wildcards.system
fluid, run = params["fluid"], params["run"]
radius = float(fluid["R"])
potential = Potential(fluid["potential"], float(fluid["coupling"]))
schedule = MCSchedule(target_acceptance=params["target_acceptance"],
                      tune_fraction=params["tune_fraction"],
                      initial_step=params["initial_step"], **run)
a = cap_grid(radius, params["n_a"])
seed = sample_seed(params["seed"], "sphere2019", system, 0)
output = Path(snakemake.output[0])
result = run_fluid(potential, radius, params["density"], params["temperature"], schedule,
                   sample_rng(seed), cos_thresholds(a, radius),
                   checkpoint=output.with_name(f".{output.stem}.checkpoint.npz"),
                   checkpoint_seconds=params["checkpoint_seconds"], log=log)
stats = result.stats
log.info("done in %.0f s: acceptance %.3f, step %.3f, U/N = %.5g +- %.2g, tau_E = %.1f sweeps, "
         "tau(a = R) = %.1f sweeps, energy halves z = %.2f, drift %.1e", stats["seconds"],
         stats["acceptance_production"], result.step, stats["energy_per_particle"],
         stats["energy_per_particle_error"], stats["tau_energy_sweeps"], stats["tau_caps_sweeps"][-1],
         stats["energy_halves_z"], stats["energy_drift_production"])
dataset = points_dataset(list(result.frames), radius, {}, extra={
    "energy": (("sweep",), result.energy, {"units": "epsilon", "long_name": "total energy after each sweep (equilibration, then production)"}),
    "acceptance": (("sweep",), result.acceptance, {"units": "1", "long_name": "acceptance rate of each sweep"}),
    "axis_counts": (("count", "origin", "a"), result.axis_counts, {"units": "1", "long_name": "particles in the cap of base radius a about the origins +x, +y, +z, recorded every count_interval production sweeps"}),
    "tau_caps": (("a",), stats["tau_caps_sweeps"], {"units": "sweep", "long_name": "integrated autocorrelation time of the three-origin cap counts"}),
})
dataset = dataset.assign_coords(
    a=("a", a, {"units": "1", "long_name": "cap base radius a (d_LJ)"}),
    origin=("origin", ["+x", "+y", "+z"], {"units": "1", "long_name": "cap centre"}),
)
dataset.attrs.update({
    "kind": "fluid", "system": system, "ensemble": "canonical", "potential": potential.name,
    "coupling": potential.coupling, "temperature": params["temperature"],
    "step": result.step, **{k: v for k, v in run.items()},
    **{k: v for k, v in stats.items() if k not in ("tau_caps_sweeps", "schedule")},
})
write_dataset(dataset, output, rule=snakemake.rule, seed=seed, config=params)
