"""3D validation media (issue 13): Poisson-plane tessellations and overlapping spheres."""

import math

import numpy as np
import pytest

from randmedia.generate.balls import digitize_balls, overlapping_ball_centers, overlapping_balls_image
from randmedia.generate.disks import overlapping_disks_image
from randmedia.generate.poisson_planes import cell_labels, poisson_plane_image, poisson_planes
from randmedia.theory.balls import poisson_intensity, unit_ball_volume
from randmedia.theory.debye_formulas import debye_specific_surface
from randmedia.theory.plane_process import crossing_fraction, plane_area_density, specific_surface

# ----------------------------------------------------------------------------- Poisson planes


def test_crossing_fraction_and_specific_surface_match_eq7():
    assert crossing_fraction(2) == pytest.approx(2 / math.pi, rel=1e-14)
    assert crossing_fraction(3) == pytest.approx(0.5, rel=1e-14)
    phi2, a = 0.3, 4.0
    # Eq. (7): -S2'(0) = omega_{d-1} / (d omega_d) s, and -S2'(0) = phi1 phi2 / a for Eq. (21)
    for d in (2, 3):
        s = specific_surface(a, phi2, d)
        assert s * unit_ball_volume(d - 1) / (d * unit_ball_volume(d)) == pytest.approx(0.7 * 0.3 / a)
    assert specific_surface(a, phi2, 3) == pytest.approx(4 * 0.7 * 0.3 / a)
    assert specific_surface(a, phi2, 2) == pytest.approx(debye_specific_surface(a, phi2))
    assert plane_area_density(a, 3) == pytest.approx(2 / a)  # P_L = S_V / 2


@pytest.mark.parametrize("dim", [2, 3])
def test_segments_are_uncrossed_with_probability_exp_minus_r_over_a(dim):
    """The geometric core of the derivation, without images: a random segment inside the
    window is crossed by a Poisson number of planes with mean r/a (one segment per plane
    set, so the segments are independent)."""
    rng = np.random.default_rng(13 + dim)
    a, side, n = 3.0, 30, 3000
    shape = (side,) * dim
    for r in (1.0, 3.0, 6.0):
        crossings = np.empty(n, dtype=int)
        for t in range(n):
            planes = poisson_planes(rng, shape, a)
            start = rng.uniform(r, side - r, size=dim)
            direction = rng.standard_normal(dim)
            end = start + r * direction / np.linalg.norm(direction)
            side_start = (start - planes.centre) @ planes.normal.T > planes.offset
            side_end = (end - planes.centre) @ planes.normal.T > planes.offset
            crossings[t] = np.count_nonzero(side_start != side_end)
        p = math.exp(-r / a)
        assert abs(np.mean(crossings == 0) - p) < 4 * math.sqrt(p * (1 - p) / n)
        # Poisson with mean r/a: mean and variance
        assert abs(crossings.mean() - r / a) < 4 * math.sqrt(r / a / n)
        assert crossings.var(ddof=1) == pytest.approx(r / a, rel=0.15)


def test_plane_count_is_poisson_with_mean_2R_over_a_kappa():
    rng = np.random.default_rng(4)
    shape, a = (24, 30, 36), 2.5
    counts = np.array([poisson_planes(rng, shape, a).offset.size for _ in range(2000)])
    radius = math.sqrt(12**2 + 15**2 + 18**2)
    expected = 2 * radius / (a * 0.5)
    assert abs(counts.mean() - expected) < 4 * math.sqrt(expected / counts.size)
    assert counts.var(ddof=1) / counts.mean() == pytest.approx(1.0, abs=0.1)


@pytest.mark.parametrize("shape", [(20, 17, 23), (31, 29), (8, 9, 10)])
def test_cell_labels_are_the_sign_vectors_of_the_planes(shape):
    """Two voxels share a label iff no plane separates their centres (brute force)."""
    rng = np.random.default_rng(len(shape) + sum(shape))
    planes = poisson_planes(rng, shape, 2.0)
    labels = cell_labels(planes, shape, rng).reshape(-1)
    centres = np.indices(shape).reshape(len(shape), -1).T[:, ::-1] + 0.5  # (x, y[, z])
    signs = (centres - planes.centre) @ planes.normal.T > planes.offset
    _, reference = np.unique(signs, axis=0, return_inverse=True)
    reference = reference.reshape(-1)
    assert labels.max() + 1 == reference.max() + 1 > 10
    # the same partition: the label pairs are a bijection
    assert len(set(zip(labels.tolist(), reference.tolist()))) == labels.max() + 1
    # labels in order of first appearance
    first = np.unique(labels, return_index=True)[1]
    assert np.all(np.diff(first) > 0)


