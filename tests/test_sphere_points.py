"""Cap number variances, g2 and exponent fits on the sphere (randmedia.describe.sphere_points,
randmedia.fit.power_law), validated on cases with known answers: uniform points (Eq. 6),
Poisson points (Eq. 7), the exact window average of one configuration (Eq. 3), lattices (delta ~ 1)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from randmedia.describe import sphere_points as sp
from randmedia.fit.power_law import power_law_exponent, window_family_exponents, window_mean
from randmedia.generate import sphere_surface as ss
from randmedia.theory.sphere_caps import (cap_area, cap_grid, poisson_variance, uniform_variance,
                                          variance_from_g2)


def _deviation(value, sem, exact):
    return np.abs(value - exact) / sem


def test_cap_counts_match_brute_force():
    rng = np.random.default_rng(31)
    points = ss.uniform_points(300, 2.0, rng)
    centres = sp.random_centres(rng, 20)
    a = cap_grid(2.0, 9)
    counts = sp.cap_counts(points, centres, a, 2.0)
    angle = np.arccos(np.clip(points @ centres.T / 2.0, -1, 1))  # (N, M)
    expected = (angle[:, :, None] <= np.arcsin(a / 2.0)[None, None, :]).sum(axis=0)
    np.testing.assert_array_equal(counts, expected)


def test_uniform_points_follow_eq6_within_their_sem():
    rng = np.random.default_rng(32)
    radius, n = 1.0, 200
    frames = [ss.uniform_points(n, radius, rng) for _ in range(400)]
    a = cap_grid(radius, 20)
    value, sem, leave_out, mean = sp.cap_variance(frames, radius, a, rng, n_centres=40, n_blocks=20)
    rho = n / (4 * np.pi)
    z = _deviation(value, sem, uniform_variance(a, radius, rho))
    assert z.max() < 4 and np.mean(z**2) < 2.0, z
    windows = 400 * 40
    assert np.all(np.abs(mean - rho * cap_area(a, radius))
                  < 4 * np.sqrt(uniform_variance(a, radius, rho) / windows))
    fit = power_law_exponent(a, value, leave_out, a_min=1 / math.sqrt(rho), a_max=0.9 * radius, sem=sem)
    assert abs(fit.value - 2.0) < 4 * fit.error and fit.error < 0.05  # Table I: a^2


def test_poisson_points_follow_eq7_within_their_sem():
    rng = np.random.default_rng(33)
    radius, mean_points = 1.0, 200.0
    frames = [ss.poisson_points(mean_points, radius, rng) for _ in range(400)]
    a = cap_grid(radius, 20)
    value, sem, leave_out, _ = sp.cap_variance(frames, radius, a, rng, n_centres=40, n_blocks=20)
    rho = np.mean([len(f) for f in frames]) / (4 * np.pi)
    z = _deviation(value, sem, poisson_variance(a, radius, rho))
    assert z.max() < 4 and np.mean(z**2) < 2.0, z
    scale = rho * cap_area(a, radius)
    level = window_mean(a, value / scale, leave_out / scale, a_min=0.1, a_max=1.0)
    assert abs(level.value - 1.0) < 4 * level.error and level.error < 0.03
    # the canonical Eq. (6) is far off at large a (the two ensembles differ, Fig. 3c)
    assert _deviation(value, sem, uniform_variance(a, radius, rho))[-1] > 10


def test_random_centres_converge_to_the_exact_window_average_eq3():
    """Eq. (3) (all window positions) of one fixed configuration against 10^4 random centres,
    and against Eq. (4) with the configuration's own finely binned g2."""
    rng = np.random.default_rng(34)
    radius = 3.0
    points = ss.uniform_points(150, radius, rng)
    a = cap_grid(radius, 15)
    exact = sp.window_average_variance(points, radius, a)
    value, sem, _, _ = sp.cap_variance([points], radius, a, rng, n_centres=20000, n_blocks=20)
    z = _deviation(value, sem, exact)
    assert z.max() < 4.5 and np.mean(z**2) < 2.5, z
    edges, g2, _ = sp.geodesic_g2([points], radius, 3000, 2)
    rho = 150 / (4 * np.pi * radius**2)
    from_g2 = variance_from_g2(a, radius, rho, edges, g2, n_particles=150)
    np.testing.assert_allclose(from_g2, exact, rtol=2e-3, atol=2e-3)


def test_g2_of_uniform_points_is_one_and_of_a_lattice_has_an_exclusion_hole():
    rng = np.random.default_rng(35)
    frames = [ss.uniform_points(100, 1.0, rng) for _ in range(200)]
    edges, g2, sem = sp.geodesic_g2(frames, 1.0, 30, 10)
    assert _deviation(g2, sem, 1.0).max() < 4.5
    lattice = ss.fibonacci_grid(1000, 1.0)
    edges, g2, _ = sp.geodesic_g2([lattice], 1.0, 400, 2)
    spacing = math.sqrt(4 * math.pi / 1000)
    assert np.all(g2[edges[1:] < 0.7 * spacing] == 0)


