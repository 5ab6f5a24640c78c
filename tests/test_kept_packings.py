"""The MRJ packings kept beside the record (record/packings/mrj2016/): each is overlap-free,
has the packing fraction it claims, was certified strictly jammed at the configured contact
gap, carries its provenance, and was made with the paper config's current packing parameters
(so a paper-config run takes it back instead of regenerating it)."""

from __future__ import annotations

import inspect
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from randmedia.blas_kernels import PINNED_KERNELS
from randmedia.config import MRJ_ROUTE_STAGES
from randmedia.generate import PARTICLE_CONFIG
from randmedia.generate.jammed import packing_fraction
from randmedia.io import read_dataset
from randmedia.mrj_stages import system_stage
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
    system = path.parent.name
    route = system_stage(SECTION, system, "route")  # mrj_md's own route
    assert made_with["route"] == route
    for stage in ("polish", "contacts") + MRJ_ROUTE_STAGES[route]:
        assert made_with[stage] == system_stage(SECTION, system, stage), \
            f"{path}: {stage} differs from config/config.yaml"
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


CERTIFICATES = sorted((REPO / "record" / "packings").glob("mrj2016*/*/sample*.certificate.json"))


@pytest.mark.skipif(not CERTIFICATES, reason="no certificates kept yet")
@pytest.mark.parametrize("path", CERTIFICATES, ids=[f"{p.parent.parent.name}/{p.parent.name}/{p.stem}"
                                                    for p in CERTIFICATES])
def test_a_kept_certificate_belongs_to_the_packing_beside_it(path):
    """A kept certificate (randmedia.kept_certificates) was computed from the packing kept beside
    it, with the configured contact options and the current code of the test (else a new machine
    would recompute it: ~80 CPU min for the uncertified N = 10 000 packing); its ladder starts at
    the configured gap with the packing's stored outcome and ends at the first pass (certified
    packings: the first rung)."""
    from randmedia.describe.jamming_resolution import gap_ladder
    from randmedia.kept_certificates import certificate_key, ladder_sources

    ds = read_dataset(path.with_name(path.name.replace(".certificate.json", ".nc")), PARTICLE_CONFIG,
                      attrs=("jammed",))
    kept = json.loads(path.read_text())
    current = certificate_key(ds["position"].values, ds["box"].values, float(ds.attrs["diameter"]),
                              {}, ladder_sources())
    assert kept["key"]["packing_sha256"] == current["packing_sha256"]
    assert kept["key"]["code_sha256"] == current["code_sha256"], (
        f"{path.relative_to(REPO)} was computed by other code of the jamming test: rerun its "
        f"certificate job (snakemake --cores 1 --force -- results/mrj2016/configs/{path.parent.name}/"
        f"{path.name.replace('.json', '.csv')}) and commit the file it rewrites")
    contacts = system_stage(SECTION, path.parent.name, "contacts")  # mrj_large: its own rank tolerance
    assert kept["key"]["contacts"] == contacts
    ladder = kept["ladder"]
    assert ladder[0]["gap_tolerance"] == contacts["gap_tolerance"]
    assert ladder[0]["jammed"] == bool(int(ds.attrs["jammed"])) == (path.parent.parent.name == "mrj2016")
    assert [row["jammed"] for row in ladder[:-1]] == [False] * (len(ladder) - 1)
    # not certified: the ladder went up to its last rung (gap_ladder's max_tolerance)
    last_rung = inspect.signature(gap_ladder).parameters["max_tolerance"].default
    assert ladder[-1]["jammed"] or ladder[-1]["gap_tolerance"] == last_rung


QUICK_PACKING = REPO / "tests" / "data" / "mrj2016_quick_mrj_sample0.nc"


def _cpu_model() -> str | None:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        return None
    return None


_REGENERATE = """
import json, sys
import numpy as np
from randmedia.generate import PARTICLE_CONFIG, particle_config_dataset
from randmedia.generate.mrj import MRJProtocol, make_packing
from randmedia.io import read_dataset
ds = read_dataset(sys.argv[1], PARTICLE_CONFIG)
config = json.loads(ds.attrs["config_json"])
packing = make_packing(int(ds.attrs["seed"]), config["n_particles"], MRJProtocol.from_config(config))
# as the packing rule writes it (positions wrapped into the cell by the file contract)
again = particle_config_dataset(packing.positions, packing.box, packing.diameter, {})
np.savez(sys.argv[2], position=again["position"].values, box=again["box"].values)
"""


def test_a_kept_quick_packing_is_regenerated_bit_for_bit_from_its_seed(tmp_path):
    """The quick config's sample 0 (tests/data, made by the packing rule with the route then
    configured) is made again from the seed and configuration it records: the same positions
    and cell to the last bit, on any x86-64 CPU with AVX2, given the same BLAS kernels. OpenBLAS
    picks its kernels by CPU, and the LP trajectory is chaotic in the last bit: from one seed,
    AVX-512 kernels (an AMD EPYC with them, an Intel Xeon) made 396 LPs, the Haswell kernels 432
    (forced on that Xeon, and the default on an AMD EPYC without AVX-512, 2026-12-07), the
    Prescott kernels 387. So the packing is kept as made with the Haswell kernels (OPENBLAS_CORETYPE,
    the .json; the ones the workflow pins for its jobs, randmedia.blas_kernels), which every AVX2 CPU runs, and regenerated with them in a fresh process (the
    variable is read when OpenBLAS loads). A CPU on which it fails is a finding to report, not a
    case to skip."""
    provenance = json.loads(QUICK_PACKING.with_suffix(".json").read_text())
    assert provenance["openblas_coretype"] == PINNED_KERNELS
    output = tmp_path / "again.npz"
    result = subprocess.run([sys.executable, "-c", _REGENERATE, str(QUICK_PACKING), str(output)],
                            env={**os.environ, "OPENBLAS_CORETYPE": PINNED_KERNELS},
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr[-3000:]
    again = np.load(output)
    ds = read_dataset(QUICK_PACKING, PARTICLE_CONFIG)
    same = (np.array_equal(again["position"], ds["position"].values)
            and np.array_equal(again["box"], ds["box"].values))
    assert same, (f"regenerated packing differs on {_cpu_model()!r} with the {PINNED_KERNELS} kernels (made on "
                  f"{provenance['cpu_model']!r}, identical on {provenance['identical_on']}): max |dx| = "
                  f"{np.abs(again['position'] - ds['position'].values).max():.3g} D")
