"""Correct reruns: a rule's code inputs are its script's import closure, a job's params are the
config values it uses, and wildcard constraints sit on the rules that need them.

* unit tests of randmedia.workflow_sources (a synthetic package and real scripts);
* every script rule's input ``code`` against an independent closure (stdlib modulefinder);
* dry runs on a copy of the workflow whose whole quick DAG was marked complete with
  ``--touch`` (empty outputs, recorded metadata: seconds instead of the minutes of a real
  run): editing a module, or changing one config key, plans exactly the jobs that use it
  and their downstream jobs.
"""

from __future__ import annotations

import modulefinder
import os
import re
from pathlib import Path

import pytest

from conftest import REPO, RESULTS_DIR, copy_workflow, probe_rules, run_snakemake
from randmedia.workflow_sources import SourceError, script_sources

PACKAGE = REPO / "src" / "randmedia"
SCRIPTS = REPO / "workflow" / "scripts"
# the quick config with chunks of 4 samples, so that the chunked describe path (rule
# mrj2016_describe_chunk, overlapping spheres: 8 samples) is in the DAG too
CHUNKS = "mrj2016:\n  descriptors:\n    chunk_size: 4\n"
CONFIG = ("--configfile", "config/quick.yaml", "chunks.yaml")


def relative(paths, package=PACKAGE):
    return sorted(str(Path(p).relative_to(package)) for p in paths)


# --------------------------------------------------------------------------- the helper


def write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


@pytest.fixture
def package(tmp_path):
    """A small package ``randmedia`` with every import form the helper must follow."""
    root = tmp_path / "src" / "randmedia"
    write(root / "__init__.py", "")
    write(root / "io.py", "import os\n")
    write(root / "unused.py", "")
    write(root / "sub" / "__init__.py", "from randmedia.io import open_file\n")
    write(root / "sub" / "a.py", "from . import b\nfrom .b import f\nfrom .. import lazy_parent\n")
    write(root / "sub" / "b.py", "import numpy as np\ndef f():\n    from randmedia.sub import c\n")
    write(root / "sub" / "c.py", "from ..deep.inner import g\n")
    write(root / "deep" / "__init__.py", "")
    write(root / "deep" / "inner.py", "def g():\n    pass\n")
    write(root / "lazy_parent.py", "")
    write(root / "other.py", "import randmedia.sub.a as a\n")
    return root


def test_closure_follows_every_import_form(package, tmp_path):
    script = tmp_path / "script.py"
    write(script, "import sys\nfrom randmedia import other\n")
    assert relative(script_sources(script, package), package) == [
        "__init__.py", "deep/__init__.py", "deep/inner.py", "io.py", "lazy_parent.py", "other.py",
        "sub/__init__.py", "sub/a.py", "sub/b.py", "sub/c.py"]
    write(script, "from randmedia.sub.b import f\n")  # a function of a module: the module only
    assert relative(script_sources(script, package), package) == [
        "__init__.py", "deep/__init__.py", "deep/inner.py", "io.py", "sub/__init__.py", "sub/b.py",
        "sub/c.py"]
    write(script, "import randmedia\n")
    assert relative(script_sources(script, package), package) == ["__init__.py"]
    write(script, "import numpy\n")
    assert script_sources(script, package) == []


def test_closure_sees_edits(package, tmp_path):
    script = tmp_path / "script.py"
    write(script, "from randmedia import io\n")
    assert relative(script_sources(script, package), package) == ["__init__.py", "io.py"]
    write(package / "io.py", "import os\nfrom randmedia import unused\n")
    assert relative(script_sources(script, package), package) == ["__init__.py", "io.py", "unused.py"]


def test_missing_script_or_module_is_named(package, tmp_path):
    with pytest.raises(SourceError, match="no_script.py"):
        script_sources(tmp_path / "no_script.py", package)
    script = tmp_path / "script.py"
    write(script, "from randmedia.sub import a\n")
    write(package / "sub" / "c.py", "from randmedia.missing import g\n")
    with pytest.raises(SourceError) as error:
        script_sources(script, package)
    assert "randmedia.missing" in str(error.value) and "sub/c.py" in str(error.value)
    assert str(script) in str(error.value)
    write(script, "import randmedia.sub.nothing\n")
    with pytest.raises(SourceError, match="randmedia.sub.nothing"):
        script_sources(script, package)


