"""Rules debye2020_hard_disks_validation and mrj2016_equilibrium_validation: the contact-value
pressure of an equilibrium hard-particle system's chains against its equation of state, the
per-sample diagnostics (acceptance, decorrelation; the digitized area fraction of the disks,
the bond order of the spheres) and the comparison rows. params.system as in chain.py."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import comparison_frame
from randmedia.compare.hard_particles import (decorrelation_rows, diagnostics_frame,
                                              digitized_fraction_row, pooled_contact,
                                              pressure_row)
from randmedia.generate import PARTICLE_CONFIG, PHASE_IMAGE
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.io import VariableSpec, read_dataset, write_csv
from randmedia.plot.hard_particles import eos_validation_figure

params = dict(snakemake.params.items())
system, k_sigma = params["system"], params["k_sigma"]
common = ["n_particles", "diameter", "contact_measurements", "chain", "sample"]
contacts = {"contact_pairs": VariableSpec(("contact_bin",), "1")}
if system == "hard_disks":
    spec = {**PHASE_IMAGE, "position": VariableSpec(("particle", "xyz"), "pixel"),
            "box": VariableSpec(("xyz", "vec"), "pixel"), **contacts}
    own = ["phi2_digitized", "phi2_disks"]
elif system == "hard_spheres":
    spec = {**PARTICLE_CONFIG, **contacts}
    own = ["phi", "global_q6", "crystalline_fraction"]
else:
    raise ValueError(f"params.system = {system!r}: expected 'hard_disks' or 'hard_spheres'")
attrs = ["reduced_pressure", "eos_reduced_pressure", *own, *common]
datasets = [read_dataset(path, spec, attrs=attrs) for path in snakemake.input.samples]
settings = MCSettings(**params["mc"])
frame = diagnostics_frame(datasets)
pooled = pooled_contact(datasets, settings)
if system == "hard_disks":
    phi = float(frame["phi2_disks"].iloc[0])
    key = f"phi2={phi:.4f}"
    rows = [pressure_row(frame, "hard_disks_reduced_pressure", key, k_sigma=k_sigma),
            digitized_fraction_row(frame, "hard_disks_area_fraction_digitized", key, k_sigma=k_sigma)]
    rows += decorrelation_rows(datasets, "hard_disks_lag1_density_correlation", k_sigma=k_sigma,
                               peak_k_over_d=7.0)
    dim, eos_names = 2, {"henderson": "Henderson", "santos": "Santos et al."}
    title = f"hard disks, $\\phi_2$ = {phi:.4f}, N = {pooled['n_particles']}"
else:
    phi = float(frame["phi_particles"].iloc[0])
    rows = [pressure_row(frame, "equilibrium_reduced_pressure", f"phi={phi:.4f},eos={params['eos']}",
                         k_sigma=k_sigma)]
    rows += decorrelation_rows(datasets, "equilibrium_lag1_density_correlation", k_sigma=k_sigma,
                               peak_k_over_d=7.0)
    dim, eos_names = 3, {"kolafa": "Kolafa", "carnahan_starling": "Carnahan-Starling"}
    title = f"hard spheres, $\\phi$ = {phi:.4f}, N = {pooled['n_particles']}"
    log.info("global Q6: max %.4f, crystal-like fraction: max %.4f; MSD between samples: min %.3f D^2",
             frame["global_q6"].max(), frame["crystalline_fraction"].max(),
             frame["msd_since_previous"].min())
for row in rows:
    log.info("%s %s: ours %.5f +- %.5f, reference %.5f, tolerance %.5f, passed %s", row["quantity"],
             row["key"], row["ours"], row["ours_sem"], row["published"], row["tolerance"], row["passed"])
log.info("pooled contact fit over %d measurements: g(D+) = %.4f, beta p / rho = %.4f",
         pooled["measurements"], pooled["contact_value"], pooled["reduced_pressure"])
write_csv(frame, snakemake.output.diagnostics)
write_csv(comparison_frame(rows), snakemake.output.comparison)
eos_validation_figure(frame, pooled, settings, dim=dim, phi=phi, eos_names=eos_names,
                      sample_msd=settings.sample_msd, title=title, pdf_path=snakemake.output.pdf)
