"""Point patterns on the sphere (randmedia.generate.sphere_surface): Tegmark's icosahedral grid,
the Fibonacci grid, uniform and Poisson points, the configuration file contract."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats
from scipy.spatial import SphericalVoronoi, cKDTree

from randmedia.generate import sphere_surface as ss


def _voronoi_spread(points: np.ndarray) -> float:
    areas = SphericalVoronoi(points / np.linalg.norm(points[0])).calculate_areas()
    return float(areas.std() / areas.mean())


@pytest.mark.parametrize("n", [1, 2, 3, 4, 6])
def test_icosahedral_grid_has_tegmarks_pixel_number(n):
    points = ss.icosahedral_grid(n, 2.0)
    assert points.shape == (40 * n * (n - 1) + 12, 3)
    np.testing.assert_allclose(np.linalg.norm(points, axis=1), 2.0)
    distance, _ = cKDTree(points).query(points, 2)
    assert distance[:, 1].min() > 0.9 * distance[:, 1].mean()  # no duplicates, near-regular


def test_icosahedral_pixels_have_nearly_equal_areas_and_inversion_symmetry():
    points = ss.icosahedral_grid(5)
    assert _voronoi_spread(points) < 0.015  # about 1 %: edge and corner cells (pure gnomonic: 4x more)
    # the grid is symmetric under p -> -p: every hemisphere holds exactly N/2 points
    distance, _ = cKDTree(points).query(-points)
    assert distance.max() < 1e-9


def test_area_equalizing_map_is_equal_area():
    """Uniform points of a planar face, moved by the inverse map and projected, are uniform on
    the spherical face (so grid pixels of equal planar area have equal solid angle)."""
    rng = np.random.default_rng(21)
    vertices, faces = ss.icosahedron()
    centre, corners = ss._face_frame(vertices, faces[0])
    planar = rng.dirichlet([1, 1, 1], 40000) @ corners
    mapped = ss._unadjust(planar, centre, corners)
    mapped /= np.linalg.norm(mapped, axis=1)[:, None]
    reference = rng.standard_normal((800000, 3))
    reference /= np.linalg.norm(reference, axis=1)[:, None]
    centres = np.array([ss._face_frame(vertices, f)[0] for f in faces])
    reference = reference[np.argmax(reference @ centres.T, axis=1) == 0]
    for direction in (centre, vertices[faces[0][0]], vertices[faces[0][1]]):
        assert stats.ks_2samp(mapped @ direction, reference @ direction).pvalue > 1e-3
    plain = planar / np.linalg.norm(planar, axis=1)[:, None]  # without the map: not equal-area
    assert stats.ks_2samp(plain @ centre, reference @ centre).pvalue < 1e-6


def test_equal_area_map_round_trip():
    h = 0.381966
    v, t = np.meshgrid(np.linspace(0.01, h, 7), np.linspace(0, math.sqrt(3), 7))
    back = ss.equal_area_to_gnomonic(*ss.gnomonic_to_equal_area(v, t, h), h)
    np.testing.assert_allclose(back[0], v, atol=1e-12)
    np.testing.assert_allclose(back[1], t, atol=1e-9)


def test_fibonacci_grid():
    points = ss.fibonacci_grid(1000, 3.0)
    assert points.shape == (1000, 3)
    np.testing.assert_allclose(np.linalg.norm(points, axis=1), 3.0)
    np.testing.assert_allclose(np.diff(points[:, 2]), 6.0 / 1000)  # equal-area latitude steps
    assert _voronoi_spread(points) < 0.05
    # odd N = 2n + 1 reproduces Swinbank & Purser: sin(latitude) = 2k / (2n + 1), k = -n..n
    odd = ss.fibonacci_grid(21)
    np.testing.assert_allclose(odd[:, 2], 2 * np.arange(-10, 11) / 21)


def test_uniform_points_are_uniform():
    rng = np.random.default_rng(22)
    points = ss.uniform_points(50000, 2.0, rng)
    assert points.shape == (50000, 3)
    assert stats.kstest(points[:, 2] / 2.0, "uniform", args=(-1, 2)).pvalue > 1e-3


def test_poisson_counts_in_disjoint_regions_are_independent_poisson():
    """Appendix 2: N(A) ~ Poiss(<N> mu(A)/mu(S)) and independent for disjoint A (regions chosen
    across the rectangles of the subdivision and of unequal areas)."""
    rng = np.random.default_rng(23)
    mean_points, radius, n = 60.0, 1.5, 4000
    regions = [
        lambda p: p[:, 2] > 0.8 * radius,                                         # polar cap
        lambda p: (np.abs(p[:, 2]) < 0.2 * radius) & (p[:, 0] > 0),               # half equatorial band
        lambda p: (p[:, 2] < -0.3 * radius) & (np.arctan2(p[:, 1], p[:, 0]) > 1.0),  # southern sector
    ]
    fractions = [0.1, 0.2 / 2, 0.35 * (np.pi - 1.0) / (2 * np.pi)]
    counts = np.array([[region(p).sum() for region in regions]
                       for p in (ss.poisson_points(mean_points, radius, rng) for _ in range(n))])
    for k, fraction in enumerate(fractions):
        expected = mean_points * fraction
        column = counts[:, k]
        assert abs(column.mean() - expected) < 4 * math.sqrt(expected / n)
        # dispersion index: (n-1) s^2 / lambda ~ chi^2(n - 1) for Poisson counts
        statistic = (n - 1) * column.var(ddof=1) / expected
        assert stats.chi2.sf(statistic, n - 1) > 1e-3 and stats.chi2.cdf(statistic, n - 1) > 1e-3
    correlation = np.corrcoef(counts.T)
    assert np.all(np.abs(correlation[np.triu_indices(3, 1)]) < 4 / math.sqrt(n))


def test_poisson_total_number_has_poisson_mean_and_variance():
    rng = np.random.default_rng(24)
    totals = np.array([len(ss.poisson_points(40.0, 1.0, rng, n_theta=5, n_phi=7)) for _ in range(4000)])
    assert abs(totals.mean() - 40.0) < 4 * math.sqrt(40.0 / 4000)
    assert abs(totals.var(ddof=1) / 40.0 - 1) < 4 * math.sqrt(2 / 4000)


def test_configuration_dataset_round_trip_pads_with_nan():
    rng = np.random.default_rng(25)
    frames = [ss.poisson_points(30.0, 2.0, rng) for _ in range(5)]
    ds = ss.points_dataset(frames, 2.0, {"system": "poisson"})
    assert ds["position"].dims == ("frame", "particle", "xyz")
    assert ds["position"].shape[1] == max(len(f) for f in frames)
    assert np.isnan(ds["position"].values).any()
    for name in ds.variables:
        assert {"units", "long_name"} <= set(ds[name].attrs)
    for original, back in zip(frames, ss.frames_of(ds)):
        np.testing.assert_array_equal(original, back)
    with pytest.raises(ValueError, match="not on the sphere"):
        ss.points_dataset([np.ones((3, 3))], 2.0, {})


@pytest.mark.parametrize("call, message", [
    (lambda: ss.icosahedral_grid(0), "resolution"),
    (lambda: ss.icosahedral_grid(3, radius=0.0), "sphere radius R"),
    (lambda: ss.fibonacci_grid(100, radius=-1.0), "sphere radius R"),
    (lambda: ss.uniform_points(10, 0.0, np.random.default_rng(0)), "sphere radius R"),
    (lambda: ss.poisson_points(0.0, 1.0, np.random.default_rng(0)), "mean number"),
    (lambda: ss.poisson_points(10.0, 1.0, np.random.default_rng(0), n_theta=0), "n_theta"),
])
def test_bad_parameters_are_rejected(call, message):
    with pytest.raises(ValueError, match=message):
        call()
