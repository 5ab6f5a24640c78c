"""The netCDF data layer: round trip, provenance, atomic writes, rejected inputs."""

import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
import xarray as xr

from randmedia.io import (PROVENANCE_ATTRS, DataFileError, VariableSpec, atomic_output,
                          read_dataset, write_dataset)

SPEC = {"S2": VariableSpec(("r",), "1"), "r": VariableSpec(("r",), "pixel")}


def small_dataset():
    r = np.arange(5.0)
    return xr.Dataset(
        {"S2": ("r", np.exp(-r), {"units": "1", "long_name": "two-point function"})},
        coords={"r": ("r", r, {"units": "pixel", "long_name": "distance"})},
    )


@pytest.fixture
def good_file(tmp_path):
    return write_dataset(small_dataset(), tmp_path / "good.nc", rule="test", seed=7,
                         config={"L": 11, "phi2": np.float64(0.3)})


def test_round_trip_with_provenance(good_file):
    ds = read_dataset(good_file, SPEC)
    np.testing.assert_array_equal(ds["S2"].values, np.exp(-np.arange(5.0)))
    for key in PROVENANCE_ATTRS:
        assert key in ds.attrs
    assert ds.attrs["seed"] == 7 and ds.attrs["rule"] == "test"
    assert json.loads(ds.attrs["config_json"]) == {"L": 11, "phi2": 0.3}
    assert ds.attrs["git_dirty"] in ("yes", "no", "unknown")


def test_written_compressed(good_file):
    with xr.open_dataset(good_file) as ds:
        assert ds["S2"].encoding.get("zlib") is True


def test_refuses_variables_without_cf_metadata(tmp_path):
    ds = small_dataset()
    del ds["S2"].attrs["long_name"]
    with pytest.raises(ValueError, match="S2: long_name"):
        write_dataset(ds, tmp_path / "x.nc", rule="test", seed=None, config={})
    assert not (tmp_path / "x.nc").exists()


def test_atomic_output_leaves_nothing_on_error(tmp_path):
    target = tmp_path / "out.nc"
    target.write_text("previous complete content")
    with pytest.raises(RuntimeError):
        with atomic_output(target) as tmp:
            tmp.write_text("half")
            raise RuntimeError("killed")
    assert target.read_text() == "previous complete content"
    assert list(tmp_path.iterdir()) == [target]


def test_atomic_output_removes_stale_partials(tmp_path):
    target = tmp_path / "out.csv"
    stale = tmp_path / ".out.csv.partial-99999.csv"
    stale.write_text("left by a killed job")
    with atomic_output(target) as tmp:
        tmp.write_text("done")
    assert target.read_text() == "done" and not stale.exists()


KILLED_WRITER = """
import sys, numpy as np, xarray as xr
from randmedia.io import write_dataset
rng = np.random.default_rng(0)
data = rng.random((3000, 3000))  # 72 MB, compressed write takes seconds
ds = xr.Dataset({"v": (("a", "b"), data, {"units": "1", "long_name": "noise"})})
print("writing", flush=True)
write_dataset(ds, sys.argv[1], rule="test", seed=0, config={})
"""


