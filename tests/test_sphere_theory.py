"""Closed forms of spherical caps (randmedia.theory.sphere_caps): Eq. (9) against a Monte Carlo
estimate of the cap intersection and its Euclidean limit, Eqs. (4)-(7), bad parameters."""

from __future__ import annotations

import numpy as np
import pytest

from randmedia.theory.sphere_caps import (cap_area, cap_grid, cap_intersection_fraction,
                                          cap_intersection_weights, cos_thresholds,
                                          disk_intersection_fraction, poisson_variance,
                                          uniform_variance, variance_from_g2)


def test_cap_area_limits():
    assert cap_area(1.0, 1.0) == pytest.approx(2 * np.pi)          # hemisphere
    assert cap_area(1e-4, 1.0) == pytest.approx(np.pi * 1e-8, rel=1e-7)  # flat disk
    a = np.linspace(0.1, 3.0, 7)
    np.testing.assert_allclose(cap_area(a, 3.0), 2 * np.pi * 9 * (1 - np.sqrt(1 - (a / 3) ** 2)))


@pytest.mark.parametrize("phi", [0.3, 0.8, 1.3, np.pi / 2])
def test_eq9_equals_a_monte_carlo_cap_intersection(phi):
    """alpha2 = |cap(c1) & cap(c2)| / |cap|, estimated from uniform points on the unit sphere."""
    rng = np.random.default_rng(11)
    g = rng.standard_normal((1_000_000, 3))
    g /= np.linalg.norm(g, axis=1)[:, None]
    in_first = g[:, 2] >= np.cos(phi)
    for psi in np.array([0.05, 0.4, 0.9, 1.5, 1.95]) * phi:
        second = np.array([np.sin(psi), 0.0, np.cos(psi)])
        both = in_first & (g @ second >= np.cos(phi))
        p = both.sum() / in_first.sum()
        error = np.sqrt(p * (1 - p) / in_first.sum())
        exact = cap_intersection_fraction(psi, np.sin(phi), 1.0)
        assert abs(exact - p) < 4 * error + 1e-12, (phi, psi, exact, p, error)


def test_eq9_limits_and_support():
    a, radius = 2.0, 5.0
    phi = np.arcsin(a / radius)
    assert cap_intersection_fraction(0.0, a, radius) == pytest.approx(1.0)
    assert cap_intersection_fraction(2 * phi * radius, a, radius) == pytest.approx(0.0, abs=1e-6)
    assert cap_intersection_fraction(2.5 * phi * radius, a, radius) == 0.0
    x = np.linspace(0, 2 * phi * radius, 50)
    assert np.all(np.diff(cap_intersection_fraction(x, a, radius)) < 0)


def test_eq9_tends_to_the_euclidean_disk_intersection():
    """R -> infinity at fixed a and x: alpha2 -> (2/pi)[acos(x/2a) - (x/2a) sqrt(1 - (x/2a)^2)]."""
    a = 1.3
    x = np.linspace(0.0, 2 * a * 0.999, 40)
    euclid = disk_intersection_fraction(x, a)
    errors = [np.max(np.abs(cap_intersection_fraction(x, a, radius) - euclid))
              for radius in (10.0, 100.0, 1000.0)]
    assert errors[-1] < 1e-5
    assert errors[0] > errors[1] > errors[2]  # converges as R grows (curvature ~ (a/R)^2)


def test_weights_integrate_alpha2_to_the_cap_area():
    """int alpha2(x; a) dA = s(a), the identity below Eq. (6)."""
    radius = 4.0
    a = cap_grid(radius, 12)
    edges = np.linspace(0, np.pi * radius, 257)
    np.testing.assert_allclose(cap_intersection_weights(edges, a, radius).sum(axis=1),
                               cap_area(a, radius), rtol=1e-6)


def test_uncorrelated_variances():
    """Eq. (6) = rho pi a^2 exactly; g2 = 1 in Eq. (4) gives Eq. (6), in Eq. (5) gives Eq. (7)."""
    radius, rho = 3.0, 0.7
    a = cap_grid(radius, 10)
    np.testing.assert_allclose(uniform_variance(a, radius, rho), rho * np.pi * a**2, rtol=1e-12)
    np.testing.assert_allclose(poisson_variance(a, radius, rho), rho * cap_area(a, radius))
    edges = np.linspace(0, np.pi * radius, 301)
    n = rho * 4 * np.pi * radius**2
    canonical = variance_from_g2(a, radius, rho, edges, np.ones(300), n_particles=n)
    np.testing.assert_allclose(canonical, uniform_variance(a, radius, rho), rtol=1e-6)
    grand = variance_from_g2(a, radius, rho, edges, np.ones(300), n_particles=None,
                             ensemble="grand_canonical")
    np.testing.assert_allclose(grand, poisson_variance(a, radius, rho), rtol=1e-6)


@pytest.mark.parametrize("call, message", [
    (lambda: cap_area(1.0, 0.0), "sphere radius R must be a finite number > 0"),
    (lambda: cap_area(1.0, -2.0), "sphere radius R"),
    (lambda: cap_area(3.0, 2.0), "exceeds R"),
    (lambda: cap_area(-1.0, 2.0), ">= 0"),
    (lambda: uniform_variance(1.0, 2.0, 0.0), "number density rho"),
    (lambda: poisson_variance(1.0, 2.0, -1.0), "number density rho"),
    (lambda: cap_intersection_fraction(7.0, 1.0, 2.0), r"\[0, pi R\]"),
    (lambda: cap_grid(2.0, 1), "n_a"),
    (lambda: cos_thresholds([1.0, 0.5], 2.0), "increase"),
    (lambda: variance_from_g2([1.0], 2.0, 0.5, [0, 1, 2], [1, 1], n_particles=None), "N >= 2"),
    (lambda: variance_from_g2([1.0], 2.0, 0.5, [0, 1, 2], [1, 1], n_particles=9, ensemble="npt"),
     "ensemble"),
])
def test_bad_parameters_are_rejected(call, message):
    with pytest.raises(ValueError, match=message):
        call()
