"""The 3D Debye study (issue 13): system table, S2 datasets against exact answers, rows."""

import numpy as np
import pytest

from conftest import SCHEMA, quick_config
from randmedia.compare.debye3d import DELTA_S2_GOAL, s2_rows
from randmedia.config import debye3d_systems, validate_config
from randmedia.generate.balls import overlapping_balls_image
from randmedia.generate.poisson_planes import poisson_plane_image
from randmedia.studies.debye3d import s2_dataset


@pytest.fixture(scope="module")
def section():
    return validate_config(quick_config(), SCHEMA)["debye3d"]


def test_system_table_of_the_quick_config(section):
    table = debye3d_systems(section)
    assert sorted(table) == ["planes_phi0.3", "planes_phi0.5", "spheres_phi0.3", "yt_phi0.3", "yt_phi0.5"]
    assert table["yt_phi0.5"]["kind"] == "yt" and table["yt_phi0.5"]["lc"] == 12.0
    assert table["planes_phi0.3"]["n_samples"] == 2 and "lc" not in table["planes_phi0.3"]
    assert table["spheres_phi0.3"]["s2_r_max"] == pytest.approx(4.0 * 3.0)  # r_max_over_length R
    assert table["yt_phi0.3"]["s2_r_max"] == pytest.approx(4.0 * 3.0)  # ... a
    no_planes = {**section, "poisson_planes": {"n_samples": 0}}
    assert not any(name.startswith("planes") for name in debye3d_systems(no_planes))


def test_sphere_s2_agrees_with_the_exact_one():
    rng = np.random.default_rng(7)
    images = np.stack([overlapping_balls_image(rng, 32, 3.0, 0.3, 3) for _ in range(8)])
    params = {"kind": "spheres", "phi2": 0.3, "radius": 3.0, "N": 32, "s2_r_max": 12.0}
    s2 = s2_dataset(images, True, params)
    assert s2["r"].attrs["units"] == "voxel" and s2.attrs["periodic"] == 1
    assert s2["S2_exact"].values[0] == pytest.approx(0.7)
    deviation = np.abs(s2["S2"] - s2["S2_exact"]).values[1:] / s2["S2_sem"].values[1:]
    assert deviation.max() < 4.0, deviation  # a biased estimator would be off in every bin
    assert "delta_S2" not in s2


def test_plane_windows_use_the_window_estimator():
    rng = np.random.default_rng(3)
    images = np.stack([poisson_plane_image(rng, (24, 24, 24), 2.0, 0.4) for _ in range(16)])
    params = {"kind": "planes", "phi2": 0.4, "a": 2.0, "N": 24, "s2_r_max": 8.0}
    s2 = s2_dataset(images, False, params)
    assert s2.attrs["estimator"] == "window" and s2.attrs["periodic"] == 0
    deviation = np.abs(s2["S2"] - s2["S2_exact"]).values[1:] / s2["S2_sem"].values[1:]
    assert deviation.max() < 4.0, deviation


def test_construction_rows_carry_delta_s2_against_the_goal():
    from randmedia.generate.yeong_torquato import AnnealingSchedule, construct
    from randmedia.theory.debye import debye_s2

    params = {"kind": "yt", "phi2": 0.3, "a": 1.5, "lc": 6.0, "N": 16, "s2_r_max": 7.0}
    images = np.stack([construct(lambda r: debye_s2(r, 0.3, 1.5), 0.3, (16, 16, 16), 6.0,
                                 np.random.default_rng(seed), AnnealingSchedule(long_range_stages=0)).image
                       for seed in (1, 2)])
    s2 = s2_dataset(images, True, params)
    assert s2["delta_S2"].shape == (2,) and (s2["delta_S2"] < DELTA_S2_GOAL).all()
    s2.attrs["system"] = "yt_phi0.3"
    rows = s2_rows("yt_phi0.3", s2, 3.0)
    keys = [row["key"] for row in rows]
    assert [row["quantity"] for row in rows] == ["S2_void"] * 3 + ["delta_S2"]  # r = a, 2a, 4a <= l_c
    assert "upper bound" in keys[-1] and all(row["passed"] for row in rows)
    # a construction far from its target fails its rows
    s2["S2"] = s2["S2"] + 0.01
    assert not any(row["passed"] for row in s2_rows("yt_phi0.3", s2, 3.0)[:3])


