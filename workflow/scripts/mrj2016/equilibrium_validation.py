"""Rule mrj2016_equilibrium_validation: contact-value pressure of the hard-sphere liquid
against the EOS; per-sample diagnostics (decorrelation, bond order) and comparison rows."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import comparison_frame
from randmedia.compare.hard_particles import (decorrelation_rows, diagnostics_frame,
                                              pooled_contact, pressure_row)
from randmedia.generate import PARTICLE_CONFIG
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.io import VariableSpec, read_dataset, write_csv
from randmedia.plot.hard_particles import eos_validation_figure

params = dict(snakemake.params.items())
spec = {**PARTICLE_CONFIG, "contact_pairs": VariableSpec(("contact_bin",), "1")}
datasets = [read_dataset(path, spec, attrs=["reduced_pressure", "eos_reduced_pressure", "phi",
                                            "global_q6", "crystalline_fraction", "n_particles",
                                            "diameter", "contact_measurements", "chain",
                                            "sample"])
            for path in snakemake.input.samples]
settings = MCSettings(**params["mc"])
frame = diagnostics_frame(datasets)
pooled = pooled_contact(datasets, settings)
phi = float(frame["phi_particles"].iloc[0])
row = pressure_row(frame, "equilibrium_reduced_pressure", f"phi={phi:.4f},eos={params['eos']}",
                   k_sigma=params["k_sigma"])
rows = [row] + decorrelation_rows(datasets, "equilibrium_lag1_density_correlation",
                                  k_sigma=params["k_sigma"], peak_k_over_d=7.0)
for r in rows:
    log.info("%s %s: ours %.5f +- %.5f, reference %.5f, tolerance %.5f, passed %s",
             r["quantity"], r["key"], r["ours"], r["ours_sem"], r["published"], r["tolerance"],
             r["passed"])
log.info("pooled contact fit over %d measurements: g(D+) = %.4f, beta p / rho = %.4f",
         pooled["measurements"], pooled["contact_value"], pooled["reduced_pressure"])
log.info("global Q6: max %.4f, crystal-like fraction: max %.4f; MSD between samples: min %.3f D^2",
         frame["global_q6"].max(), frame["crystalline_fraction"].max(),
         frame["msd_since_previous"].min())
write_csv(frame, snakemake.output.diagnostics)
write_csv(comparison_frame(rows), snakemake.output.comparison)
eos_validation_figure(frame, pooled, settings, dim=3, phi=phi,
                      eos_names={"kolafa": "Kolafa", "carnahan_starling": "Carnahan-Starling"},
                      sample_msd=settings.sample_msd,
                      title=f"hard spheres, $\\phi$ = {phi:.4f}, N = {pooled['n_particles']}",
                      pdf_path=snakemake.output.pdf)
