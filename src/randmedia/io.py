"""netCDF data layer: atomic writes with provenance, validating reads.

Every file the workflow writes goes through :func:`atomic_output`: the content
is written to a hidden temporary file in the destination folder and renamed
onto the destination only once complete (``os.replace`` is atomic on POSIX), so
a job killed mid-write never leaves a truncated output behind.

netCDF files are written by :func:`write_dataset`, which insists on CF-style
``units`` and ``long_name`` on every variable and coordinate and stamps the
provenance attributes listed in :data:`PROVENANCE_ATTRS`.  :func:`read_dataset`
is the only reader: it checks that the file is one of ours and carries the
variables, dimensions, units and attributes the caller needs, and raises
:class:`DataFileError` naming the file and what is wrong otherwise.
"""

from __future__ import annotations

import contextlib
import functools
import json
import os
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Mapping, Sequence

import numpy as np
import xarray as xr

import randmedia

#: attributes stamped on every file by :func:`write_dataset`
PROVENANCE_ATTRS = ("randmedia_version", "git_commit", "git_dirty", "rule", "seed", "config_json")


class DataFileError(ValueError):
    """A data file is missing, foreign, truncated, corrupt or lacks what is needed."""


@dataclass(frozen=True)
class VariableSpec:
    """What a reader needs of one variable: its dimensions (in order) and units."""

    dims: tuple[str, ...]
    units: str


# --------------------------------------------------------------------------- writing


@contextlib.contextmanager
def atomic_output(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it onto ``path`` on success.

    On any exception the temporary file is removed and ``path`` is untouched.
    Stale temporaries of the same destination left by a killed process are
    removed first.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    for stale in path.parent.glob(f".{path.name}.partial-*"):
        stale.unlink(missing_ok=True)
    tmp = path.with_name(f".{path.name}.partial-{os.getpid()}{path.suffix}")
    try:
        yield tmp
        with open(tmp, "rb") as handle:
            os.fsync(handle.fileno())
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)


@functools.lru_cache(maxsize=1)
def git_state() -> tuple[str, str]:
    """(commit hash, dirty flag) of the repository holding this package.

    Returns ``("unknown", "unknown")`` outside a git checkout. The dirty flag
    is ``"yes"`` when tracked or untracked-but-not-ignored files differ from
    the commit.
    """
    repo = Path(randmedia.__file__).resolve().parents[2]
    try:
        commit = subprocess.run(
            ["git", "-C", str(repo), "rev-parse", "HEAD"],
            capture_output=True, text=True, check=True, timeout=10,
        ).stdout.strip()
        status = subprocess.run(
            ["git", "-C", str(repo), "status", "--porcelain"],
            capture_output=True, text=True, check=True, timeout=10,
        ).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return "unknown", "unknown"
    return commit, ("yes" if status else "no")


def provenance_attrs(*, rule: str, seed: int | None, config: Mapping) -> dict[str, str | int]:
    """The provenance attributes every output file carries.

    Parameters
    ----------
    rule : str
        Name of the producing workflow rule.
    seed : int or None
        Seed of the sample (None: no randomness, stored as -1).
    config : Mapping
        Configuration values the rule used (stored as JSON).

    Returns
    -------
    dict
        ``randmedia_version``, ``git_commit``, ``git_dirty``, ``rule``, ``seed``, ``config_json``.
    """
    commit, dirty = git_state()
    return {
        "randmedia_version": randmedia.__version__,
        "git_commit": commit,
        "git_dirty": dirty,
        "rule": rule,
        # netCDF attributes cannot be None; -1 marks "no randomness involved"
        "seed": -1 if seed is None else int(seed),
        "config_json": json.dumps(config, sort_keys=True, default=_json_default),
    }


def _json_default(value):
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"not JSON serializable: {type(value).__name__}")


def _check_cf_metadata(ds: xr.Dataset) -> None:
    missing = [
        f"{name}: {key}"
        for name in list(ds.data_vars) + list(ds.coords)
        for key in ("units", "long_name")
        if key not in ds[name].attrs
    ]
    if missing:
        raise ValueError("refusing to write variables without CF metadata -> " + "; ".join(missing))


