"""The MRJ packings kept beside the record (record/mrj2016/packings/): each is overlap-free,
has the packing fraction it claims, was certified strictly jammed at the configured contact
gap, carries its provenance, and was made with the paper config's current packing parameters
(so a paper-config run takes it back instead of regenerating it)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import yaml

from randmedia.generate import PARTICLE_CONFIG
from randmedia.generate.jammed import packing_fraction
from randmedia.io import read_dataset
from randmedia.periodic import Cell, min_pair_distance

REPO = Path(__file__).resolve().parents[1]
KEPT = sorted((REPO / "record" / "mrj2016" / "packings").glob("*/sample*.nc"))
SECTION = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["mrj2016"]["mrj"]


@pytest.mark.skipif(not KEPT, reason="no packings kept in record/mrj2016/packings yet")
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
    route = SECTION["route"]
    assert made_with["route"] == route
    for stage in ("polish", "contacts", "dilute" if route == "dilute" else "compression"):
        assert made_with[stage] == SECTION[stage], f"{path}: {stage} differs from config/config.yaml"
    assert np.isfinite(positions).all()
