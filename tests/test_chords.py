"""Lineal path and chord-length density: exact identities and overlapping disks (Eqs. 38-39)."""

import numpy as np
import pytest

from randmedia.describe.chords import (chord_density_from_runs, lineal_path_and_chords,
                                       lineal_path_from_runs, sample_chords, smoothed_level_set)
from randmedia.generate.disks import overlapping_disks_image


def test_lineal_path_from_runs_is_exact_on_a_known_line():
    # one line of length 10: runs of 3 and 2 -> L(z) = [(3-z)+ + (2-z)+] / (10 - z)
    runs = np.array([3.0, 2.0])
    z = np.array([0.0, 1.0, 2.5, 4.0])
    expected = np.array([5.0 / 10, 3.0 / 9, 0.5 / 7.5, 0.0])
    np.testing.assert_allclose(lineal_path_from_runs(runs, 10.0, 1, z), expected)


def test_chord_density_is_normalized_and_weights_long_chords():
    runs = np.array([1.5, 2.5, 7.5])
    complete = np.array([True, True, False])
    edges = np.arange(0.0, 11.0)
    density, mean_chord = chord_density_from_runs(runs, complete, 10.0, edges)
    assert np.sum(density * np.diff(edges)) == pytest.approx(1.0)
    w = 10 / np.array([8.5, 7.5])  # Miles-Lantuejoul weights T / (T - l)
    assert mean_chord == pytest.approx(np.sum(w * [1.5, 2.5]) / w.sum())


def test_level_set_keeps_volume_fraction():
    image = overlapping_disks_image(np.random.default_rng(1), 101, 6.0, 0.3)
    field, threshold = smoothed_level_set(image, 0, sigma=1.0)
    assert np.count_nonzero(field > threshold) == np.count_nonzero(image == 0)


def test_uniform_phase_gives_one_cut_run_per_line():
    image = np.zeros((50, 50), dtype=np.uint8)
    runs, complete, length, n_lines = sample_chords(image, 0, np.random.default_rng(0),
                                                    n_directions=4, lines_per_direction=2)
    assert n_lines == 8 and runs.size == 8 and not complete.any()
    np.testing.assert_allclose(runs, length)


@pytest.fixture(scope="module")
def disks_chords():
    radius, phi2 = 10.0, 0.3
    rng = np.random.default_rng(2020)
    images = np.stack([overlapping_disks_image(rng, 301, radius, phi2) for _ in range(10)])
    return radius, phi2, lineal_path_and_chords(images, 0, rng, z_max=6 * radius)


def test_lineal_path_of_overlapping_disks_matches_eq_38(disks_chords):
    radius, phi2, ds = disks_chords
    exact = (1 - phi2) ** (1 + 2 * ds["z"].values / (np.pi * radius))
    assert np.all(np.abs(ds["L"].values - exact) <= 3 * ds["L_sem"].values)


def test_chord_density_of_overlapping_disks_matches_eq_39(disks_chords):
    """Resolved chords (z >= 3 px) within 3 SEM; shorter ones lie below the pixel scale."""
    radius, phi2, ds = disks_chords
    eta = -np.log(1 - phi2)
    z = ds["z_chord"].values
    exact = 2 * eta / (np.pi * radius) * (1 - phi2) ** (2 * z / (np.pi * radius))
    resolved = z >= 3.0
    assert np.all(np.abs(ds["p"].values - exact)[resolved] <= 3 * ds["p_sem"].values[resolved])


def test_mean_chord_of_overlapping_disks_is_pi_phi1_over_s(disks_chords):
    """Eq. (20) with s of Eq. (34): l_C = pi phi1 / s = pi R / (2 eta)."""
    radius, phi2, ds = disks_chords
    values = ds["mean_chord_samples"].values
    exact = np.pi * radius / (2 * -np.log(1 - phi2))
    assert abs(values.mean() - exact) <= 3 * values.std(ddof=1) / np.sqrt(values.size)
