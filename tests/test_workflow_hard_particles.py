"""Quick-config outputs of the hard-particle rules (debye2020 hard disks, mrj2016 liquid).

Uses the session's quick run. Until the lead adds HARD_DISKS_TARGETS and
EQUILIBRIUM_TARGETS to the default target, the fixture builds the named targets
``debye2020_hard_disks`` and ``mrj2016_equilibrium`` in that folder (a no-op once `all`
contains them).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from conftest import QUICK_RESULTS, quick_config, run_snakemake
from randmedia.compare import COLUMNS
from randmedia.generate import PARTICLE_CONFIG, PHASE_IMAGE
from randmedia.generate.disks import digitize_disks
from randmedia.generate.hard_particles.geometry import count_overlaps
from randmedia.io import VariableSpec, read_dataset
from randmedia.theory.hard_spheres import compressibility_factor

pytestmark = pytest.mark.workflow


@pytest.fixture(scope="module")
def hard_particles_run(quick_run):
    result = run_snakemake(quick_run, "debye2020_hard_disks", "mrj2016_equilibrium", "--cores", "2",
                           "--configfile", "config/quick.yaml")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return quick_run, quick_config(quick_run)


def test_hard_disk_images(hard_particles_run):
    workdir, config = hard_particles_run
    section = config["debye2020"]["hard_disks"]
    n_samples = section["n_chains"] * section["samples_per_chain"]
    side, radius = section["L"], section["radius"]
    n_disks = round(section["phi2"] * side**2 / (np.pi * radius**2))
    spec = {**PHASE_IMAGE, "position": VariableSpec(("particle", "xyz"), "pixel"),
            "box": VariableSpec(("xyz", "vec"), "pixel")}
    folder = workdir / f"{QUICK_RESULTS}/debye2020/hard_disks/phi{section['phi2']:g}"
    assert len(list(folder.glob("sample*.nc"))) == n_samples
    for k in range(n_samples):
        ds = read_dataset(folder / f"sample{k}.nc", spec, attrs=["phi2", "radius", "L", "sample"])
        positions = ds["position"].values
        assert positions.shape == (n_disks, 2) and ds["phase"].shape == (side, side)
        assert ds["phase"].dtype == np.uint8 and ds.attrs["sample"] == k
        assert count_overlaps(positions, [side, side], 2 * radius) == 0
        # the image is the pixel-centre digitization of the stored disks
        np.testing.assert_array_equal(ds["phase"].values,
                                      digitize_disks(positions, radius, (side, side)))
        assert ds.attrs["msd_since_previous"] >= section["mc"]["sample_msd"]
        assert ds.attrs["phi2_digitized"] == pytest.approx(ds["phase"].values.mean())
    comparison = pd.read_csv(workdir / f"{QUICK_RESULTS}/debye2020/validation/hard_disks_comparison.csv")
    assert tuple(comparison.columns) == COLUMNS and comparison["passed"].all(), comparison
    for name in ("eos.pdf", "eos.png", "diagnostics.csv"):
        assert (workdir / f"{QUICK_RESULTS}/debye2020/validation/hard_disks_{name}").stat().st_size > 0


def test_liquid_samples(hard_particles_run):
    workdir, config = hard_particles_run
    section = config["mrj2016"]["equilibrium"]
    n_samples = section["n_chains"] * section["samples_per_chain"]
    folder = workdir / f"{QUICK_RESULTS}/mrj2016/configs/equilibrium"
    assert len(list(folder.glob("sample*.nc"))) == n_samples
    assert not list(folder.glob(".*checkpoint*"))  # removed after a finished chain
    for k in range(n_samples):
        ds = read_dataset(folder / f"sample{k}.nc", PARTICLE_CONFIG,
                          attrs=["diameter", "phi", "seed", "chain", "global_q6",
                                 "crystalline_fraction", "msd_since_previous", "acceptance"])
        box = np.diag(ds["box"].values)
        assert ds["position"].shape == (section["n_particles"], 3) and ds.attrs["diameter"] == 1.0
        assert ds.attrs["phi"] == pytest.approx(section["phi"], rel=1e-12)
        assert count_overlaps(ds["position"].values, box, 1.0) == 0
        assert ds.attrs["msd_since_previous"] >= section["mc"]["sample_msd"]
        assert ds.attrs["global_q6"] < 0.1 and ds.attrs["crystalline_fraction"] < 0.05
        assert abs(ds.attrs["acceptance"] - section["mc"]["target_acceptance"]) < 0.05
    frame = pd.read_csv(workdir / f"{QUICK_RESULTS}/mrj2016/validation/equilibrium_diagnostics.csv")
    z = frame["reduced_pressure"]
    expected = compressibility_factor(section["phi"], 3, section["eos"])
    # 4 samples of 500 spheres: SEM ~0.3 %; the acceptance criterion is 1 %
    assert z.mean() == pytest.approx(expected, rel=0.01)
    comparison = pd.read_csv(workdir / f"{QUICK_RESULTS}/mrj2016/validation/equilibrium_comparison.csv")
    assert comparison["passed"].all(), comparison
