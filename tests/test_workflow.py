"""End to end through Snakemake: dry runs, config rejection, quick DAG, determinism, kill/resume.

Every run happens in a copy of the workflow in a temporary folder, so the
checkout's own results/ and .snakemake/ are never touched.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from bad_configs import BAD_CONFIGS, bad_config
from conftest import QUICK_RESULTS, copy_workflow, quick_config, run_snakemake, snakemake_command
from randmedia.compare import COLUMNS, UPPER_BOUND_NOTE, judged_deviation
from randmedia.io import PROVENANCE_ATTRS, read_dataset
from randmedia.record import PAPERS

pytestmark = pytest.mark.workflow

QUICK = ("--configfile", "config/quick.yaml")
EXPECTED_OUTPUTS = [
    f"{QUICK_RESULTS}/debye2020/comparison.csv",
    f"{QUICK_RESULTS}/debye2020/validation/overlapping_disks_S2.pdf",
    f"{QUICK_RESULTS}/debye2020/validation/overlapping_disks_S2.png",
    f"{QUICK_RESULTS}/debye2020/descriptors/overlapping_disks_phi0.3_S2.nc",
    f"{QUICK_RESULTS}/debye2020/tables/numbers.csv",
    f"{QUICK_RESULTS}/debye2020/fits/lineal_path.nc",
] + [f"{QUICK_RESULTS}/debye2020/figures/fig{n:02d}.{ext}" for n in (1, 2, 6, 7) for ext in ("pdf", "png")]


#: the folders of the default target's outputs; the quick run's debye3d/ and record/ exist only
#: once a test asks for them (tests/test_record.py's `record` makes both)
DEFAULT_TARGET_FOLDERS = PAPERS


def netcdf_files(workdir: Path, folders=DEFAULT_TARGET_FOLDERS) -> list[Path]:
    """The netCDF outputs under workdir's quick results folders ``folders`` (default: those of
    the default target)."""
    return sorted(path for folder in folders for path in (workdir / QUICK_RESULTS / folder).rglob("*.nc"))


def _result_tables(root: Path, folders=DEFAULT_TARGET_FOLDERS) -> list[Path]:
    """The CSV files under root's quick results folders ``folders`` but the run times
    (benchmarks.csv: measured, and asking for it would make every figure job run)."""
    return sorted(path.relative_to(root) for folder in folders
                  for path in (root / QUICK_RESULTS / folder).rglob("*.csv") if path.name != "benchmarks.csv")


def assert_same_data(first: Path, second: Path, folders=DEFAULT_TARGET_FOLDERS) -> None:
    """Every netCDF file and CSV table under ``folders`` has identical data in both runs."""
    files = [p.relative_to(first) for p in netcdf_files(first, folders)]
    assert files == [p.relative_to(second) for p in netcdf_files(second, folders)]
    assert files, "no netCDF outputs"
    for relative in files:
        a, b = read_dataset(first / relative), read_dataset(second / relative)
        assert sorted(a.data_vars) == sorted(b.data_vars), relative
        for name in a.variables:
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=str(relative))
        assert a.attrs["seed"] == b.attrs["seed"]
    tables = _result_tables(first, folders)
    assert tables == _result_tables(second, folders)
    for relative in tables:  # comparison.csv, tables/*.csv of every paper
        a, b = pd.read_csv(first / relative), pd.read_csv(second / relative)
        assert list(a.columns) == list(b.columns), relative
        measured_times = [name for name in a.columns if name.endswith("_seconds")]  # cpu_seconds
        pd.testing.assert_frame_equal(a.drop(columns=measured_times), b.drop(columns=measured_times),
                                      obj=str(relative))


@pytest.mark.parametrize("extra", [(), QUICK], ids=["paper", "quick"])
def test_dry_run(tmp_path, extra):
    workdir = copy_workflow(tmp_path)
    result = run_snakemake(workdir, "-n", *extra)
    assert result.returncode == 0, result.stderr[-3000:]
    assert "debye2020_overlapping_disks_image" in result.stdout
    assert not (workdir / "results").exists()


#: the first bad config of each top-level config key. Snakemake refuses every bad config through
#: one call (randmedia.config.validate_config, from the Snakefile), which test_config.py runs on
#: all of them; through Snakemake (~3 s each) one per section shows that each section's schema is
#: checked there before any job runs.
SNAKEMAKE_BAD_CONFIGS = [case for index, case in enumerate(BAD_CONFIGS)
                         if all(case[2].split(".")[0] != earlier[2].split(".")[0]
                                for earlier in BAD_CONFIGS[:index])]


@pytest.mark.parametrize("case_id, mutation, key", SNAKEMAKE_BAD_CONFIGS, ids=[c[0] for c in SNAKEMAKE_BAD_CONFIGS])
def test_bad_config_stops_before_any_job(tmp_path, case_id, mutation, key):
    """The user's config/config.yaml is bad: Snakemake refuses it, naming the key, runs nothing."""
    workdir = copy_workflow(tmp_path)
    with open(workdir / "config" / "config.yaml", "w") as handle:
        yaml.safe_dump(bad_config(mutation), handle)
    result = run_snakemake(workdir, "--cores", "1")
    assert result.returncode != 0
    output = result.stdout + result.stderr
    assert f"'{key}" in output, output[-2000:]
    assert not (workdir / "results").exists()