@pytest.mark.parametrize("script, must, must_not", [
    ("mrj2016/jammed_packing.py",
     ["checkpoint.py", "periodic.py", "generate/packing_lp.py", "generate/__init__.py", "__init__.py",
      "generate/jammed.py", "describe/jamming.py", "jobs.py", "io.py", "seeding.py"],
     ["plot/style.py", "describe/spectral.py"]),
    ("mrj2016/describe_chunk.py",
     ["studies/mrj2016.py", "describe/averages.py", "describe/spectral.py", "describe/points.py",
      "describe/packings.py", "periodic.py", "fit/number_variance.py", "generate/spheres.py", "describe/__init__.py"],
     ["checkpoint.py", "generate/jammed.py"]),
    ("debye2020/media_sample.py",  # the construction bins with numerics, not the describe layer
     ["checkpoint.py", "generate/yeong_torquato.py", "numerics/radial.py", "theory/debye.py"],
     ["describe/two_phase.py", "describe/spectral.py", "generate/jammed.py"]),
    ("sphere2019/fluid.py", ["checkpoint.py", "generate/sphere_mc.py", "theory/sphere_caps.py"],
     ["describe/sphere_points.py"]),
])
def test_closure_of_workflow_scripts(script, must, must_not):
    found = relative(script_sources(SCRIPTS / script, PACKAGE))
    assert set(must) <= set(found), sorted(set(must) - set(found))
    assert not set(must_not) & set(found)
    assert found == sorted(found)


def test_closure_of_a_small_script_exactly():
    assert relative(script_sources(SCRIPTS / "sphere2019" / "comparison.py", PACKAGE)) == [
        "__init__.py", "compare/__init__.py", "compare/sphere2019.py", "io.py", "jobs.py"]


def modulefinder_closure(script: Path, package: Path = PACKAGE) -> list[str]:
    """Package modules of ``script`` found by the standard library's modulefinder (bytecode
    scan, another implementation than the ast walk): searches only ``package``'s parent, so
    third-party imports are left unresolved instead of scanned."""
    finder = modulefinder.ModuleFinder(path=[str(package.parent)])
    finder.run_script(str(script))
    name = package.name
    return sorted(str(Path(module.__file__).relative_to(package))
                  for key, module in finder.modules.items()
                  if (key == name or key.startswith(name + ".")) and module.__file__)


@pytest.mark.parametrize("script", sorted(str(p.relative_to(SCRIPTS)) for p in SCRIPTS.rglob("*.py")))
def test_closure_agrees_with_modulefinder(script):
    assert relative(script_sources(SCRIPTS / script, PACKAGE)) == modulefinder_closure(SCRIPTS / script)


# --------------------------------------------------------------------------- the rules

@pytest.fixture(scope="module")
def parsed(parsed_workflow):
    """(workflow copy, {"paper": probe, "quick": probe}) of every rule (conftest.probe_rules)."""
    return parsed_workflow


@pytest.mark.workflow
@pytest.mark.parametrize("config", ["paper", "quick"])
def test_every_script_rule_lists_its_import_closure(parsed, config):
    workdir, probes = parsed
    package = workdir / "src" / "randmedia"
    scripts = 0
    for name, rule in probes[config]["rules"].items():
        if rule["script"] is None:
            assert rule["code"] is None, name
            continue
        scripts += 1
        assert rule["code"] is not None, f"rule {name} has no static input `code`"
        expected = modulefinder_closure(Path(rule["script"]), package)
        assert relative(rule["code"], package) == expected, name
    assert scripts >= 50


