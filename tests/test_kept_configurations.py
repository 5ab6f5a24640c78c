"""Kept configurations: taken back only for the same seed and configuration."""

from __future__ import annotations

import numpy as np
import xarray as xr

from randmedia.io import write_dataset
from randmedia.kept_configurations import keep, kept_path, matching_kept


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
