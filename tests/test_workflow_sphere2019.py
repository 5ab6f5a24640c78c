"""sphere2019 through Snakemake on the quick config (the session's quick_run): file contracts,
Table I and its comparison rows with tolerances from the fit uncertainty, Monte Carlo records."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from conftest import QUICK_RESULTS, assert_comparison_notes, quick_config
from randmedia.compare import COLUMNS, judged_deviation
from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of
from randmedia.io import PROVENANCE_ATTRS, read_dataset

pytestmark = pytest.mark.workflow

SYSTEMS = ["icosahedral", "fibonacci", "uniform", "poisson", "lj_R15", "udd_R15", "uddpar_a1_R15",
           "udc_R15", "ucc_R15", "uddpar_a1_R5", "uddpar_a3_R5", "uddpar_a6_R5", "uddcubed_a3_R5",
           "uddcubed_a6_R5", "udd_flipped_R15"]


@pytest.fixture(scope="module")
def quick(quick_run):
    return quick_run, quick_config(quick_run)["sphere2019"]


def test_every_sphere2019_target_exists(quick):
    workdir, _ = quick
    outputs = ["comparison.csv", "comparison_notes.csv", "tables/table1.csv", "tables/mc_runs.csv", "fits/exponents.nc"]
    outputs += [f"figures/fig{n:02d}.{ext}" for n in range(1, 9) for ext in ("pdf", "png")]
    outputs += [f"figures/fig{n:02d}_alpha_cubed.{ext}" for n in range(5, 9) for ext in ("pdf", "png")]
    for relative in outputs:
        assert (workdir / f"{QUICK_RESULTS}/sphere2019" / relative).stat().st_size > 0, relative


@pytest.mark.parametrize("system", SYSTEMS)
def test_configuration_files_follow_the_contract(quick, system):
    workdir, section = quick
    ds = read_dataset(workdir / f"{QUICK_RESULTS}/sphere2019/configs/{system}.nc", SPHERE_CONFIG, attrs=["R"])
    assert all(key in ds.attrs for key in PROVENANCE_ATTRS)
    assert ds["position"].dims == ("frame", "particle", "xyz")
    for name in ds.variables:
        assert {"units", "long_name"} <= set(ds[name].attrs), name
    radius = float(ds.attrs["R"])
    for frame in frames_of(ds):
        np.testing.assert_allclose(np.linalg.norm(frame, axis=1), radius, rtol=1e-9)
    if system == "poisson":  # grand canonical: frames differ in size, NaN rows pad them
        assert len(set(ds["n_points"].values)) > 1 and np.isnan(ds["position"].values).any()
    elif system in section["fluids"]["systems"]:
        fluid = section["fluids"]["systems"][system]
        assert radius == fluid["R"]
        assert int(ds["n_points"].values[0]) == round(section["fluids"]["density"] * 4 * np.pi * radius**2)
        assert ds.attrs["potential"] == fluid["potential"]


def test_table1_and_comparison_rows(quick):
    workdir, section = quick
    reference = pd.read_csv(workdir / "config/reference/sphere2019_table1_exponents.csv")
    table = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/tables/table1.csv")
    comparison = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/comparison.csv")
    # every published entry once as printed; U_dd (R = 15), alpha = 3 and 6 at R = 5 also in
    # their second readings
    assert len(table) == len(comparison) == len(reference) + 3
    assert (table["reading"] == "as printed").sum() == len(reference)
    second = table[table["reading"] != "as printed"]
    assert list(second["system"]) == ["udd_flipped_R15", "uddcubed_a3_R5", "uddcubed_a6_R5"]
    assert list(second["published_delta"]) == [2.0, 1.3, 1.1]
    assert tuple(comparison.columns) == COLUMNS
    assert (comparison["passed"] == (judged_deviation(comparison) <= comparison["tolerance"])).all()
    # tolerance: 3 errors + the measured window systematic + half the published digit
    exponents = comparison["quantity"] == "number_variance_exponent_delta"
    margin = table.loc[table["pattern"] != "poisson", "window_systematic"].to_numpy()
    np.testing.assert_allclose(comparison.loc[exponents, "tolerance"],
                               3.0 * comparison.loc[exponents, "ours_sem"] + margin
                               + section["fit"]["rounding_margin"])
    spread = table[["delta_window_min", "delta_window_max"]].to_numpy()
    assert (spread[:, 0] <= table["delta"]).all() and (table["delta"] <= spread[:, 1]).all()
    np.testing.assert_allclose(table["window_systematic"],
                               np.maximum(table["delta"] - spread[:, 0], spread[:, 1] - table["delta"]))
    assert (table["delta_err"] > 0).all() and np.isfinite(table["delta"]).all()
    fluids = table[table["system"].isin(section["fluids"]["systems"])]
    assert np.isfinite(fluids["delta_three_origins"]).all() and (fluids["delta_three_origins_err"] > 0).all()


def test_comparison_notes_follow_the_comparison_rows(quick):
    """comparison_notes.csv: a row per comparison row, same order, budget = tolerance (the
    rounding margin of every exponent row is config rounding_margin), reasons of failing rows."""
    from randmedia.compare.sphere2019 import FAILURE_REASONS

    workdir, section = quick
    comparison = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/comparison.csv")
    notes = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/comparison_notes.csv")
    assert_comparison_notes(comparison, notes, quick_config(workdir)["comparison"]["k_sigma"])
    exponents = (comparison["quantity"] == "number_variance_exponent_delta").to_numpy()
    assert (notes.loc[exponents, "rounding"] == section["fit"]["rounding_margin"]).all()
    table = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/tables/table1.csv")
    reasons = notes["reason"].astype(object).fillna("")
    for system, passed, reason in zip(table["system"], comparison["passed"], reasons):
        assert reason == ("" if passed else FAILURE_REASONS.get(system, "not identified")), system


def test_quick_table_entries_with_known_answers(quick):
    """Poisson: sigma^2/(<rho> s) = 1 (Eq. 7) and uniform: delta = 2 (Eq. 6, sigma^2 = rho pi a^2)
    within 3 x their fit uncertainty; the two lattices within the stated 0.15 of delta = 1."""
    workdir, _ = quick
    table = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/tables/table1.csv").set_index("system")
    poisson = table.loc["poisson"]
    assert abs(poisson["scaled_variance_mean"] - 1.0) <= 3 * poisson["scaled_variance_mean_err"]
    uniform = table.loc["uniform"]
    assert abs(uniform["delta"] - 2.0) <= 3 * uniform["delta_err"]
    for lattice in ("icosahedral", "fibonacci"):
        assert abs(table.loc[lattice, "delta"] - 1.0) <= 0.15 + 3 * table.loc[lattice, "delta_err"]


def test_descriptors_two_variants_agree_for_the_fluids(quick):
    """Random centres per stored frame and the paper's three origins per sweep estimate the same
    sigma^2(a): their difference is within a few combined standard errors."""
    workdir, section = quick
    for system in section["fluids"]["systems"]:
        ds = read_dataset(workdir / f"{QUICK_RESULTS}/sphere2019/descriptors/{system}.nc", CAP_VARIANCE)
        sigma2, sem = ds["sigma2"].values, ds["sigma2_sem"].values
        z = np.abs(sigma2[0] - sigma2[1]) / np.hypot(sem[0], sem[1])
        assert np.median(z) < 2.0 and z.max() < 5.0, (system, z)


def test_monte_carlo_runs_are_recorded(quick):
    workdir, section = quick
    runs = pd.read_csv(workdir / f"{QUICK_RESULTS}/sphere2019/tables/mc_runs.csv").set_index("system")
    assert set(section["fluids"]["systems"]) == set(runs.index)
    target = section["fluids"]["target_acceptance"]
    assert (abs(runs["acceptance_production"] - target) < 0.15).all()
    assert (runs["energy_drift_production"] < 1e-8).all()
    assert (runs["tau_energy_sweeps"] >= 0.5).all() and (runs["tau_caps_R_sweeps"] >= 0.5).all()
    # stored frames are at least one energy correlation time apart
    assert (runs["frame_interval"] >= runs["tau_energy_sweeps"]).all()
