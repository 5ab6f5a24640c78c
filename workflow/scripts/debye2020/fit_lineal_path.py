"""Rule debye2020_fit_lineal_path: L_w of Eq. (29) per phi2 and <R^2>/<R> of Eq. (30)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import numpy as np
import xarray as xr

from randmedia.describe.chords import CHORDS
from randmedia.fit import per_sample_mean
from randmedia.fit.debye2020 import lineal_path_length, r2_over_r
from randmedia.io import read_dataset, write_dataset

params = dict(snakemake.params.items())
rows = []
for path in snakemake.input.chords:
    ds = read_dataset(path, CHORDS, attrs=["phi2"])
    phi2 = float(ds.attrs["phi2"])
    z, phi1 = ds["z"].values, 1.0 - phi2
    # value and error: per-sample fits, mean +- SEM; goodness of fit: the mean curve
    value, error = per_sample_mean([lineal_path_length(z, curve, phi1)
                                    for curve in ds["L_samples"].values])
    mean_curve = lineal_path_length(z, ds["L"].values, phi1, ds["L_sem"].values)
    rows.append((phi2, value, error, mean_curve.chi2_per_dof))
    log.info("phi2 = %g: L_w = %.3f +- %.3f px (mean-curve fit %.3f, chi2/dof %.2f)", phi2,
             value, error, mean_curve.value, mean_curve.chi2_per_dof)
phi2 = np.array([r[0] for r in rows])
a = params["a"]
lw = np.array([r[1] for r in rows])
lw_err = np.array([r[2] for r in rows])
ratio = r2_over_r(lw, 1.0 - phi2) / a
ratio_err = r2_over_r(lw_err, 1.0 - phi2) / a
fits = xr.Dataset(
    {
        "L_w": ("phi2", lw, {"units": "pixel", "long_name": "lineal size L_w of Eq. (29)"}),
        "L_w_err": ("phi2", lw_err, {"units": "pixel",
                    "long_name": "standard error of L_w over per-sample fits"}),
        "chi2_per_dof": ("phi2", [r[3] for r in rows], {"units": "1", "long_name":
                         "chi^2 per degree of freedom of the SEM-weighted fit to the mean L(z)"}),
        "R2_over_R": ("phi2", ratio, {"units": "a", "long_name": "<R^2>/<R> from L_w via Eq. (30)"}),
        "R2_over_R_err": ("phi2", ratio_err, {"units": "a", "long_name": "standard error of <R^2>/<R>"}),
    },
    coords={"phi2": ("phi2", phi2, {"units": "1", "long_name": "volume fraction of phase 2"})},
    attrs={"a": a},
)
write_dataset(fits.sortby("phi2"), snakemake.output[0], rule=snakemake.rule, seed=None,
              config=params)
