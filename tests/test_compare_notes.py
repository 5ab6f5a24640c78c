"""comparison_notes.csv: the error budget and reason kept by compare(), notes_frame(), and the
reasons the debye2020 and sphere2019 row builders attach to their kinds of row."""

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from conftest import REPO, assert_comparison_notes
from randmedia.compare import COLUMNS, NOT_IDENTIFIED, checked_row, compare, comparison_frame, notes_frame
from randmedia.compare import debye2020, sphere2019
from randmedia.compare.mrj2016 import Rows
from randmedia.numerics.radial import RadialBinning
from randmedia.theory.overlapping import specific_surface, surface_void

K_SIGMA = 3.0


def assert_notes_match(frame: pd.DataFrame, notes: pd.DataFrame, k_sigma=K_SIGMA):
    """The contract columns, and the notes against their rows (conftest.assert_comparison_notes)."""
    assert tuple(frame.columns) == COLUMNS
    assert_comparison_notes(frame, notes, k_sigma)


def test_compare_keeps_the_budget_it_adds_up():
    row = compare("q", "k", 1.0, 1.2, 0.03, k_sigma=K_SIGMA, published_err=0.04, rounding=0.005,
                  systematic=0.01, reason_if_failed="because")
    assert row["tolerance"] == pytest.approx(K_SIGMA * 0.05 + 0.015)
    assert (row["published_err"], row["rounding"], row["systematic"]) == (0.04, 0.005, 0.01)
    assert row["reason_if_failed"] == "because"
    # the comparison table keeps exactly its contract columns
    assert tuple(comparison_frame([row]).columns) == COLUMNS


def test_exact_rows_pass_only_on_equality():
    assert compare("q", "k", math.inf, math.inf, 0.1, k_sigma=K_SIGMA, exact=True)["passed"] is True
    row = compare("q", "k", math.inf, 1e9, 0.1, k_sigma=K_SIGMA, rounding=0.5, exact=True)
    assert row["passed"] is False and row["tolerance"] == 0.0


def test_notes_frame_rows_reasons_and_deviations():
    rows = [
        compare("a", "pass", 1.0, 1.1, 0.1, k_sigma=K_SIGMA, reason_if_failed="never shown"),
        compare("b", "fail, reason", 1.0, 2.0, 0.1, k_sigma=K_SIGMA, reason_if_failed="our phi differs"),
        compare("c", "fail, none", 1.0, 2.0, 0.1, k_sigma=K_SIGMA, rounding=0.05),
        compare("d", "missing", 1.0, math.nan, 0.1, k_sigma=K_SIGMA),
        compare("e", "bound", 2e-4, 1e-6, 1e-7, k_sigma=K_SIGMA, upper_bound=True),
        compare("f", "exact", math.inf, math.inf, 0.0, k_sigma=K_SIGMA, exact=True),
    ]
    frame, notes = comparison_frame(rows), notes_frame(rows)
    assert_notes_match(frame, notes)
    assert list(notes["reason"]) == ["", "our phi differs", NOT_IDENTIFIED, NOT_IDENTIFIED, "", ""]
    deviation = notes["deviation_in_tolerances"].to_numpy()
    np.testing.assert_allclose(deviation[:3], [0.1 / 0.3, 1.0 / 0.3, 1.0 / 0.35])
    assert deviation[4] < 0  # an upper-bound row's deviation is signed, as it was judged
    assert np.isnan(deviation[3]) and np.isnan(deviation[5])  # missing value; zero tolerance
    finite = np.isfinite(deviation)
    assert ((deviation[finite] <= 1) == frame["passed"].to_numpy()[finite]).all()


def test_notes_frame_needs_the_budget():
    bare = {column: value for column, value in compare("q", "k", 1.0, 1.0, 0.1, k_sigma=K_SIGMA).items()
            if column in COLUMNS}
    with pytest.raises(ValueError, match="lacks its budget"):
        notes_frame([bare])


def test_checked_rows_keep_their_values_and_take_the_margin_as_systematic():
    original = compare("q", "k", 2.0, 2.5, 0.1, k_sigma=K_SIGMA, systematic=0.04)
    row = checked_row({c: original[c] for c in COLUMNS}, k_sigma=K_SIGMA, reason_if_failed="see file")
    assert {c: row[c] for c in COLUMNS} == {c: original[c] for c in COLUMNS}
    assert row["systematic"] == pytest.approx(0.04) and row["published_err"] == row["rounding"] == 0.0
    frame, notes = comparison_frame([row]), notes_frame([row])
    assert notes["reason"].iloc[0] == "see file"
    assert_notes_match(frame, notes)


