"""Validation of the equilibrium hard-disk / hard-sphere samples (randmedia.generate.hard_spheres).

Per-sample diagnostics (read from the sample files' attributes) and comparison rows:

* reduced pressure beta p / rho from the contact value against an accurate equation of
  state (:mod:`randmedia.theory.hard_spheres`). ours = mean of the per-sample estimates
  (each from the pair counts near contact since the previous sample; the estimator is
  linear in the counts, so the mean is unbiased), ours_sem = their standard error.
  Stated systematic margin: 1 % of the EOS value -- the acceptance criterion of the
  issue, covering the EOS's own accuracy (Henderson 0.03 % at phi = 0.3, Kolafa
  0.02 % of the virial series at phi <= 0.3), the spread of contact extrapolations
  (0.15 %, measured) and finite-N effects of the NVT ensemble (~0.2-0.3 % at N = 500).
* digitized area fraction of the hard-disk images against N pi R^2 / L^2: for a
  translation-invariant ensemble every pixel centre is covered with probability
  N pi R^2 / L^2 (disks do not overlap), so this is the exact expectation; margin 0.
"""

from __future__ import annotations

from typing import Iterable, Sequence

import numpy as np
import pandas as pd

from randmedia.compare import compare
from randmedia.generate.hard_spheres import MCSettings, contact_fit
from randmedia.stats import standard_error

#: per-sample attributes copied into the diagnostics table (those present)
DIAGNOSTIC_ATTRS = ("sample", "chain", "sample_in_chain", "acceptance", "msd_since_previous",
                    "sweeps_since_previous", "contact_value", "reduced_pressure",
                    "eos_reduced_pressure", "phi2_digitized", "phi2_disks", "phi_particles",
                    "global_q6", "crystalline_fraction", "equilibration_msd",
                    "equilibration_sweeps", "sample_interval_sweeps", "step_over_diameter")

#: relative systematic margin of the pressure comparison (module docstring)
PRESSURE_MARGIN = 0.01


def diagnostics_frame(datasets: Iterable) -> pd.DataFrame:
    """One row per sample file with the attributes of :data:`DIAGNOSTIC_ATTRS`."""
    rows = [{key: ds.attrs[key] for key in DIAGNOSTIC_ATTRS if key in ds.attrs} for ds in datasets]
    return pd.DataFrame(rows).sort_values("sample").reset_index(drop=True)


def pooled_contact(datasets: Sequence, settings: MCSettings) -> dict:
    """The contact fit on the pair counts of all samples together (box and diameter from the
    first file; every file must describe the same system)."""
    first = datasets[0]
    box = np.diag(first["box"].values)
    n, diameter = int(first.attrs["n_particles"]), float(first.attrs["diameter"])
    hist = np.zeros(first.sizes["contact_bin"], dtype=np.int64)
    measurements = 0
    for ds in datasets:
        if int(ds.attrs["n_particles"]) != n or not np.allclose(np.diag(ds["box"].values), box):
            raise ValueError("samples of different systems cannot be pooled")
        hist += ds["contact_pairs"].values.astype(np.int64)
        measurements += int(ds.attrs["contact_measurements"])
    fit = contact_fit(hist, measurements, n, box, diameter, settings)
    fit.update({"histogram": hist, "measurements": measurements, "n_particles": n,
                "box": box, "diameter": diameter})
    return fit


def pressure_row(frame: pd.DataFrame, quantity: str, key: str, *, k_sigma: float) -> dict:
    """Mean per-sample contact-value pressure against the EOS value (module docstring)."""
    eos = float(frame["eos_reduced_pressure"].iloc[0])
    z = frame["reduced_pressure"].to_numpy(float)
    return compare(quantity, key, eos, float(z.mean()), float(standard_error(z)),
                   k_sigma=k_sigma, systematic=PRESSURE_MARGIN * eos)


def digitized_fraction_row(frame: pd.DataFrame, quantity: str, key: str, *, k_sigma: float) -> dict:
    """Mean digitized disk fraction against its exact expectation N pi R^2 / L^2."""
    values = frame["phi2_digitized"].to_numpy(float)
    return compare(quantity, key, float(frame["phi2_disks"].iloc[0]), float(values.mean()),
                   float(standard_error(values)), k_sigma=k_sigma)
