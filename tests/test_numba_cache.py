"""numba's cache and edits of the package (randmedia.workflow_sources.numba_cache_dir).

numba invalidates a cached kernel only when its own file changes, so a kernel calling a
jitted function of another module keeps the callee's old code after an edit. The workflow and
the tests therefore use one cache folder per package content; these tests show the hazard
with a fixed folder and its absence with numba_cache_dir."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from randmedia.workflow_sources import numba_cache_dir, package_digest

CALLEE = "from numba import njit\n\n\n@njit(cache=True)\ndef g(x):\n    return x + {increment}\n"
CALLER = "from numba import njit\n\nfrom pkg.callee import g\n\n\n@njit(cache=True)\ndef f(x):\n    return g(x) * 10\n"


def _package(root: Path, increment: int) -> Path:
    package = root / "pkg"
    package.mkdir(exist_ok=True)
    (package / "__init__.py").write_text("")
    (package / "callee.py").write_text(CALLEE.format(increment=increment))
    (package / "caller.py").write_text(CALLER)
    return package


def _caller_result(root: Path, cache: Path) -> int:
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache), "PYTHONPATH": str(root)}
    result = subprocess.run([sys.executable, "-c", "from pkg.caller import f; print(f(1))"], env=env,
                            capture_output=True, text=True, timeout=300, check=True)
    return int(result.stdout.split()[-1])


@pytest.mark.parametrize("per_content", [False, True])
def test_an_edited_callee_is_never_run_from_a_stale_cache(tmp_path, per_content):
    package = _package(tmp_path, increment=1)
    cache = numba_cache_dir(package, tmp_path / "cache") if per_content else tmp_path / "cache"
    assert _caller_result(tmp_path, cache) == 20
    # the callee's module is edited (its size stays the same); the caller's file is not
    _package(tmp_path, increment=2)
    cache = numba_cache_dir(package, tmp_path / "cache") if per_content else tmp_path / "cache"
    stale = _caller_result(tmp_path, cache)
    if per_content:
        assert stale == 30
    else:  # numba's own rule: the caller's cached code still holds the old callee
        assert stale == 20


def test_package_digest_follows_content_not_timestamps(tmp_path):
    package = _package(tmp_path, increment=1)
    before = package_digest(package)
    os.utime(package / "callee.py", (0, 0))
    assert package_digest(package) == before
    _package(tmp_path, increment=3)
    assert package_digest(package) != before
    assert numba_cache_dir(package, tmp_path).name == package_digest(package)[:16]


def test_tests_and_workflow_use_the_per_content_cache():
    from conftest import NUMBA_CACHE_SET_HERE

    repo = Path(__file__).resolve().parents[1]
    expected = numba_cache_dir(repo / "src" / "randmedia", repo / ".cache" / "numba")
    if NUMBA_CACHE_SET_HERE:  # (a NUMBA_CACHE_DIR set by the user is left alone)
        assert os.environ["NUMBA_CACHE_DIR"] == str(expected)
    assert "_numba_cache_dir(PACKAGE_DIR" in (repo / "workflow" / "rules" / "common.smk").read_text()