@pytest.mark.parametrize("name, points", [
    ("icosahedral", ss.icosahedral_grid(5)),
    ("fibonacci", ss.fibonacci_grid(1000)),
])
def test_lattices_give_delta_near_one(name, points):
    """Sec. III, Table I: sigma^2 ~ a for the regular patterns (rho^(-1/2) <= a <= 0.9 R)."""
    rng = np.random.default_rng(36)
    radius = math.sqrt(len(points) / (4 * math.pi * 0.5))
    points = points * radius
    a = cap_grid(radius, 60)
    value, sem, leave_out, _ = sp.cap_variance([points], radius, a, rng, n_centres=10000, n_blocks=20)
    fit = power_law_exponent(a, value, leave_out, a_min=1 / math.sqrt(0.5), a_max=0.9 * radius, sem=sem)
    assert abs(fit.value - 1.0) < 0.15, (name, fit)
    assert fit.error < 0.05


def test_inversion_symmetric_grid_has_no_hemisphere_fluctuation():
    """Every hemisphere of the icosahedral grid holds N/2 points: sigma^2(a = R) = 0."""
    rng = np.random.default_rng(37)
    points = ss.icosahedral_grid(4)
    counts = sp.cap_counts(points, sp.random_centres(rng, 500), [0.5, 1.0], 1.0)
    assert np.all(counts[:, 1] == len(points) // 2)


def test_three_origin_counts_and_the_jackknife():
    rng = np.random.default_rng(38)
    counts = rng.poisson(20.0, size=(4000, 3, 5))
    value, sem, leave_out, mean = sp.axis_count_variance(counts, 20)
    assert np.all(np.abs(value - 20.0) < 4 * sem)
    # jackknife SEM of a variance of Poisson(20) counts: sqrt((mu4 - sigma^4)/n), mu4 = 3 l^2 + l
    expected = math.sqrt((3 * 20.0**2 + 20.0 - 20.0**2) / counts[:, :, 0].size)
    np.testing.assert_allclose(sem, expected, rtol=0.4)
    assert leave_out.shape == (20, 5)


def test_power_law_fit_recovers_an_exact_exponent():
    a = np.linspace(0.5, 5, 40)
    curves = np.array([2.0 * a**1.37 * (1 + 0.01 * k) for k in range(10)])
    fit = power_law_exponent(a, 2.0 * a**1.37, curves, a_min=1.0, a_max=4.0)
    assert fit.value == pytest.approx(1.37, abs=1e-12)
    assert fit.error == pytest.approx(0.0, abs=1e-12)
    assert fit.n_points == int(((a >= 1.0) & (a <= 4.0)).sum())
    with pytest.raises(ValueError, match="fewer than 3"):
        power_law_exponent(a, a, curves, a_min=4.9, a_max=5.0)
    with pytest.raises(ValueError, match="a_min < a_max"):
        power_law_exponent(a, a, curves, a_min=3.0, a_max=2.0)
    with pytest.raises(ValueError, match="> 0"):
        power_law_exponent(a, a - 2.0, curves, a_min=1.0, a_max=4.0)


def test_window_family_measures_the_spread_of_the_exponent():
    """An exact power law has no window systematic; a curve that bends (a^2 below a = 2,
    a^1 above) gives exponents in [1, 2] that depend on the window, and windows that
    hold < 3 points or sigma^2 <= 0 (a lattice's sigma^2(R) = 0) are skipped."""
    a = np.linspace(5 / 60, 5, 60)
    family = {"a_min_rho_half": [1.0, 1.5, 2.0], "a_max_over_R": [0.8, 0.9, 1.0]}
    exact = window_family_exponents(a, 3.0 * a**1.5, rho=0.5, radius=5.0, **family)
    assert exact.size == 9
    np.testing.assert_allclose(exact, 1.5, atol=1e-12)
    bent = np.where(a < 2, a**2, 2 * a)
    deltas = window_family_exponents(a, bent, rho=0.5, radius=5.0, **family)
    assert np.all((deltas > 1 - 1e-12) & (deltas < 2)) and np.ptp(deltas) > 0.1
    np.testing.assert_allclose(deltas[3:], 1.0, atol=1e-12)  # windows starting above a = 2
    lattice = 3.0 * a**1.5
    lattice[-1] = 0.0
    assert window_family_exponents(a, lattice, rho=0.5, radius=5.0, **family).size == 6
    assert window_family_exponents(a, bent, rho=0.5, radius=5.0, a_min_rho_half=[5.0],
                                   a_max_over_R=[0.8]).size == 0


def test_bad_window_parameters_are_rejected():
    with pytest.raises(ValueError, match="exceeds R"):
        sp.cap_counts(np.zeros((1, 3)), np.array([[0, 0, 1.0]]), [0.5, 1.5], 1.0)
    with pytest.raises(ValueError, match="sphere radius R"):
        sp.geodesic_g2([np.zeros((2, 3))], 0.0, 10, 2)
    with pytest.raises(ValueError, match="blocks"):
        sp.cap_variance([np.zeros((2, 3))] * 3, 1.0, [0.5], np.random.default_rng(0), n_centres=2,
                        n_blocks=5)
