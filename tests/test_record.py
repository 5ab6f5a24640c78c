"""The record of a paper-config run (randmedia.record, workflow/rules/record.smk): its files and
provenance, the checks that catch an inconsistent record, the folder a configuration writes to,
a record made from the quick run, and the committed record itself."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pandas as pd
import pytest

from conftest import QUICK_RESULTS, REPO, run_snakemake
from randmedia import record
from randmedia.blas_kernels import pin_blas_kernels
from randmedia.compare import NOTE_COLUMNS

PAPERS = record.PAPERS
RECORDED = record.STUDIES


TABLE1 = REPO / "config" / "reference" / "sphere2019_table1_exponents.csv"


def _tiny_run(tmp_path: Path, drop_published: float | None = None, reasons: bool = True) -> tuple[Path, dict]:
    """A sphere2019 record: one comparison row per published delta of Table I (the first passes,
    the others fail with a reason unless ``reasons`` is false), without the row of
    ``drop_published`` if given."""
    published = [v for v in pd.read_csv(TABLE1)["delta"].dropna().unique() if v != drop_published]
    n = len(published)
    passed = [True] + [False] * (n - 1)
    comparison = pd.DataFrame({"quantity": [f"delta_{i}" for i in range(n)], "key": "R=15",
                               "published": published, "ours": published, "ours_sem": 0.01,
                               "tolerance": 0.05, "passed": passed})
    notes = pd.DataFrame({"quantity": comparison["quantity"], "key": comparison["key"], "published_err": 0.0,
                          "rounding": 0.005, "systematic": 0.0, "deviation_in_tolerances": 0.0,
                          "reason": ["" if ok or not reasons else "ours is biased" for ok in passed]}
                         )[list(NOTE_COLUMNS)]
    sources = tmp_path / "results"
    sources.mkdir()
    comparison.to_csv(sources / "comparison.csv", index=False)
    notes.to_csv(sources / "comparison_notes.csv", index=False)
    (sources / "fig01.png").write_bytes(b"\x89PNG fake")
    benchmarks = pd.DataFrame({"rule": ["fluid", "fluid", "fit"], "wildcards": ["k=0", "k=1", ""],
                               "s": [10.0, 12.0, 1.5], "cpu_time": [9.0, 11.0, 1.0], "max_rss": [100, 120, 50],
                               "file": ["a", "b", "c"]})
    config = {"seed": 1, "comparison": {"k_sigma": 3.0}, "sphere2019": {"R": [5, 15]}, "debye2020": {"L": 501}}
    folder = record.write_record(
        tmp_path / "record" / "sphere2019",
        {"comparison.csv": sources / "comparison.csv", "comparison_notes.csv": sources / "comparison_notes.csv",
         "figures/fig01.png": sources / "fig01.png"},
        benchmarks,
        lambda files: record.run_info("sphere2019", config, tmp_path, comparison, benchmarks, files))
    return folder, json.loads((folder / "run.json").read_text())


def test_record_files_and_provenance(tmp_path):
    folder, info = _tiny_run(tmp_path)
    assert sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file()) == \
        ["comparison.csv", "comparison_notes.csv", "figures/fig01.png", "run.json", "runtimes.csv"]
    assert set(info) == set(record.RUN_FIELDS)
    assert info["files"] == sorted(info["files"]) and "run.json" in info["files"]
    # only the paper's own part of the config, and its hash
    assert set(info["config"]) == {"seed", "comparison", "sphere2019"}
    assert info["config_sha256"] == record.config_sha256(info["config"])
    n = pd.read_csv(TABLE1)["delta"].dropna().nunique()
    assert info["comparison"] == {"rows": n, "passed": 1, "failed": n - 1}
    assert info["jobs_with_benchmark"] == 3
    assert info["wall_seconds_summed"] == 23.5 and info["cpu_seconds_summed"] == 21.0
    assert "numpy" in info["packages"] and info["machine"]["logical_cpus"] >= 1
    # tmp_path is no git checkout: no commit, and a committed record needs one
    assert info["git_commit"] is None and info["git_changes"] is None
    assert record.check_record(folder, REPO / "config" / "reference", require_commit=False) == []
    assert any("git_commit" in p for p in record.check_record(folder, REPO / "config" / "reference"))
    runtimes = pd.read_csv(folder / "runtimes.csv")
    assert runtimes.set_index("rule").loc["fluid", "jobs"] == 2
    assert runtimes.set_index("rule").loc["fluid", "wall_s_total"] == 22.0


def test_record_replaces_previous_record_whole(tmp_path):
    folder, _ = _tiny_run(tmp_path)
    (folder / "stale.csv").write_text("x\n1\n")
    shutil.rmtree(tmp_path / "results")
    folder, _ = _tiny_run(tmp_path)  # the same record made again
    assert not (folder / "stale.csv").exists()
    assert not list(folder.parent.glob(".*"))  # no staging or previous copy left behind


@pytest.mark.parametrize("change, expected", [
    ("pass_count", "run.json: comparison"),
    ("missing_value", "no row for the published value 1.3"),
    ("no_reason", "failing rows without a reason"),
    ("missing_file", "listed in run.json but missing"),
    ("config_hash", "config_sha256"),
])
def test_check_record_finds_inconsistencies(tmp_path, change, expected):
    reference = REPO / "config" / "reference"
    if change == "missing_value":  # Table I's printed delta = 1 replaced by another number
        folder, _ = _tiny_run(tmp_path, drop_published=1.3)
    elif change == "no_reason":
        folder, _ = _tiny_run(tmp_path, reasons=False)
    else:
        folder, info = _tiny_run(tmp_path)
        if change == "pass_count":
            info["comparison"]["passed"] = 2
        elif change == "config_hash":
            info["config"]["seed"] = 2
        (folder / "run.json").write_text(json.dumps(info))
        if change == "missing_file":
            (folder / "figures" / "fig01.png").unlink()
    problems = record.check_record(folder, reference, require_commit=False)
    assert any(expected in problem for problem in problems), problems


def test_status_table_counts_each_paper(tmp_path):
    folder, _ = _tiny_run(tmp_path)
    n = pd.read_csv(TABLE1)["delta"].dropna().nunique()
    table = record.status_table(folder.parent)
    assert table.to_dict("records")[0] | {"date_utc": None} == {
        "paper": "sphere2019", "comparison_rows": n, "passed": 1, "passed_percent": round(100 / n, 1),
        "date_utc": None,
        "git_commit": "", "wall_hours_summed": round(23.5 / 3600, 2), "cpu_hours_summed": round(21 / 3600, 2)}
    text = record.write_status(folder.parent).read_text()
    assert f"| [sphere2019](sphere2019/comparison.csv) | {n} | 1 | {round(100 / n, 1)} |" in text


def test_table5_is_required_only_with_large_packings():
    with_large = {"mrj2016": {"mrj": {"mrj_large": {"n_samples": 14}}}}
    without = {"mrj2016": {"mrj": {"mrj_large": {"n_samples": 0}}}}
    assert "mrj2016_table5_spectral_mrj.csv" in record.published_values("mrj2016", with_large)
    assert "mrj2016_table5_spectral_mrj.csv" not in record.published_values("mrj2016", without)


def test_only_the_paper_config_writes_the_committed_record(parsed_workflow):
    _, probes = parsed_workflow
    for paper in RECORDED:
        assert probes["paper"]["rules"][f"{paper}_record"]["output"] == [f"record/{paper}"]
        assert probes["quick"]["rules"][f"{paper}_record"]["output"] == [f"{QUICK_RESULTS}/record/{paper}"]
    assert probes["paper"]["rules"]["record"]["output"] == ["record/README.md"]
    assert probes["quick"]["rules"]["record"]["output"] == [f"{QUICK_RESULTS}/record/README.md"]
    # `snakemake record` records the 3D study too; the default target `all` does not run it
    assert sorted(probes["paper"]["rules"]["record"]["input"]) == sorted(f"record/{paper}" for paper in RECORDED)
    assert not any("/debye3d/" in path for path in probes["paper"]["rules"]["all"]["input"])


@pytest.fixture(scope="module")
def quick_record(quick_run) -> Path:
    result = run_snakemake(quick_run, "record", "--cores", "2", "--configfile", "config/quick.yaml")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-5000:]
    return quick_run / QUICK_RESULTS / "record"


@pytest.mark.parametrize("paper", RECORDED)
def test_quick_run_record_is_consistent(quick_record, quick_run, paper):
    folder = quick_record / paper
    assert record.check_record(folder, quick_run / "config" / "reference", require_commit=False) == []
    info = json.loads((folder / "run.json").read_text())
    figures = sorted(p.name for p in (quick_run / QUICK_RESULTS / paper / "figures").glob("*.png"))
    assert sorted(p.name for p in (folder / "figures").glob("*.png")) == figures
    # debye3d has no tables but its comparison
    assert (folder / "tables").is_dir() == (paper != "debye3d") and info["jobs_with_benchmark"] > 0
    assert info["cpu_seconds_summed"] > 0
    # the jobs ran with the OpenBLAS kernels the workflow pins (common.smk)
    assert info["machine"]["openblas_coretype"] == pin_blas_kernels(dict(os.environ))
    status = record.status_table(quick_record).set_index("paper")
    assert status.loc[paper, "passed"] == info["comparison"]["passed"]
    assert f"[{paper}]({paper}/comparison.csv)" in (quick_record / "README.md").read_text()


COMMITTED = sorted(p.parent.name for p in (REPO / "record").glob("*/run.json"))


@pytest.mark.parametrize("paper", COMMITTED)
def test_committed_record_is_consistent(paper):
    """The committed record (made from a paper-config run): provenance complete, counts and
    rows consistent, the status table regenerated from it unchanged."""
    assert record.check_record(REPO / "record" / paper, REPO / "config" / "reference") == []
    status = (REPO / "record" / "README.md").read_text()
    info = json.loads((REPO / "record" / paper / "run.json").read_text())
    summary = info["comparison"]
    assert f"| [{paper}]({paper}/comparison.csv) | {summary['rows']} | {summary['passed']} |" in status


def test_committed_record_is_small():
    """The record's tables and figures stay small; the kept MRJ packings (record/packings/mrj2016/,
    ~0.3 MB per N = 2000 packing) have their own budget: the paper config's 40 of them."""
    files = [p for p in (REPO / "record").rglob("*") if p.is_file()] if (REPO / "record").exists() else []
    packings = REPO / "record" / "packings" / "mrj2016"
    kept = sum(p.stat().st_size for p in files if packings in p.parents)
    assert sum(p.stat().st_size for p in files) - kept < 20e6
    assert kept < 40e6
