"""Style gates: ruff over the package, rule scripts, tests and benchmarks (configuration in
pyproject.toml, with Snakemake's injected `snakemake` declared), and Snakemake's own linter
over the workflow, which must report nothing but the per-rule conda/container lint (the
environment is the virtualenv built from requirements.lock, see the README)."""

from __future__ import annotations

import re
import subprocess
import sys

from conftest import REPO, copy_workflow, run_snakemake

#: the only lint accepted: software comes from requirements.lock, not per-rule environments
ACCEPTED_LINTS = {"Specify a conda environment or container for each rule."}


def test_ruff_is_clean():
    result = subprocess.run([sys.executable, "-m", "ruff", "check", "src", "workflow/scripts", "tests",
                             "benchmarks"], cwd=REPO, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]


def test_snakemake_lint_reports_only_the_environment_lint(tmp_path):
    result = run_snakemake(copy_workflow(tmp_path), "--lint")
    output = result.stdout + result.stderr
    lints = set(re.findall(r"^\s+\* (.+?):$", output, re.MULTILINE))
    assert lints, output[-2000:]  # the linter ran and reported the accepted lint
    assert lints <= ACCEPTED_LINTS, lints - ACCEPTED_LINTS
