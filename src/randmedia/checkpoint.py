"""Checkpoints of long constructions: one ``.npz`` file per run, written atomically.

Every generator that runs for minutes (Yeong–Torquato annealing, hard-particle chains,
Monte Carlo on the sphere, Torquato–Jiao packings) saves its state here and resumes from
it after a kill. A checkpoint carries a *key*, the SHA-256 of everything that defines the
run (parameters, start state, random state); a file with another key, or one that cannot
be read, is ignored with a warning and the run starts afresh, so a stale checkpoint can
never leak into a different run. The random generator's state is stored with the arrays,
so a resumed run draws the same numbers as an uninterrupted one (bit-identical results).
"""

from __future__ import annotations

import hashlib
import json
import logging
import os
from pathlib import Path

import numpy as np

from randmedia.io import atomic_output

_KEY = "checkpoint_key"
_RNG = "checkpoint_rng_state"


def array_digest(*arrays: np.ndarray) -> str:
    """SHA-256 of the arrays' bytes (C order), for a key that names a start state."""
    digest = hashlib.sha256()
    for array in arrays:
        digest.update(np.ascontiguousarray(array).tobytes())
    return digest.hexdigest()


def checkpoint_key(**parts) -> str:
    """SHA-256 of the JSON of ``parts`` (sorted keys; non-JSON values via ``str``)."""
    payload = json.dumps(parts, sort_keys=True, default=str)
    return hashlib.sha256(payload.encode()).hexdigest()


def save_checkpoint(path: str | os.PathLike, key: str, arrays: dict,
                    rng: np.random.Generator | None = None) -> None:
    """Write ``arrays`` (name -> array or scalar) and, if given, the state of ``rng``.

    Parameters
    ----------
    path : str or os.PathLike
        The .npz file, written atomically.
    key : str
        Identity of the run (:func:`checkpoint_key`), checked on loading.
    arrays : dict
        Name -> array or scalar.
    rng : numpy.random.Generator, optional
        Generator whose bit-generator state is stored (as JSON).
    """
    extra = {_RNG: json.dumps(rng.bit_generator.state, default=int)} if rng is not None else {}
    with atomic_output(path) as tmp:
        with open(tmp, "wb") as handle:
            np.savez(handle, **{_KEY: key}, **extra, **{name: np.asarray(v) for name, v in arrays.items()})


def load_checkpoint(path: str | os.PathLike, key: str, log: logging.Logger,
                    rng: np.random.Generator | None = None) -> dict | None:
    """The arrays of the checkpoint at ``path`` (copies), or None if there is none, it
    belongs to another run (other key) or cannot be read. With ``rng``, its state is set
    to the saved one (only when the checkpoint is used).

    Parameters
    ----------
    path : str or os.PathLike
        The .npz file.
    key : str
        Identity of the current run; a checkpoint with another key is ignored.
    log : logging.Logger
        Receives a warning when a checkpoint is ignored.
    rng : numpy.random.Generator, optional
        Set to the saved state when the checkpoint is used.

    Returns
    -------
    dict or None
        Name -> array (the saved arrays), or None.
    """
    path = Path(path)
    if not path.is_file():
        return None
    try:
        with np.load(path) as data:
            if str(data[_KEY]) != key:
                log.warning("%s belongs to another run; starting afresh", path)
                return None
            arrays = {name: data[name].copy() for name in data.files if name not in (_KEY, _RNG)}
            rng_state = json.loads(str(data[_RNG])) if rng is not None else None
    except (OSError, ValueError, KeyError) as exc:
        log.warning("%s is unreadable (%s); starting afresh", path, exc)
        return None
    if rng is not None:
        rng.bit_generator.state = rng_state
    return arrays
