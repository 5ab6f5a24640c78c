"""The record of a paper-config run: the small final outputs of one paper copied into a
committed folder with their provenance, a status table generated from the records, and the
checks that keep a record honest.

Layout (rules ``{paper}_record`` and ``record``, workflow/rules/record.smk)::

    record/{paper}/comparison.csv          every published value against ours
    record/{paper}/comparison_notes.csv    the error budget of each row, the reason of each failure
    record/{paper}/tables/*.csv            the paper's tables (and validation/*.csv, packings.csv:
                                           every CSV target of the paper, paths as under results/{paper}/)
    record/{paper}/figures/*.png           the paper's figures (the PDFs stay in results/)
    record/{paper}/runtimes.csv            per rule: jobs, wall and CPU time, peak memory
                                           (Snakemake's benchmark files of the jobs)
    record/{paper}/run.json                provenance (:func:`run_info`)
    record/README.md                       the status table of every recorded paper (:func:`status_table`)

Only a run with the paper's own configuration (its config section, ``seed`` and
``comparison`` equal to config/config.yaml) is recorded under ``record/``; any other
configuration writes the same folder under ``results/record/``, so a quick or extended run can
never overwrite the committed record.

``run.json`` holds: the paper, the date (UTC), the git commit and the files that differed from
it outside ``record/`` and ``results/`` (none for a clean checkout), the SHA-256 of the paper's
configuration (canonical JSON of its section, ``seed`` and ``comparison``) and that
configuration itself, the installed package versions, the machine (platform, CPU model, logical
CPUs, memory), the comparison summary (rows, passing rows), and the jobs' wall and CPU time
summed over the benchmark files present (the wall time summed over jobs, not the elapsed time of
the run: jobs run in parallel). A job that ran before its rule had a benchmark has no file; the
number of files is recorded as ``jobs_with_benchmark``.

:func:`check_record` lists what is wrong with a record folder: missing files or provenance
fields, a pass count in ``run.json`` that disagrees with ``comparison.csv``, a comparison without
a row for a published value of the paper's reference tables (:data:`PUBLISHED_VALUES`), notes
that do not match the comparison row by row.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import json
import os
import platform
import shutil
import subprocess
from importlib import metadata
from pathlib import Path
from typing import Iterable, Mapping

import numpy as np
import pandas as pd

from randmedia import blas_kernels
from randmedia.compare import NOTE_COLUMNS
from randmedia.io import atomic_output, write_csv
from randmedia.report import benchmark_summary

__all__ = ["PAPERS", "PUBLISHED_VALUES", "STUDIES", "RUN_FIELDS", "check_record", "comparison_summary", "config_sha256",
           "paper_config", "published_values", "run_info", "status_table", "write_record", "write_status"]

#: the three papers the study reproduces (the default target ``all`` runs them)
PAPERS = ("debye2020", "mrj2016", "sphere2019")
#: what ``snakemake record`` records: the papers and the 3D study beyond them (docs/debye3d.md)
STUDIES = (*PAPERS, "debye3d")

#: per paper: reference file (under config/reference/) -> its columns holding published values
#: (the other columns are coordinates: r/D, kD, R, ...); every finite value must appear as the
#: ``published`` value of a row of the paper's comparison.csv
PUBLISHED_VALUES: dict[str, dict[str, tuple[str, ...]]] = {
    "debye2020": {"debye2020_quoted_numbers.csv": ("value",)},
    "mrj2016": {
        "mrj2016_quoted_numbers.csv": ("value",),
        "mrj2016_table2_equilibrium.csv": ("S2", "Fsv_over_s", "Fss_over_s2", "EV"),
        "mrj2016_table3_mrj.csv": ("S2", "Fsv_over_s", "Fss_over_s2", "EV"),
        "mrj2016_table4_spectral_equilibrium.csv": ("chiV_over_D3",),
        # Table V only when the run made packings of 10 000 spheres (mrj2016.mrj.mrj_large)
        "mrj2016_table5_spectral_mrj.csv": ("chiV_over_D3",),
    },
    "sphere2019": {"sphere2019_table1_exponents.csv": ("delta",)},
}



def published_values(paper: str, config: Mapping) -> dict[str, tuple[str, ...]]:
    """:data:`PUBLISHED_VALUES` of ``paper`` that a run with ``config`` (its paper_config)
    computes: mrj2016's Table V needs mrj_large packings."""
    values = dict(PUBLISHED_VALUES.get(paper, {}))
    if paper == "mrj2016" and not config.get("mrj2016", {}).get("mrj", {}).get("mrj_large", {}).get("n_samples"):
        values.pop("mrj2016_table5_spectral_mrj.csv")
    return values


