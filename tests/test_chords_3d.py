"""Lineal path and chord-length density of 3D voxel images: direction set, a slab with an exact
answer, and overlapping spheres (exact L(z), p(z); Ma & Torquato 2020, Eqs. 19-20)."""

import math

import numpy as np
import pytest
from scipy import stats

from randmedia.describe.chords import (_walk3, chord_density_from_runs, hemisphere_directions,
                                       lineal_path_and_chords, lineal_path_from_runs, random_rotation,
                                       sample_chords, smoothed_level_set, sphere_line_directions)
from randmedia.generate.balls import digitize_balls, overlapping_ball_centers
from randmedia.stats import standard_error
from randmedia.theory.overlapping import chord_rate, lineal_path_void

# ------------------------------------------------------------------ direction set


def test_hemisphere_directions_are_unit_vectors_stratified_in_solid_angle():
    n = 50
    u = hemisphere_directions(n)
    np.testing.assert_allclose(np.linalg.norm(u, axis=1), 1.0)
    # one direction per zone of equal area: cos(theta) at the zone midpoints (Archimedes)
    np.testing.assert_allclose(np.sort(u[:, 2]), (np.arange(n) + 0.5) / n)
    # second moments of the undirected set: isotropic up to O(1/n^2)
    np.testing.assert_allclose(u.T @ u / n, np.eye(3) / 3, atol=0.01)
    with pytest.raises(ValueError):
        hemisphere_directions(0)