def test_quick_debye3d_target_runs_and_its_comparison_is_consistent(tmp_path):
    """`snakemake debye3d` (not part of `all`) on the quick config, in a workflow copy of its
    own (the shared quick run's folder must hold exactly the default target's outputs)."""
    import pandas as pd
    import xarray as xr

    from conftest import QUICK_RESULTS, assert_comparison_notes, copy_workflow, run_snakemake

    workdir = copy_workflow(tmp_path / "debye3d")
    # the target after `--`: --configfile takes every following word as a config file
    result = run_snakemake(workdir, "--cores", "2", "--configfile", "config/quick.yaml", "--", "debye3d")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    out = workdir / QUICK_RESULTS / "debye3d"
    table = pd.read_csv(out / "comparison.csv")
    assert_comparison_notes(table, pd.read_csv(out / "comparison_notes.csv"), k_sigma=3.0)
    assert set(table["quantity"]) >= {"S2_void", "delta_S2", "F_sv (Eq. 44)", "F_ss (Eq. 45)",
                                      "L (exponential, L'(0) = -s/4)", "F_sv (spheres, exact)",
                                      "<delta> (spheres, exact)", "mean chord (4 phi1 / s, Eq. 20)"}
    assert table[table["quantity"] == "delta_S2"]["passed"].all()  # every construction converged
    # chords walk the surface functions' tuned level set (config chords.sigma: tuned)
    surface = xr.load_dataset(out / "descriptors" / "yt_phi0.5_surface.nc")
    chords = xr.load_dataset(out / "descriptors" / "yt_phi0.5_chords.nc")
    assert chords.attrs["sigma"] == surface.attrs["sigma"] and chords.attrs["supersample"] == 2
    assert abs(surface.attrs["s_tuned"] / surface.attrs["s_exact"] - 1) < 0.01
    # the windows: tuned, measured, walked and probed on one interior (the surface file's margin)
    window = xr.load_dataset(out / "descriptors" / "planes_phi0.3_surface.nc")
    assert float(window["s_samples"].mean()) == pytest.approx(window.attrs["s_tuned"], rel=1e-9)
    for kind in ("chords", "pores"):
        other = xr.load_dataset(out / "descriptors" / f"planes_phi0.3_{kind}.nc")
        assert other.attrs["estimator"] == "window" and other.attrs["margin"] == window.attrs["margin"]
    assert set(table["quantity"]) >= {"F_sv (Poisson planes, exact)", "F_ss (Poisson planes, exact)"}
    for name in ("media", "s2", "surface", "pores", "chords"):
        assert (out / "figures" / f"{name}.pdf").stat().st_size > 0
        assert (out / "figures" / f"{name}.png").stat().st_size > 0


def test_shell_average_weights_the_bin_by_r_squared():
    from randmedia.compare.debye3d import shell_average

    assert shell_average(lambda r: np.full_like(r, 2.5), 4.03, 0.5) == pytest.approx(2.5)
    # bin of 4.03 at width 0.5 is [3.75, 4.25]: <r> = (3/4)(b^4 - a^4)/(b^3 - a^3)
    low, high = 3.75, 4.25
    expected = 0.75 * (high**4 - low**4) / (high**3 - low**3)
    assert shell_average(lambda r: r, 4.03, 0.5) == pytest.approx(expected, rel=1e-12)
    # a cusp inside the bin is averaged, not read at the label
    cusp = shell_average(lambda r: np.abs(r - 4.0), 4.0, 0.5)
    assert 0.1 < cusp < 0.15
