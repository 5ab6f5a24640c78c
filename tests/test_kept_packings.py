"""The MRJ packings kept beside the record (record/packings/mrj2016/): each is overlap-free,
has the packing fraction it claims, was certified strictly jammed at the configured contact
gap, carries its provenance, and was made with the paper config's current packing parameters
(so a paper-config run takes it back instead of regenerating it)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import yaml

from randmedia.config import MRJ_ROUTE_STAGES
from randmedia.generate import PARTICLE_CONFIG, particle_config_dataset
from randmedia.generate.jammed import packing_fraction
from randmedia.io import read_dataset
from randmedia.periodic import Cell, min_pair_distance

REPO = Path(__file__).resolve().parents[1]
KEPT = sorted((REPO / "record" / "packings" / "mrj2016").glob("*/sample*.nc"))
SECTION = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["mrj2016"]["mrj"]


@pytest.mark.skipif(not KEPT, reason="no packings kept in record/packings/mrj2016 yet")
@pytest.mark.parametrize("path", KEPT, ids=[f"{p.parent.name}/{p.stem}" for p in KEPT])
def test_a_kept_packing_is_certified_and_made_with_the_paper_config(path):
    ds = read_dataset(path, PARTICLE_CONFIG, attrs=("phi", "jammed", "gap_tolerance", "n_particles",
                                                      "config_json", "seed", "git_commit"))
    positions, box = ds["position"].values, ds["box"].values
    diameter = float(ds.attrs["diameter"])
    assert positions.shape == (SECTION[path.parent.name]["n_particles"], 3)
    assert min_pair_distance(Cell(box), positions, 1.1 * diameter) >= diameter * (1 - 1e-9)
    assert packing_fraction(positions, box, diameter) == pytest.approx(float(ds.attrs["phi"]), rel=1e-12)
    # strictly jammed by the independent test at the one configured contact gap
    assert int(ds.attrs["jammed"]) == 1
    assert float(ds.attrs["gap_tolerance"]) == SECTION["contacts"]["gap_tolerance"]
    assert int(ds.attrs["isostatic_excess"]) == 0
    made_with = json.loads(ds.attrs["config_json"])
    system = SECTION[path.parent.name]
    route = system.get("route", SECTION["route"])  # mrj_md's own route (workflow/rules/common.smk)
    assert made_with["route"] == route
    for stage in ("polish", "contacts") + MRJ_ROUTE_STAGES[route]:
        # a system's own stage keys over the shared ones (workflow/rules/common.smk)
        wanted = {**SECTION[stage], **system.get(stage, {})}
        assert made_with[stage] == wanted, f"{path}: {stage} differs from config/config.yaml"
    assert np.isfinite(positions).all()


UNCERTIFIED = sorted((REPO / "record" / "packings" / "mrj2016_uncertified").glob("*/sample*.nc"))


@pytest.mark.skipif(not UNCERTIFIED, reason="no uncertified packings kept")
@pytest.mark.parametrize("path", UNCERTIFIED, ids=[f"{p.parent.name}/{p.stem}" for p in UNCERTIFIED])
def test_an_uncertified_kept_packing_is_overlap_free_and_says_it_is_not_jammed(path):
    """The packings that failed the jamming test are kept beside the certified ones (counted,
    not replaced): overlap-free, with the packing fraction and provenance they claim."""
    ds = read_dataset(path, PARTICLE_CONFIG, attrs=("phi", "jammed", "gap_tolerance", "config_json",
                                                      "seed", "git_commit"))
    positions, box = ds["position"].values, ds["box"].values
    diameter = float(ds.attrs["diameter"])
    assert min_pair_distance(Cell(box), positions, 1.1 * diameter) >= diameter * (1 - 1e-9)
    assert packing_fraction(positions, box, diameter) == pytest.approx(float(ds.attrs["phi"]), rel=1e-12)
    assert int(ds.attrs["jammed"]) == 0
    assert json.loads(ds.attrs["config_json"])["n_particles"] == positions.shape[0]


QUICK_PACKING = REPO / "tests" / "data" / "mrj2016_quick_mrj_sample0.nc"


def _cpu_model() -> str | None:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        return None
    return None


def test_a_kept_quick_packing_is_regenerated_bit_for_bit_from_its_seed():
    """The quick config's sample 0 (tests/data, made by the packing rule with the route then
    configured) is made again from the seed and configuration it records: the same positions
    and cell to the last bit, on any CPU. The BLAS libraries pick kernels by CPU, so this was
    first claimed only on the CPU model that made the file (AMD EPYC); regenerated on an Intel
    Xeon with AVX-512 (2026-12-05) it was identical too, 396 LPs, and forcing OpenBLAS' Haswell
    kernels there (OPENBLAS_CORETYPE) changed it (432 LPs): so the defaults give the same bits
    on both CPU kinds seen here (the .json lists them). A CPU on which it fails is a finding
    to report, not a case to skip."""
    from randmedia.generate.mrj import MRJProtocol, make_packing

    provenance = json.loads(QUICK_PACKING.with_suffix(".json").read_text())
    ds = read_dataset(QUICK_PACKING, PARTICLE_CONFIG)
    config = json.loads(ds.attrs["config_json"])
    packing = make_packing(int(ds.attrs["seed"]), config["n_particles"], MRJProtocol.from_config(config))
    # as the packing rule writes it (positions wrapped into the cell by the file contract)
    again = particle_config_dataset(packing.positions, packing.box, packing.diameter, {})
    same = (np.array_equal(again["position"].values, ds["position"].values)
            and np.array_equal(again["box"].values, ds["box"].values))
    assert same, (f"regenerated packing differs on {_cpu_model()!r} (made on {provenance['cpu_model']!r}, "
                  f"identical on {provenance['identical_on']}): max |dx| = "
                  f"{np.abs(again['position'].values - ds['position'].values).max():.3g} D")