def test_process_killed_mid_write_leaves_no_output_and_rerun_completes(tmp_path):
    target = tmp_path / "big.nc"
    proc = subprocess.Popen([sys.executable, "-c", KILLED_WRITER, str(target)],
                            stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "writing"
    deadline = time.time() + 60
    while not list(tmp_path.glob(".big.nc.partial-*")) and time.time() < deadline:
        time.sleep(0.01)
    assert list(tmp_path.glob(".big.nc.partial-*")), "writer never started its temporary file"
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    assert not target.exists(), "a killed write must not leave the output path"
    # rerun: completes, and the stale temporary file is gone
    subprocess.run([sys.executable, "-c", KILLED_WRITER, str(target)], check=True,
                   capture_output=True)
    assert read_dataset(target, {"v": VariableSpec(("a", "b"), "1")})["v"].shape == (3000, 3000)
    assert not list(tmp_path.glob(".big.nc.partial-*"))


# ---- bad inputs: each rejected with a message naming the file


def _missing_variable(path, good):
    ds = small_dataset().drop_vars("S2")
    ds["other"] = ("r", np.zeros(5), {"units": "1", "long_name": "x"})
    write_dataset(ds, path, rule="t", seed=0, config={})


def _wrong_dims(path, good):
    ds = xr.Dataset({"S2": (("q",), np.zeros(5), {"units": "1", "long_name": "x"})},
                    coords={"r": ("r", np.arange(3.0), {"units": "pixel", "long_name": "d"})})
    write_dataset(ds, path, rule="t", seed=0, config={})


def _wrong_units(path, good):
    ds = small_dataset()
    ds["r"].attrs["units"] = "meter"
    write_dataset(ds, path, rule="t", seed=0, config={})


def _truncated(path, good):
    data = good.read_bytes()
    path.write_bytes(data[: len(data) // 2])


def _empty(path, good):
    path.write_bytes(b"")


def _not_netcdf(path, good):
    path.write_text("r,S2\n0,0.7\n1,0.6\n")


def _foreign(path, good):
    small_dataset().to_netcdf(path, engine="netcdf4")  # valid netCDF, no provenance


def _corrupt_bytes(path, good):
    data = bytearray(good.read_bytes())
    data[:8] = b"GARBAGE!"
    path.write_bytes(bytes(data))


BAD_FILES = {
    "missing_variable": (_missing_variable, "missing variable 'S2'"),
    "wrong_dims": (_wrong_dims, "has dims"),
    "wrong_units": (_wrong_units, "units 'meter', expected 'pixel'"),
    "truncated": (_truncated, "not a readable netCDF4 file"),
    "empty": (_empty, "not a readable netCDF4 file"),
    "not_netcdf": (_not_netcdf, "not a readable netCDF4 file"),
    "foreign": (_foreign, "not written by randmedia"),
    "corrupt_header": (_corrupt_bytes, "not a readable netCDF4 file"),
}


@pytest.mark.parametrize("case", sorted(BAD_FILES))
def test_bad_netcdf_rejected_naming_file(case, tmp_path, good_file):
    make, expected = BAD_FILES[case]
    path = tmp_path / f"{case}.nc"
    make(path, good_file)
    with pytest.raises(DataFileError) as error:
        read_dataset(path, SPEC)
    message = str(error.value)
    assert str(path) in message and expected in message


def test_missing_file_and_missing_attribute(tmp_path, good_file):
    with pytest.raises(DataFileError, match="does not exist"):
        read_dataset(tmp_path / "nope.nc", SPEC)
    with pytest.raises(DataFileError, match=r"missing attributes \['phi2'\]") as error:
        read_dataset(good_file, SPEC, attrs=["phi2"])
    assert str(good_file) in str(error.value)


def test_particle_config_round_trip_wraps_into_triclinic_cell(tmp_path):
    from randmedia.generate import PARTICLE_CONFIG, particle_config_dataset
    from randmedia.periodic import Cell

    box = np.array([[5.0, 1.0, 0.0], [0.0, 5.0, 0.5], [0.0, 0.0, 5.0]])
    positions = np.random.default_rng(0).normal(scale=6.0, size=(30, 3))
    ds = particle_config_dataset(positions, box, 1.0, {"phi": 0.1})
    path = write_dataset(ds, tmp_path / "c.nc", rule="t", seed=1, config={})
    back = read_dataset(path, PARTICLE_CONFIG, attrs=["diameter", "phi"])
    f = Cell(back["box"].values).fractional(back["position"].values)
    assert np.all((f >= 0) & (f < 1))
    # the same points, up to lattice translations
    shift = Cell(box).fractional(back["position"].values - positions)
    np.testing.assert_allclose(shift, np.rint(shift), atol=1e-9)
    with pytest.raises(ValueError, match="diameter"):
        particle_config_dataset(positions, box, 0.0, {})
