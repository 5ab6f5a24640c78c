"""Rule sphere2019_fit: exponents delta of sigma^2 ~ a^delta (Eq. 10, Table I)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.fit.power_law import sphere_exponents
from randmedia.io import read_dataset, write_dataset

fit = dict(snakemake.params.fit)
descriptors = {}
for path in snakemake.input.descriptors:
    ds = read_dataset(path, CAP_VARIANCE, attrs=["system", "R", "density", "ensemble"])
    descriptors[ds.attrs["system"]] = ds
fits = sphere_exponents(descriptors, a_min_rho_half=fit["a_min_rho_half"],
                        a_max_over_R=fit["a_max_over_R"], window_family=fit["window_family"])
for system in fits["system"].values:
    f = fits.sel(system=system)
    log.info("%-14s delta = %.3f +- %.3f (three origins %.3f +- %.3f), a in [%.3g, %.3g]; "
             "%d other windows: %.3f-%.3f", system,
             float(f["delta"]), float(f["delta_err"]), float(f["delta_three_origins"]),
             float(f["delta_three_origins_err"]), float(f["fit_a_min"]), float(f["fit_a_max"]),
             int(f["windows_used"]), float(f["delta_window_min"]), float(f["delta_window_max"]))
write_dataset(fits, snakemake.output[0], rule=snakemake.rule, seed=None, config=fit)