def test_mrj2016_rows_use_the_shared_notes():
    rows = Rows(K_SIGMA)
    rows.add("q", "no sem", 1.0, 1.3, math.nan, systematic=0.5)  # a missing SEM adds nothing
    rows.add("q", "inf", math.inf, math.inf, exact_match=True)
    rows.add("q", "fails", 0.5, 0.4, 0.01, published_err=0.01, rounding=5e-4, reason_if_failed="phi")
    frame, notes = comparison_frame(rows.rows), notes_frame(rows.rows)
    assert math.isnan(frame["ours_sem"].iloc[0]) and frame["tolerance"].iloc[0] == 0.5
    assert list(frame["passed"]) == [True, True, False]
    assert list(notes["reason"]) == ["", "", "phi"]
    assert_notes_match(frame, notes)


# --------------------------------------------------------------------------- debye2020


def quoted_debye2020() -> pd.DataFrame:
    return pd.read_csv(REPO / "config/reference/debye2020_quoted_numbers.csv")


def surface_pore_fits() -> xr.Dataset:
    """Fits as the paper-config run of docs/debye2020.md measured them (a = 5 px)."""
    phi2 = np.array([0.1, 0.2, 0.3, 0.4, 0.5])
    a = 5.0
    formula = np.pi * phi2 / a
    per_phi2 = {
        "p0_measured": formula * 1.002, "p0_measured_sem": formula * 0.003, "p0_bin_margin": formula * 0.01,
        "p2_free": formula * np.array([0.972, 0.987, 0.988, 0.994, 0.993]), "p2_free_sem": formula * 0.001,
        "eq27_normalization": np.ones(5),
        "euler_formula": np.pi * (1 - 2 * phi2) * (1 - phi2) * phi2 / (4 * a * a),
        "euler_slope": np.pi * (1 - 2 * phi2) * (1 - phi2) * phi2 / (4 * a * a) + 1e-5,
        "euler_slope_sem": np.full(5, 3e-5), "euler_slope_window_shift": np.full(5, 1e-5),
        "eq28_rel_error": np.array([0.037, 0.121, 0.175, 0.183, 0.173]),
        "eq28_rel_error_sem": np.full(5, 0.003),
        "eq28_rel_error_pixel_centres": np.array([-0.020, 0.016, 0.022, -0.011, -0.054]),
        "eq28_rel_error_pixel_centres_sem": np.full(5, 0.002),
    }
    data = {name: ("phi2", values) for name, values in per_phi2.items()}
    data["p1_coefficients"] = ("c", [0.74, 2.03, 0.93])
    data["p1_coefficients_covariance"] = (("c", "c2"), np.diag([0.04, 0.35, 0.65]) ** 2)
    data["p1_coefficients_pixel_centres"] = ("c", [0.61, 3.30, -1.41])
    data["p1_coefficients_pixel_centres_covariance"] = (("c", "c2"), np.diag([0.03, 0.25, 0.43]) ** 2)
    return xr.Dataset(data, coords={"phi2": phi2}, attrs={
        "percolation_crossing": 0.46, "percolation_crossing_err": 0.01, "percolation_bracket": 0.1})


def test_debye2020_surface_pore_rows_carry_the_reasons_of_their_kind():
    rows = debye2020.surface_pore_rows(quoted_debye2020(), surface_pore_fits(), a=5.0, k_sigma=K_SIGMA)
    frame, notes = comparison_frame(rows), notes_frame(rows)
    assert_notes_match(frame, notes)
    by_kind = {
        "p1 cubic": (frame["quantity"] == "p1_coefficients", debye2020.REASON_P1_CUBIC),
        "free p2": (frame["key"].str.contains("free p2"), debye2020.REASON_FREE_P2),
        "Eq. 28, level set": (frame["quantity"].str.startswith("mean_pore_size_formula_rel_error")
                              & ~frame["key"].str.endswith(debye2020.PIXEL_CENTRE_READING),
                              debye2020.REASON_EQ28_LEVEL_SET),
        "Eq. 28, pixel centres": (frame["key"].str.endswith(debye2020.PIXEL_CENTRE_READING)
                                  & (frame["quantity"] != "p1_coefficients"),
                                  debye2020.REASON_EQ28_PIXEL_CENTRES),
    }
    # as in the paper-config run: all six p1 coefficients and the five free p2 fail, the
    # Eq. (28) range misses at its upper end (level sets) and at both ends (pixel centres)
    assert not frame.loc[by_kind["p1 cubic"][0], "passed"].any()
    assert not frame.loc[by_kind["free p2"][0], "passed"].any()
    assert list(frame.loc[by_kind["Eq. 28, level set"][0], "passed"]) == [True, False]
    assert not frame.loc[by_kind["Eq. 28, pixel centres"][0], "passed"].any()
    for kind, (mask, reason) in by_kind.items():
        assert mask.sum() > 0, kind
        failed = mask & ~frame["passed"]
        assert (notes.loc[failed, "reason"] == reason).all(), kind
        assert "docs/debye2020.md" in reason, kind
    others = ~np.logical_or.reduce([mask for mask, _ in by_kind.values()])
    assert frame.loc[others, "passed"].all()  # p0, normalization, Euler, percolation


