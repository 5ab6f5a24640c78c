"""Rule debye2020_hard_disks_validation: contact-value pressure of the hard-disk chains
against the 2D equation of state; per-sample diagnostics and comparison rows."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import comparison_frame
from randmedia.compare.hard_particles import (decorrelation_rows, diagnostics_frame,
                                              digitized_fraction_row, pooled_contact,
                                              pressure_row)
from randmedia.generate import PHASE_IMAGE
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.io import VariableSpec, read_dataset, write_csv
from randmedia.plot.hard_particles import eos_validation_figure

params = dict(snakemake.params.items())
spec = {**PHASE_IMAGE, "position": VariableSpec(("particle", "xyz"), "pixel"),
        "box": VariableSpec(("xyz", "vec"), "pixel"), "contact_pairs": VariableSpec(("contact_bin",), "1")}
datasets = [read_dataset(path, spec, attrs=["reduced_pressure", "eos_reduced_pressure",
                                            "phi2_digitized", "phi2_disks", "n_particles",
                                            "diameter", "contact_measurements", "chain", "sample"])
            for path in snakemake.input.samples]
settings = MCSettings(**params["mc"])
frame = diagnostics_frame(datasets)
pooled = pooled_contact(datasets, settings)
phi = float(frame["phi2_disks"].iloc[0])
key = f"phi2={phi:.4f}"
rows = [pressure_row(frame, "hard_disks_reduced_pressure", key, k_sigma=params["k_sigma"]),
        digitized_fraction_row(frame, "hard_disks_area_fraction_digitized", key,
                               k_sigma=params["k_sigma"])]
rows += decorrelation_rows(datasets, "hard_disks_lag1_density_correlation",
                           k_sigma=params["k_sigma"], peak_k_over_d=7.0)
for row in rows:
    log.info("%s: ours %.5f +- %.5f, reference %.5f, tolerance %.5f, passed %s", row["quantity"],
             row["ours"], row["ours_sem"], row["published"], row["tolerance"], row["passed"])
log.info("pooled contact fit over %d measurements: g(D+) = %.4f, beta p / rho = %.4f",
         pooled["measurements"], pooled["contact_value"], pooled["reduced_pressure"])
write_csv(frame, snakemake.output.diagnostics)
write_csv(comparison_frame(rows), snakemake.output.comparison)
eos_validation_figure(frame, pooled, settings, dim=2, phi=phi,
                      eos_names={"henderson": "Henderson", "santos": "Santos et al."},
                      sample_msd=settings.sample_msd,
                      title=f"hard disks, $\\phi_2$ = {phi:.4f}, N = {pooled['n_particles']}",
                      pdf_path=snakemake.output.pdf)