def test_quick_run_produces_every_target(quick_run):
    for relative in EXPECTED_OUTPUTS:
        assert (quick_run / relative).stat().st_size > 0, relative
    samples = sorted((quick_run / f"{QUICK_RESULTS}/debye2020/overlapping_disks/phi0.3").glob("sample*.nc"))
    assert len(samples) == 8
    for path in (quick_run / QUICK_RESULTS).rglob("*.nc"):  # debye3d's too, once made
        ds = read_dataset(path)
        assert all(key in ds.attrs for key in PROVENANCE_ATTRS)
        for name in ds.variables:
            assert {"units", "long_name"} <= set(ds[name].attrs), (path, name)


def test_quick_media_converged_and_recorded(quick_run):
    """Every constructed medium records Delta S2 <= tolerance, and the describe step agrees."""
    media = quick_config(quick_run)["debye2020"]["media"]
    for phi2 in media["phi2"]:
        s2 = read_dataset(quick_run / f"{QUICK_RESULTS}/debye2020/descriptors/media_phi{phi2:g}_S2.nc")
        for k in range(media["n_samples"]):
            sample = read_dataset(quick_run / f"{QUICK_RESULTS}/debye2020/media/phi{phi2:g}/sample{k}.nc")
            assert sample["phase"].dtype == np.uint8
            assert sample["phase"].values.sum() == round(phi2 * media["L"] ** 2)
            assert 0 < sample.attrs["delta_S2"] <= media["schedule"]["tolerance"]
            assert sample.attrs["delta_S2"] == pytest.approx(s2["delta_S2"].values[k], abs=1e-12)
    numbers = pd.read_csv(quick_run / f"{QUICK_RESULTS}/debye2020/tables/numbers.csv")
    construction = numbers[numbers["quantity"].str.startswith("mean_abs_S2_discrepancy")
                           | numbers["quantity"].isin(["L_w", "R2_over_R"])]
    assert set(construction["phi2"]) == set(media["phi2"]) and len(construction) == 4 * len(media["phi2"])


