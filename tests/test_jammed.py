"""Torquato-Jiao jammed packings: RSA start, LP rows, cell reduction, the SLP, contacts,
rattlers, isostatic counting and the LP jamming test (randmedia.generate.jammed,
randmedia.generate.packing_lp, randmedia.generate.rsa, randmedia.describe.jamming).

Counting tested exactly: a strictly jammed backbone of N_b spheres in a deformable
periodic cell has M >= d (N_b - 1) + d (d + 1) / 2 contacts (translations without the
global one plus the symmetric strain); the TJ packings are exactly isostatic, M equal to
that bound, so the mean contact number of the non-rattlers is 2 M / N_b =
2 d + (d^2 - d) / N_b (3D: 6 + 6 / N_b).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from conftest import killed_after
from randmedia.describe import bond_order, jamming
from randmedia.generate import jammed, packing_lp
from randmedia.generate.rsa import RSA_SATURATION, random_sequential_addition
from randmedia.periodic import Cell, pairs_within
from randmedia.theory.balls import ball_volume


def min_gap(positions, box, cutoff=1.2):
    _, _, _, distance = pairs_within(Cell(box), positions, cutoff)
    return distance.min() - 1.0


@pytest.fixture(scope="module")
def packing3d():
    start, box = random_sequential_addition(np.random.default_rng(3), 64, 0.25)
    return jammed.jam(start, box, jammed.TJParameters())


@pytest.fixture(scope="module")
def packing2d():
    start, box = random_sequential_addition(np.random.default_rng(5), 40, 0.3, dim=2)
    return jammed.jam(start, box, jammed.TJParameters())


# --------------------------------------------------------------------------- start and input


@pytest.mark.parametrize("dim", [2, 3])
def test_rsa_start_is_nonoverlapping_at_the_requested_fraction(dim):
    positions, box = random_sequential_addition(np.random.default_rng(1), 300, 0.2, dim=dim)
    assert positions.shape == (300, dim)
    assert jammed.packing_fraction(positions, box) == pytest.approx(0.2, rel=1e-12)
    assert min_gap(positions, box, 1.5) >= 0
    again, _ = random_sequential_addition(np.random.default_rng(1), 300, 0.2, dim=dim)
    np.testing.assert_array_equal(positions, again)


@pytest.mark.parametrize("kwargs, message", [
    (dict(n=1, phi=0.2), "at least 2"),
    (dict(n=100, phi=0.9 * RSA_SATURATION[3]), "RSA start"),
    (dict(n=100, phi=0.0), "RSA start"),
    (dict(n=100, phi=0.2, diameter=0.0), "diameter"),
    (dict(n=100, phi=0.2, dim=4), "dimension"),
])
def test_rsa_refuses_impossible_input(kwargs, message):
    with pytest.raises(ValueError, match=message):
        random_sequential_addition(np.random.default_rng(0), **kwargs)


@pytest.mark.parametrize("n, phi, diameter, message", [
    (1, 0.5, 1.0, "at least 2"),
    (100, 0.75, 1.0, "impossible"),  # above fcc, pi / sqrt(18) = 0.7405
    (100, 0.5, -1.0, "diameter"),
])
def test_packing_input_validation(n, phi, diameter, message):
    with pytest.raises(ValueError, match=message):
        jammed.validate_packing_input(n, phi, 3, diameter)


def test_jam_refuses_overlapping_start():
    positions, box = random_sequential_addition(np.random.default_rng(0), 60, 0.2)
    positions[1] = positions[0] + [0.5, 0, 0]
    with pytest.raises(ValueError, match="overlaps"):
        jammed.jam(positions, box)


def test_jam_refuses_a_start_denser_than_fcc():
    positions, box = bond_order.cubic_lattice("fcc", 3)
    with pytest.raises(ValueError, match="impossible"):
        jammed.jam(positions, box * 0.99)


@pytest.mark.parametrize("field, value", [
    ("influence_gap", 0.0), ("max_normal_strain", 0.5), ("max_shear_strain", -0.01),
    ("translation_fraction", 1.5), ("tolerance", 0.0), ("max_lps", 0), ("backend", "glpk"),
])
def test_bad_tj_parameters_are_refused(field, value):
    with pytest.raises(ValueError, match=field):
        jammed.TJParameters(**{field: value})


# --------------------------------------------------------------------------- LP building blocks


def test_constraint_rows_are_the_first_order_change_of_the_pair_distance():
    """Row . x = (|r'|^2 - |r|^2) / (2 rho) + O(x^2) for r' = (I + eps)(r + u_j - u_i)."""
    rng = np.random.default_rng(2)
    n, dim = 5, 3
    i, j = np.array([0, 1, 3]), np.array([2, 4, 4])
    separation = rng.normal(size=(3, dim))
    distance = np.linalg.norm(separation, axis=1)
    matrix = packing_lp.constraint_matrix(n, i, j, separation, distance).toarray()
    direction = rng.normal(size=matrix.shape[1])
    for scale in (1e-4, 1e-5):
        x = scale * direction
        eps = packing_lp.strain_matrix(x[:6], dim)
        u = x[6:].reshape(n, dim)
        moved = (separation + u[j] - u[i]) @ (np.eye(dim) + eps).T
        exact = (np.einsum("ij,ij->i", moved, moved) - distance**2) / (2 * distance)
        assert np.abs(matrix @ x - exact).max() < 50 * scale**2


def test_translation_bound_keeps_pairs_beyond_the_influence_sphere_apart():
    """Worst cases of the bound: extreme strains and displacements never bring a pair at
    distance >= D (1 + delta) below D."""
    params = jammed.TJParameters(influence_gap=0.2, max_normal_strain=0.02, max_shear_strain=0.01)
    delta = params.translation_bound(3)
    rng = np.random.default_rng(4)
    for _ in range(2000):
        r = rng.normal(size=3)
        r *= (1 + params.influence_gap) / np.linalg.norm(r) * (1 + rng.random() * 0.1)
        values = np.r_[rng.choice([-1, 1], 3) * params.max_normal_strain,
                       rng.choice([-1, 1], 3) * params.max_shear_strain]
        eps = packing_lp.strain_matrix(values, 3)
        u = -np.sign(r) * delta * 2  # both spheres moving towards each other at the bound
        moved = (np.eye(3) + eps) @ (r + u)
        assert np.linalg.norm(moved) >= 1.0 - 1e-12


def test_reduce_cell_keeps_the_lattice_and_shortens_vectors():
    box = np.array([[1.0, 7.0, 3.0], [0.0, 1.0, 5.0], [0.0, 0.0, 1.0]]) * 4.0
    reduced = jammed.reduce_cell(box)
    change = np.linalg.solve(box, reduced)  # reduced = box @ change, change unimodular
    np.testing.assert_allclose(change, np.rint(change), atol=1e-9)
    assert abs(np.linalg.det(np.rint(change))) == pytest.approx(1.0)
    assert np.linalg.det(reduced) == pytest.approx(np.linalg.det(box))
    assert Cell(reduced).half_width > 3 * Cell(box).half_width
    assert np.linalg.norm(reduced, axis=0).max() < np.linalg.norm(box, axis=0).max()


def test_remove_overlaps_rescales_to_contact():
    positions = np.array([[0.0, 0.0, 0.0], [0.9, 0.0, 0.0], [2.0, 2.0, 2.0]])
    box = np.eye(3) * 4.0
    moved, new_box, factor = jammed.remove_overlaps(positions, box, 1.0)
    assert factor == pytest.approx(1 / 0.9)
    assert np.linalg.norm(moved[1] - moved[0]) >= 1.0
    assert np.linalg.norm(moved[1] - moved[0]) - 1.0 < 1e-14
    np.testing.assert_allclose(new_box, box * factor)


# --------------------------------------------------------------------------- the construction


@pytest.mark.parametrize("which", ["packing3d", "packing2d"])
def test_tj_packing_is_strictly_jammed_and_exactly_isostatic(request, which):
    packing = request.getfixturevalue(which)
    dim = packing.positions.shape[1]
    assert min_gap(packing.positions, packing.box) >= -1e-12  # no overlap beyond 1e-12 D
    low, high = {3: (0.60, 0.66), 2: (0.80, jammed.MAX_PACKING_FRACTION[2])}[dim]
    assert low < packing.phi < high
    # a convergence criterion held: the last LP (full bounds) could not lower the volume, or
    # phi stalled over the last two accepted LPs, or the trust factor collapsed
    history = packing.history
    accepted = history["phi"][history["accepted"] == 1]
    assert (-history["trace"][-1] <= 1e-12
            or abs(accepted[-1] - accepted[-3]) <= 1e-12 * accepted[-1]
            or history["trust_next"][-1] < jammed.MIN_TRUST)
    analysis = jamming.analyse(packing.positions, packing.box, load_test=True)
    assert analysis.jammed
    assert analysis.max_motion < 1e-6 and analysis.min_trace > -1e-6
    n_b, m = analysis.n_backbone, analysis.n_backbone_contacts
    if dim == 3:  # 2D monodisperse disks crystallize (hyperstatic); 3D TJ packings do not
        assert m == dim * (n_b - 1) + dim * (dim + 1) // 2
        assert analysis.isostatic_excess == 0
        assert analysis.z_mean_backbone == pytest.approx(2 * dim + (dim**2 - dim) / n_b)
    else:
        assert analysis.isostatic_excess >= 0
    assert analysis.n_force_bearing >= dim * (n_b - 1) + dim * (dim + 1) // 2


def test_contacts_separate_cleanly_from_gaps(packing3d):
    """Converged contacts close to ~1e-13 D; the same network for tolerances 1e-11..1e-7."""
    networks = [jamming.contact_network(packing3d.positions, packing3d.box, gap_tolerance=t)
                for t in (1e-11, 1e-9, 1e-7)]
    for network in networks[1:]:
        np.testing.assert_array_equal(network.pairs, networks[0].pairs)
    assert networks[0].gap.max() < 1e-11


def test_forces_balance_the_pressure(packing3d):
    """Duals of the jamming test: sum_k f_k rho_k n_k n_k^T = I and force balance per sphere."""
    analysis = jamming.analyse(packing3d.positions, packing3d.box)
    network = analysis.network
    on = analysis.backbone_contacts
    separation = network.separation[on]
    rho = np.linalg.norm(separation, axis=1)
    normal = separation / rho[:, None]
    forces = analysis.forces[on]
    assert (forces > 0).all()
    stress = np.einsum("k,k,ka,kb->ab", forces, rho, normal, normal)
    np.testing.assert_allclose(stress, np.eye(3), atol=1e-6)
    net = np.zeros((len(packing3d.positions), 3))
    np.add.at(net, network.i[on], -forces[:, None] * normal)
    np.add.at(net, network.j[on], forces[:, None] * normal)
    assert np.abs(net).max() < 1e-6 * forces.mean()


def test_lattices_jammed_or_not():
    """fcc (hyperstatic, strictly jammed) passes; simple cubic (floppy under shear: M = 3N <
    3(N-1) + 6) fails, both by the certificate and by Donev's random-load LPs."""
    fcc = jamming.analyse(*bond_order.cubic_lattice("fcc", 2), load_test=True)
    assert fcc.jammed and fcc.rattler_fraction == 0 and fcc.isostatic_excess == 6 * 32 - 99
    sc = jamming.analyse(*bond_order.cubic_lattice("sc", 3), load_test=True)
    assert sc.n_backbone_contacts == 81 and sc.isostatic_excess == 81 - (3 * 26 + 6)
    assert not sc.jammed and sc.max_motion > 0.1 and sc.rank_ratio < 1e-12


def test_the_cone_motion_keeps_contacts_and_lowers_the_volume():
    """fcc stretched by 2 % along x keeps only its contacts in the yz planes: the test's motion
    (analysis.motion) compresses x, with Tr epsilon = the cone LP's optimum < 0, keeping or
    opening every contact to first order (the rows of constraint_matrix); leaving the vertex
    along it closes the stretched gaps and raises phi."""
    positions, box = bond_order.cubic_lattice("fcc", 2)
    stretch = np.diag([1.02, 1.0, 1.0])
    positions, box = positions @ stretch.T, stretch @ box
    loose = jamming.analyse(positions, box)
    strain, displacement = loose.motion
    assert not loose.jammed and loose.min_trace < -0.5
    assert np.trace(strain) == pytest.approx(loose.min_trace, abs=1e-9) and strain[0, 0] < 0
    net = loose.network
    normal = net.separation / np.linalg.norm(net.separation, axis=1)[:, None]
    rate = (np.einsum("ma,ma->m", normal, displacement[net.j] - displacement[net.i])
            + np.einsum("ma,ab,mb->m", normal, strain, normal) * np.linalg.norm(net.separation, axis=1))
    assert rate.min() > -1e-9
    moved, new_box, step = jammed.leave_vertex(positions, box, strain, displacement, reach=0.1)
    assert 0 < step and min_gap(moved, new_box) >= 0.0 and min_gap(moved, new_box) < 1e-12
    assert jammed.packing_fraction(moved, new_box) > jammed.packing_fraction(positions, box)
    fcc = jamming.analyse(*bond_order.cubic_lattice("fcc", 2))
    assert abs(np.trace(fcc.motion[0])) < 1e-9  # jammed: the cone holds nothing that lowers V


def test_leave_vertex_stops_at_the_first_new_contact():
    """Two spheres 0.1 D apart, the second moving towards the first at unit rate: the step is
    the gap, after which they touch; a motion that closes nothing moves reach / rate."""
    positions = np.array([[1.0, 1.0, 1.0], [2.1, 1.0, 1.0], [1.0, 3.0, 1.0]])
    box = 6.0 * np.eye(3)
    displacement = np.zeros((3, 3))
    displacement[1, 0] = -1.0
    moved, new_box, step = jammed.leave_vertex(positions, box, np.zeros((3, 3)), displacement, reach=0.2)
    assert step == pytest.approx(0.1, rel=1e-12)
    assert min_gap(moved, new_box) == pytest.approx(0.0, abs=1e-12) and min_gap(moved, new_box) >= 0.0
    assert np.linalg.det(new_box) == pytest.approx(216.0, rel=1e-12)
    _, _, apart = jammed.leave_vertex(positions, box, np.zeros((3, 3)), -displacement, reach=0.2)
    assert apart == pytest.approx(0.2)


def test_certified_packing_is_left_as_it_is(packing3d):
    from randmedia.studies.jammed_certificate import certified

    packing, analysis, repair = certified(packing3d, jammed.TJParameters(), {"gap_tolerance": 1e-9})
    assert analysis.jammed and repair.rounds == 0 and repair.lps == 0 and packing is packing3d
    assert repair.attrs()["repair_rounds"] == 0


def test_rattlers_are_found():
    """A sphere of fcc moved off its lattice site keeps < d + 1 contacts: a rattler, and
    the only one (its neighbours keep their other contacts)."""
    positions, box = bond_order.cubic_lattice("fcc", 2)
    loose = positions.copy()
    loose[0] = loose[0] + np.array([0.01, 0.0, 0.0])  # moved off its contacts -> rattler
    analysis = jamming.analyse(loose, box)
    assert analysis.rattler[0] and analysis.rattler.sum() == 1


@pytest.mark.parametrize("backend", ["highs-hipo", "highs-simplex"])
def test_tj_is_deterministic_and_resumes_bit_for_bit(tmp_path, monkeypatch, backend):
    """Also with the warm-started dual simplex, whose basis the checkpoint carries."""
    start, box = random_sequential_addition(np.random.default_rng(11), 50, 0.25)
    params = jammed.TJParameters(backend=backend)
    reference = jammed.jam(start, box, params)
    again = jammed.jam(start, box, params)
    np.testing.assert_array_equal(reference.positions, again.positions)
    np.testing.assert_array_equal(reference.box, again.box)
    # a run killed after 20 LPs (state saved at every LP boundary) and resumed
    checkpoint = tmp_path / "state.npz"
    real_step = jammed.tj_step
    monkeypatch.setattr(jammed, "tj_step", killed_after(20, real_step))
    with pytest.raises(KeyboardInterrupt):
        jammed.jam(start, box, params, checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert checkpoint.is_file()
    monkeypatch.setattr(jammed, "tj_step", real_step)
    resumed = jammed.jam(start, box, params, checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert not checkpoint.exists()
    assert resumed.n_lp == reference.n_lp
    np.testing.assert_array_equal(resumed.positions, reference.positions)
    np.testing.assert_array_equal(resumed.box, reference.box)
    # a checkpoint of another construction is ignored, not used
    other = tmp_path / "other.npz"
    np.savez(other, key="not this one")
    fresh = jammed.jam(start, box, params, checkpoint=other)
    np.testing.assert_array_equal(fresh.positions, reference.positions)


def test_a_run_resumes_under_a_changed_cap_unless_it_is_past_it(tmp_path, monkeypatch):
    """max_lps is not part of the checkpoint's key: a run killed after 8 LPs under one cap
    resumes under another and ends where an uninterrupted run with that cap ends; a cap below
    the checkpoint's LP count is refused before any LP (a fresh run would have ended sooner)."""
    start, box = random_sequential_addition(np.random.default_rng(0), 50, 0.25)
    checkpoint = tmp_path / "state.npz"
    real_step = jammed.tj_step
    monkeypatch.setattr(jammed, "tj_step", killed_after(8, real_step))
    with pytest.raises(KeyboardInterrupt):
        jammed.jam(start, box, jammed.TJParameters(max_lps=5000), checkpoint=checkpoint, checkpoint_seconds=0.0)
    monkeypatch.setattr(jammed, "tj_step", real_step)
    saved = checkpoint.read_bytes()
    with pytest.raises(ValueError, match="holds 8 LPs .* max_lps = 6"):
        jammed.jam(start, box, jammed.TJParameters(max_lps=6), checkpoint=checkpoint, at_max_lps="end")
    assert checkpoint.read_bytes() == saved  # refused, nothing lost
    capped = jammed.TJParameters(max_lps=12)
    resumed = jammed.jam(start, box, capped, checkpoint=checkpoint, at_max_lps="end")
    uninterrupted = jammed.jam(start, box, capped, at_max_lps="end")
    assert resumed.n_lp == uninterrupted.n_lp == 12 and resumed.stop == "max_lps"
    np.testing.assert_array_equal(resumed.positions, uninterrupted.positions)
    assert not checkpoint.exists()


def test_carried_basis_keeps_the_status_of_rows_still_listed_and_enters_new_ones_basic():
    previous = packing_lp.LPBasis(col_status=np.array([0, 1, 2], np.int8),
                                  row_status=np.array([2, 1, 0], np.int8),
                                  row_keys=np.array([30, 10, 20]))
    cols, rows = packing_lp.carry_basis(previous, np.array([20, 40, 30]), 3)
    np.testing.assert_array_equal(cols, [0, 1, 2])
    np.testing.assert_array_equal(rows, [0, 1, 2])   # 20 was at its bound 0, 40 is new, 30 kept 2
    with pytest.raises(ValueError, match="columns"):
        packing_lp.carry_basis(previous, np.array([20]), 4)


def test_warm_started_dual_simplex_reaches_the_cold_optimum_in_fewer_iterations(packing3d):
    """The TJ LP of a state one step away from the previous LP's state (the packing
    expanded by 1 %, then one step), solved from the previous basis and from scratch."""
    params = jammed.TJParameters(backend="highs-simplex")
    positions, box = packing3d.positions * 1.01, packing3d.box * 1.01
    moved, moved_box, first = jammed.tj_step(positions, box, params)
    assert isinstance(first["basis"], packing_lp.LPBasis)
    _, _, warm = jammed.tj_step(moved, moved_box, params, basis=first["basis"])
    _, _, cold = jammed.tj_step(moved, moved_box, params)
    assert warm["trace"] == pytest.approx(cold["trace"], abs=1e-12)
    assert warm["simplex_iterations"] < cold["simplex_iterations"] / 2
    # an interior point gives no basis and takes none
    assert jammed.tj_step(moved, moved_box, jammed.TJParameters())[2]["basis"] is None


def test_a_failed_lp_is_solved_by_the_fallback_and_logged(packing3d, monkeypatch, caplog):
    """A backend failure on a feasible LP (seen once with HiPO at N = 10 000) is not fatal:
    packing_lp.fallback's backend solves the same LP, to the same optimum, and the
    construction's log names the failure (the retry can cost ~30x the LP)."""
    positions, box = packing3d.positions * 1.01, packing3d.box * 1.01
    params = jammed.TJParameters(max_lps=1)
    clean = jammed.tj_step(positions, box, params)[2]
    assert clean["fallback"] == ""
    real_solve, calls = packing_lp.solve, []

    def hipo_fails(*args, backend, **options):
        calls.append(backend)
        if backend == "highs-hipo":
            raise packing_lp.LPError("LP not solved to optimality (highs-hipo): Unknown")
        return real_solve(*args, backend=backend, **options)

    monkeypatch.setattr(packing_lp, "solve", hipo_fails)
    record = jammed.tj_step(positions, box, params)[2]
    assert calls == ["highs-hipo", "highs-ipm"]
    assert clean["basis"] is None and record["basis"] is not None  # the fallback's vertex
    assert record["fallback"] == ("LP not solved to optimality (highs-hipo): Unknown; "
                                  "solved by highs-ipm")
    assert record["trace"] == pytest.approx(clean["trace"], abs=1e-10)
    with caplog.at_level("WARNING"), pytest.raises(jammed.ConstructionError, match="max_lps"):
        jammed.jam(positions, box, params)
    assert "LP 1: LP not solved to optimality (highs-hipo)" in caplog.text


def test_unconverged_construction_raises():
    start, box = random_sequential_addition(np.random.default_rng(0), 50, 0.25)
    with pytest.raises(jammed.ConstructionError, match="max_lps"):
        jammed.jam(start, box, jammed.TJParameters(max_lps=5))


def test_unconverged_construction_can_end_at_max_lps_instead(caplog):
    """at_max_lps="end": the run stops after max_lps LPs and returns that state, marked
    "max_lps" (and so logged) -- the same positions as a run with a larger cap has after as
    many LPs."""
    start, box = random_sequential_addition(np.random.default_rng(0), 50, 0.25)
    with caplog.at_level("INFO"):
        ended = jammed.jam(start, box, jammed.TJParameters(max_lps=5), at_max_lps="end")
    assert ended.stop == "max_lps" and ended.n_lp == 5 and ended.phi > 0.26
    assert "ended at max_lps after 5 LPs" in caplog.text
    assert not any(record.getMessage().startswith("converged") for record in caplog.records)
    longer = jammed.jam(start, box, jammed.TJParameters(max_lps=5000))
    assert longer.stop == "converged" and longer.n_lp > 5
    np.testing.assert_array_equal(ended.history["phi"], longer.history["phi"][:5])
    with pytest.raises(ValueError, match="at_max_lps"):
        jammed.jam(start, box, at_max_lps="continue")


def test_a_run_with_a_final_backend_ends_at_max_lps_after_one_vertex_lp():
    """With a final_backend, a run ended at max_lps first solves one LP with it (the final
    phase's first), so the state it returns has its contacts closed at a vertex; the LPs
    before are those of the same run without the final backend."""
    start, box = random_sequential_addition(np.random.default_rng(0), 50, 0.25)
    params = jammed.TJParameters(max_lps=5, backend="highs-hipo")
    interior = jammed.jam(start, box, params, at_max_lps="end")
    ended = jammed.jam(start, box, replace(params, final_backend="highs-ipm"), at_max_lps="end")
    assert ended.stop == "max_lps" and ended.n_lp == 6
    assert list(ended.history["final"]) == [0, 0, 0, 0, 0, 1]
    np.testing.assert_array_equal(ended.history["phi"][:5], interior.history["phi"])
    assert ended.phi >= interior.phi * (1 - 1e-10)


def test_summary_table_means_and_sems():
    records = [{"system": "mrj", "sample": k, "n_particles": 10, "phi": 0.63 + 0.001 * k,
                "z_mean_nonrattlers": 6.1, "rattler_fraction": 0.01 * k, "isostatic_excess": 0,
                "jammed": 1, "Q6": 0.05, "crystal_fraction": 0.0, "n_lp": 50 + k}
               for k in range(4)]
    table = jamming.summary_table(records)
    mean = table[(table["system"] == "mrj") & (table["sample"] == "mean")].iloc[0]
    sem = table[(table["system"] == "mrj") & (table["sample"] == "sem")].iloc[0]
    assert mean["phi"] == pytest.approx(0.6315)
    assert sem["phi"] == pytest.approx(np.std([0.63, 0.631, 0.632, 0.633], ddof=1) / 2)
    assert ball_volume(0.5, 3) == pytest.approx(np.pi / 6)


def test_rank_test_tells_a_floppy_mode_from_a_soft_rigid_one(monkeypatch):
    """The rank part of the jamming test (lambda_min / lambda_max of B^T B, B: backbone contact
    rows + volume row) on the kept quick packing (N = 100, rigid: 9e-8) and on the same matrix
    with two backbone contacts removed, which leaves a motion with no contact and no volume
    change (a floppy mode): that ratio must fall to round-off (measured 0 - 2e-19), below
    mrj_large's rank tolerance 1e-15, which lies far below the rigid packing's ratio."""
    path = Path(__file__).parent / "data" / "mrj2016_quick_mrj_sample0.nc"
    with xr.open_dataset(path) as ds:
        positions, box = ds["position"].values, ds["box"].values
        diameter = float(ds.attrs["diameter"])
    seen = []
    ratio = jamming._smallest_eigenvalue_ratio
    monkeypatch.setattr(jamming, "_smallest_eigenvalue_ratio",
                        lambda cone: seen.append(cone) or ratio(cone))
    analysis = jamming.analyse(positions, box, diameter, gap_tolerance=1e-9)
    cone = seen[0].tocsr()
    assert analysis.jammed and analysis.rank_ratio > 1e-9
    rng = np.random.default_rng(0)
    volume_row = cone.shape[0] - 1
    for _ in range(3):
        removed = rng.choice(volume_row, 2, replace=False)
        kept = np.r_[np.setdiff1d(np.arange(volume_row), removed), volume_row]
        assert ratio(cone[kept]) < 1e-17 < 1e-15 < analysis.rank_ratio
