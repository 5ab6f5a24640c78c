"""Appendix A of Klatt & Torquato 2016: exact S2, F_sv, F_ss of finite packings (randmedia.describe.packings)."""

import math

import numpy as np
import pytest

from mrj_helpers import TRICLINIC, monte_carlo_correlations, rsa_packing
from randmedia.describe import packings
from randmedia.generate.spheres import lattice_spheres, overlapping_spheres
from randmedia.periodic import Cell, pairs_within
from randmedia.theory import overlapping as theory
from randmedia.theory.balls import poisson_intensity

R = 0.5
V_R, A_R = 4 * math.pi * R**3 / 3, 4 * math.pi * R**2


def paper_kernels(rho, r):
    """Eqs. (A7), (A14), (A21) exactly as printed (valid for rho >= D)."""
    inside = (r >= rho - 2 * R) & (r < rho + 2 * R)
    u = np.abs(r - rho)
    p = inside / (160 * R**3 * rho * r) * (2 * R - u) ** 3 * (u**2 + 2 * R * (3 * u + 2 * R))
    q = inside / (24 * R * rho * r) * (2 * R - u) ** 2 * (u + R)
    a = inside / (4 * rho * r) * (2 * R - u)
    return p, q, a


@pytest.mark.parametrize("rho", [1.0, 1.0 + 1e-7, 1.37, 2.5, 4.2])
def test_direction_averaged_kernels_equal_the_paper_for_hard_spheres(rho):
    r = np.linspace(1e-3, rho + 1.5, 700)
    p, q, a = paper_kernels(rho, r)
    np.testing.assert_allclose(packings.pair_kernel("v", rho, r, R) / V_R, p, atol=1e-13)
    np.testing.assert_allclose(packings.pair_kernel("h", rho, r, R) / A_R, q, atol=1e-13)
    np.testing.assert_allclose(packings.pair_kernel("J", rho, r, R) / A_R, a, atol=1e-13)


