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

A packing that takes longer than a session on one machine (N = 10 000: ~10-20 CPU h predicted)
must also survive a change of machine *unfinished*. While it runs, its job copies its
checkpoints (``.sample{k}.checkpoint*.npz`` beside the output) to
``record/packings/mrj2016/{system}/unfinished/`` (:class:`CheckpointKeeper`; the copies are
committed with the record), and a job that finds no checkpoint of its own takes those copies
back first, so it resumes where the last machine stopped. A checkpoint carries the key of its
run (seed, size, protocol: :mod:`randmedia.checkpoint`), so a copy from another configuration
is ignored, never resumed. The copies are removed when the packing is made.
"""

from __future__ import annotations

import json
import logging
import os
import shutil
import threading
from collections.abc import Mapping
from pathlib import Path

from randmedia.io import DataFileError, atomic_output, read_dataset

__all__ = ["RUN_ONLY_KEYS", "UNCERTIFIED_SUFFIX", "CheckpointKeeper", "kept_path", "keep", "matching_kept", "unfinished_dir"]

#: config keys that steer how a job runs, not what it makes
RUN_ONLY_KEYS = ("checkpoint_seconds", "keep_dir")


def _packing_config(config: Mapping) -> dict:
    return {key: value for key, value in config.items() if key not in RUN_ONLY_KEYS}


#: appended to ``keep_dir`` for the folder of the packings that are not certified strictly jammed
UNCERTIFIED_SUFFIX = "_uncertified"


def kept_path(keep_dir: str | os.PathLike, system: str, index: int, *, certified: bool = True) -> Path:
    """Where sample ``index`` of ``system`` is kept: under ``keep_dir`` if it is certified
    strictly jammed, under ``keep_dir`` + :data:`UNCERTIFIED_SUFFIX` otherwise (counted beside
    the record's packings, never in their place)."""
    folder = Path(keep_dir)
    if not certified:
        folder = folder.with_name(folder.name + UNCERTIFIED_SUFFIX)
    return folder / system / f"sample{int(index)}.nc"


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


def unfinished_dir(keep_dir: str | os.PathLike, system: str) -> Path:
    """Where the checkpoints of the unfinished samples of ``system`` are kept under ``keep_dir``."""
    return Path(keep_dir) / system / "unfinished"


class CheckpointKeeper:
    """Keeps the checkpoints of the job writing ``output`` in ``folder`` while it runs (module
    docstring), as a context manager around the construction.

    On entry, every kept checkpoint of this sample (``{stem}.checkpoint*.npz`` in ``folder``)
    whose local file (``.{stem}.checkpoint*.npz`` beside ``output``) is missing is copied
    back. While the block runs, a background thread copies each local checkpoint that changed
    (size or modification time) to ``folder`` every ``seconds``; a kill loses at most that
    interval. A kept copy whose local file is gone (a finished stage, whose result the next
    stage's checkpoint holds) stays until the end: removing it before the next stage's first
    copy would leave nothing kept. On a normal exit (the packing is written and kept whole) the
    kept checkpoints and any local one left (a finished stage's, taken back) are removed; on an
    exception they are brought up to date once more and left for the next run. Every copy is
    atomic (:func:`randmedia.io.atomic_output`).
    """

    def __init__(self, output: str | os.PathLike, folder: str | os.PathLike, *, seconds: float = 60.0,
                 log: logging.Logger | None = None):
        self.output, self.folder, self.seconds = Path(output), Path(folder), float(seconds)
        self.log = log or logging.getLogger(__name__)
        self._copied: dict[str, tuple[int, int]] = {}
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def _local(self) -> dict[str, Path]:
        """Kept name -> local checkpoint file of this sample."""
        pattern = f".{self.output.stem}.checkpoint*.npz"
        return {path.name[1:]: path for path in self.output.parent.glob(pattern)}

    def _kept(self) -> dict[str, Path]:
        return {path.name: path for path in self.folder.glob(f"{self.output.stem}.checkpoint*.npz")}

    def take_back(self) -> list[Path]:
        """Copy the kept checkpoints that have no local file back beside the output."""
        local, restored = self._local(), []
        for name, kept in sorted(self._kept().items()):
            if name not in local:
                restored.append(keep(kept, self.output.parent / f".{name}"))
                self.log.info("took the kept checkpoint %s back (the run resumes from it)", kept)
        return restored

    def sync(self) -> None:
        """Copy the local checkpoints that changed since the last copy to the folder."""
        for name, path in self._local().items():
            try:
                stat = path.stat()
            except FileNotFoundError:  # replaced or removed meanwhile: the next sync sees it
                continue
            stamp = (stat.st_size, stat.st_mtime_ns)
            if self._copied.get(name) != stamp:
                try:
                    keep(path, self.folder / name)
                except FileNotFoundError:  # removed meanwhile (a stage just finished)
                    continue
                self._copied[name] = stamp

    def _sync_or_warn(self) -> None:
        """:meth:`sync`, an OSError only warned of: a full disk must not stop the construction,
        and on the way out the construction's own error is the one to raise."""
        try:
            self.sync()
        except OSError as error:
            self.log.warning("could not keep the checkpoints in %s: %s", self.folder, error)

    def _run(self) -> None:
        while not self._stop.wait(self.seconds):
            self._sync_or_warn()

    def __enter__(self) -> "CheckpointKeeper":
        self.take_back()
        self._thread = threading.Thread(target=self._run, name="checkpoint-keeper", daemon=True)
        self._thread.start()
        return self

    def __exit__(self, exc_type, exc, traceback) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        if exc_type is None:
            # the packing is made: its checkpoints are stale, here and kept -- locally too, where
            # a finished stage's copy was taken back and the run resumed past it
            for path in [*self._kept().values(), *self._local().values()]:
                path.unlink(missing_ok=True)
            if self.folder.is_dir() and not any(self.folder.iterdir()):
                self.folder.rmdir()
        else:
            self._sync_or_warn()
