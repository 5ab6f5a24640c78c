"""Shared fixtures: the repository, workflow copies in temporary folders, quick runs."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]

# numba caches of kernels compiled in this process: one folder per package content, as in the
# workflow (randmedia.workflow_sources.numba_cache_dir), never a stale callee after an edit
NUMBA_CACHE_SET_HERE = "NUMBA_CACHE_DIR" not in os.environ
if NUMBA_CACHE_SET_HERE:
    from randmedia.workflow_sources import numba_cache_dir

    os.environ["NUMBA_CACHE_DIR"] = str(numba_cache_dir(REPO / "src" / "randmedia", REPO / ".cache" / "numba"))
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"
WORKFLOW_PARTS = ("Snakefile", "workflow", "config", "profiles", "src")


def killed_after(calls: int, step):
    """``step``, but raising KeyboardInterrupt (a kill) on its call number ``calls`` + 1."""
    done = {"n": 0}

    def dying_step(*args, **kwargs):
        done["n"] += 1
        if done["n"] > calls:
            raise KeyboardInterrupt("killed")
        return step(*args, **kwargs)

    return dying_step


def quick_config(workdir: Path = REPO) -> dict:
    """The quick config as Snakemake sees it: config/quick.yaml merged over config/config.yaml
    (before schema defaults are filled in)."""
    from randmedia.config import load_config

    return load_config(workdir / "config" / "config.yaml", workdir / "config" / "quick.yaml")


#: each configuration's results folder (config key results_dir): a quick run never writes the
#: paper config's results/
RESULTS_DIR = {"paper": "results", "quick": quick_config()["results_dir"]}
QUICK_RESULTS = RESULTS_DIR["quick"]


def assert_comparison_notes(table, notes, k_sigma: float) -> None:
    """comparison_notes.csv against its comparison.csv: the notes columns, one row per comparison
    row with the same quantity and key in the same order, a reason for every failing row and
    none for a passing one, and a budget that adds up to the tolerance:
    k_sigma hypot(SEM, published_err) + rounding + systematic (a missing SEM counts as 0)."""
    import numpy as np

    from randmedia.compare import NOTE_COLUMNS

    assert tuple(notes.columns) == NOTE_COLUMNS
    assert len(notes) == len(table)
    assert list(notes["quantity"]) == list(table["quantity"])
    assert list(notes["key"]) == list(table["key"])
    passed = table["passed"].to_numpy(bool)
    reasons = notes["reason"].astype(object).fillna("")  # read back as NaN where empty
    assert (reasons[passed] == "").all(), notes[passed & (reasons != "")]
    assert (reasons[~passed] != "").all(), table[~passed & (reasons == "")]
    budget = (k_sigma * np.hypot(table["ours_sem"].fillna(0.0), notes["published_err"])
              + notes["rounding"] + notes["systematic"])
    np.testing.assert_allclose(budget, table["tolerance"], rtol=1e-12, atol=1e-15)


def kill_and_resume(script: str, stage_marker: str, stages: int, tmp_path: Path):
    """A construction killed (SIGKILL) and rerun, against one never interrupted.

    ``script`` is Python run as ``python -c script CHECKPOINT OUTPUT.npy``: it logs to stdout,
    checkpoints at every stage and saves its result to OUTPUT. The first run is killed once
    ``stages`` lines containing ``stage_marker`` were printed and the checkpoint exists; the
    rerun must resume from it, finish and remove it; a third run without a checkpoint gives
    the uninterrupted result. Returns (stdout of the resumed run, its result, the
    uninterrupted result)."""
    import numpy as np

    checkpoint, first, second = tmp_path / "c.npz", tmp_path / "a.npy", tmp_path / "b.npy"
    command = [sys.executable, "-c", script, str(checkpoint)]
    proc = subprocess.Popen(command + [str(first)], stdout=subprocess.PIPE, text=True)
    stages_seen = 0
    for line in proc.stdout:  # kill after a few checkpointed stages
        stages_seen += stage_marker in line
        if stages_seen >= stages and checkpoint.exists():
            break
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    assert checkpoint.exists() and not first.exists()
    resumed = subprocess.run(command + [str(first)], capture_output=True, text=True)
    assert resumed.returncode == 0, resumed.stderr[-2000:]
    assert "resumed from" in resumed.stdout
    assert not checkpoint.exists()  # removed on success
    subprocess.run([sys.executable, "-c", script, str(tmp_path / "none.npz"), str(second)],
                   check=True, capture_output=True)
    return resumed.stdout, np.load(first), np.load(second)


def copy_workflow(destination: Path) -> Path:
    """A runnable copy of the workflow (its own results/, .snakemake/, numba cache)."""
    destination.mkdir(parents=True, exist_ok=True)
    for part in WORKFLOW_PARTS:
        source = REPO / part
        if source.is_dir():
            shutil.copytree(source, destination / part,
                            ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
        else:
            shutil.copy2(source, destination / part)
    return destination


def snakemake_command(*args: str) -> list[str]:
    return [sys.executable, "-m", "snakemake", *args]


def run_snakemake(workdir: Path, *args: str, timeout: float = 1500) -> subprocess.CompletedProcess:
    """Run Snakemake in ``workdir`` (its default profile applies), capturing output. The
    timeout only stops a hung run: the whole quick DAG takes ~4 min on 2 idle cores, and
    over 10 min on a machine shared with paper-config runs."""
    env = dict(os.environ)
    env.pop("NUMBA_CACHE_DIR", None)  # each copy keeps its own cache (set by common.smk)
    return subprocess.run(snakemake_command(*args), cwd=workdir, env=env, capture_output=True,
                          text=True, timeout=timeout)


@pytest.fixture(scope="session")
def quick_run(tmp_path_factory) -> Path:
    """The whole DAG on config/quick.yaml with 2 cores; returns the working folder."""
    workdir = copy_workflow(tmp_path_factory.mktemp("quick_2cores"))
    result = run_snakemake(workdir, "--cores", "2", "--configfile", "config/quick.yaml")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-5000:]
    return workdir


PROBE = """
import json, sys
from pathlib import Path
from snakemake.api import SnakemakeApi
from snakemake.io import get_flag_value, is_flagged
from snakemake.settings.types import ConfigSettings, OutputSettings, ResourceSettings