def write_dataset(
    ds: xr.Dataset,
    path: str | os.PathLike,
    *,
    rule: str,
    seed: int | None,
    config: Mapping,
) -> Path:
    """Write ``ds`` to ``path`` as zlib-compressed netCDF4, atomically, with provenance.

    ``config`` is the set of configuration values the producing rule used; it
    is stored as JSON text in the ``config_json`` attribute. Boolean attributes
    are written as 0/1 (netCDF has no boolean attribute type).

    Parameters
    ----------
    ds : xarray.Dataset
        Data with CF metadata (checked).
    path : str or os.PathLike
        Output file.
    rule : str
        Name of the producing rule.
    seed : int or None
        Seed of the sample (None: no randomness).
    config : Mapping
        Configuration values the rule used.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    _check_cf_metadata(ds)
    ds = ds.copy()
    ds.attrs.update(provenance_attrs(rule=rule, seed=seed, config=config))
    # netCDF has no boolean attribute type: flags are written as 0/1
    ds.attrs.update({k: int(v) for k, v in ds.attrs.items() if isinstance(v, (bool, np.bool_))})
    encoding = {
        name: {"zlib": True, "complevel": 4}
        for name in list(ds.data_vars) + list(ds.coords)
        if ds[name].dtype.kind in "biuf"
    }
    path = Path(path)
    with atomic_output(path) as tmp:
        ds.to_netcdf(tmp, engine="netcdf4", format="NETCDF4", encoding=encoding)
    return path


# --------------------------------------------------------------------------- reading


def read_dataset(
    path: str | os.PathLike,
    variables: Mapping[str, VariableSpec] | None = None,
    attrs: Sequence[str] = (),
) -> xr.Dataset:
    """Read a netCDF file written by :func:`write_dataset`, fully into memory.

    Checks, in order: the file exists; it is readable netCDF (not truncated or
    corrupt); it carries our provenance attributes (not a foreign file); each
    variable in ``variables`` exists with the given dimensions and units; each
    attribute in ``attrs`` exists. Raises :class:`DataFileError` naming the
    file and the first problem found.

    Parameters
    ----------
    path : str or os.PathLike
        The netCDF file.
    variables : Mapping[str, VariableSpec], optional
        Required variables with their dims and units.
    attrs : sequence of str, optional
        Required global attributes.

    Returns
    -------
    xarray.Dataset
        The file's contents, loaded.
    """
    path = Path(path)
    if not path.is_file():
        raise DataFileError(f"{path}: file does not exist")
    try:
        with xr.open_dataset(path, engine="netcdf4") as handle:
            ds = handle.load()
    except Exception as exc:  # netCDF4/HDF5 raise OSError, RuntimeError, ValueError, ...
        raise DataFileError(
            f"{path}: not a readable netCDF4 file (truncated, corrupt or another format): {exc}"
        ) from exc

    missing_prov = [key for key in PROVENANCE_ATTRS if key not in ds.attrs]
    if missing_prov:
        raise DataFileError(
            f"{path}: not written by randmedia (missing provenance attributes {missing_prov})"
        )
    for name, spec in (variables or {}).items():
        if name not in ds.variables:
            raise DataFileError(f"{path}: missing variable '{name}' (has {sorted(ds.variables)})")
        var = ds[name]
        if tuple(var.dims) != tuple(spec.dims):
            raise DataFileError(
                f"{path}: variable '{name}' has dims {tuple(var.dims)}, expected {tuple(spec.dims)}"
            )
        units = var.attrs.get("units")
        if units != spec.units:
            raise DataFileError(
                f"{path}: variable '{name}' has units {units!r}, expected {spec.units!r}"
            )
    missing_attrs = [key for key in attrs if key not in ds.attrs]
    if missing_attrs:
        raise DataFileError(f"{path}: missing attributes {missing_attrs}")
    return ds


def write_csv(frame, path: str | os.PathLike, **to_csv_kwargs) -> Path:
    """Write a pandas DataFrame to CSV atomically (no index unless asked)."""
    to_csv_kwargs.setdefault("index", False)
    path = Path(path)
    with atomic_output(path) as tmp:
        frame.to_csv(tmp, **to_csv_kwargs)
    return path
