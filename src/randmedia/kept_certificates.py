"""The jamming certificates of kept packings, kept beside them and taken back instead of recomputed.

A packing's certificate (rule ``mrj2016_packing_certificate``: the contact-gap ladder of
:func:`randmedia.describe.jamming_resolution.gap_ladder`) is a function of the packing's
coordinates, the contact options and the code of the test, nothing else. It costs ~9 CPU s at
N = 2000 but ~45 CPU min for an uncertified packing of N = 10 000 (two rungs with cone LPs and
rank checks on ~30 000 contacts), and a new machine starts without ``results/``. So each
certificate job of a kept packing (:mod:`randmedia.kept_configurations`) keeps its ladder beside
the packing, as ``sample{k}.certificate.json``, with the key it was computed from
(:func:`certificate_key`):

- ``packing_sha256``: SHA-256 of the centres, the cell and the diameter (float64 bytes);
- ``contacts``: the contact options passed to the test;
- ``code_sha256``: SHA-256 of the package modules that compute the ladder
  (:func:`ladder_sources`: :mod:`randmedia.describe.jamming_resolution` and every module it
  imports), so any change to the test's code recomputes it, and a change to the job's
  reading, writing, logging or keeping (which cannot change a ladder) does not.

A later job takes the ladder back only when all three are equal (:func:`kept_ladder`); any
difference, or an unreadable file, recomputes it and replaces the kept file.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Iterable, Mapping
from pathlib import Path

import numpy as np

import randmedia
from randmedia.describe import jamming_resolution
from randmedia.io import atomic_output
from randmedia.kept_configurations import kept_path
from randmedia.workflow_sources import script_sources

__all__ = ["certificate_key", "keep_ladder", "kept_certificate_path", "kept_ladder", "ladder_sources"]


def kept_certificate_path(keep_dir: str | os.PathLike, system: str, index: int, *,
                          certified: bool = True) -> Path:
    """Where the certificate of sample ``index`` of ``system`` is kept: beside the kept packing
    ``sample{index}.nc`` (:func:`randmedia.kept_configurations.kept_path`: under ``keep_dir``
    if the packing is certified, under the uncertified folder otherwise)."""
    return kept_path(keep_dir, system, index, certified=certified).with_name(
        f"sample{int(index)}.certificate.json")


def ladder_sources() -> list[Path]:
    """The package modules that compute a ladder: ``randmedia/describe/jamming_resolution.py``
    and the transitive closure of its imports of the package
    (:func:`randmedia.workflow_sources.script_sources`) -- the ``code`` of a kept key."""
    module = Path(jamming_resolution.__file__)
    return [module, *script_sources(module, Path(randmedia.__file__).parent)]


def _module_name(path: Path) -> str:
    """``path`` from its package directory on (``randmedia/describe/jamming.py``), so that the
    key does not depend on where the checkout lies."""
    parts = path.parts
    return "/".join(parts[parts.index("randmedia"):]) if "randmedia" in parts else path.name


def certificate_key(positions, box, diameter: float, contacts: Mapping,
                    code: Iterable[str | os.PathLike]) -> dict:
    """The key of a certificate (module docstring): packing hash, contact options, code hash."""
    packing = hashlib.sha256()
    for array in (positions, box, [diameter]):
        packing.update(np.ascontiguousarray(array, dtype=np.float64).tobytes())
    sources = hashlib.sha256()
    for path in sorted((Path(p) for p in code), key=_module_name):
        sources.update(_module_name(path).encode() + b"\0" + path.read_bytes() + b"\0")
    return {"packing_sha256": packing.hexdigest(),
            "contacts": json.loads(json.dumps(dict(contacts), sort_keys=True)),
            "code_sha256": sources.hexdigest()}


def kept_ladder(path: str | os.PathLike, key: Mapping) -> list[dict] | None:
    """The ladder kept in ``path`` if it was computed with ``key``; None if there is none, it
    cannot be read, or its key differs."""
    try:
        kept = json.loads(Path(path).read_text())
        return list(kept["ladder"]) if kept["key"] == dict(key) else None
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _plain(value):
    """numpy scalars as Python numbers (for json)."""
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"not JSON serializable: {type(value).__name__}")


def keep_ladder(path: str | os.PathLike, key: Mapping, ladder: list[Mapping]) -> Path:
    """Write ``ladder`` with its ``key`` to ``path``, atomically."""
    path = Path(path)
    with atomic_output(path) as tmp:
        tmp.write_text(json.dumps({"key": dict(key), "ladder": [dict(row) for row in ladder]},
                                  indent=1, default=_plain) + "\n")
    return path
