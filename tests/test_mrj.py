"""MRJ packings: inflation LPs in the fixed cell (randmedia.generate.inflation) and the
three-stage protocol (randmedia.generate.mrj).

Known answers: an inflation step never creates an overlap and realizes the inflation
it predicts; touching fcc and bcc crystals admit no inflation (collectively jammed in
their cells); every packing of the protocol is strictly jammed by the LP test, exactly
isostatic (M = 3 N_b + 3 contacts among N_b non-rattlers), free of overlaps; a run
killed and resumed from its checkpoint gives the same packing.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from conftest import killed_after
from randmedia.describe import bond_order, jamming
from randmedia.generate import inflation, mrj
from randmedia.generate.jammed import ConstructionError, packing_dataset, packing_fraction
from randmedia.generate.lubachevsky_stillinger import LSParameters
from randmedia.io import read_dataset, write_dataset
from randmedia.periodic import Cell, pairs_within

QUICK = mrj.MRJProtocol(compression=LSParameters(growth_rate=0.1, slowdown_pressure=80,
                                                 target_pressure=1e4), route="compression")


def min_gap(positions, box, cutoff=1.2):
    _, _, _, distance = pairs_within(Cell(box), positions, cutoff)
    return distance.min() - 1.0


@pytest.fixture(scope="module")
def packing():
    return mrj.make_packing(3, 120, QUICK)


def test_inflation_step_is_exact_and_never_overlaps():
    from randmedia.generate.rsa import random_sequential_addition

    positions, box = random_sequential_addition(np.random.default_rng(2), 200, 0.3)
    phi = packing_fraction(positions, box)
    for bound in (0.1, 0.05, 0.01):
        positions, box, record = inflation.inflation_step(positions, box, bound)
        assert min_gap(positions, box, 1.5) >= -1e-12
        assert min_gap(positions, box, 1.5) <= 1e-12  # the closest pair touches
        new_phi = packing_fraction(positions, box)
        assert new_phi > phi
        # realized inflation = predicted up to the solver's round-off (conservative rows)
        assert record["realized"] >= record["inflation"] - 1e-8
        assert np.log(new_phi / phi) / 3 == pytest.approx(np.log1p(record["realized"]), abs=1e-12)
        phi = new_phi


@pytest.mark.parametrize("kind, cells", [("fcc", 3), ("bcc", 3)])
def test_touching_crystals_admit_no_inflation(kind, cells):
    positions, box = bond_order.cubic_lattice(kind, cells)
    _, record = inflation.inflation_step(positions, box, 0.005)[1:]
    assert record["inflation"] < 1e-9
    assert inflation.stop_reason([record["inflation"]], [0.7], inflation.InflationParameters()) == "no inflation"


def test_convergence_by_stall():
    params = inflation.InflationParameters(tolerance=1e-10, stall_lps=3)
    assert inflation.stop_reason([1e-6] * 3, [0.6, 0.61, 0.62], params) is None
    assert inflation.stop_reason([1e-6] * 5, [0.6, 0.62, 0.62, 0.62, 0.62], params) == "stalled"
    assert inflation.stop_reason([], [], params) is None


def test_a_creeping_inflation_ends_at_max_lps_but_is_not_called_jammed():
    """phi still grows every LP (sqrt(Gamma) - 1 ~ 1e-7 >> tolerance): the stage ends at
    max_lps as "max_lps", not as collectively jammed; a converged last LP wins."""
    params = inflation.InflationParameters(tolerance=1e-10, stall_lps=5, max_lps=11)
    phis = list(0.6357 * (1 + 3e-7 * np.arange(11)))
    inflations = [1e-7] * 11
    assert inflation.stop_reason(inflations[:10], phis[:10], params) is None
    assert inflation.stop_reason(inflations, phis, params) == "max_lps"
    assert inflation.stop_reason(inflations, phis, replace(params, max_lps=12)) is None
    assert inflation.stop_reason([1e-11] * 11, phis, params) == "no inflation"


def test_inflation_refuses_a_cutoff_beyond_the_cell():
    positions, box = bond_order.cubic_lattice("fcc", 1)
    with pytest.raises(ValueError, match="half width"):
        inflation.inflation_step(positions, box, 0.1)


@pytest.mark.parametrize("field, value", [
    ("displacement_bound", 0.0), ("displacement_bound", 0.5), ("final_displacement_bound", 0.1),
    ("tolerance", 0.0), ("stall_lps", 1), ("max_lps", 0), ("backend", "glpk"),
])
def test_bad_inflation_parameters_are_refused(field, value):
    with pytest.raises(ValueError, match=field):
        inflation.InflationParameters(**{field: value})


def test_protocol_packing_is_strictly_jammed_and_isostatic(packing):
    analysis = jamming.analyse(packing.positions, packing.box, packing.diameter)
    assert analysis.jammed
    assert analysis.isostatic_excess == 0
    assert min_gap(packing.positions, packing.box) >= -1e-9
    assert 0.62 < packing.phi < 0.65
    assert analysis.rattler_fraction < 0.1
    # every stage is recorded: compression, inflation LPs, TJ polish LPs
    assert packing.compression["pressure"] >= 1e4
    assert packing.n_inflation_lp >= 1 and packing.n_lp > packing.n_inflation_lp
    lps = packing.lp_history()
    assert len(lps["phi"]) == packing.n_lp
    assert np.all(np.diff(lps["phi"][lps["stage"] == 0]) >= -1e-12)  # inflation never loses phi


def test_same_seed_same_packing(packing, tmp_path):
    """Same seed, same packing -- and the same data variables in the written file
    (timings are run metadata and live in attributes, never in data variables)."""
    again = mrj.make_packing(3, 120, QUICK)
    np.testing.assert_array_equal(packing.positions, again.positions)
    np.testing.assert_array_equal(packing.box, again.box)
    written = []
    for k, p in enumerate((packing, again)):
        dataset = packing_dataset(p, jamming.analyse(p.positions, p.box, p.diameter), {})
        path = write_dataset(dataset, tmp_path / f"{k}.nc", rule="test", seed=3, config={})
        written.append(read_dataset(path))
    first, second = written
    assert sorted(first.data_vars) == sorted(second.data_vars)
    for name in first.variables:
        np.testing.assert_array_equal(first[name].values, second[name].values, err_msg=name)
    assert len(first.attrs["lp_solve_seconds"]) == packing.n_lp


def test_killed_run_resumes_from_its_checkpoint(tmp_path, monkeypatch, packing):
    """A kill after a few inflation LPs: the rerun resumes from the checkpoint (it does not
    compress again) and ends with the same packing as the uninterrupted run."""
    checkpoint = tmp_path / "sample.checkpoint.npz"
    real_step = inflation.inflation_step
    monkeypatch.setattr(inflation, "inflation_step", killed_after(3, real_step))
    with pytest.raises(KeyboardInterrupt):
        mrj.make_packing(3, 120, QUICK, checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert checkpoint.is_file()
    monkeypatch.setattr(inflation, "inflation_step", real_step)

    def no_compression(*args, **kwargs):
        raise AssertionError("the resumed run compressed again")

    monkeypatch.setattr(mrj, "compress", no_compression)
    resumed = mrj.make_packing(3, 120, QUICK, checkpoint=checkpoint, checkpoint_seconds=0.0)
    np.testing.assert_array_equal(resumed.positions, packing.positions)
    assert resumed.n_lp == packing.n_lp
    assert not checkpoint.exists()


def test_a_dilute_stage_at_max_lps_hands_over_to_the_polish(tmp_path, monkeypatch):
    """A dilute stage still compacting after max_lps LPs is not discarded: the polish takes
    over (as after the inflation stage's cap), certifies the packing and the file says why
    the dilute stage ended."""
    protocol = mrj.MRJProtocol(route="dilute", dilute=mrj.DiluteTJ(max_lps=30))
    packing = mrj.make_packing(2, 100, protocol)
    assert packing.n_dilute_lp == 30 and packing.dilute_stop == "max_lps"
    assert packing.construction_attrs()["dilute_stop"] == "max_lps"
    assert packing.n_lp > 30  # the polish ran
    analysis = jamming.analyse(packing.positions, packing.box, packing.diameter)
    assert analysis.jammed and analysis.isostatic_excess == 0
    # a kill in the polish: the resumed run still knows why the dilute stage ended
    resumed = made_again_after_a_kill_in_the_polish(2, 100, protocol, tmp_path / "capped.npz")
    assert resumed.dilute_stop == "max_lps" and np.array_equal(resumed.positions, packing.positions)
    # the cap is not in the checkpoint's key, but a stage it ended is only taken back under
    # the same cap (a fresh run under another one would end elsewhere)
    from randmedia.generate import jammed

    checkpoint = tmp_path / "recapped.npz"
    real_step = jammed.tj_step
    monkeypatch.setattr(jammed, "tj_step", killed_in_polish_after(0, real_step))
    with pytest.raises(KeyboardInterrupt):
        mrj.make_packing(2, 100, protocol, checkpoint=checkpoint, checkpoint_seconds=0.0)
    monkeypatch.setattr(jammed, "tj_step", real_step)
    for cap in (20, 40):
        with pytest.raises(ValueError, match=f"ended \\(max_lps\\) after 30 LPs.*max_lps = {cap}"):
            mrj.make_packing(2, 100, replace(protocol, dilute=mrj.DiluteTJ(max_lps=cap)), checkpoint=checkpoint)
    assert checkpoint.exists()


def test_a_polish_at_max_lps_ends_and_is_tested_when_so_configured():
    """polish.at_max_lps "end" (mrj_large's): a polish still compacting at its cap ends after
    one vertex LP, the packing is returned by the first attempt (no redraw) and marked
    "max_lps", and the certificate tests it without repairing it; "redraw" (the shared
    polish's, the default) raises, so make_packing_retrying discards the start."""
    from randmedia.studies.jammed_certificate import certified

    polish = replace(mrj.MRJProtocol().polish, max_lps=3, backend="highs-hipo", final_backend="highs-ipm")
    capped = mrj.MRJProtocol(route="dilute", dilute=mrj.DiluteTJ(max_lps=30), polish=polish,
                             polish_at_max_lps="end")
    packing, attempt = mrj.make_packing_retrying([2, 3], 100, capped)
    assert attempt == 0 and packing.stop == "max_lps" and packing.n_lp == 30 + 4
    assert list(packing.history["final"]) == [0, 0, 0, 1]
    attrs = packing.construction_attrs()
    assert attrs["polish_stop"] == "max_lps" and attrs["polish_at_max_lps"] == "end"
    tested, analysis, repair = certified(packing, capped.polish, {})
    assert repair.rounds == 0 and np.array_equal(tested.positions, packing.positions)
    assert analysis.jammed == jamming.analyse(packing.positions, packing.box, packing.diameter).jammed
    with pytest.raises(ConstructionError, match="max_lps"):
        mrj.make_packing(2, 100, replace(capped, polish_at_max_lps="redraw"))
    with pytest.raises(ValueError, match="polish.at_max_lps"):
        replace(capped, polish_at_max_lps="keep")


def test_the_cap_rules_come_from_the_config():
    """The paper config: mrj_large's polish ends at its cap, the shared polish (mrj, mrj_md)
    redraws, with the key absent (so the kept N = 2000 packings' configuration is unchanged);
    mrj_large's dilute stage ends at the TJ code's 2000 LPs, the shared one at 5000."""
    from conftest import REPO, SCHEMA
    from randmedia.config import load_config, validate_config

    config = load_config(REPO / "config" / "config.yaml")
    validate_config(config, SCHEMA)  # what Snakemake sees: the schema's defaults filled in
    section = config["mrj2016"]["mrj"]
    assert "at_max_lps" not in section["polish"]
    shared = mrj.MRJProtocol.from_config(section)
    assert shared.polish_at_max_lps == "redraw" and shared.dilute.max_lps == 5000
    large = {**section, **{stage: {**section[stage], **section["mrj_large"][stage]} for stage in ("dilute", "polish")}}
    protocol = mrj.MRJProtocol.from_config(large)
    assert protocol.polish_at_max_lps == "end" and protocol.polish.max_lps == 750
    # the TJ code's max_iterations (sdatkinson/TJ, test3d/parameters_3d.txt)
    assert protocol.dilute.max_lps == 2000


def test_unconverged_inflation_hands_over_to_the_polish():
    """After max_lps inflation LPs the TJ polish takes over; the packing is still strictly
    jammed (the polish's own test) and records why the inflation stage ended."""
    protocol = mrj.MRJProtocol(compression=QUICK.compression,
                               inflation=inflation.InflationParameters(max_lps=1), route="compression")
    packing = mrj.make_packing(5, 120, protocol)
    assert packing.n_inflation_lp == 1 and packing.inflation_stop == "max_lps"
    assert packing.construction_attrs()["inflation_stop"] == "max_lps"
    analysis = jamming.analyse(packing.positions, packing.box, packing.diameter)
    assert analysis.jammed and analysis.isostatic_excess == 0


def test_a_packing_whose_polish_creeps_is_made_again_from_the_next_seed(packing, monkeypatch, tmp_path):
    """make_packing_retrying: the first seed's polish fails (ConstructionError, as at max_lps),
    the next seed's packing is returned with its attempt index, each attempt with its own
    checkpoint file, removed once a later attempt made the packing; when every seed fails the
    last error is raised."""
    real = mrj.make_packing
    calls = []

    def creeping_first(seed, n, protocol, *, checkpoint=None, **options):
        calls.append((seed, checkpoint))
        if seed == 11:
            if checkpoint is not None:  # as a real attempt leaves them at max_lps
                checkpoint.write_bytes(b"inflation")
                mrj._polish_checkpoint(checkpoint).write_bytes(b"polish")
            raise ConstructionError("TJ did not converge within max_lps = 500 LPs")
        return real(seed, n, protocol, checkpoint=checkpoint, **options)

    monkeypatch.setattr(mrj, "make_packing", creeping_first)
    checkpoint = tmp_path / ".sample8.checkpoint.npz"
    made, attempt = mrj.make_packing_retrying([11, 3], 120, QUICK, checkpoint=checkpoint)
    assert attempt == 1
    np.testing.assert_array_equal(made.positions, packing.positions)  # seed 3's packing
    assert [c for _, c in calls] == [checkpoint, tmp_path / ".sample8.checkpoint.attempt1.npz"]
    assert sorted(tmp_path.iterdir()) == []  # the discarded attempt's checkpoints are gone
    with pytest.raises(ConstructionError, match="max_lps"):
        mrj.make_packing_retrying([11, 11], 120, QUICK)
    with pytest.raises(ValueError, match="at least one seed"):
        mrj.make_packing_retrying([], 120, QUICK)
    assert mrj.attempt_checkpoint(None, 2) is None


def test_protocol_from_config_names_bad_keys():
    with pytest.raises(ValueError, match="displacement_bound"):
        mrj.MRJProtocol.from_config({"compression": {}, "polish": {},
                                     "inflation": {"displacement_bound": -1.0}})


def test_the_dilute_route_has_the_tj_codes_constants():
    """DiluteTJ: strain bound 0.1 D / L_0 of the phi_0 = 0.1 start (the TJ code scales comp_max
    by its start's diameter), translation 0.01 D in lattice coordinates, no trust region, the
    volume criterion relative to the start volume."""
    import math

    params = mrj.DiluteTJ().tj_parameters(2000)
    side = (2000 * math.pi / 6 / 0.1) ** (1 / 3)
    assert params.max_normal_strain == params.max_shear_strain == pytest.approx(0.1 / side)
    assert params.max_normal_strain == pytest.approx(0.00457, abs=1e-5)
    assert params.translation_max == 0.01 and params.influence_gap == 0.2
    assert not params.trust_region and params.volume_tolerance_start == 1e-8
    # the translation bound follows the cell's linear size
    assert params.translation_bound(3, 1.0, 0.5) == pytest.approx(0.005)
    with pytest.raises(ValueError, match="route"):
        mrj.MRJProtocol(route="lubachevsky")


def test_the_dilute_route_makes_a_strictly_jammed_packing_and_resumes_after_its_first_stage(tmp_path):
    protocol = mrj.MRJProtocol(route="dilute")
    packing = mrj.make_packing(2, 100, protocol)
    assert packing.n_dilute_lp > 50 and packing.n_inflation_lp == 0
    analysis = jamming.analyse(packing.positions, packing.box, packing.diameter)
    assert analysis.jammed and analysis.isostatic_excess == 0
    history = packing.lp_history()
    assert (history["stage"][:packing.n_dilute_lp] == 2).all() and (history["stage"][packing.n_dilute_lp:] == 1).all()
    assert packing.construction_attrs()["route_name"] == "dilute"
    assert packing.dilute_stop == "converged"
    # a kill in the polish: the run resumes after the dilute stage, with the same packing
    resumed = made_again_after_a_kill_in_the_polish(2, 100, protocol, tmp_path / "dilute.npz")
    assert np.array_equal(resumed.positions, packing.positions) and np.array_equal(resumed.box, packing.box)


def made_again_after_a_kill_in_the_polish(seed, n, protocol, checkpoint):
    """make_packing killed in its polish (the second jam call: the dilute stage ran), then
    run again from ``checkpoint``: the second run resumes after the dilute stage (only the
    polish runs) and removes the checkpoint. Returns the second run's packing."""
    import unittest.mock as mock

    calls = {"n": 0}
    original = mrj.jam

    def jam_killed_in_the_polish(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 2:
            raise KeyboardInterrupt
        return original(*args, **kwargs)

    with mock.patch.object(mrj, "jam", jam_killed_in_the_polish), pytest.raises(KeyboardInterrupt):
        mrj.make_packing(seed, n, protocol, checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert checkpoint.exists()
    with mock.patch.object(mrj, "jam", side_effect=lambda *a, **k: original(*a, **k)) as spy:
        resumed = mrj.make_packing(seed, n, protocol, checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert spy.call_count == 1  # the polish only
    assert not checkpoint.exists()
    return resumed


def killed_in_polish_after(calls: int, step):
    """``step``, but raising KeyboardInterrupt on the polish's (trust-region) LP ``calls`` + 1;
    the dilute stage's LPs (``trust_region`` False, the TJ code's) pass."""
    dying = killed_after(calls, step)
    return lambda positions, box, params, *args, **kwargs: (
        (dying if params.trust_region else step)(positions, box, params, *args, **kwargs))


# the polish case stops the dilute stage early (volume tolerance 5e-4 instead of 1e-8), so
# that its polish has ~60 LPs to be killed in
@pytest.mark.parametrize("stage, kill, volume_tolerance", [
    ("dilute", lambda step: killed_after(60, step), 1e-8),
    ("polish", lambda step: killed_in_polish_after(30, step), 5e-4)])
def test_a_stage_killed_and_resumed_counts_the_cpu_of_both_processes(tmp_path, monkeypatch, stage, kill,
                                                                      volume_tolerance):
    """The packing's cpu_seconds after a kill inside the dilute stage, or inside the polish
    (its own checkpoint), include the killed process's LPs (the stage's checkpoint keeps its
    clocks), not only the resumed one's (sample 9 of the paper config said 3953 CPU s for
    5266 before the polish was counted)."""
    import time

    from randmedia.generate import jammed

    protocol = mrj.MRJProtocol(route="dilute", dilute=mrj.DiluteTJ(volume_tolerance=volume_tolerance))
    checkpoint = tmp_path / "dilute.npz"
    real_step = jammed.tj_step
    monkeypatch.setattr(jammed, "tj_step", kill(real_step))
    with pytest.raises(KeyboardInterrupt):
        mrj.make_packing(2, 100, protocol, checkpoint=checkpoint, checkpoint_seconds=0.0)
    # the killed process's stage CPU as its checkpoint recorded it (the process's own clock
    # would also count imports and numba compilation, which no run clock sees)
    killed = float(np.load(checkpoint.with_name(f"dilute.{stage}.npz"))["cpu"])
    # the packing's own checkpoint (after the dilute stage): its clock already counts that stage
    before = float(np.load(checkpoint)["cpu"]) if checkpoint.exists() else 0.0
    monkeypatch.setattr(jammed, "tj_step", real_step)
    resumed_cpu = time.process_time()
    resumed = mrj.make_packing(2, 100, protocol, checkpoint=checkpoint, checkpoint_seconds=0.0)
    resumed_cpu = time.process_time() - resumed_cpu
    assert killed > 0.2
    assert resumed.cpu_seconds > before + resumed_cpu + 0.5 * killed