#: the fields every run.json has
RUN_FIELDS = ("paper", "date_utc", "git_commit", "git_changes", "config_sha256", "config", "python",
              "packages", "machine", "comparison", "jobs_with_benchmark", "wall_seconds_summed",
              "cpu_seconds_summed", "files")

#: the top-level config keys that belong to every paper's configuration
SHARED_CONFIG_KEYS = ("seed", "comparison")


# --------------------------------------------------------------------------- provenance


def paper_config(config: Mapping, paper: str) -> dict:
    """The part of the (validated) Snakemake ``config`` that determines ``paper``'s results:
    its section and the shared keys (:data:`SHARED_CONFIG_KEYS`)."""
    return {key: config[key] for key in (paper, *SHARED_CONFIG_KEYS) if key in config}


def config_sha256(config: Mapping) -> str:
    """SHA-256 of ``config`` as canonical JSON (sorted keys, no whitespace)."""
    text = json.dumps(config, sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _git(repo: Path, *args: str) -> str | None:
    try:
        return subprocess.run(["git", "-C", str(repo), *args], capture_output=True, text=True,
                              check=True, timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return None


def git_commit_and_changes(repo: Path, ignore: Iterable[str] = ("record/", "results/")) -> tuple[str | None, list[str] | None]:
    """(HEAD commit, paths that differ from it -- modified, staged or untracked-not-ignored --
    outside the ``ignore`` folders) of the git checkout ``repo``; (None, None) outside one."""
    commit = _git(repo, "rev-parse", "HEAD")
    status = _git(repo, "status", "--porcelain", "--untracked-files=all")
    if commit is None or status is None:
        return None, None
    changes = sorted(line[3:] for line in status.splitlines()
                     if line[3:] and not any(line[3:].startswith(prefix) for prefix in ignore))
    return commit.strip(), changes


def installed_packages() -> dict[str, str]:
    """{distribution name (lower case): version} of every installed distribution."""
    packages = {}
    for distribution in metadata.distributions():
        name = distribution.metadata["Name"]
        if name:
            packages[name.lower()] = distribution.version
    return dict(sorted(packages.items()))


def machine() -> dict:
    """Platform, CPU model, logical CPUs (and the ones this process may use), memory, and the
    OpenBLAS kernels the jobs ran with (``OPENBLAS_CORETYPE``: randmedia.blas_kernels; None where
    OpenBLAS chose them by CPU)."""
    info = {"platform": platform.platform(), "machine": platform.machine(),
            "openblas_coretype": os.environ.get(blas_kernels.VARIABLE) or None,
            "logical_cpus": os.cpu_count(),
            "usable_cpus": len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None,
            "cpu_model": platform.processor() or None, "memory_gib": None}
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                info["cpu_model"] = line.split(":", 1)[1].strip()
                break
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal:"):
                info["memory_gib"] = round(int(line.split()[1]) / 2**20, 1)
                break
    except OSError:
        pass
    return info


def comparison_summary(comparison: pd.DataFrame) -> dict:
    """{"rows", "passed", "failed"} of a comparison table (column ``passed``)."""
    passed = _passed(comparison)
    return {"rows": int(len(comparison)), "passed": int(passed.sum()), "failed": int((~passed).sum())}


def _passed(comparison: pd.DataFrame) -> np.ndarray:
    return comparison["passed"].map(lambda v: str(v).strip().lower() in ("true", "1", "yes")).to_numpy(bool)


def run_info(paper: str, config: Mapping, repo: Path, comparison: pd.DataFrame,
             benchmarks: pd.DataFrame, files: Iterable[str], date: _dt.datetime | None = None) -> dict:
    """The provenance ``run.json`` of ``paper``'s record (module docstring).

    Parameters
    ----------
    paper : the paper's name (debye2020, mrj2016, sphere2019).
    config : the validated Snakemake config of the run.
    repo : the repository (a git checkout, or a copy without git: commit and changes are null).
    comparison : the paper's comparison.csv.
    benchmarks : the merged benchmark files of the paper's jobs (results/{paper}/benchmarks.csv).
    files : the record's files, relative to its folder.
    date : the record's date (default: now, UTC).
    """
    commit, changes = git_commit_and_changes(Path(repo))
    section = paper_config(config, paper)
    numeric = {column: pd.to_numeric(benchmarks[column], errors="coerce") if column in benchmarks
               else pd.Series(dtype=float) for column in ("s", "cpu_time")}
    date = date or _dt.datetime.now(_dt.timezone.utc)
    return {
        "paper": paper,
        "date_utc": date.strftime("%Y-%m-%dT%H:%M:%SZ"),
        "git_commit": commit,
        "git_changes": changes,
        "config_sha256": config_sha256(section),
        "config": section,
        "python": platform.python_version(),
        "packages": installed_packages(),
        "machine": machine(),
        "comparison": comparison_summary(comparison),
        "jobs_with_benchmark": int(len(benchmarks)),
        "wall_seconds_summed": round(float(numeric["s"].sum()), 1),
        "cpu_seconds_summed": round(float(numeric["cpu_time"].sum()), 1),
        "files": sorted(files),
    }


# --------------------------------------------------------------------------- writing


def write_record(folder, sources: Mapping[str, str | os.PathLike], benchmarks: pd.DataFrame,
                 info_for_files) -> Path:
    """Make the record folder ``folder``: copy ``sources`` ({path in the record: source file}),
    write ``runtimes.csv`` from ``benchmarks`` and ``run.json`` = ``info_for_files(files)``.

    The folder is assembled beside ``folder`` and renamed onto it at the end, so an
    interrupted job leaves the previous record (or none) in place, never half of one.

    Parameters
    ----------
    folder : str or os.PathLike
        The record folder to (re)create.
    sources : Mapping[str, str or os.PathLike]
        Path in the record -> source file to copy.
    benchmarks : pandas.DataFrame
        Snakemake benchmarks of the jobs (one row per job), summarized into runtimes.csv.
    info_for_files : callable
        list of file names in the record -> the dict written as run.json.

    Returns
    -------
    pathlib.Path
        ``folder``.
    """
    folder = Path(folder)
    staging = folder.with_name(f".{folder.name}.incomplete")
    shutil.rmtree(staging, ignore_errors=True)
    staging.mkdir(parents=True)
    for name, source in sources.items():
        destination = staging / name
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, destination)
    write_csv(benchmark_summary(benchmarks), staging / "runtimes.csv")
    files = [*sources, "runtimes.csv", "run.json"]
    (staging / "run.json").write_text(json.dumps(info_for_files(files), indent=1) + "\n")
    if folder.exists():
        old = folder.with_name(f".{folder.name}.previous")
        shutil.rmtree(old, ignore_errors=True)
        folder.rename(old)
        staging.rename(folder)
        shutil.rmtree(old)
    else:
        staging.rename(folder)
    return folder


def status_table(root) -> pd.DataFrame:
    """One row per record folder ``root/{paper}/`` with a run.json: paper, comparison rows,
    passing rows, pass percentage, date, commit, job time summed (wall, CPU hours)."""
    rows = []
    for run_json in sorted(Path(root).glob("*/run.json")):
        info = json.loads(run_json.read_text())
        summary = info["comparison"]
        rows.append({"paper": info["paper"], "comparison_rows": summary["rows"], "passed": summary["passed"],
                     "passed_percent": round(100 * summary["passed"] / max(summary["rows"], 1), 1),
                     "date_utc": info["date_utc"], "git_commit": (info["git_commit"] or "")[:10],
                     "wall_hours_summed": round(info["wall_seconds_summed"] / 3600, 2),
                     "cpu_hours_summed": round(info["cpu_seconds_summed"] / 3600, 2)})
    return pd.DataFrame(rows, columns=["paper", "comparison_rows", "passed", "passed_percent", "date_utc",
                                       "git_commit", "wall_hours_summed", "cpu_hours_summed"])


def write_status(root) -> Path:
    """``root/README.md``: the status table of the records under ``root`` (:func:`status_table`)
    with a pointer to each paper's comparison."""
    table = status_table(root)
    lines = ["# Record of the last paper-config run", "",
             "Generated by `snakemake record` (workflow/rules/record.smk) from each `{paper}/run.json`; "
             "do not edit. Each paper's folder holds its comparison.csv (every published value against "
             "ours), comparison_notes.csv (the error budget of each row and the reason of each failure), "
             "tables, figures, runtimes.csv and run.json (commit, configuration hash, package versions, "
             "machine).", "",
             "| paper | comparison rows | pass | pass % | date (UTC) | commit | job wall h (summed) | job CPU h (summed) |",
             "|---|---:|---:|---:|---|---|---:|---:|"]
    for row in table.itertuples(index=False):
        lines.append(f"| [{row.paper}]({row.paper}/comparison.csv) | {row.comparison_rows} | {row.passed} | "
                     f"{row.passed_percent} | {row.date_utc} | {row.git_commit} | {row.wall_hours_summed} | "
                     f"{row.cpu_hours_summed} |")
    path = Path(root) / "README.md"
    with atomic_output(path) as tmp:
        tmp.write_text("\n".join(lines) + "\n")
    return path


# --------------------------------------------------------------------------- checking


def check_record(folder, reference_dir, require_commit: bool = True) -> list[str]:
    """What is wrong with the record folder ``folder`` (an empty list if nothing): run.json
    fields, the files it lists, its pass count against comparison.csv, a row for every
    published value (:data:`PUBLISHED_VALUES`, files in ``reference_dir``), notes that match
    the comparison row by row with a reason for every failing row. ``require_commit``: the
    record must name a git commit and no changed files (a committed record).

    Parameters
    ----------
    folder : str or os.PathLike
        The record folder (its name is the paper).
    reference_dir : str or os.PathLike
        Folder of the published reference tables.
    require_commit : bool, optional
        Require a git commit and a clean checkout in run.json (default True).

    Returns
    -------
    list of str
        One message per problem found.
    """
    folder = Path(folder)
    problems: list[str] = []
    run_json = folder / "run.json"
    if not run_json.exists():
        return [f"{run_json}: missing"]
    info = json.loads(run_json.read_text())
    problems += [f"run.json: field {field!r} missing" for field in RUN_FIELDS if field not in info]
    if problems:
        return problems
    paper = info["paper"]
    if paper != folder.name:
        problems.append(f"run.json: paper {paper!r} but folder {folder.name!r}")
    for name in ("comparison.csv", "comparison_notes.csv", "runtimes.csv", "run.json"):
        if name not in info["files"]:
            problems.append(f"run.json: files do not list {name}")
    problems += [f"{name}: listed in run.json but missing" for name in info["files"] if not (folder / name).exists()]
    if require_commit:
        if not (isinstance(info["git_commit"], str) and len(info["git_commit"]) == 40):
            problems.append(f"run.json: git_commit {info['git_commit']!r} is not a commit hash")
        if info["git_changes"]:
            problems.append(f"run.json: made from a checkout with changed files {info['git_changes'][:5]}")
    if config_sha256(info["config"]) != info["config_sha256"]:
        problems.append("run.json: config_sha256 is not the hash of config")
    for key in ("python", "packages", "machine", "date_utc"):
        if not info[key]:
            problems.append(f"run.json: {key} empty")
    if not (folder / "comparison.csv").exists():
        return problems
    comparison = pd.read_csv(folder / "comparison.csv")
    if comparison_summary(comparison) != info["comparison"]:
        problems.append(f"run.json: comparison {info['comparison']} but comparison.csv has "
                        f"{comparison_summary(comparison)}")
    published = comparison["published"].to_numpy(float)
    for name, columns in published_values(paper, info["config"]).items():
        reference = pd.read_csv(Path(reference_dir) / name)
        for column in columns:
            for value in pd.to_numeric(reference[column], errors="coerce").dropna():
                if np.isfinite(value) and not np.isclose(published, value, rtol=1e-9, atol=0).any():
                    problems.append(f"comparison.csv: no row for the published value {value:g} "
                                    f"({name}, column {column})")
    notes_path = folder / "comparison_notes.csv"
    if notes_path.exists():
        notes = pd.read_csv(notes_path)
        if tuple(notes.columns) != NOTE_COLUMNS:
            problems.append(f"comparison_notes.csv: columns {list(notes.columns)}, expected {list(NOTE_COLUMNS)}")
        elif list(zip(notes["quantity"], notes["key"].astype(str))) != \
                list(zip(comparison["quantity"], comparison["key"].astype(str))):
            problems.append("comparison_notes.csv: rows differ from comparison.csv (quantity, key)")
        else:
            reasons = notes["reason"].astype(object).fillna("").astype(str).to_numpy()
            failed = ~_passed(comparison)
            if (reasons[failed] == "").any():
                problems.append(f"comparison_notes.csv: {(reasons[failed] == '').sum()} failing rows without a reason")
    return problems
