"""Window (minus-sampling) lineal path and chords of 3D images: randmedia.describe.window_chords.

Exact checks (box chords, run bookkeeping, a uniform window, a slab), and statistical checks
against the exactly exponential L(z), p(z) of Poisson-plane tessellations and the exact
overlapping-sphere L(z) (docs/debye3d.md, 'Window chords').
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from randmedia.describe.window_chords import (box_chord, sample_window_chords, window_lineal_path,
                                              window_lineal_path_and_chords)
from randmedia.describe.window_surface import default_margin
from randmedia.generate.balls import overlapping_balls_image
from randmedia.generate.poisson_planes import poisson_plane_image
from randmedia.theory import overlapping as ov


def test_box_chord_of_axis_diagonal_and_missing_lines():
    low, high = np.zeros(3), np.full(3, 10.0)
    centre = np.full(3, 5.0)
    t_in, t_out = box_chord(centre, np.array([1.0, 0.0, 0.0]), low, high)
    assert (t_in, t_out) == (-5.0, 5.0)
    diagonal = np.ones(3) / math.sqrt(3.0)
    t_in, t_out = box_chord(centre, diagonal, low, high)
    assert t_out - t_in == pytest.approx(10.0 * math.sqrt(3.0))
    t_in, t_out = box_chord(np.array([5.0, 5.0, 20.0]), np.array([1.0, 0.0, 0.0]), low, high)
    assert t_out <= t_in  # parallel to x, above the box
    t_in, t_out = box_chord(np.array([-5.0, 5.0, 30.0]), np.array([0.6, 0.0, 0.8]), low, high)
    assert t_out <= t_in  # oblique, passes beside the box


def test_runs_fit_their_lines():
    rng = np.random.default_rng(1)
    image = (rng.random((20, 22, 24)) < 0.4).astype(np.uint8)
    runs, complete, run_length, lines, ends = sample_window_chords(
        image, 0, np.random.default_rng(2), sigma=0.5, supersample=2, n_directions=6, lines_per_direction=3)
    margin = default_margin(0.5, 2) / 2
    interior = np.array([24, 22, 20]) - 2 * margin
    assert lines.size == 18
    assert np.all(lines <= np.linalg.norm(interior) + 1e-9)
    assert np.all(runs > 0) and np.all(runs <= run_length + 1e-9)
    assert np.all(runs[complete] < run_length[complete])
    # every run ends on the interface but those cut by the end of their line (<= one per line)
    assert runs.size - lines.size <= ends <= runs.size
    assert np.count_nonzero(complete) <= ends
    # runs of one line are consecutive and never add up to more than the line
    for length in np.unique(run_length):
        assert runs[run_length == length].sum() <= length * np.count_nonzero(lines == length) + 1e-9


def test_uniform_window_is_one_run_per_line():
    image = np.zeros((16, 16, 16), dtype=np.uint8)
    runs, complete, run_length, lines, ends = sample_window_chords(
        image, 0, np.random.default_rng(3), sigma=0.4, supersample=1, n_directions=4, lines_per_direction=2)
    np.testing.assert_allclose(np.sort(runs), np.sort(lines))
    assert not complete.any() and ends == 0
    z = np.array([0.0, 1.0, 3.0])
    np.testing.assert_allclose(window_lineal_path(runs, lines, z), 1.0)


def test_lineal_path_counts_positions_on_lines_of_different_lengths():
    """Two lines (T = 10 and 4), runs 6 (on the first) and 4 (all of the second):
    L(z) = (max(0, 6 - z) + max(0, 4 - z)) / (max(0, 10 - z) + max(0, 4 - z))."""
    runs, lines = np.array([6.0, 4.0]), np.array([10.0, 4.0])
    z = np.array([0.0, 2.0, 5.0])
    expected = [(6 + 4) / (10 + 4), (4 + 2) / (8 + 2), 1 / 5]
    np.testing.assert_allclose(window_lineal_path(runs, lines, z), expected)
    with pytest.raises(ValueError, match="no line longer"):
        window_lineal_path(runs, lines, np.array([12.0]))


@pytest.fixture(scope="module")
def planes():
    """8 Poisson-plane windows 40^3, a = 3, phi2 = 0.3, window chords at sigma 0.35."""
    rng = np.random.default_rng(77)
    images = np.array([poisson_plane_image(rng, (40,) * 3, 3.0, 0.3) for _ in range(8)])
    return window_lineal_path_and_chords(images, 0, np.random.default_rng(5), z_max=18.0, sigma=0.35,
                                         supersample=2, n_directions=24, lines_per_direction=6)


def test_window_chords_of_poisson_planes_are_exactly_exponential(planes):
    """L(z) = phi1 e^(-phi2 z / a) and p(z) = (phi2 / a) e^(-phi2 z / a) exactly for these
    tessellations: L within 3 SEM + 0.01 (digitization of cells thinner than a voxel), p (bin
    averages, from 3 voxels on, as validated for the periodic estimator) within 3 SEM +
    10 %; mean chord a / phi2 within 3 SEM + 5 %."""
    a, phi2 = 3.0, 0.3
    z = planes["z"].values
    exact = 0.7 * np.exp(-phi2 * z / a)
    assert np.all(np.abs(planes["L"].values - exact) <= 3 * planes["L_sem"].values + 0.01)
    zc = planes["z_chord"].values
    keep = zc >= 3.0
    exact_p = np.exp(-phi2 * (zc - 0.5) / a) - np.exp(-phi2 * (zc + 0.5) / a)
    dev = np.abs(planes["p"].values - exact_p)[keep]
    assert np.all(dev <= 3 * planes["p_sem"].values[keep] + 0.1 * exact_p[keep])
    chords = planes["mean_chord_samples"].values
    sem = chords.std(ddof=1) / np.sqrt(chords.size)
    assert abs(chords.mean() - a / phi2) <= 3 * sem + 0.05 * a / phi2
    assert planes.attrs["estimator"] == "window"


def test_window_chords_of_overlapping_spheres_match_exact():
    """Periodic overlapping-sphere images read as windows: L(z) within 3 SEM + 0.01 of the
    exact 3D Boolean-model L (the window never uses the periodicity)."""
    rng = np.random.default_rng(11)
    radius, phi2 = 4.0, 0.3
    images = np.array([overlapping_balls_image(rng, 36, radius, phi2, 3) for _ in range(6)])
    ds = window_lineal_path_and_chords(images, 0, np.random.default_rng(6), z_max=12.0, sigma=0.5,
                                       supersample=2, n_directions=16, lines_per_direction=6)
    z = ds["z"].values
    exact = ov.lineal_path_void(z, radius, phi2, dim=3)
    assert np.all(np.abs(ds["L"].values - exact) <= 3 * ds["L_sem"].values + 0.01)