def test_kernels_are_directional_averages_of_the_lens_volume():
    """p_ij(r) = <v_lens(|rho - r u|)>_u / v_R, also for overlapping pairs (rho + r < D)."""
    rng = np.random.default_rng(0)
    u = rng.normal(size=(400_000, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    for rho, r in [(0.3, 0.4), (0.8, 0.15), (1.2, 0.5)]:
        t = np.linalg.norm(np.array([rho, 0, 0]) - r * u, axis=1)
        lens = np.where(t < 2 * R, math.pi / 12 * (4 * R + t) * (2 * R - t) ** 2, 0.0)
        assert packings.pair_kernel("v", rho, r, R) == pytest.approx(lens.mean(), rel=3e-3)


def test_one_body_terms_match_the_exact_overlapping_sphere_functions():
    """p_ii = 2 - v2/v1 (lens volume), q_ii = 1 - f_out and a_ii = J/a_R, as implied by the
    exact overlapping-sphere S2, F_sv and F_ss of randmedia.theory.overlapping."""
    r = np.linspace(0.01, 0.99, 50)
    phi = 0.3
    one = packings.one_body_terms(r, R)
    s2v = theory.s2_void(r, R, phi, 3)
    eta = theory.reduced_density(phi)
    np.testing.assert_allclose(one["p"], 2.0 + np.log(s2v) / eta, rtol=1e-12)
    s_over_phi1 = theory.specific_surface(R, phi, 3) / (1 - phi)
    f_out = theory.surface_void(r, R, phi, 3) / (s_over_phi1 * s2v)
    np.testing.assert_allclose(one["q"], 1.0 - f_out, rtol=1e-12)
    rho_J = theory.surface_surface(r, R, phi, 3) / s2v - (s_over_phi1 * f_out) ** 2
    np.testing.assert_allclose(one["a"], rho_J / poisson_intensity(phi, R, 3) / A_R, rtol=1e-10)


def test_pair_distances_match_the_kd_tree_pair_search_in_a_triclinic_cell():
    rng = np.random.default_rng(1)
    cell = Cell(TRICLINIC)
    x = cell.random_points(rng, 300) + rng.normal(scale=3.0, size=(300, 3))
    cutoff = cell.half_width
    *_, expected = pairs_within(cell, x, cutoff)
    np.testing.assert_allclose(packings.pair_distances(x, TRICLINIC, cutoff), np.sort(expected), atol=1e-12)


def test_prefix_sum_evaluation_equals_the_direct_pair_sum():
    rng = np.random.default_rng(2)
    box = np.eye(3) * 9.0
    x = rsa_packing(rng, box, 250)
    r = np.linspace(0.005, packings.max_radius(box) - 1e-6, 300)
    rho = packings.pair_distances(x, box, Cell(box).half_width)
    sums = packings.PairSums(rho, R)
    for kernel in ("v", "h", "J"):
        fast = np.asarray(sums(kernel, r), dtype=float)
        direct = np.array([2 * ri * packings.pair_kernel(kernel, rho, ri, R).sum() for ri in r])
        np.testing.assert_allclose(fast, direct, rtol=1e-10, atol=1e-10 * np.abs(direct).max())


@pytest.fixture(scope="module")
def rsa_triclinic():
    rng = np.random.default_rng(3)
    return rsa_packing(rng, TRICLINIC, 160)


def test_appendix_a_agrees_with_brute_force_monte_carlo(rsa_triclinic):
    """S2, F_sv (spheres as void) and F_ss of an RSA packing in a triclinic cell against sampling."""
    x = rsa_triclinic
    r = np.array([0.3, 0.8, 1.1, 1.7, 2.2])
    exact = packings.correlation_functions(x, TRICLINIC, r)
    rng = np.random.default_rng(4)
    for i, ri in enumerate(r):
        mc = monte_carlo_correlations(x, TRICLINIC, ri, 50_000, rng)
        s = exact["s"]
        assert mc["s"] == pytest.approx(s)
        for name, ours in (("S2", exact["S2"][i]), ("F_sv_spheres", s - exact["F_sv"][i]),
                           ("F_ss", exact["F_ss"][i])):
            value, se = mc[name]
            assert abs(value - ours) < 4.5 * se + 1e-12, (name, ri, value, ours, se)


def test_limits_and_sum_rules(rsa_triclinic):
    x = rsa_triclinic
    cell = Cell(TRICLINIC)
    r = np.arange(0, packings.max_radius(TRICLINIC), 0.01)
    f = packings.correlation_functions(x, TRICLINIC, r)
    phi, s = f["phi"], f["s"]
    assert f["S2"][0] == pytest.approx(phi, abs=1e-14)
    assert f["F_sv"][0] == pytest.approx(s / 2, abs=1e-14)
    assert np.isinf(f["F_ss"][0])
    assert phi == pytest.approx(len(x) * V_R / cell.volume)
    # slope of S2 at 0 is -s/4 (Sec. III B): the one-body part gives -s/4 + s r^2/12 exactly;
    # the two-body part (pairs with gap < r) is >= 0 and below phi z r^2/4 (Eq. A7 at contact)
    # with z <= 12
    two_body = f["S2"][1] - phi * packings.one_body_terms(0.01, R)["p"]
    assert 0 <= two_body < 12 * phi * 0.01**2 / 4
    one_body_slope = (phi * packings.one_body_terms(0.01, R)["p"] - phi) / 0.01
    assert one_body_slope == pytest.approx(-s / 4 + s * 0.01**2 / 12, rel=1e-9)
    # F*_sv, F*_ss vanish below the smallest gap; two-body parts are the full functions beyond D
    beyond = r > 1.0
    np.testing.assert_allclose(f["F_ss"][beyond], f["F_ss_two_body"][beyond], rtol=1e-12)
    np.testing.assert_allclose(s - f["F_sv"][beyond], f["F_sv_two_body"][beyond], rtol=1e-12)
    assert np.all(f["S2"] >= 0) and np.all(f["S2"] <= phi + 1e-12)


def test_radius_beyond_h_w_minus_d_is_refused(rsa_triclinic):
    limit = packings.max_radius(TRICLINIC)
    with pytest.raises(ValueError, match="h_w - D"):
        packings.correlation_functions(rsa_triclinic, TRICLINIC, np.array([0.1, limit + 0.01]))


def test_poisson_expectation_of_the_two_body_parts_is_exact():
    """With the kernels exact for overlapping pairs, the pair sums of Poisson centres average to
    eta^2 (S2), s eta (F*_sv) and s^2 (F*_ss) at every r, eta = rho v_R, s = rho a_R."""
    rng = np.random.default_rng(5)
    phi = 0.3
    r = np.array([0.2, 0.7, 1.3, 2.0])
    values = []
    for _ in range(40):
        x, box = overlapping_spheres(rng, phi, 300)
        f = packings.correlation_functions(x, box, r)
        one = packings.one_body_terms(r, R)
        two_s2 = f["S2"] - f["phi"] * one["p"]
        values.append(np.concatenate([two_s2, f["F_sv_two_body"], f["F_ss_two_body"]]))
    values = np.array(values)
    rho = poisson_intensity(phi, R, 3)
    eta, s = rho * V_R, rho * A_R
    expected = np.concatenate([np.full(4, eta**2), np.full(4, s * eta), np.full(4, s**2)])
    sem = values.std(axis=0, ddof=1) / np.sqrt(len(values))
    assert np.all(np.abs(values.mean(axis=0) - expected) < 4 * sem), (values.mean(axis=0), expected, sem)


@pytest.mark.parametrize("lattice, z", [("fcc", 12), ("bcc", 8)])
def test_contact_number_of_lattices(lattice, z):
    """Touching spheres: Eqs. (B3) and (B4) give the coordination number exactly."""
    x, box = lattice_spheres(lattice, 3)
    c = packings.contact_number(x, box, r=1e-4)
    assert c["z_B4"] == pytest.approx(z, rel=1e-9)
    assert c["z_B3"] == pytest.approx(z, rel=1e-3)  # O(r) correction of the slope estimate
    assert c["n_within"] == pytest.approx(z)


def test_contact_number_weights_gapped_pairs():
    """A pair with gap g < r counts (1 - g/r) in Eq. (B4)."""
    box = np.eye(3) * 10.0
    x = np.array([[1.0, 1.0, 1.0], [2.0005, 1.0, 1.0], [5.0, 5.0, 5.0], [6.0, 5.0, 5.0]])
    c = packings.contact_number(x, box, r=1e-3)
    expected_pairs = 1.0 + (1 - 0.0005 / 1e-3) * 1.0005 ** -1 * 1.0  # rho D / rho ~ 1
    assert c["z_B4"] == pytest.approx(2 * expected_pairs / 4, rel=1e-3)


def test_prefix_sums_at_window_ends_do_not_depend_on_which_radii_share_a_pass(rsa_triclinic):
    """The prefix sums are evaluated only at the window ends of the asked radii, and kept for
    later calls: radii asked one at a time, in another order, or after other radii give the
    same sums as all radii in one call."""
    rho = packings.pair_distances(rsa_triclinic, TRICLINIC, Cell(TRICLINIC).half_width)
    r = np.linspace(0.01, packings.max_radius(TRICLINIC) - 1e-6, 60)
    together = packings.PairSums(rho, R)
    reused = packings.PairSums(rho, R)
    reused("v", r[::7])  # fills the kept prefix sums with other window ends first
    for kernel in ("v", "h", "J"):
        whole = np.asarray(together(kernel, r), dtype=float)
        single = np.array([float(packings.PairSums(rho, R)(kernel, [ri])[0]) for ri in r[::-1]])[::-1]
        np.testing.assert_array_equal(single, whole)
        np.testing.assert_array_equal(np.asarray(reused(kernel, r), dtype=float), whole)
