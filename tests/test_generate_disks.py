"""Overlapping-disk generator: digitization and Poisson statistics."""

import math

import numpy as np
import pytest

from randmedia.generate.disks import digitize_disks, overlapping_disk_centers, overlapping_disks_image
from randmedia.theory.balls import poisson_intensity


def lattice_points_in_disk(cx, cy, radius, side):
    yy, xx = np.mgrid[:side, :side] + 0.5
    dx = (xx - cx + side / 2) % side - side / 2
    dy = (yy - cy + side / 2) % side - side / 2
    return dx**2 + dy**2 <= radius**2


@pytest.mark.parametrize("center", [(20.3, 17.9), (0.2, 39.7), (39.9, 0.1)])
def test_one_disk_is_exactly_the_pixel_centres_inside_it_periodically(center):
    side, radius = 40, 7.3
    image = digitize_disks(np.array([center]), radius, (side, side))
    np.testing.assert_array_equal(image.astype(bool), lattice_points_in_disk(*center, radius, side))


def test_intensity_gives_requested_void_fraction():
    rho = poisson_intensity(0.3, 10.0, 2)
    assert math.isclose(math.exp(-rho * math.pi * 100.0), 0.7)


def test_realized_volume_fraction_is_unbiased():
    rng = np.random.default_rng(11)
    fractions = [overlapping_disks_image(rng, 101, 5.0, 0.3).mean() for _ in range(40)]
    mean, sem = np.mean(fractions), np.std(fractions, ddof=1) / np.sqrt(len(fractions))
    assert abs(mean - 0.3) <= 3 * sem


def test_number_of_centres_is_poisson():
    rng = np.random.default_rng(5)
    counts = np.array([len(overlapping_disk_centers(rng, 50.0, 4.0, 0.2)) for _ in range(2000)])
    expected = poisson_intensity(0.2, 4.0, 2) * 2500.0
    assert abs(counts.mean() - expected) < 4 * math.sqrt(expected / counts.size)
    assert abs(counts.var(ddof=1) / counts.mean() - 1.0) < 0.1  # Poisson: variance = mean


@pytest.mark.parametrize("phi2, radius", [(0.0, 1.0), (1.0, 1.0), (0.3, 0.0), (0.3, -2.0)])
def test_rejects_impossible_parameters(phi2, radius):
    with pytest.raises(ValueError):
        poisson_intensity(phi2, radius, 2)


def test_same_seed_same_image():
    a = overlapping_disks_image(np.random.default_rng(9), 64, 4.0, 0.3)
    b = overlapping_disks_image(np.random.default_rng(9), 64, 4.0, 0.3)
    np.testing.assert_array_equal(a, b)