def test_debye2020_parameter_rows_say_the_config_differs():
    media = {"a": 3, "lc": 30, "L": 201, "n_samples": 2, "phi2": [0.1, 0.2, 0.3, 0.4, 0.5]}
    rows = debye2020.parameter_rows(quoted_debye2020(), media, {"phi2": 0.3}, 0.3)
    frame, notes = comparison_frame(rows), notes_frame(rows)
    assert_notes_match(frame, notes)
    assert (notes.loc[~frame["passed"], "reason"] == debye2020.REASON_PARAMETER).all()
    assert (~frame["passed"]).sum() == 4


def overlapping_disks_surface(radius: float, side: int = 64, supersample: int = 4) -> xr.Dataset:
    """A level-set surface dataset of overlapping disks whose F_ss misses everywhere (zeros),
    F_sv and s are exact and the Euler characteristic is Mecke's."""
    r_max, width = 2.5 * radius, 0.5
    binning = RadialBinning.build((side * supersample,) * 2, r_max * supersample, width * supersample)
    r = binning.r_mean / supersample
    exact_sv = binning.average_of(
        lambda d: surface_void(d / supersample, radius, 0.3, dim=2))
    eta = -np.log1p(-0.3)
    mecke = eta / (np.pi * radius**2) * 0.7 * (1.0 - eta)
    s = specific_surface(radius, 0.3, 2)
    return xr.Dataset({
        "F_sv": ("r", exact_sv), "F_sv_sem": ("r", np.full(r.size, 1e-6)),
        "F_ss": ("r", np.zeros(r.size)), "F_ss_sem": ("r", np.full(r.size, 1e-9)),
        "s_samples": ("sample", [s, s]), "euler_samples": ("sample", [0.8 * mecke, 0.8 * mecke]),
    }, coords={"r": r}, attrs={"supersample": supersample, "image_side": side, "r_max": r_max,
                               "bin_width": width})


def test_debye2020_overlapping_disk_f_ss_reasons_follow_the_bin():
    radius = 10.0
    rows = debye2020.overlapping_disks_surface_rows(
        overlapping_disks_surface(radius), radius=radius, phi2=0.3, compare_r_max=2.5 * radius,
        r_min=1.0, k_sigma=K_SIGMA)
    frame, notes = comparison_frame(rows), notes_frame(rows)
    assert_notes_match(frame, notes)
    f_ss = frame["quantity"].str.startswith("F_ss_")
    assert not frame.loc[f_ss, "passed"].any()
    r = frame.loc[f_ss, "key"].str.removeprefix("r/R=").astype(float) * radius
    expected = np.where(np.abs(r - 2 * radius) < 2.0, debye2020.REASON_F_SS_SINGULARITY,
                        np.where(r <= debye2020.F_SS_PIXEL_STEP_RANGE, debye2020.REASON_F_SS_PIXEL_STEPS,
                                 NOT_IDENTIFIED))
    assert list(notes.loc[f_ss, "reason"]) == list(expected)
    assert {debye2020.REASON_F_SS_SINGULARITY, debye2020.REASON_F_SS_PIXEL_STEPS, NOT_IDENTIFIED} == set(expected)
    euler = frame["quantity"].str.startswith("euler_characteristic")
    assert not frame.loc[euler, "passed"].any()
    assert (notes.loc[euler, "reason"] == debye2020.REASON_EULER_OVERLAPPING).all()
    assert frame.loc[~f_ss & ~euler, "passed"].all()  # F_sv and s are exact here


# --------------------------------------------------------------------------- sphere2019