def test_poisson_plane_image_is_reproducible_binary_and_unbiased():
    rng = np.random.default_rng(7)
    images = [poisson_plane_image(rng, (24, 24, 24), 3.0, 0.3) for _ in range(60)]
    assert all(im.dtype == np.uint8 and im.shape == (24, 24, 24) for im in images)
    assert set(np.unique(np.concatenate([im.ravel() for im in images]))) == {0, 1}
    fractions = np.array([im.mean() for im in images])
    assert abs(fractions.mean() - 0.3) < 3 * fractions.std(ddof=1) / math.sqrt(len(fractions))
    a = poisson_plane_image(np.random.default_rng(9), (16, 20), 3.0, 0.4)
    b = poisson_plane_image(np.random.default_rng(9), (16, 20), 3.0, 0.4)
    np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("kwargs", [dict(phi2=0.0, a=1.0), dict(phi2=1.0, a=1.0),
                                    dict(phi2=0.3, a=0.0)])
def test_poisson_planes_reject_impossible_parameters(kwargs):
    with pytest.raises(ValueError):
        poisson_plane_image(np.random.default_rng(0), (8, 8, 8), **kwargs)


def test_poisson_planes_reject_wrong_dimension():
    with pytest.raises(ValueError, match="dim"):
        poisson_planes(np.random.default_rng(0), (8,), 2.0)

# ----------------------------------------------------------------------------- overlapping balls


@pytest.mark.parametrize("seed, side, radius, phi2", [(0, 101, 5.3, 0.4), (1, 64, 4.0, 0.3),
                                                      (2, 37, 7.7, 0.6), (3, 151, 10.0, 0.3)])
def test_two_dimensional_balls_are_bit_identical_to_disks(seed, side, radius, phi2):
    """The d-generic painter gives the debye2020 overlapping-disk images unchanged."""
    a = overlapping_disks_image(np.random.default_rng(seed), side, radius, phi2)
    b = overlapping_balls_image(np.random.default_rng(seed), side, radius, phi2, 2)
    assert a.dtype == b.dtype == np.uint8
    np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("center", [(10.3, 7.9, 12.2), (0.2, 19.7, 0.4), (19.9, 0.1, 19.95)])
def test_one_sphere_is_exactly_the_voxel_centres_inside_it_periodically(center):
    side, radius = 20, 5.3
    image = digitize_balls(np.array([center]), radius, (side, side, side))
    zz, yy, xx = np.mgrid[:side, :side, :side] + 0.5
    d = [(q - c + side / 2) % side - side / 2 for q, c in zip((xx, yy, zz), center)]
    np.testing.assert_array_equal(image.astype(bool), d[0]**2 + d[1]**2 + d[2]**2 <= radius**2)


def test_overlapping_spheres_volume_fraction_and_poisson_count():
    rng = np.random.default_rng(12)
    fractions = [overlapping_balls_image(rng, 40, 4.0, 0.3, 3).mean() for _ in range(30)]
    mean, sem = np.mean(fractions), np.std(fractions, ddof=1) / np.sqrt(len(fractions))
    assert abs(mean - 0.3) <= 3 * sem
    counts = np.array([len(overlapping_ball_centers(rng, 20.0, 3.0, 0.2, 3)) for _ in range(2000)])
    expected = poisson_intensity(0.2, 3.0, 3) * 20.0**3
    assert expected == pytest.approx(-math.log(0.8) / (4 / 3 * math.pi * 27) * 8000)
    assert abs(counts.mean() - expected) < 4 * math.sqrt(expected / counts.size)


def test_balls_reject_bad_dimension_and_parameters():
    with pytest.raises(ValueError, match="dim"):
        digitize_balls(np.zeros((1, 4)), 1.0, (4, 4, 4, 4))
    with pytest.raises(ValueError):
        poisson_intensity(1.0, 1.0, 3)
    with pytest.raises(ValueError):
        digitize_balls(np.zeros((1, 3)), 0.0, (4, 4, 4))
