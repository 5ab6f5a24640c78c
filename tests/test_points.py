"""Pore sizes, exclusion probability, covering radius and window counts (randmedia.describe.points)."""

import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from mrj_helpers import TRICLINIC, rsa_packing
from randmedia.describe import points
from randmedia.generate.spheres import lattice_covering_radius, lattice_spheres, overlapping_spheres
from randmedia.periodic import Cell, padded_images
from randmedia.theory import overlapping as theory
from randmedia.theory.balls import poisson_intensity


@pytest.mark.parametrize("box", [TRICLINIC, np.eye(3) * 5.3], ids=["triclinic", "cubic"])
def test_nearest_distances_and_window_counts_against_a_kd_tree(box):
    rng = np.random.default_rng(0)
    cell = Cell(box)
    x = cell.random_points(rng, 120) + rng.normal(scale=4.0, size=(120, 3))
    queries = cell.random_points(rng, 3000)
    images, _ = padded_images(cell, x, cell.face_distances.min() * 0.999)
    tree = cKDTree(images)
    cells = points.CellList(x, box)
    np.testing.assert_allclose(points.nearest_distances(cells, queries), tree.query(queries)[0], atol=1e-12)
    radii = np.linspace(0.2, cell.half_width, 15)
    throws = points.throws_per_radius(cell.volume, radii, 0.8, 400)
    counts = points.window_counts(x, box, queries[:400], radii, throws)
    for i, R in enumerate(radii):
        expected = tree.query_ball_point(queries[: throws[i]], R, return_length=True)
        np.testing.assert_array_equal(counts[: throws[i], i], expected)
        assert np.all(counts[throws[i]:, i] == -1)


def test_throws_rule():
    """Sec. VI B: n(R) balls of volume v(R) cover at most phi_B of the cell."""
    volume = 1000.0
    radii = np.array([0.5, 2.0, 5.0, 6.2])
    n = points.throws_per_radius(volume, radii, 0.8, 500)
    ball = 4 * math.pi * radii**3 / 3
    assert np.all((n * ball <= 0.8 * volume + 1e-9) | (n == 1))
    assert n[0] == 500 and n[-1] == 1
    assert np.all(((n + 1) * ball > 0.8 * volume) | (n == 500))


@pytest.fixture(scope="module")
def poisson_samples():
    rng = np.random.default_rng(1)
    return [overlapping_spheres(rng, 0.636, 500) for _ in range(24)]


def test_pore_sizes_and_exclusion_probability_of_overlapping_spheres(poisson_samples):
    """E_V(r) = exp(-rho 4 pi r^3/3), F(delta) and <delta>, <delta^2> of the Boolean model (exact)."""
    phi, R = 0.636, 0.5
    edges = points.distance_bins(0.001, 2.5)
    ev, F, moments = [], [], []
    for k, (x, box) in enumerate(poisson_samples):
        st = points.nearest_distance_statistics(x, box, 1.0, np.random.default_rng(100 + k), 20_000, edges)
        e = points.exclusion_from_histogram(st["hist"], st["n_points"], st["overflow"])
        ev.append(e[[200, 500, 800]])
        F.append(e[[550, 600, 700]] / e[500])
        moments.append([st["sum_delta"] / st["n_matrix"], st["sum_delta2"] / st["n_matrix"]])
        assert st["n_matrix"] == 20_000
    rho = poisson_intensity(phi, R, 3)
    for values, exact in (
        (ev, theory.exclusion_probability(np.array([0.2, 0.5, 0.8]), rho, 3)),
        (F, theory.pore_size_complementary_cdf(np.array([0.05, 0.1, 0.2]), R, phi, 3)),
        (moments, [theory.pore_size_moment(1, R, phi, 3), theory.pore_size_moment(2, R, phi, 3)]),
    ):
        values = np.array(values)
        sem = values.std(axis=0, ddof=1) / np.sqrt(len(values))
        assert np.all(np.abs(values.mean(axis=0) - exact) < 4 * sem), (values.mean(axis=0), exact, sem)