@pytest.mark.workflow
@pytest.mark.parametrize("config", ["paper", "quick"])
def test_wildcard_constraints_are_on_the_rules(parsed, config):
    """Only k is constrained globally; every other wildcard of every rule output carries its
    rule's own constraint (no include-order dependence)."""
    rules = parsed[1][config]["rules"]
    assert parsed[1][config]["global_constraints"] == {"k": r"\d+"}
    for name, rule in rules.items():
        for pattern in rule["output"]:
            for wildcard in re.findall(r"\{([^{}]*)\}", pattern):
                assert "," in wildcard, (name, pattern)
    level_set = rules["debye2020_level_set"]["output"][0]
    assert "{system,media_phi0\\.1|" in level_set and "hard_disks_phi" in level_set
    for name in ("mrj2016_describe", "mrj2016_describe_chunk"):
        assert "{system,overlapping|fcc|bcc|equilibrium|mrj|mrj_large|mrj_md}" in rules[name]["output"][0]
    assert "{system,mrj|mrj_large|mrj_md}" in rules["mrj2016_jammed_packing"]["output"][0]


@pytest.mark.workflow
def test_each_config_writes_only_its_own_results_folder(parsed):
    """Every output, log and benchmark of the quick config lies under its results_dir
    (results/quick/), and none of the paper config's does: a quick run in a checkout holding
    paper-config results cannot replace (Snakemake deletes a job's outputs before it runs) or
    touch them. The paper config writes under results/ and the committed record/ only."""
    quick, paper = RESULTS_DIR["quick"], RESULTS_DIR["paper"]
    assert quick.startswith(f"{paper}/") and quick != paper
    counted = 0
    for config, own, allowed in (("quick", quick, (f"{quick}/",)),
                                 ("paper", paper, (f"{paper}/", "record/"))):
        for name, rule in parsed[1][config]["rules"].items():
            paths = [*rule["output"], *rule["log"], *([rule["benchmark"]] if rule["benchmark"] else [])]
            for path in paths:
                counted += 1
                assert path.startswith(allowed), (config, name, path)
                if config == "paper":
                    assert not path.startswith(f"{quick}/"), (name, path)
    assert counted > 300


@pytest.mark.workflow
def test_rule_without_code_or_with_missing_module_stops_the_workflow(tmp_path):
    workdir = copy_workflow(tmp_path / "nocode")
    rules = workdir / "workflow" / "rules" / "sphere2019.smk"
    text = rules.read_text()
    line = '        code=script_sources("../scripts/sphere2019/comparison.py"),\n'
    assert line in text
    rules.write_text(text.replace(line, ""))
    result = run_snakemake(workdir, "-n")
    assert result.returncode != 0
    assert "rule sphere2019_comparison -- no static input `code`" in result.stdout + result.stderr

    workdir = copy_workflow(tmp_path / "missing")
    script = workdir / "workflow" / "scripts" / "sphere2019" / "figure.py"
    script.write_text(script.read_text() + "from randmedia.no_such_module import x  # noqa\n")
    result = run_snakemake(workdir, "-n")
    assert result.returncode != 0
    output = result.stdout + result.stderr
    assert "randmedia.no_such_module" in output and "sphere2019/figure.py" in output


# --------------------------------------------------------------------------- dry runs

def parse_jobs(text: str) -> dict:
    """Jobs of a dry run's log: {(rule, outputs): {"input": [...], "reason": str, "wildcards": {}}}."""
    jobs, current = [], None
    for line in text.splitlines():
        start = re.match(r"^(?:local)?rule (\S+):$", line)
        if start:
            current = {"rule": start.group(1), "input": [], "output": [], "reason": "", "wildcards": {}}
            jobs.append(current)
            continue
        field = re.match(r"^    (\w+): (.*)$", line)
        if current is not None and field:
            key, value = field.groups()
            if key in ("input", "output"):
                current[key] = value.split(", ")
            elif key == "reason":
                current["reason"] = value
            elif key == "wildcards":
                current["wildcards"] = dict(item.split("=", 1) for item in value.split(", "))
        elif not line.startswith(" "):
            current = None
    keyed = {(job["rule"], tuple(job["output"])): job for job in jobs}
    assert len(keyed) == len(jobs), "two jobs with the same rule and outputs"
    return keyed


def descendants(dag: dict, seeds: set) -> set:
    """``seeds`` and every job downstream of them in ``dag`` (from parse_jobs)."""
    producer = {path: key for key, job in dag.items() for path in job["output"]}
    consumers = {key: set() for key in dag}
    for key, job in dag.items():
        for path in job["input"]:
            if path in producer:
                consumers[producer[path]].add(key)
    found, queue = set(seeds), list(seeds)
    while queue:
        for consumer in consumers[queue.pop()] - found:
            found.add(consumer)
            queue.append(consumer)
    return found


