"""Shared fixtures: the repository, workflow copies in temporary folders, quick runs."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"
WORKFLOW_PARTS = ("Snakefile", "workflow", "config", "profiles", "src")


def quick_config(workdir: Path = REPO) -> dict:
    """The quick config as Snakemake sees it: config/quick.yaml merged over config/config.yaml
    (before schema defaults are filled in)."""
    from randmedia.config import load_config

    return load_config(workdir / "config" / "config.yaml", workdir / "config" / "quick.yaml")


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
