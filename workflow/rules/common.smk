# Shared helpers and environment of every rule.
import os
from pathlib import Path

# Parallel jobs must not fail on HDF5 file locks (our writes are atomic
# renames), and share one numba cache per working directory. numba writes its
# cache index and data files to a temporary name and renames them, so
# concurrent jobs compiling the same kernel do not corrupt the cache.
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
os.environ.setdefault("NUMBA_CACHE_DIR", str(Path(".cache/numba").resolve()))

PACKAGE_DIR = Path(workflow.basedir) / "src" / "randmedia"


def package_sources(*modules):
    """Paths of the package modules a rule's science lives in (plus the I/O
    layer), listed among the rule's inputs so that editing them reruns it."""
    files = [PACKAGE_DIR / "io.py"] + [PACKAGE_DIR / m for m in modules]
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        raise WorkflowError(f"package sources named by a rule do not exist: {missing}")
    return [str(f) for f in files]


wildcard_constraints:
    k=r"\d+",