def test_random_rotation_is_proper_and_sphere_line_directions_are_uniform():
    rng = np.random.default_rng(11)
    rotation = random_rotation(rng)
    np.testing.assert_allclose(rotation @ rotation.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(rotation) == pytest.approx(1.0)
    # each direction of the rotated set is uniform on the sphere: |u . e| uniform on [0, 1]
    # (Archimedes) for every fixed axis e, and the azimuth about e uniform
    first = np.array([sphere_line_directions(8, rng)[3] for _ in range(600)])
    for axis in range(3):
        assert stats.kstest(np.abs(first[:, axis]), "uniform").pvalue > 1e-3
    azimuth = np.arctan2(first[:, 1], first[:, 0]) % (2 * np.pi)
    assert stats.kstest(azimuth / (2 * np.pi), "uniform").pvalue > 1e-3


# ------------------------------------------------------------------ slab: a known, non-random answer


def _slab(width=8, nz=24, n=6):
    image = np.zeros((nz, n, n), dtype=np.uint8)
    image[width:] = 1  # phase 0 = the slab 0 <= z < width, periodic along z
    return image


def test_walk3_measures_the_slab_chord_w_over_cos_theta():
    """sigma = 0: the field is the indicator, linear in z between voxel centres, so the level
    set at 1/2 is exactly the slab 0 <= z < w; a line at polar angle theta crosses it in
    chords of length w / |cos theta|, each end placed to within step/2 by the walk."""
    width, step = 8, 0.1
    image = _slab(width)
    field, threshold = smoothed_level_set(image, 0, 0.0)
    assert threshold == 0.5
    n_steps = 2000
    runs = np.empty(n_steps // 2 + 2)
    complete = np.empty(n_steps // 2 + 2, dtype=np.bool_)
    for theta in (0.0, 0.3, 0.9, 1.2):
        u = (math.sin(theta) * math.cos(0.7), math.sin(theta) * math.sin(0.7), math.cos(theta))
        count = _walk3(field, threshold, 1.3, 2.1, 12.37, *u, n_steps, step, runs, complete)
        chords = runs[:count][complete[:count]]
        assert chords.size >= 2
        np.testing.assert_allclose(chords, width / math.cos(theta), atol=step)


def test_slab_lineal_path_and_chords_match_isotropic_lines():
    """Isotropic lines through a periodic slab (width w, period P): a segment of length z at
    |cos theta| = mu lies in it with probability (w - z mu)+ / P, mu uniform on [0, 1], so
    L(z) = (w - z/2)/P for z <= w and w^2 / (2 z P) beyond; chords are counted in proportion
    to mu, so P(chord > l) = (w / l)^2 for l >= w. Tolerance 3 SEM over the samples (each
    its own random rotation) + the step bound: every run is off by <= step, a line has at
    most T/P + 1 runs, so |dL| <= step (T/P + 1) / (T - z)."""
    width, period, step = 8, 24, 0.1
    images = np.stack([_slab(width, period)] * 8)
    ds = lineal_path_and_chords(images, 0, np.random.default_rng(3), z_max=16.0, dz=1.0, sigma=0.0,
                                n_directions=24, lines_per_direction=4, step=step)
    assert ds["z"].attrs["units"] == "voxel" and ds["p"].attrs["units"] == "1/voxel"
    z = ds["z"].values
    exact = np.where(z <= width, (width - z / 2) / period, width**2 / (2 * np.maximum(z, 1e-9) * period))
    T = 4 * period
    margin = step * (T / period + 1) / (T - z)
    assert np.all(np.abs(ds["L"].values - exact) <= 3 * ds["L_sem"].values + margin)
    # chord-length distribution, conditional on l <= 4w (longer chords are rarely complete)
    rng = np.random.default_rng(4)
    cdf = []
    for image in images:
        runs, complete, length, _ = sample_chords(image, 0, rng, n_directions=24, lines_per_direction=4,
                                                  sigma=0.0, step=step)
        chords = runs[complete]
        assert chords.min() >= width - step
        weights = length / (length - chords)
        kept = chords <= 4 * width
        cdf.append([np.sum(weights[kept & (chords <= c * width)]) / np.sum(weights[kept]) for c in (1.5, 2, 3)])
    cdf = np.array(cdf)
    c = np.array([1.5, 2, 3])
    exact_cdf = (1 - c**-2.0) / (1 - 4**-2.0)
    assert np.all(np.abs(cdf.mean(0) - exact_cdf) <= 3 * standard_error(cdf) + 0.01)


# ------------------------------------------------------------------ overlapping spheres


def _line_draws(rng, shape, n_directions, lines_per_direction):
    """The lines :func:`sample_chords` draws in 3D from ``rng`` (same order of draws)."""
    nz, ny, nx = shape
    lines = []
    for u in sphere_line_directions(n_directions, rng):
        for _ in range(lines_per_direction):
            lines.append((np.array([rng.random() * nx, rng.random() * ny, rng.random() * nz]), u))
    return lines


def _continuum_void_runs(centers, radius, side, lines, length):
    """Exact void runs of the continuum (undigitized) periodic overlapping balls along lines:
    the gaps between the union of the chords each ball image cuts on the segment [0, T]."""
    runs, flags = [], []
    for p0, u in lines:
        p1 = p0 + length * u
        lo, hi = np.minimum(p0, p1) - radius, np.maximum(p0, p1) + radius
        shifts = [np.arange(math.floor(lo[a] / side) - 1, math.ceil(hi[a] / side) + 1) for a in range(3)]
        offsets = np.stack(np.meshgrid(*shifts, indexing="ij"), -1).reshape(-1, 3) * side
        rel = (centers[:, None, :] + offsets[None]).reshape(-1, 3) - p0
        t = rel @ u
        d2 = np.einsum("ij,ij->i", rel, rel) - t * t
        hit = d2 <= radius * radius
        half = np.sqrt(radius * radius - d2[hit])
        a, b = np.clip(t[hit] - half, 0, length), np.clip(t[hit] + half, 0, length)
        order = np.argsort(a)
        covered = 0.0
        for start, end in zip(a[order], b[order]):
            if start > covered:
                runs.append(start - covered)
                flags.append(covered > 0)
            covered = max(covered, end)
        if covered < length:
            runs.append(length - covered)
            flags.append(False)
    return np.array(runs), np.array(flags, dtype=bool)


RADIUS, PHI2, SIDE, N_SAMPLES, N_DIR, N_LINES = 4.0, 0.3, 40, 10, 32, 8


@pytest.fixture(scope="module")
def spheres():
    """Void-phase L(z), p(z) of 10 periodic 40^3 images of overlapping spheres (R = 4 voxels,
    phi2 = 0.3), from the digitized level set and from the continuum along the same lines."""
    centers = [overlapping_ball_centers(np.random.default_rng(900 + k), SIDE, RADIUS, PHI2, 3)
               for k in range(N_SAMPLES)]
    images = np.stack([digitize_balls(c, RADIUS, (SIDE,) * 3) for c in centers])
    z_max = 6 * RADIUS
    ds = lineal_path_and_chords(images, 0, np.random.default_rng(5), z_max=z_max,
                                n_directions=N_DIR, lines_per_direction=N_LINES)
    rng = np.random.default_rng(5)  # the same lines again
    edges = np.arange(0.0, z_max + 1.0, 1.0)
    length = 4.0 * SIDE
    lineal, density = [], []
    for c in centers:
        lines = _line_draws(rng, (SIDE,) * 3, N_DIR, N_LINES)
        runs, complete = _continuum_void_runs(c, RADIUS, SIDE, lines, length)
        lineal.append(lineal_path_from_runs(runs, length, len(lines), ds["z"].values))
        density.append(chord_density_from_runs(runs, complete, length, edges)[0])
    rate = chord_rate(RADIUS, PHI2, 3)
    exact_bins = (np.exp(-rate * edges[:-1]) - np.exp(-rate * edges[1:])) / np.diff(edges)
    return ds, np.array(lineal), np.array(density), exact_bins


def _scores(mean, sem, exact, margin=0.0):
    return np.maximum(np.abs(mean - exact) - margin, 0.0) / sem


def test_continuum_along_the_sampled_lines_matches_the_exact_overlapping_spheres(spheres):
    """Isolates the 3D line geometry (directions, origins, periodic lines, the L and p
    estimators) from the digitization: exact runs of the continuum medium along the lines
    sample_chords draws. L: every z within 3 SEM (z bins are strongly correlated). p: ~24
    nearly independent bins, SEM from 10 samples (t_9): chi^2 per bin < 2 and none beyond
    5 SEM (as the 2D test); exact p is the bin average, so there is no labelling bias."""
    ds, lineal, density, exact_bins = spheres
    exact = lineal_path_void(ds["z"].values, RADIUS, PHI2, 3)
    assert np.all(_scores(lineal.mean(0), standard_error(lineal), exact) <= 3)
    scores = _scores(density.mean(0), standard_error(density), exact_bins)
    assert np.mean(scores**2) < 2 and scores.max() < 5


#: systematic margins of the sigma = 0.5 voxel level set at R = 4 voxels, phi2 = 0.3: the
#: largest mean |level set - continuum| along the same lines + 2 of its SEM, from 16 other
#: samples of 48^3 (docs/debye3d.md, "Lineal path and chords in 3D"): L(z <= 6R)
#: 4.48e-3 + 2 x 0.40e-3, p(z >= 3) 4.64e-3 + 2 x 0.68e-3.
MARGIN_L, MARGIN_P = 5.3e-3, 6.0e-3


def test_lineal_path_of_digitized_overlapping_spheres_is_exponential(spheres):
    """L(z) = phi1 exp(-lambda z), lambda = 3 eta / (4 R) (mean chord 4 phi1 / s, Eq. 20 in
    3D): within 3 SEM + the level set's measured systematic (MARGIN_L)."""
    ds = spheres[0]
    exact = lineal_path_void(ds["z"].values, RADIUS, PHI2, 3)
    assert np.all(_scores(ds["L"].values, ds["L_sem"].values, exact, MARGIN_L) <= 3)


def test_chord_density_of_digitized_overlapping_spheres_from_3_voxels(spheres):
    """p(z) = lambda exp(-lambda z) for z >= 3 voxels (the level set closes sub-voxel gaps:
    the first bin holds half the exact weight), within the calibrated chi^2 criterion of the
    continuum test after the measured systematic (MARGIN_P); and the level set against the
    continuum of the same realizations along the same lines, paired."""
    ds, lineal, density, exact_bins = spheres
    resolved = ds["z_chord"].values >= 3.0
    scores = _scores(ds["p"].values, ds["p_sem"].values, exact_bins, MARGIN_P)[resolved]
    assert np.mean(scores**2) < 2 and scores.max() < 5
    paired = ds["L_samples"].values - lineal
    assert np.all(_scores(paired.mean(0), standard_error(paired), 0.0, MARGIN_L) <= 3)
    paired = (ds["p_samples"].values - density)[:, resolved]
    scores = _scores(paired.mean(0), standard_error(paired), 0.0, MARGIN_P)
    assert np.mean(scores**2) < 2 and scores.max() < 5


def test_mean_chord_of_digitized_overlapping_spheres_is_4_phi1_over_s(spheres):
    """Eq. (20) in 3D: l_C = 4 phi1 / s = 4 R / (3 eta). The level set at sigma = 0.5 voxel
    makes chords 3.1 +- 0.3 % longer than the continuum at R = 4 (docs), the margin."""
    values = spheres[0]["mean_chord_samples"].values
    exact = 4 * RADIUS / (3 * -math.log(1 - PHI2))
    assert abs(values.mean() - exact) <= 3 * values.std(ddof=1) / math.sqrt(values.size) + 0.037 * exact


def test_sample_chords_rejects_other_ranks():
    with pytest.raises(ValueError, match="2D or 3D"):
        sample_chords(np.zeros(10, dtype=np.uint8), 0, np.random.default_rng(0))
    with pytest.raises(ValueError, match="n_samples"):
        lineal_path_and_chords(np.zeros((2, 2, 4, 4, 4)), 0, np.random.default_rng(0), z_max=2.0)


def test_walk_on_a_level_set_grid_gives_the_same_slab_chords():
    """model="pixels", supersample 2, sigma 0: the fine grid is the voxel union, its level set
    the slab itself; the same draws give the same lines, so every run equals the default
    walk's run within one step (positions and steps in sub-voxel units, runs back in voxels)."""
    image = _slab(8, 24)
    step = 0.1
    kwargs = dict(n_directions=12, lines_per_direction=3, sigma=0.0, step=step)
    runs, complete, length, n = sample_chords(image, 0, np.random.default_rng(5), **kwargs)
    fine_runs, fine_complete, fine_length, fine_n = sample_chords(
        image, 0, np.random.default_rng(5), model="pixels", supersample=2, **kwargs)
    assert (fine_length, fine_n) == (length, n)
    np.testing.assert_array_equal(fine_complete, complete)
    np.testing.assert_allclose(fine_runs, runs, atol=step)
    assert fine_runs[fine_complete].min() >= 8 - step