workdir = Path(sys.argv[1])
with SnakemakeApi(OutputSettings()) as api:
    workflow = api.workflow(
        resource_settings=ResourceSettings(cores=1), snakefile=workdir / "Snakefile", workdir=workdir,
        config_settings=ConfigSettings(configfiles=[workdir / f for f in sys.argv[2:]]))._workflow
    rules = {}
    for rule in workflow.rules:
        code = rule.input.get("code")
        reported = []
        for f in rule.output:
            if is_flagged(f, "report"):
                flag = get_flag_value(f, "report")
                reported.append({"path": str(f), "category": flag.category, "subcategory": flag.subcategory,
                                 "caption": flag.caption.get_path_or_uri(secret_free=True) if flag.caption else None})
        rules[rule.name] = {
            "script": str(Path(str(rule.basedir)) / rule.script) if rule.script else None,
            "code": None if code is None or callable(code) else [str(f) for f in code],
            "input": [str(f) for f in rule.input if isinstance(f, str)],
            "output": [str(f) for f in rule.output],
            "log": [str(f) for f in rule.log],
            "benchmark": None if rule.benchmark is None else str(rule.benchmark),
            "report": reported,
        }
    report_text = workflow.report_text.get_path_or_uri(secret_free=True) if workflow.report_text else None
    print("PROBE" + json.dumps({"global_constraints": dict(workflow.modifier.wildcard_constraints),
                                "rules": rules, "report_text": report_text}))
"""


def probe_rules(workdir: Path, *configfiles: str) -> dict:
    """Every rule of the workflow in ``workdir`` as Snakemake parsed it: script, input
    ``code``, static inputs, output patterns (with their wildcard constraints), benchmark
    pattern, outputs marked for the report (category, subcategory, caption file); the global
    constraints and the report's description file."""
    env = dict(os.environ)
    env.pop("NUMBA_CACHE_DIR", None)
    result = subprocess.run([sys.executable, "-c", PROBE, str(workdir), *configfiles], cwd=workdir,
                            env=env, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-3000:]
    line = next(line for line in result.stdout.splitlines() if line.startswith("PROBE"))
    return json.loads(line.removeprefix("PROBE"))


@pytest.fixture(scope="session")
def parsed_workflow(tmp_path_factory) -> tuple[Path, dict]:
    """(workflow copy, {"paper": probe, "quick": probe}): the rules parsed once per session for
    the paper and the quick config (tests/test_reruns.py, tests/test_report.py)."""
    workdir = copy_workflow(tmp_path_factory.mktemp("probe"))
    return workdir, {name: probe_rules(workdir, *files)
                     for name, files in (("paper", ()), ("quick", ("config/quick.yaml",)))}
