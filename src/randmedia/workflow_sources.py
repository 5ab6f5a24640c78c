"""The package modules a workflow script runs: the transitive closure of its imports.

Every script rule of the workflow lists ``script_sources(script, package_dir)``
among its inputs (named ``code``), so that editing any module the script can
reach reruns the rule's jobs (Snakemake's ``mtime`` and ``input`` triggers)
and editing any other module reruns nothing.

The closure is read from the source text with :mod:`ast`, never by importing:

* ``import randmedia.a.b`` (with or without ``as``) runs ``randmedia/__init__.py``,
  ``randmedia/a/__init__.py`` and ``randmedia/a/b.py``;
* ``from randmedia.a import x`` runs ``randmedia.a`` (and its parents) and, when
  ``x`` is a submodule or subpackage of ``randmedia.a``, that too;
  ``from randmedia.a import *`` is taken to reach every module of the package;
* relative imports inside the package (``from . import x``, ``from ..a import y``)
  resolve against the importing module;
* every ``import`` statement counts, also those inside functions and under
  ``if`` (a lazily imported module still decides the results of the job).

numba's on-disk cache (``cache=True``) has the opposite gap: it invalidates a compiled
kernel only when *its own* file changes, so a kernel that calls a jitted function of
another module keeps the callee's old machine code after that module is edited (checked with
numba 0.68: tests/test_numba_cache.py). :func:`numba_cache_dir` therefore names one cache folder per content of the
package; the workflow (``common.smk``) and the tests use it, so an edit anywhere in the
package compiles afresh and never runs a stale kernel.

Imports built at run time (``importlib.import_module(name)``, ``__import__``)
are not seen; the package uses none for its own modules. A script or an
imported ``randmedia`` module that does not exist raises
:class:`SourceError` naming the script and the importing file.
"""

from __future__ import annotations

import ast
import hashlib
import os
from functools import lru_cache
from pathlib import Path

__all__ = ["SourceError", "numba_cache_dir", "package_digest", "script_sources"]


class SourceError(Exception):
    """A workflow script, or a package module it imports, is missing or unreadable."""


def _normalized(path) -> Path:
    return Path(os.path.normpath(os.path.abspath(os.fspath(path))))


@lru_cache(maxsize=None)
def _imports(path: str, mtime_ns: int, size: int, module: str | None, is_package: bool):
    """((dotted name, required, lineno), ...) of every import in one file; ``module`` is the
    file's dotted name inside the package (None for a script). Cached per file version."""
    try:
        tree = ast.parse(Path(path).read_bytes(), filename=path)
    except (OSError, SyntaxError, ValueError) as exc:
        raise SourceError(f"cannot parse {path}: {exc}") from exc
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.extend((alias.name, True, node.lineno) for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                if module is None:
                    raise SourceError(f"{path}, line {node.lineno}: relative import outside the package")
                parts = module.split(".") if is_package else module.split(".")[:-1]
                if node.level - 1 >= len(parts):
                    raise SourceError(f"{path}, line {node.lineno}: relative import beyond the package")
                base = ".".join(parts[:len(parts) - (node.level - 1)])
                if node.module:
                    base = f"{base}.{node.module}"
            else:
                base = node.module
            found.append((base, True, node.lineno))
            for alias in node.names:  # a name imported from a package may be a submodule
                found.append((f"{base}.{alias.name}", False, node.lineno))
    return tuple(found)


def _module_file(package_dir: Path, name: str) -> Path | None:
    """File that runs when the dotted ``name`` (inside the package) is imported: its ``.py``
    or the package's ``__init__.py``; None if there is no such module or package."""
    relative = name.split(".")[1:]
    candidate = package_dir.joinpath(*relative)
    if relative and candidate.with_suffix(".py").is_file():
        return candidate.with_suffix(".py")
    if (candidate / "__init__.py").is_file():
        return candidate / "__init__.py"
    return None


def _package_modules(package_dir: Path, name: str) -> list[str]:
    """Dotted names of every module below the package ``name`` (for ``import *``)."""
    root = package_dir.joinpath(*name.split(".")[1:])
    names = []
    for path in sorted(root.rglob("*.py")):
        parts = path.relative_to(package_dir).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        names.append(".".join((package_dir.name, *parts)))
    return names


def _dotted_name(package_dir: Path, path: Path) -> tuple[str, bool]:
    parts = path.relative_to(package_dir).with_suffix("").parts
    is_package = parts[-1] == "__init__"
    if is_package:
        parts = parts[:-1]
    return ".".join((package_dir.name, *parts)), is_package


def script_sources(script, package_dir) -> list[Path]:
    """Sorted absolute paths of every ``.py`` file of the package in ``package_dir`` (e.g.
    ``src/randmedia``) that running ``script`` can execute: its imports of the package,
    their imports, ... and the ``__init__.py`` of every package on the way."""
    script, package_dir = _normalized(script), _normalized(package_dir)
    package = package_dir.name
    if not script.is_file():
        raise SourceError(f"workflow script {script} does not exist")
    if not (package_dir / "__init__.py").is_file():
        raise SourceError(f"{package_dir} is not a package (no __init__.py); "
                          f"needed for the sources of {script}")
    found: set[Path] = set()
    queue: list[tuple[Path, str | None, bool]] = [(script, None, False)]
    while queue:
        path, module, is_package = queue.pop()
        stat = path.stat()
        for name, required, lineno in _imports(str(path), stat.st_mtime_ns, stat.st_size,
                                               module, is_package):
            if name != package and not name.startswith(package + "."):
                continue
            if name.endswith(".*"):
                names = _package_modules(package_dir, name[:-2])
            else:
                names = [name]
            for full in names:
                pieces = full.split(".")
                for depth in range(1, len(pieces) + 1):
                    prefix = ".".join(pieces[:depth])
                    target = _module_file(package_dir, prefix)
                    if target is None:
                        if depth == len(pieces) and not required:
                            break  # ``from module import name``: name is not a submodule
                        if package_dir.joinpath(*pieces[1:depth]).is_dir():
                            continue  # directory without __init__.py (namespace package)
                        raise SourceError(
                            f"{path}, line {lineno}, imports {full}, which is not a module of "
                            f"{package_dir} (needed for the sources of workflow script {script})")
                    if target not in found:
                        found.add(target)
                        queue.append((target, *_dotted_name(package_dir, target)))
    return sorted(found, key=str)


def package_digest(package_dir) -> str:
    """SHA-256 of every ``.py`` file of the package (relative paths and bytes, sorted by path)."""
    package_dir = _normalized(package_dir)
    digest = hashlib.sha256()
    for path in sorted(package_dir.rglob("*.py")):
        digest.update(str(path.relative_to(package_dir)).encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()


def numba_cache_dir(package_dir, root) -> Path:
    """The numba cache folder of this content of the package: ``root/<16 hex digits of
    package_digest>`` (module docstring: numba does not track calls across modules). Folders
    of earlier contents stay beside it until ``root`` is deleted (safe at any time)."""
    return Path(root).resolve() / package_digest(package_dir)[:16]