@pytest.fixture(scope="module")
def complete(tmp_path_factory):
    """A workflow copy on the quick config (chunks of 4) whose every output exists, is up to date
    and has Snakemake's metadata (params, input checksums): empty files marked done by
    ``--touch --forceall``. Returns (workdir, full DAG, rules)."""
    workdir = copy_workflow(tmp_path_factory.mktemp("complete"))
    (workdir / "chunks.yaml").write_text(CHUNKS)
    summary = run_snakemake(workdir, *CONFIG, "--detailed-summary")
    assert summary.returncode == 0, summary.stderr[-3000:]
    for row in summary.stdout.splitlines()[1:]:
        path = workdir / row.split("\t")[0]
        path.parent.mkdir(parents=True, exist_ok=True)
        path.touch()
    touched = run_snakemake(workdir, *CONFIG, "--touch", "--forceall", "--cores", "1")
    assert touched.returncode == 0, touched.stderr[-3000:]
    assert "Nothing to be done" in plan_text(workdir)
    full = run_snakemake(workdir, "-n", "--forceall", *CONFIG)
    assert full.returncode == 0, full.stderr[-3000:]
    return workdir, parse_jobs(full.stdout), probe_rules(workdir, *CONFIG[1:])["rules"]


def assert_same_jobs(planned: dict, expected: set) -> None:
    extra, missing = sorted(set(planned) - expected), sorted(expected - set(planned))
    assert not extra and not missing, \
        f"planned, not expected: {extra[:5]}; expected, not planned: {missing[:5]}"


def plan_text(workdir: Path, *extra: str) -> str:
    result = run_snakemake(workdir, "-n", *CONFIG, *extra)
    assert result.returncode == 0, result.stderr[-3000:]
    return result.stdout + result.stderr


def plan(workdir: Path, *extra: str) -> dict:
    return parse_jobs(plan_text(workdir, *extra))


def plan_after_editing(workdir: Path, path: Path) -> dict:
    """The dry run's jobs with ``path``'s content edited (a comment appended), then the file
    restored with its old modification time."""
    original, stat = path.read_bytes(), path.stat()
    try:
        path.write_bytes(original + b"\n# edited by test_reruns\n")
        return plan(workdir)
    finally:
        path.write_bytes(original)
        os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))


@pytest.mark.workflow
# stats.py: imported by 12 modules of the package and by no script directly. (periodic.py, the
# same kind of module, reaches every job of the quick DAG since every figure rule of a paper runs
# the paper's one figure script, which reads generated files: generate/__init__.py imports it.)
@pytest.mark.parametrize("module", ["checkpoint.py", "stats.py", "describe/spectral.py",
                                    "generate/packing_lp.py", "theory/debye.py"])
def test_editing_a_module_reruns_exactly_its_importers(complete, module):
    """Edit (content, not just mtime: Snakemake compares input checksums) one module: the plan is
    every job of every rule whose script imports it, directly or through other modules (the
    closure helper), plus their downstream jobs -- and nothing else."""
    workdir, dag, rules = complete
    package = workdir / "src" / "randmedia"
    path = package / module
    importers = {name for name, rule in rules.items() if rule["script"]
                 and path in script_sources(rule["script"], package)}
    assert importers
    seeds = {key for key in dag if key[0] in importers}
    expected = descendants(dag, seeds)
    assert expected != set(dag)  # the edit must leave some jobs alone to prove anything
    planned = plan_after_editing(workdir, path)
    assert_same_jobs(planned, expected)
    for key, job in planned.items():  # a job reruns because of the edit or of an upstream rerun
        assert job["reason"] in (f"Updated input files: {path}",) or job["reason"].startswith(
            "Input files updated by another job"), (key, job["reason"])


