"""Kept configurations: taken back only for the same seed and configuration."""

from __future__ import annotations

import time

import numpy as np
import pytest
import xarray as xr

from randmedia.io import write_dataset
from randmedia.kept_configurations import CheckpointKeeper, keep, kept_path, matching_kept, unfinished_dir


def _write(path, seed, config):
    ds = xr.Dataset({"position": (("particle", "xyz"), np.arange(6.0).reshape(2, 3),
                                  {"units": "D", "long_name": "centre"})})
    write_dataset(ds, path, rule="test", seed=seed, config=config)


def test_a_kept_file_matches_only_its_own_seed_and_configuration(tmp_path):
    config = {"n_particles": 100, "polish": {"tolerance": 1e-10}, "checkpoint_seconds": 120,
              "keep_dir": "record/packings/mrj2016"}
    path = kept_path(tmp_path, "mrj", 3)
    assert path == tmp_path / "mrj" / "sample3.nc"
    assert not matching_kept(path, 7, config)  # nothing kept yet
    _write(path, 7, config)
    assert matching_kept(path, 7, config)
    # how the job runs does not matter, what it makes does
    assert matching_kept(path, 7, {**config, "checkpoint_seconds": 5, "keep_dir": "elsewhere"})
    assert not matching_kept(path, 8, config)
    assert not matching_kept(path, 7, {**config, "polish": {"tolerance": 1e-12}})
    assert not matching_kept(path, 7, {**config, "route": "dilute"})


def test_an_unreadable_kept_file_does_not_match_and_keep_replaces_it(tmp_path):
    path = kept_path(tmp_path, "mrj", 0)
    path.parent.mkdir(parents=True)
    path.write_bytes(b"truncated")
    assert not matching_kept(path, 1, {})
    output = tmp_path / "out.nc"
    _write(output, 1, {})
    keep(output, path)
    assert matching_kept(path, 1, {})
    assert path.read_bytes() == output.read_bytes()


def _checkpoint(path, content: bytes):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(content)
    return path


def test_the_checkpoints_of_an_unfinished_packing_are_kept_and_taken_back(tmp_path):
    """A job keeps its checkpoints beside the record while it runs; a job on a machine without
    them takes them back before it starts, and the copies are removed once the packing is made."""
    folder = unfinished_dir(tmp_path / "record", "mrj_large")
    assert folder == tmp_path / "record" / "mrj_large" / "unfinished"
    output = tmp_path / "results" / "sample0.nc"
    output.parent.mkdir()
    other_sample = _checkpoint(output.with_name(".sample1.checkpoint.npz"), b"sample 1")
    # machine 1: the run writes checkpoints, is killed (an exception here), keeps them
    with pytest.raises(RuntimeError):
        with CheckpointKeeper(output, folder, seconds=3600) as keeper:
            stage = _checkpoint(output.with_name(".sample0.checkpoint.dilute.npz"), b"dilute, 10 LPs")
            keeper.sync()
            assert (folder / "sample0.checkpoint.dilute.npz").read_bytes() == b"dilute, 10 LPs"
            stage.write_bytes(b"dilute, 20 LPs")
            raise RuntimeError("killed")
    # brought up to date on the way out; another sample's checkpoint is not this job's
    assert (folder / "sample0.checkpoint.dilute.npz").read_bytes() == b"dilute, 20 LPs"
    assert sorted(p.name for p in folder.iterdir()) == ["sample0.checkpoint.dilute.npz"]
    # machine 2 (no results/): the kept checkpoint is taken back, a local one is never overwritten
    stage.unlink()
    local_top = _checkpoint(output.with_name(".sample0.checkpoint.npz"), b"local")
    _checkpoint(folder / "sample0.checkpoint.npz", b"kept, older")
    with CheckpointKeeper(output, folder, seconds=0.01):
        assert stage.read_bytes() == b"dilute, 20 LPs"
        assert local_top.read_bytes() == b"local"
        # the stage finishes and its checkpoint goes; its kept copy stays until the end
        stage.unlink()
        local_top.write_bytes(b"after the dilute stage")
        for _ in range(500):  # the background copy, every 0.01 s
            if (folder / "sample0.checkpoint.npz").read_bytes() == b"after the dilute stage":
                break
            time.sleep(0.01)
        assert (folder / "sample0.checkpoint.npz").read_bytes() == b"after the dilute stage"
        assert (folder / "sample0.checkpoint.dilute.npz").exists()
    # the packing is made: nothing of it stays unfinished, here or kept
    assert not folder.exists() and not local_top.exists()
    assert other_sample.read_bytes() == b"sample 1"
    # machine 3 (no results/), after a kill in the polish: both kept checkpoints come back, the
    # run resumes from the top-level one and never opens the finished stage's; made, neither stays
    kept_top = _checkpoint(folder / "sample0.checkpoint.npz", b"after the dilute stage")
    kept_stage = _checkpoint(folder / "sample0.checkpoint.dilute.npz", b"dilute, finished")
    with CheckpointKeeper(output, folder, seconds=3600):
        assert stage.read_bytes() == b"dilute, finished" and local_top.exists()
        local_top.unlink()  # the packing is made from it
    assert not stage.exists() and not kept_stage.exists() and not kept_top.exists()
    assert other_sample.read_bytes() == b"sample 1"