#: (system, reading, published delta, delta, delta_err, window systematic) of the paper-config
#: run of docs/sphere2019.md
SPHERE_RUN = [
    ("uniform", "as printed", 2.0, 2.000, 0.007, 0.002),
    ("icosahedral", "as printed", 1.0, 1.005, 0.004, 0.041),
    ("lj_R15", "as printed", 2.0, 1.858, 0.032, 0.027),
    ("udd_R15", "as printed", 2.0, 1.799, 0.021, 0.023),
    ("udd_flipped_R15", "flipped", 2.0, 1.819, 0.016, 0.053),
    ("uddpar_a1_R15", "as printed", 1.8, 1.806, 0.019, 0.028),
    ("ucc_R15", "as printed", 1.4, 1.598, 0.019, 0.009),
    ("uddpar_a3_R5", "as printed", 1.3, 1.635, 0.009, 0.065),
    ("uddcubed_a3_R5", "cubed", 1.3, 1.291, 0.003, 0.067),
    ("uddpar_a6_R5", "as printed", 1.1, 1.540, 0.005, 0.078),
    ("uddcubed_a6_R5", "cubed", 1.1, 1.123, 0.002, 0.129),
]


def sphere_table() -> pd.DataFrame:
    rows = [{"pattern": "poisson", "R": np.nan, "coupling": np.nan, "system": "poisson",
             "reading": "as printed", "published_delta": np.nan, "delta": np.nan, "delta_err": np.nan,
             "window_systematic": np.nan, "fit_a_min": 0.1, "fit_a_max": 0.9,
             "scaled_variance_mean": 1.006, "scaled_variance_mean_err": 0.005}]
    for system, reading, published, delta, error, window in SPHERE_RUN:
        rows.append({"pattern": system, "R": np.nan, "coupling": np.nan, "system": system, "reading": reading,
                     "published_delta": published, "delta": delta, "delta_err": error,
                     "window_systematic": window, "fit_a_min": 1.41, "fit_a_max": 13.5,
                     "scaled_variance_mean": np.nan, "scaled_variance_mean_err": np.nan})
    return pd.DataFrame(rows)


def test_sphere2019_rows_carry_the_reason_of_their_system():
    frame, notes = sphere2019.comparison(sphere_table(), k_sigma=K_SIGMA, rounding_margin=0.05)
    assert_notes_match(frame, notes)
    assert (notes["rounding"].iloc[1:] == 0.05).all()
    systems = ["poisson"] + [system for system, *_ in SPHERE_RUN]
    failed = {system for system, passed in zip(systems, frame["passed"]) if not passed}
    # the paper-config failures: U_dd (both readings), U_cc, alpha = 3, 6 as printed
    assert failed == {"udd_R15", "udd_flipped_R15", "ucc_R15", "uddpar_a3_R5", "uddpar_a6_R5"}
    for system, reason in zip(systems, notes["reason"]):
        if system in failed:
            assert reason == sphere2019.FAILURE_REASONS[system] and "docs/sphere2019.md" in reason
    assert sphere2019.FAILURE_REASONS["ucc_R15"].startswith(NOT_IDENTIFIED)


def test_debye2020_overlapping_disk_rows_average_the_exact_functions_like_the_data():
    """A surface dataset binned with angular weights (attribute bin_weighting) is compared with
    the exact functions averaged with the same weights: exact F_sv passes in every bin; a
    dataset that does not say how it was binned is read as equal weights and its bin labels
    then do not match."""
    radius, side, m = 10.0, 64, 4
    r_max, width = 2.5 * radius, 0.5
    binning = RadialBinning.build((side * m,) * 2, r_max * m, width * m, angular=True)
    exact_sv = binning.average_of(lambda d: surface_void(d / m, radius, 0.3, dim=2))
    r = binning.r_mean / m
    s = specific_surface(radius, 0.3, 2)
    ds = xr.Dataset({
        "F_sv": ("r", exact_sv), "F_sv_sem": ("r", np.full(r.size, 1e-9)),
        "F_ss": ("r", np.zeros(r.size)), "F_ss_sem": ("r", np.full(r.size, 1e-9)),
        "s_samples": ("sample", [s, s]), "euler_samples": ("sample", [0.0, 0.0]),
    }, coords={"r": r}, attrs={"supersample": m, "image_side": side, "r_max": r_max,
                               "bin_width": width, "bin_weighting": "angular"})
    rows = debye2020.overlapping_disks_surface_rows(ds, radius=radius, phi2=0.3, compare_r_max=r_max,
                                                    r_min=1.0, k_sigma=K_SIGMA)
    frame = comparison_frame(rows)
    f_sv = frame["quantity"].str.startswith("F_sv_")
    assert f_sv.sum() > 40 and frame.loc[f_sv, "passed"].all()
    del ds.attrs["bin_weighting"]
    with pytest.raises(ValueError, match="bins do not match"):
        debye2020.overlapping_disks_surface_rows(ds, radius=radius, phi2=0.3, compare_r_max=r_max,
                                                 r_min=1.0, k_sigma=K_SIGMA)
