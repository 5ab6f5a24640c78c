"""The MRJ packings of the quick run: file contract, strict jamming, isostaticity, summary."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from conftest import QUICK_RESULTS, quick_config, run_snakemake
from randmedia.describe import jamming
from randmedia.generate import PARTICLE_CONFIG
from randmedia.io import read_dataset
from randmedia.mrj_stages import system_stage
from randmedia.periodic import Cell, pairs_within

pytestmark = pytest.mark.workflow


@pytest.fixture(scope="module")
def jammed_run(quick_run):
    """The quick run with the MRJ packings. Until mrj2016.smk puts JAMMED_TARGETS into
    MRJ2016_TARGETS (hence into `all`), the named target mrj2016_jammed is built here in the
    same working folder (only its own jobs run); afterwards this is a no-op."""
    if not (quick_run / f"{QUICK_RESULTS}/mrj2016/packings.csv").exists():
        result = run_snakemake(quick_run, "mrj2016_jammed", "--cores", "2", "--configfile",
                               "config/quick.yaml")
        assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-5000:]
    return quick_run


@pytest.fixture(scope="module")
def section(jammed_run):
    return quick_config(jammed_run)["mrj2016"]["mrj"]


SYSTEMS = ("mrj", "mrj_large", "mrj_md")


def packing_files(workdir, section):
    return [(system, k, workdir / f"{QUICK_RESULTS}/mrj2016/configs/{system}/sample{k}.nc")
            for system in SYSTEMS for k in range(section[system]["n_samples"])]


def test_packings_follow_the_contract_and_are_jammed(jammed_run, section):
    for system, k, path in packing_files(jammed_run, section):
        ds = read_dataset(path, PARTICLE_CONFIG, attrs=jamming.PACKING_ATTRS + ("seconds", "seed"))
        positions, box = ds["position"].values, ds["box"].values
        assert positions.shape == (section[system]["n_particles"], 3)
        assert ds.attrs["diameter"] == 1.0 and ds.attrs["system"] == system
        _, _, _, distance = pairs_within(Cell(box), positions, 1.2)
        assert distance.min() >= 1.0 - 1e-12  # no overlap
        assert 0.58 < ds.attrs["phi"] < 0.66
        assert ds.attrs["phi"] == pytest.approx(len(positions) * np.pi / 6 / np.linalg.det(box))
        assert ds.attrs["jammed"] == 1 and ds.attrs["isostatic_excess"] == 0
        n_b = len(positions) - int(ds["rattler"].values.sum())
        assert ds.attrs["z_mean_nonrattlers"] == pytest.approx(6 + 6 / n_b)
        # the stored contact list is the gap-test network of the stored packing
        network = jamming.contact_network(positions, box, gap_tolerance=ds.attrs["gap_tolerance"])
        np.testing.assert_array_equal(ds["contact"].values, network.pairs)
        # the tolerance lies in an empty range of gaps: contacts are closed to the LP's
        # round-off, set by HiPO's feasibility tolerance 1e-10 (packing_lp.HIPO_OPTIONS; 1.03e-11 D
        # in a quick packing of the dilute route, ~1e-12 with IPX + crossover), far below it;
        # non-contacts lie above it. (Jammed packings have a power-law excess of near contacts,
        # g(h) ~ h^-0.4, so the nearest non-contact can come within a decade of the tolerance:
        # 8e-9 D in one quick packing.)
        max_contact_gap = ds["contact_gap"].values.max()
        assert max_contact_gap < ds.attrs["gap_tolerance"] / 10
        assert ds.attrs["min_noncontact_gap"] > ds.attrs["gap_tolerance"]
        assert ds.attrs["min_noncontact_gap"] > 1e3 * max(max_contact_gap, 1e-16)
        assert 0 <= ds.attrs["Q6"] < 0.2 and ds.attrs["crystal_fraction"] < 0.05


def test_a_system_polishes_with_its_own_solver(jammed_run, section):
    """mrj_large's own polish and contacts keys (the paper config's, which the quick config
    keeps: HiPO, then IPX + crossover in a final phase, a larger cap; a lower rank tolerance)
    reach its packings, and only them; the test above certifies them strictly jammed at the
    same contact gap."""
    assert section["mrj_large"]["polish"]["backend"] != section["polish"]["backend"]
    assert section["mrj_large"]["polish"]["max_lps"] != section["polish"]["max_lps"]
    assert section["mrj_large"]["polish"]["at_max_lps"] == "end" and "at_max_lps" not in section["polish"]
    assert section["mrj_large"]["contacts"]["rank_tolerance"] != section["contacts"]["rank_tolerance"]
    for system, k, path in packing_files(jammed_run, section):
        made_with = json.loads(read_dataset(path).attrs["config_json"])
        for stage in ("polish", "contacts"):
            assert made_with[stage] == system_stage(section, system, stage)


def test_md_like_packings_are_ls_compressions_at_their_own_rate(jammed_run, section):
    """mrj_md (the MD packings of Ref. [29]) is made by the compression route with its own
    constant growth rate over the shared compression keys, while the MRJ systems keep the
    paper's dilute route and carry no compression keys; its packings pass the same jamming
    test (test_packings_follow_the_contract_and_are_jammed)."""
    own = section["mrj_md"]["compression"]
    assert own["slowdown_pressure"] == own["target_pressure"]  # constant growth
    assert section["route"] == "dilute" and section["mrj_md"]["route"] == "compression"
    for system, k, path in packing_files(jammed_run, section):
        attrs = read_dataset(path).attrs
        made_with = json.loads(attrs["config_json"])
        if system == "mrj_md":
            assert made_with["route"] == "compression" and made_with["dilute"] == {}
            assert made_with["compression"] == {**section["compression"], **own}
            assert attrs["compression_growth_rate"] == own["growth_rate"]
            assert attrs["compression_final_pressure"] >= own["target_pressure"]
        else:
            assert made_with["route"] == "dilute" and made_with["compression"] == {}


def test_packings_table_matches_the_files(jammed_run, section):
    table = pd.read_csv(jammed_run / f"{QUICK_RESULTS}/mrj2016/packings.csv")
    for system in SYSTEMS:
        rows = table[(table["system"] == system) & ~table["sample"].isin(["mean", "sem"])]
        assert len(rows) == section[system]["n_samples"]
        mean = table[(table["system"] == system) & (table["sample"] == "mean")].iloc[0]
        assert mean["phi"] == pytest.approx(rows["phi"].mean())
        assert mean["jammed"] == 1.0
    for system, k, path in packing_files(jammed_run, section):
        row = table[(table["system"] == system) & (table["sample"] == str(k))].iloc[0]
        attrs = read_dataset(path).attrs
        assert row["phi"] == pytest.approx(attrs["phi"], rel=1e-12)
        assert row["attempt"] == attrs["attempt"]  # which seed made it (0: the first)
        if attrs.get("route_name") == "dilute":  # which rule ended the dilute stage
            assert row["dilute_stop"] == attrs["dilute_stop"] and row["dilute_stop"] in ("converged", "max_lps")
        # why the polish ended: every quick polish converges (mrj_large's would end at its cap)
        assert row["polish_stop"] == attrs["polish_stop"] == "converged"
        # the cost of its construction (issue 26 section 4), the file's own measurement
        assert row["cpu_seconds"] == pytest.approx(attrs["cpu_seconds"], rel=1e-12)
        assert row["cpu_seconds"] > 0
        # jammed at the configured tolerance, so certified at the first rung of the ladder
        assert row["certified_gap_tolerance"] == pytest.approx(section["contacts"]["gap_tolerance"])


def test_each_packing_has_its_certificate(jammed_run, section):
    """One certificate per packing (rule mrj2016_packing_certificate): the test repeated at the
    configured gap tolerance gives the packing's stored outcome and network, so the quick
    packings (all jammed) stop at that first rung."""
    for system, k, path in packing_files(jammed_run, section):
        certificate = pd.read_csv(path.with_name(f"sample{k}.certificate.csv"))
        attrs = read_dataset(path).attrs
        assert len(certificate) == 1, (system, k)
        first = certificate.iloc[0]
        assert first["gap_tolerance"] == pytest.approx(section["contacts"]["gap_tolerance"])
        assert bool(first["jammed"]) == bool(attrs["jammed"]) is True
        assert first["n_pairs"] == attrs["n_contacts"]
        assert first["isostatic_excess"] == attrs["isostatic_excess"] == 0
        assert first["n_backbone"] == round(attrs["n_particles"] * (1 - attrs["rattler_fraction"]))
        assert first["min_force_ratio"] > 0 and first["cpu_seconds"] > 0


def test_every_packing_and_its_certificate_are_kept_and_taken_back(jammed_run, section, tmp_path):
    """Each packing job keeps a copy beside the record (here the quick config's
    {results}/record/packings/mrj2016/ when certified, .../mrj2016_uncertified/ otherwise), and
    each certificate job keeps its ladder beside it (randmedia.kept_certificates); a job on a
    machine without results/ takes both back (same seed and configuration; same packing, contact
    options and code) instead of making them again."""
    from conftest import copy_workflow
    from randmedia.kept_certificates import kept_certificate_path
    from randmedia.kept_configurations import kept_path, unfinished_dir

    keep_dir = f"{QUICK_RESULTS}/record/packings/mrj2016"
    for system, k, path in packing_files(jammed_run, section):
        made = read_dataset(path)
        certified = bool(int(made.attrs["jammed"]))
        kept = read_dataset(jammed_run / kept_path(keep_dir, system, k, certified=certified))
        assert kept.identical(made)
        assert not (jammed_run / kept_path(keep_dir, system, k, certified=not certified)).exists()
        # the checkpoints kept while it ran are gone once it is made
        assert not (jammed_run / unfinished_dir(keep_dir, system)).exists()
        kept_certificate = json.loads(
            (jammed_run / kept_certificate_path(keep_dir, system, k, certified=certified)).read_text())
        certificate = pd.read_csv(path.with_name(f"sample{k}.certificate.csv"))
        assert pd.DataFrame(kept_certificate["ladder"]).equals(certificate)
        # a system's own contact keys over the shared ones (mrj_large: its rank tolerance)
        assert kept_certificate["key"]["contacts"] == system_stage(section, system, "contacts")
    fresh = copy_workflow(tmp_path / "fresh")
    for target in (kept_path(keep_dir, "mrj", 0), kept_certificate_path(keep_dir, "mrj", 0)):
        (fresh / target).parent.mkdir(parents=True, exist_ok=True)
        (fresh / target).write_bytes((jammed_run / target).read_bytes())
    output = f"{QUICK_RESULTS}/mrj2016/configs/mrj/sample0.nc"
    certificate = output.removesuffix(".nc") + ".certificate.csv"
    result = run_snakemake(fresh, certificate, "--cores", "1", "--configfile", "config/quick.yaml")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-5000:]
    log = (fresh / f"{QUICK_RESULTS}/mrj2016/logs/jammed_mrj_sample0.log").read_text()
    assert "taken from the kept copy" in log
    assert read_dataset(fresh / output).identical(read_dataset(jammed_run / output))
    log = (fresh / f"{QUICK_RESULTS}/mrj2016/logs/packing_certificate_mrj_sample0.log").read_text()
    assert "taken from the kept certificate" in log
    assert (fresh / certificate).read_bytes() == (jammed_run / certificate).read_bytes()