def test_exclusion_probability_of_hard_spheres_below_the_radius():
    """Eq. (21): E_V(r) = 1 - rho 4 pi r^3 / 3 for r <= D/2 (binomial count of points in spheres)."""
    rng = np.random.default_rng(2)
    x = rsa_packing(rng, TRICLINIC, 150)
    edges = points.distance_bins(0.01, 2.0)
    st = points.nearest_distance_statistics(x, TRICLINIC, 1.0, rng, 60_000, edges)
    e = points.exclusion_from_histogram(st["hist"], st["n_points"], st["overflow"])
    rho = len(x) / Cell(TRICLINIC).volume
    for i in (20, 35, 50):
        p = 1 - rho * 4 * math.pi * edges[i] ** 3 / 3
        assert abs(e[i] - p) < 4 * math.sqrt(p * (1 - p) / st["n_points"])


@pytest.mark.parametrize("lattice", ["fcc", "bcc"])
def test_covering_radius_of_lattices(lattice):
    x, box = lattice_spheres(lattice, 3, rng=np.random.default_rng(3))
    exact = lattice_covering_radius(lattice)
    assert points.covering_radius(x, box) == pytest.approx(exact, rel=1e-12)
    edges = points.distance_bins(0.001, 1.0)
    st = points.nearest_distance_statistics(x, box, 1.0, np.random.default_rng(4), 50_000, edges)
    assert st["max_distance"] <= exact + 1e-12
    e = points.exclusion_from_histogram(st["hist"], st["n_points"], st["overflow"])
    assert np.all(e[edges > exact] == 0) and e[edges < 0.9 * exact].min() > 0


def test_number_variance_of_poisson_centres_is_the_mean(poisson_samples):
    """Sec. VI B benchmark: sigma_N^2(R) = rho v(R) for the Poisson centres, pooled with jackknife SEM;
    skewness 1/sqrt(mu) and excess kurtosis 1/mu of the Poisson distribution."""
    radii = np.array([0.5, 1.0, 1.5, 2.0])
    moments = []
    for k, (x, box) in enumerate(poisson_samples):
        cell = Cell(box)
        n = points.throws_per_radius(cell.volume, radii, 0.8, 2000)
        centres = cell.random_points(np.random.default_rng(200 + k), int(n.max()))
        m = points.window_moments(points.window_counts(x, box, centres, radii, n))
        moments.append([m[key] for key in ("n_throws", "sum_N", "sum_N2", "sum_N3", "sum_N4")])
    moments = np.array(moments).transpose(1, 0, 2)
    mean, var, mean_sem, var_sem = points.pooled_number_variance(*moments[:3])
    mu = poisson_intensity(0.636, 0.5, 3) * 4 * math.pi * radii**3 / 3
    assert np.all(np.abs(mean - mu) < 4 * mean_sem)
    assert np.all(np.abs(var - mu) < 4 * var_sem), (var, mu, var_sem)
    skew, kurt = points.pooled_shape(*moments)
    np.testing.assert_allclose(skew[:2], 1 / np.sqrt(mu[:2]), rtol=0.25)
    assert kurt[0] == pytest.approx(1 / mu[0], rel=0.3)


def test_pooled_variance_and_jackknife():
    rng = np.random.default_rng(5)
    samples = [rng.normal(10, 2, size=500) for _ in range(30)]
    n = np.array([[len(s)] for s in samples], float)
    s1 = np.array([[s.sum()] for s in samples])
    s2 = np.array([[(s * s).sum()] for s in samples])
    mean, var, mean_sem, var_sem = points.pooled_number_variance(n, s1, s2)
    pooled = np.concatenate(samples)
    assert mean[0] == pytest.approx(pooled.mean())
    assert var[0] == pytest.approx(pooled.var(ddof=1))
    assert mean_sem[0] == pytest.approx(pooled.std() / math.sqrt(pooled.size), rel=0.3)
    assert var_sem[0] == pytest.approx(4 * math.sqrt(2 / pooled.size), rel=0.35)  # sqrt(2/n) sigma^2
