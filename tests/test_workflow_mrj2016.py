"""mrj2016 end to end on the quick config (the session's quick_run): outputs, tables, comparison."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from conftest import QUICK_RESULTS, assert_comparison_notes, quick_config
from randmedia.compare import COLUMNS, judged_deviation
from randmedia.io import read_dataset

pytestmark = pytest.mark.workflow

RESULTS = f"{QUICK_RESULTS}/mrj2016"
REFERENCE = "config/reference"


def quick_section(workdir):
    return quick_config(workdir)["mrj2016"]


def test_figures_tables_and_comparison_exist(quick_run):
    for n in range(1, 14):
        for ext in ("pdf", "png"):
            assert (quick_run / f"{RESULTS}/figures/fig{n:02d}.{ext}").stat().st_size > 1000, (n, ext)
    for name in ("comparison.csv", "comparison_notes.csv", "tables/table1.csv"):
        assert (quick_run / RESULTS / name).stat().st_size > 0


def test_generated_systems(quick_run):
    section = quick_section(quick_run)
    for k in range(section["overlapping"]["n_samples"]):
        ds = read_dataset(quick_run / f"{RESULTS}/configs/overlapping/sample{k}.nc")
        assert ds.attrs["diameter"] == 1.0 and ds.attrs["phi"] == section["overlapping"]["phi"]
    for lattice, cells, per_cell in (("fcc", "fcc_cells", 4), ("bcc", "bcc_cells", 2)):
        ds = read_dataset(quick_run / f"{RESULTS}/configs/{lattice}/sample0.nc")
        assert ds.sizes["particle"] == per_cell * section["lattices"][cells] ** 3


def test_comparison_table_is_consistent(quick_run):
    """Every published table cell and quoted number has a row; passed = |ours - published| <= tol,
    tol >= 3 SEM; the rows with exact references (overlapping spheres, lattices, Eq. 21) pass."""
    table = pd.read_csv(quick_run / f"{RESULTS}/comparison.csv")
    notes = pd.read_csv(quick_run / f"{RESULTS}/comparison_notes.csv")
    assert tuple(table.columns) == COLUMNS
    assert_comparison_notes(table, notes, quick_config(quick_run)["comparison"]["k_sigma"])
    finite = np.isfinite(table["ours"]) & np.isfinite(table["published"])
    deviation = judged_deviation(table)
    assert (table.loc[finite, "passed"] == (deviation[finite] <= table.loc[finite, "tolerance"])).all()
    sem = table["ours_sem"].fillna(0)
    assert (table["tolerance"] + 1e-15 >= 3 * sem).all()
    # every cell of Tables II-V and every quoted number
    for number, name, columns in ((2, "table2_equilibrium", ["S2", "Fsv_over_s", "Fss_over_s2", "EV"]),
                                  (3, "table3_mrj", ["S2", "Fsv_over_s", "Fss_over_s2", "EV"]),
                                  (4, "table4_spectral_equilibrium", ["chiV_over_D3"]),
                                  (5, "table5_spectral_mrj", ["chiV_over_D3"])):
        reference = pd.read_csv(quick_run / f"{REFERENCE}/mrj2016_{name}.csv")
        cells = int(reference[columns].notna().sum().sum())
        assert table["quantity"].str.startswith(f"table{number}_").sum() == cells, number
    quoted = pd.read_csv(quick_run / f"{REFERENCE}/mrj2016_quoted_numbers.csv")
    for quantity in quoted["quantity"].unique():
        assert (table["quantity"] == quantity).sum() >= (quoted["quantity"] == quantity).sum(), quantity
    failed = notes.loc[~table["passed"].to_numpy(), "reason"]
    assert (failed.fillna("") != "").all()  # every failing row says why
    validation = table[table["quantity"].str.startswith("validation_")]
    assert len(validation) >= 25
    assert validation["passed"].all(), validation[~validation["passed"]]


def test_exact_quoted_numbers_are_reproduced(quick_run):
    table = pd.read_csv(quick_run / f"{RESULTS}/comparison.csv").set_index(["quantity", "key"])
    for key in [("covering_radius_over_lambda", "bcc"), ("covering_radius_over_lambda", "fcc"),
                ("covering_radius_over_D", "bcc"), ("covering_radius_over_D", "fcc"),
                ("fcc_packing_fraction", "fcc"), ("bcc_packing_fraction", "bcc"),
                ("specific_surface", "overlapping_phi0.636"), ("mean_pore_size", "overlapping_phi0.636")]:
        assert table.loc[key, "passed"], key


def test_tables_on_the_papers_grids(quick_run):
    for number, reference, column in ((2, "table2_equilibrium", "r_over_D"), (3, "table3_mrj", "r_over_D"),
                                      (4, "table4_spectral_equilibrium", "kD"), (5, "table5_spectral_mrj", "kD")):
        path = quick_run / f"{RESULTS}/tables/table{number}.csv"
        if not path.exists():  # the system's generator is not part of this workflow
            continue
        ours = pd.read_csv(path)
        published = pd.read_csv(quick_run / f"{REFERENCE}/mrj2016_{reference}.csv")
        np.testing.assert_allclose(ours[column], published[column])
        if number in (2, 3):
            assert ours["S2"].iloc[0] == pytest.approx(ours["S2"].iloc[-1] ** 0.5, rel=0.01)  # S2(0)^2 ~ S2(inf)
            assert ours["Fsv_over_s"].iloc[0] == pytest.approx(0.5)
            assert np.isinf(ours["Fss_over_s2"].iloc[0])
    summary = pd.read_csv(quick_run / f"{RESULTS}/tables/table1.csv")
    assert {"overlapping", "fcc", "bcc"} <= set(summary["system"])
    assert {"characteristic", "symbol", "unit", "system", "value", "sem"} <= set(summary.columns)


def test_descriptor_files(quick_run):
    spec = read_dataset(quick_run / f"{RESULTS}/descriptors/fcc_spectral.nc")
    assert (spec["n_peaks"].values == spec.attrs["expected_peaks"]).all()
    win = read_dataset(quick_run / f"{RESULTS}/descriptors/overlapping_windows.nc")
    assert {"number_variance", "number_variance_sem", "count_probability"} <= set(win.data_vars)
    np.testing.assert_allclose(win["count_probability"].values.sum(axis=1), 1.0)
    pts = read_dataset(quick_run / f"{RESULTS}/descriptors/overlapping_points.nc")
    assert pts["E_V_mean"].values[0] == 1.0 and np.all(np.diff(pts["E_V_mean"].values) <= 0)
