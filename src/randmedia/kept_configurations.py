"""Generated configurations kept beside the record, and taken back instead of regenerated.

A paper-config MRJ packing costs CPU minutes to hours (mrj2016, docs/mrj2016.md), and a new
machine starts without ``results/``. Each packing job of the paper config therefore keeps a
copy of its output (the same compressed netCDF file, provenance included) under
``record/packings/mrj2016/{system}/sample{k}.nc`` as soon as it is written, and a later job
for the same sample takes that copy back instead of generating the packing again -- but
only when the copy was made from the same inputs: its ``seed`` attribute and its
configuration (``config_json``, less the keys in :data:`RUN_ONLY_KEYS` that cannot change a
packing) must equal the job's. Anything else is regenerated, so a change of protocol never
reuses an old packing.
"""

from __future__ import annotations

import json
import os
import shutil
from collections.abc import Mapping
from pathlib import Path

from randmedia.io import DataFileError, atomic_output, read_dataset

__all__ = ["RUN_ONLY_KEYS", "kept_path", "keep", "matching_kept"]

#: config keys that steer how a job runs, not what it makes
RUN_ONLY_KEYS = ("checkpoint_seconds", "keep_dir")


def _packing_config(config: Mapping) -> dict:
    return {key: value for key, value in config.items() if key not in RUN_ONLY_KEYS}


def kept_path(keep_dir: str | os.PathLike, system: str, index: int) -> Path:
    """Where sample ``index`` of ``system`` is kept under ``keep_dir``."""
    return Path(keep_dir) / system / f"sample{int(index)}.nc"


def matching_kept(path: str | os.PathLike, seed: int, config: Mapping) -> bool:
    """Whether the kept file ``path`` exists and was made with ``seed`` and ``config`` (module
    docstring). A kept file that cannot be read is reported as not matching (and is then
    overwritten by the regenerated one)."""
    path = Path(path)
    if not path.is_file():
        return False
    try:
        attrs = read_dataset(path).attrs
    except DataFileError:
        return False
    kept_config = json.loads(attrs["config_json"])
    wanted = json.loads(json.dumps(config, sort_keys=True, default=str))
    return int(attrs["seed"]) == int(seed) and _packing_config(kept_config) == _packing_config(wanted)


def keep(output: str | os.PathLike, path: str | os.PathLike) -> Path:
    """Copy the finished ``output`` to the kept ``path``, atomically."""
    path = Path(path)
    with atomic_output(path) as tmp:
        shutil.copyfile(output, tmp)
    return path