def test_quick_comparison_table(quick_run):
    """Table-comparison test: estimators on overlapping disks against the exact Eqs. (32)-(33),
    (38) and (20) within 3 SEM (+ stated margins), and <R^2>/<R> against the quoted 0.94 +- 0.04."""
    table = pd.read_csv(quick_run / f"{QUICK_RESULTS}/debye2020/comparison.csv")
    assert tuple(table.columns) == COLUMNS
    # quality bounds (Delta S2) pass below the published value; every other row is two-sided
    upper = table["key"].str.endswith(UPPER_BOUND_NOTE)
    assert set(table.loc[upper, "quantity"]) == {"mean_abs_S2_discrepancy_min", "mean_abs_S2_discrepancy_max"}
    assert (table["passed"] == (judged_deviation(table) <= table["tolerance"])).all()
    assert (table["tolerance"] >= 3 * table["ours_sem"]).all()
    s2 = table[table["quantity"].str.startswith("S2_void_overlapping_disks")]
    r_over_R = s2["key"].str.removeprefix("r/R=").astype(float)
    assert len(s2) >= 20 and r_over_R.max() <= 4.0 and r_over_R.min() == 0.0
    lineal = table[table["quantity"].str.startswith("L_void_overlapping_disks")]
    assert len(lineal) == 9
    assert table["quantity"].str.startswith("mean_chord_void_overlapping_disks").sum() == 1
    ratio = table[table["quantity"] == "R2_over_R_mean"]
    assert len(ratio) == 1 and ratio["tolerance"].iloc[0] >= 3 * 0.04
    covered = pd.concat([s2, lineal, ratio,
                         table[table["quantity"].str.startswith("mean_chord_void_overlapping_disks")]])
    assert covered["passed"].all(), covered[~covered["passed"]]  # other rows: test_workflow_debye2020


def test_changed_parameter_reruns_only_what_it_affects(quick_run, tmp_path):
    override = tmp_path / "override.yaml"
    override.write_text("comparison:\n  k_sigma: 2.5\n")
    result = run_snakemake(quick_run, "-n", "--configfile", "config/quick.yaml", str(override))
    assert result.returncode == 0, result.stderr[-3000:]
    assert "debye2020_comparison" in result.stdout
    for untouched in ("debye2020_overlapping_disks_image", "debye2020_overlapping_disks_s2",
                      "debye2020_overlapping_disks_figure"):
        assert f"rule {untouched}:" not in result.stdout
    nothing = run_snakemake(quick_run, "-n", *QUICK)
    assert "Nothing to be done" in nothing.stdout + nothing.stderr


#: the papers the killed 1-core run remakes: debye2020, where the kill lands, and sphere2019,
#: whose descriptor jobs are the only ones that take 2 threads (so the only outputs a core count
#: could change). mrj2016's jobs take 1 thread each, and its kill/resume has its own tests
#: (test_workflow_mrj_jammed.py, test_checkpoint*.py); leaving it out halves the test's time.
RESUMED_PAPERS = ("debye2020", "sphere2019")


def test_killed_one_core_run_leaves_no_partial_output_and_resumes_to_identical_data(quick_run, tmp_path):
    """Same config, 1 core instead of the fixture's 2, another folder, killed mid-run (SIGKILL,
    no clean-up) and finished by a second 1-core run: no output path ever holds a partial file,
    and every data variable of RESUMED_PAPERS' netCDF and CSV outputs (the run's targets: data and
    tables, not figures or run times, 78 jobs of 102) equals the uninterrupted 2-core run's (one
    test, so CI runs part of the quick DAG a second time only once)."""
    workdir = copy_workflow(tmp_path)
    targets = ([str(path.relative_to(quick_run)) for path in netcdf_files(quick_run, RESUMED_PAPERS)]
               + [str(path) for path in _result_tables(quick_run, RESUMED_PAPERS)])
    env = dict(os.environ)
    env.pop("NUMBA_CACHE_DIR", None)
    proc = subprocess.Popen(snakemake_command("--cores", "1", *QUICK, "--", *targets), cwd=workdir,
                            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    sample_dir = workdir / f"{QUICK_RESULTS}/debye2020/overlapping_disks/phi0.3"
    deadline = time.time() + 300
    while time.time() < deadline and len(list(sample_dir.glob("sample*.nc"))) < 2:
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)  # snakemake and its running job, no clean-up
    proc.wait()
    finished = list(sample_dir.glob("sample*.nc"))
    assert 2 <= len(finished) < 8, "the kill should land mid-run"
    for path in netcdf_files(workdir):
        read_dataset(path)  # every file at an output path is complete
    assert run_snakemake(workdir, "--unlock").returncode == 0
    result = run_snakemake(workdir, "--cores", "1", *QUICK, "--", *targets)
    assert result.returncode == 0, result.stderr[-3000:]
    assert_same_data(quick_run, workdir, RESUMED_PAPERS)