@pytest.mark.workflow
@pytest.mark.parametrize("script", ["sphere2019/comparison.py", "mrj2016/jammed_packings.py"])
def test_editing_a_script_reruns_exactly_its_rules(complete, script):
    """Edit one rule script (not a package module): Snakemake's code trigger plans every job of
    the rules that run it, plus their downstream jobs, and nothing else -- so a script needs no
    place in the rules' input ``code`` (tried 2026-12-06 with Snakemake 9.27 on rules included
    from workflow/rules/ with a relative script path)."""
    workdir, dag, rules = complete
    path = workdir / "workflow" / "scripts" / script
    users = {name for name, rule in rules.items()
             if rule["script"] and Path(rule["script"]).resolve() == path.resolve()}
    assert users
    expected = descendants(dag, {key for key in dag if key[0] in users})
    assert expected != set(dag)
    planned = plan_after_editing(workdir, path)
    assert_same_jobs(planned, expected)
    for key, job in planned.items():
        assert job["reason"] == "Code has changed since last execution" or job["reason"].startswith(
            "Input files updated by another job"), (key, job["reason"])


def describe_job(kind, stage=None):
    rule = {"chunk": "mrj2016_describe_chunk", "merge": "mrj2016_describe"}
    return lambda key, job: (key[0] in ([rule[stage]] if stage else rule.values())
                             and job["wildcards"].get("kind") == kind)


def rule_job(name, **wildcards):
    return lambda key, job: key[0] == name and all(job["wildcards"].get(w) == v for w, v in wildcards.items())


#: (config override, jobs whose params contain the key, jobs that must not rerun)
PARAMETER_CASES = {
    "mrj2016_windows": (
        "mrj2016:\n  number_variance:\n    max_windows: 1500\n",
        [describe_job("windows"), rule_job("mrj2016_comparison")],
        [describe_job("correlation"), describe_job("spectral"), describe_job("points")]),
    "mrj2016_windows_fit": (  # used by the merge alone: no chunk job reruns
        "mrj2016:\n  number_variance:\n    fit_r_min: 1.25\n",
        [describe_job("windows", "merge"), rule_job("mrj2016_fig09"),
         rule_job("mrj2016_fig10"), rule_job("mrj2016_comparison")],
        [describe_job("windows", "chunk"), describe_job("points"), rule_job("mrj2016_fig08")]),
    "mrj2016_spectral": (
        "mrj2016:\n  spectral:\n    nufft_eps: 1.0e-8\n",
        [describe_job("spectral"), rule_job("mrj2016_comparison")],
        [describe_job("correlation"), describe_job("points"), describe_job("windows"),
         rule_job("mrj2016_fig03")]),
    "mrj2016_figures": (
        "mrj2016:\n  figures:\n    render_side: 6.0\n",
        [rule_job("mrj2016_fig01")],
        [rule_job("mrj2016_fig02"), describe_job("windows")]),
    "debye2020": (
        "debye2020:\n  overlapping_disks:\n    compare_r_max_over_R: 3.5\n",
        [rule_job("debye2020_overlapping_disks_figure"), rule_job("debye2020_comparison")],
        [rule_job("debye2020_overlapping_disks_image"), rule_job("debye2020_overlapping_disks_s2")]),
    "sphere2019": (
        "sphere2019:\n  patterns:\n    fibonacci_points: 320\n",
        [rule_job("sphere2019_pattern", system="fibonacci")],
        [rule_job("sphere2019_pattern", system="icosahedral"),
         rule_job("sphere2019_describe", system="uniform")]),
}


@pytest.mark.workflow
@pytest.mark.parametrize("case", sorted(PARAMETER_CASES))
def test_changing_one_key_reruns_only_the_jobs_using_it(complete, case, tmp_path):
    workdir, dag, _ = complete
    text, using, untouched = PARAMETER_CASES[case]
    override = tmp_path / "override.yaml"
    override.write_text(text)
    seeds = {key for key, job in dag.items() if any(match(key, job) for match in using)}
    assert seeds
    expected = descendants(dag, seeds)
    planned = plan(workdir, str(override))
    assert_same_jobs(planned, expected)
    for key, job in planned.items():
        assert job["reason"].startswith(("Params have changed", "Input files updated by another job")), \
            (key, job["reason"])
        assert not any(match(key, job) for match in untouched), key
    assert any(job["reason"].startswith("Params have changed") for job in planned.values())
