"""Rule debye2020_fit_surface_pores: Sec. V A-B numbers of the Debye media per phi2
(Eqs. 24, 26 deviations, Eq. 27 fits and the p1 cubic, Eq. 28, Euler characteristic, wrapping)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.pore_size import PORES
from randmedia.describe.surface import SURFACE
from randmedia.fit.debye2020 import surface_pore_fits
from randmedia.io import read_dataset, write_dataset

params = dict(snakemake.params.items())
systems = {}
for surface_path, pores_path in zip(snakemake.input.surface, snakemake.input.pores):
    surface = read_dataset(surface_path, SURFACE, attrs=["phi2", "sigma"])
    pores = read_dataset(pores_path, PORES, attrs=["phi2"])
    systems[float(surface.attrs["phi2"])] = (surface, pores)
fits = surface_pore_fits(systems, a=params["a"], fits=params["fits"])
for i, phi2 in enumerate(fits["phi2"].values):
    log.info("phi2 = %g: chi2/dof Eq.24 %.3g, Eq.26 %.3g; a^2 p1 = %.4f +- %.4f; <delta> = %.3f px "
             "(Eq. 28: %+.1f %%); Euler slope %.3g vs %.3g", phi2,
             fits["F_sv_chi2_per_dof"].values[i], fits["F_ss_chi2_per_dof"].values[i],
             fits["p1"].values[i] * params["a"] ** 2, fits["p1_sem"].values[i] * params["a"] ** 2,
             fits["mean_delta"].values[i], 100 * fits["eq28_rel_error"].values[i],
             fits["euler_slope"].values[i], fits["euler_formula"].values[i])
log.info("p1 cubic coefficients %s (paper 1.05, -2.41, 4.16)", fits["p1_coefficients"].values)
write_dataset(fits, snakemake.output[0], rule=snakemake.rule, seed=None, config=params)
