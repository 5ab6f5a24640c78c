"""Table I of sphere2019 and its comparison rows.

Every Table I entry is matched to one of our systems (:data:`TABLE1_SYSTEMS`).
Exponents: delta of sigma^2_n ~ a^delta (:mod:`randmedia.fit.power_law`, window
stated in the table) against the published one with

    tolerance = k_sigma * (jackknife error) + (window systematic) + 0.05,

the same rule for every exponent row: the window systematic is measured on our
curve, max |delta_w - delta| over a family of fit windows (the paper fits "in the
regime rho^(-1/2) << a < R" without stating the window;
:func:`randmedia.fit.power_law.window_family_exponents`), and 0.05 is half the last
digit of the one-decimal published exponents (config ``rounding_margin``). The
Poisson entry ("sigma^2 ~ s") is checked as the window mean of sigma^2/(<rho> s)
against Eq. (7)'s exact 1, with tolerance = k_sigma * (jackknife error) and no margin.

Second readings. For alpha = 3 and 6 at R = 5, Eq. (12b) as printed (U_LJ + alpha/r^3)
is the Table I row; :data:`TABLE1_ALTERNATIVES` adds a second row per entry from the
systems with the dipole term read as epsilon (alpha d_LJ/r)^3 (coupling alpha^3,
potential ``uddpar_cubed``), and for U_dd (R = 15) one from Eq. (12a) with one s.r
factor of opposite sign (potential ``udd_flipped``), labelled in the ``reading`` column.

Every row carries the reason we identified should it fail (:data:`FAILURE_REASONS`, by our
system: the kind of row), for comparison_notes.csv; a system without one gets "not
identified".
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr

from randmedia.compare import compare, comparison_frame, notes_frame

#: (pattern, R, coupling) of config/reference/sphere2019_table1_exponents.csv -> our system
TABLE1_SYSTEMS = {
    ("poisson", None, None): "poisson",
    ("uniform", None, None): "uniform",
    ("triangular_lattice", None, None): "icosahedral",
    ("fibonacci_lattice", None, None): "fibonacci",
    ("lj", 15, None): "lj_R15",
    ("udd_perpendicular_dipoles", 15, "alpha=1"): "udd_R15",
    ("udd_parallel_r3", 15, "alpha=1"): "uddpar_a1_R15",
    ("udc_r2", 15, "gamma=1"): "udc_R15",
    ("ucc_r1", 15, "beta=1"): "ucc_R15",
    ("udd_parallel_r3", 5, "alpha=1"): "uddpar_a1_R5",
    ("udd_parallel_r3", 5, "alpha=3"): "uddpar_a3_R5",
    ("udd_parallel_r3", 5, "alpha=6"): "uddpar_a6_R5",
}

#: Table I entries computed a second time under another reading of the paper (module
#: docstring): (pattern, R, coupling) -> (our system, reading)
TABLE1_ALTERNATIVES = {
    ("udd_perpendicular_dipoles", 15, "alpha=1"): ("udd_flipped_R15", "one s.r factor of Eq. (12a) flipped: attractive tail"),
    ("udd_parallel_r3", 5, "alpha=3"): ("uddcubed_a3_R5", "eps (alpha d/r)^3 = alpha^3/r^3"),
    ("udd_parallel_r3", 5, "alpha=6"): ("uddcubed_a6_R5", "eps (alpha d/r)^3 = alpha^3/r^3"),
}

#: the reading of the paper's equations behind every other row
AS_PRINTED = "as printed"

_DIFFERS = "docs/sphere2019.md, 'What differs and why'"
_ALPHA_AS_PRINTED = (
    "with Eq. (12b) as printed the dipolar coupling Gamma = alpha (pi rho)^(3/2) / T* (1.1 at "
    "alpha = 3, 2.3 at alpha = 6) is far below the freezing of 2D dipoles (Gamma ~ 60): the fluid "
    "stays liquid-like, while the second reading alpha^3/r^3 gives the published delta "
    f"({_DIFFERS} (i); 'Second reading of Eq. (12b)')")

#: our system -> the reason its exponent row misses the published one (module docstring)
FAILURE_REASONS = {
    "lj_R15": ("sigma^2 ~ a^2 holds only for a much larger than the correlation length; over "
               f"rho^(-1/2) <= a <= 0.9 R the fitted exponent stays below 2 ({_DIFFERS} (iv))"),
    "udd_R15": ("Eq. (12a) as printed is U_dd-parallel plus a weak repulsive Coulomb tail "
                "alpha/(4 R^2 r), so it behaves like U_dd-parallel (delta ~ 1.8), not like the "
                "attractive interaction the paper's text describes (delta = 2) "
                f"({_DIFFERS} (ii); 'Radial dipoles (Eq. 12a)')"),
    "udd_flipped_R15": ("the attractive tail -5 alpha/(4 R^2 r) of this reading is too weak to "
                        "matter (5/900 at R = 15): in the paper-config run delta moves only from "
                        f"1.80 to 1.82, and neither reading of Eq. (12a) reaches 2 ({_DIFFERS} (ii))"),
    "ucc_R15": ("not identified: in the paper-config run our fluid gives delta = 1.60 in every "
                "window of the fit-window family and planar Debye-Hueckel for point charges 1.48 "
                f"over our window; no window reaches the paper's 1.4 ({_DIFFERS} (iii))"),
    "uddpar_a3_R5": _ALPHA_AS_PRINTED,
    "uddpar_a6_R5": _ALPHA_AS_PRINTED,
}

#: half the last published digit of Table I's exponents (module docstring)
ROUNDING_MARGIN = 0.05

REFERENCE_COLUMNS = ("pattern", "R", "coupling", "scaling", "delta")


def _key(row) -> tuple:
    radius = None if pd.isna(row["R"]) else int(row["R"])
    coupling = None if pd.isna(row["coupling"]) else str(row["coupling"])
    return (str(row["pattern"]), radius, coupling)


def reference_systems(reference: pd.DataFrame) -> list[tuple[dict, str, str]]:
    """Triples (reference row, our system name, reading), in the order of the reference
    table; an entry of :data:`TABLE1_ALTERNATIVES` is followed by its second reading."""
    triples = []
    for _, row in reference.iterrows():
        key = _key(row)
        if key not in TABLE1_SYSTEMS:
            raise ValueError(f"Table I entry {key} has no system in TABLE1_SYSTEMS")
        triples.append((row.to_dict(), TABLE1_SYSTEMS[key], AS_PRINTED))
        if key in TABLE1_ALTERNATIVES:
            triples.append((row.to_dict(), *TABLE1_ALTERNATIVES[key]))
    return triples


def table1(reference: pd.DataFrame, fits: xr.Dataset) -> pd.DataFrame:
    """Table I: the published scaling beside our exponent (both window-centre variants for
    the fluids), fit window and uncertainty; the Poisson row also carries sigma^2/(<rho> s)."""
    systems = list(fits["system"].values)
    rows = []
    for ref, system, reading in reference_systems(reference):
        if system not in systems:
            raise ValueError(f"no fit for system {system!r} (Table I entry {ref['pattern']})")
        f = fits.sel(system=system)
        rows.append({
            "pattern": ref["pattern"], "R": ref["R"], "coupling": ref["coupling"], "system": system,
            "reading": reading,
            "published_scaling": ref["scaling"], "published_delta": ref["delta"],
            "delta": float(f["delta"]), "delta_err": float(f["delta_err"]),
            "delta_chi2_per_dof": float(f["delta_chi2_per_dof"]),
            "delta_three_origins": float(f["delta_three_origins"]),
            "delta_three_origins_err": float(f["delta_three_origins_err"]),
            "fit_a_min": float(f["fit_a_min"]), "fit_a_max": float(f["fit_a_max"]),
            "fit_points": int(f["fit_points"]),
            "delta_window_min": float(f["delta_window_min"]),
            "delta_window_max": float(f["delta_window_max"]),
            "window_systematic": float(f["window_systematic"]),
            "windows_used": int(f["windows_used"]),
            "scaled_variance_mean": float(f["scaled_mean"]),
            "scaled_variance_mean_err": float(f["scaled_mean_err"]),
            "R_ours": float(f["R"]), "n_particles": float(f["n_particles"]),
            "ensemble": str(f["ensemble"].values),
        })
    return pd.DataFrame(rows)


def comparison_rows(table: pd.DataFrame, *, k_sigma: float,
                    rounding_margin: float = ROUNDING_MARGIN) -> list[dict]:
    """One row per Table I entry and reading (module docstring): tolerance k_sigma *
    (jackknife error) + the row's measured window systematic + ``rounding_margin``.

    Parameters
    ----------
    table : pandas.DataFrame
        Table I as built by :func:`table1`.
    k_sigma : float
        Multiple of the jackknife error in the tolerance.
    rounding_margin : float, optional
        Half the last published digit of the exponents.

    Returns
    -------
    list of dict
        Comparison rows with their budget and failure reason.
    """
    rows = []
    for _, row in table.iterrows():
        if row["pattern"] == "poisson":
            rows.append(compare(
                quantity="scaled_number_variance_poisson",
                key="window mean of sigma^2/(<rho> s) (Eq. 7: 1)",
                published=1.0, ours=row["scaled_variance_mean"],
                ours_sem=row["scaled_variance_mean_err"], k_sigma=k_sigma,
            ))
            continue
        where = f"R={row['R']:g}" if not pd.isna(row["R"]) else ""
        coupling = row["coupling"] if not pd.isna(row["coupling"]) else ""
        key = " ".join(part for part in (row["pattern"], where, coupling) if part)
        reading = "" if row["reading"] == AS_PRINTED else f"; reading {row['reading']}"
        rows.append(compare(
            quantity="number_variance_exponent_delta",
            key=f"{key} ({row['system']}; a in [{row['fit_a_min']:.3g}, {row['fit_a_max']:.3g}]{reading})",
            published=float(row["published_delta"]), ours=float(row["delta"]),
            ours_sem=float(row["delta_err"]), k_sigma=k_sigma,
            rounding=rounding_margin, systematic=float(row["window_systematic"]),
            reason_if_failed=FAILURE_REASONS.get(row["system"], ""),
        ))
    return rows


def comparison(table: pd.DataFrame, *, k_sigma: float,
               rounding_margin: float = ROUNDING_MARGIN) -> tuple[pd.DataFrame, pd.DataFrame]:
    """(comparison frame, notes frame) of :func:`comparison_rows`.

    Parameters
    ----------
    table : pandas.DataFrame
        Table I as built by :func:`table1`.
    k_sigma : float
        Multiple of the jackknife error in the tolerance.
    rounding_margin : float, optional
        Half the last published digit of the exponents.

    Returns
    -------
    tuple of pandas.DataFrame
        (comparison frame, notes frame).
    """
    rows = comparison_rows(table, k_sigma=k_sigma, rounding_margin=rounding_margin)
    return comparison_frame(rows), notes_frame(rows)


def run_summary(descriptors: dict[str, xr.Dataset]) -> pd.DataFrame:
    """One row per Monte Carlo system: the run statistics the describe step carried over, and
    production_sweeps / (2 tau) effectively independent samples of the energy and of the
    three-origin counts in caps of a = 1 ("small") and a = R."""
    keys = ("potential", "coupling", "R", "n_particles", "temperature", "equilibration_sweeps",
            "production_sweeps", "frame_interval", "count_interval", "n_frames", "step",
            "acceptance_equilibration", "acceptance_production", "tau_energy_sweeps",
            "tau_caps_small_sweeps", "tau_caps_half_R_sweeps", "tau_caps_R_sweeps",
            "energy_per_particle", "energy_per_particle_error", "energy_halves_z",
            "energy_drift_production")  # (run times vary between runs: in the logs and file attrs)
    rows = []
    for system, ds in sorted(descriptors.items()):
        if ds.attrs.get("kind") != "fluid":
            continue
        row = {"system": system, **{k: ds.attrs.get(k, np.nan) for k in keys}}
        # effectively independent samples of the run for an observable of correlation time tau
        for label, tau in (("small", "tau_caps_small_sweeps"), ("R", "tau_caps_R_sweeps"),
                           ("energy", "tau_energy_sweeps")):
            row[f"independent_samples_{label}"] = row["production_sweeps"] / (2.0 * row[tau])
        rows.append(row)
    return pd.DataFrame(rows)
