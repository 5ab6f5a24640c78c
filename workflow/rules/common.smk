# Shared helpers and environment of every rule.
import os
from pathlib import Path

from randmedia.workflow_sources import SourceError, script_sources as _script_sources

# Parallel jobs must not fail on HDF5 file locks (our writes are atomic
# renames), and share one numba cache per working directory. numba writes its
# cache index and data files to a temporary name and renames them, so
# concurrent jobs compiling the same kernel do not corrupt the cache.
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
os.environ.setdefault("NUMBA_CACHE_DIR", str(Path(".cache/numba").resolve()))

PACKAGE_DIR = Path(workflow.basedir) / "src" / "randmedia"


def script_sources(script):
    """The package modules (.py files) that the rule script ``script`` (a path relative to the
    calling rule file, as in its ``script:``) can run: the transitive closure of its imports
    of randmedia (randmedia.workflow_sources). Every script rule lists them as its input
    ``code``, so that editing any of them reruns the rule and editing any other module
    reruns nothing; check_script_rules() (end of the Snakefile) enforces it."""
    path = Path(str(workflow.current_basedir)) / script
    try:
        return [str(f) for f in _script_sources(path, PACKAGE_DIR)]
    except SourceError as error:
        raise WorkflowError(f"sources of rule script {script}: {error}")


def check_script_rules():
    """Every rule with a Python ``script:`` has the input ``code`` = script_sources(script)."""
    problems = []
    for rule in workflow.rules:
        if not rule.script or not str(rule.script).endswith(".py"):
            continue
        script = Path(str(rule.basedir)) / rule.script
        try:
            expected = sorted(str(f) for f in _script_sources(script, PACKAGE_DIR))
        except SourceError as error:
            problems.append(f"rule {rule.name}: {error}")
            continue
        code = rule.input.get("code")
        if code is None or callable(code):
            problems.append(f"rule {rule.name}: no static input `code` "
                            f"(add code=script_sources({str(rule.script)!r}))")
        elif sorted(str(f) for f in ([code] if isinstance(code, str) else code)) != expected:
            problems.append(f"rule {rule.name}: input `code` is not script_sources({str(rule.script)!r})")
    if problems:
        raise WorkflowError("package sources of script rules:\n  " + "\n  ".join(problems))


wildcard_constraints:
    k=r"\d+",
