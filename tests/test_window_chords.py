"""Window (minus-sampling) lineal path and chords of 3D images: randmedia.describe.window_chords.

Exact checks (box chords, run bookkeeping, a uniform window, a slab), and statistical checks
against the exactly exponential L(z), p(z) of Poisson-plane tessellations and the exact
overlapping-sphere L(z) (docs/debye3d.md, 'Window chords'). The estimators are also run on the
exact (continuum) runs of Poisson-plane tessellations along the same lines, which separates
the estimators from the digitization of the level set.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from randmedia.describe.chords import chord_grids
from randmedia.describe.window_chords import (WindowLines, WindowRuns, box_chord, sample_window_chords,
                                              window_chord_density, window_lineal_path,
                                              window_lineal_path_and_chords, window_lines)
from randmedia.generate.balls import overlapping_balls_image
from randmedia.generate.poisson_planes import Planes, poisson_plane_image, poisson_planes
from randmedia.numerics.gaussian import default_margin
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


def _mix64(h: np.ndarray) -> np.ndarray:
    """splitmix64 finalizer: distinct uint64 inputs -> effectively independent uniform outputs."""
    h = h ^ (h >> np.uint64(30))
    h = h * np.uint64(0xBF58476D1CE4E5B9)
    h = h ^ (h >> np.uint64(27))
    h = h * np.uint64(0x94D049BB133111EB)
    return h ^ (h >> np.uint64(31))


@dataclass
class ColouredPlanes:
    """A continuum Poisson-plane tessellation (:func:`poisson_planes`) whose cells are coloured
    by a hash of their sign vector (the generator's XOR of plane keys, then mixed with a seed),
    so that any point, not only voxel centres, has its cell's colour: the voxel image and the
    exact runs along any line belong to one realization."""

    planes: Planes
    keys: np.ndarray
    seed: np.uint64
    phi2: float
    side: int

    @classmethod
    def draw(cls, rng: np.random.Generator, side: int, a: float, phi2: float) -> ColouredPlanes:
        planes = poisson_planes(rng, (side,) * 3, a)
        top = np.iinfo(np.uint64).max
        keys = rng.integers(0, top, size=planes.offset.size, dtype=np.uint64, endpoint=True)
        return cls(planes, keys, rng.integers(0, top, dtype=np.uint64, endpoint=True), phi2, side)

    def solid(self, points: np.ndarray) -> np.ndarray:
        """Phase 2 (True) or 1 of the cells holding ``points`` (n, 3), (x, y, z) in voxels."""
        above = (points - self.planes.centre) @ self.planes.normal.T - self.planes.offset > 0.0
        cell = np.bitwise_xor.reduce(np.where(above, self.keys, np.uint64(0)), axis=1)
        uniform = (_mix64(cell ^ self.seed) >> np.uint64(11)).astype(np.float64) / 2.0**53
        return uniform < self.phi2

    def image(self) -> np.ndarray:
        """The window image (z, y, x): the colour at every voxel centre."""
        i, j = np.indices((self.side,) * 2).reshape(2, -1) + 0.5
        layers = [self.solid(np.column_stack([j, i, np.full(i.size, k + 0.5)])) for k in range(self.side)]
        return np.array(layers).reshape((self.side,) * 3).astype(np.uint8)

    def runs(self, lines: WindowLines, supersample: int, phase: int) -> WindowRuns:
        """Exact runs of ``phase`` along ``lines`` (sub-voxel coordinates of the level set) on
        [0, T_i]: the segments between the planes' crossings, coloured at their midpoints,
        merged where neighbours share the phase; a run is complete when neither end is a
        line end, and every run not cut by the line's end ends on the interface."""
        normal, offset, centre = self.planes.normal, self.planes.offset, self.planes.centre
        runs, flags, run_lengths = [], [], []
        ends = 0
        lengths = lines.lengths / supersample
        for start, direction, length in zip(lines.starts / supersample, lines.directions, lengths):
            with np.errstate(divide="ignore"):
                t = (offset - (start - centre) @ normal.T) / (normal @ direction)
            cuts = np.concatenate([[0.0], np.sort(t[(t > 0.0) & (t < length)]), [length]])
            middle = start + 0.5 * (cuts[:-1] + cuts[1:])[:, None] * direction
            in_phase = self.solid(middle) == bool(phase)
            change = np.flatnonzero(np.diff(in_phase.astype(np.int8))) + 1
            bounds = np.concatenate([[0], change, [in_phase.size]])
            for first, stop in zip(bounds[:-1], bounds[1:]):
                if in_phase[first]:
                    runs.append(cuts[stop] - cuts[first])
                    flags.append(first > 0 and stop < in_phase.size)
                    run_lengths.append(length)
                    ends += int(stop < in_phase.size)
        return WindowRuns(np.array(runs), np.array(flags, dtype=bool), np.array(run_lengths), lengths, ends)


def _exact_plane_chord_bins(edges: np.ndarray, a: float, phi2: float) -> np.ndarray:
    """Bin averages of p(z) = (phi2 / a) e^(-phi2 z / a)."""
    return -np.diff(np.exp(-phi2 * edges / a)) / np.diff(edges)


def test_coloured_planes_colour_cells_independently_with_probability_phi2():
    """The mixed hash makes even consecutive cell hashes (the worst case for a weak mix) solid
    with frequency phi2 (within 4 binomial SD), and the image is the colour at voxel centres."""
    hashes = np.arange(20_000, dtype=np.uint64)
    uniform = (_mix64(hashes ^ np.uint64(99)) >> np.uint64(11)).astype(np.float64) / 2.0**53
    assert abs(np.mean(uniform < 0.3) - 0.3) <= 4 * math.sqrt(0.21 / hashes.size)
    tessellation = ColouredPlanes.draw(np.random.default_rng(3), 24, 3.0, 0.3)
    image = tessellation.image()
    voxels = np.array([[0, 0, 0], [5, 17, 9], [23, 1, 12]])  # (k, i, j)
    centres = voxels[:, ::-1] + 0.5
    np.testing.assert_array_equal(image[tuple(voxels.T)], tessellation.solid(centres))


def test_exact_runs_across_a_single_plane():
    """One plane z = 10 in a 20^3 window, solid below and void above: a line up the z axis from
    z = 2 to 18 has one void run of 8 cut by its end (incomplete, no interface end); the same
    line downwards has that run ending on the interface."""
    plane = Planes(np.array([[0.0, 0.0, 1.0]]), np.array([0.0]), np.full(3, 10.0), 10.0 * math.sqrt(3.0))
    for seed in range(64):  # the first seed that colours the two half-spaces solid below, void above
        tessellation = ColouredPlanes(plane, np.array([12345], dtype=np.uint64), np.uint64(seed), 0.5, 20)
        if tessellation.solid(np.array([[10.0, 10.0, 5.0], [10.0, 10.0, 15.0]])).tolist() == [True, False]:
            break
    else:
        pytest.fail("no seed colours the half-spaces differently")
    up = WindowLines(np.array([[20.0, 20.0, 4.0]]), np.array([[0.0, 0.0, 1.0]]), np.array([160]), 0.2)
    sampled = tessellation.runs(up, 2, 0)  # voxels: z from 2 to 18
    np.testing.assert_allclose(sampled.runs, [8.0])
    np.testing.assert_allclose(sampled.line_lengths, [16.0])
    assert not sampled.complete.any() and sampled.interface_ends == 0
    down = WindowLines(np.array([[20.0, 20.0, 36.0]]), np.array([[0.0, 0.0, -1.0]]), np.array([160]), 0.2)
    sampled = tessellation.runs(down, 2, 0)
    np.testing.assert_allclose(sampled.runs, [8.0])
    assert not sampled.complete.any() and sampled.interface_ends == 1
    solid = tessellation.runs(down, 2, 1)
    np.testing.assert_allclose(solid.runs, [8.0])
    assert solid.interface_ends == 0


@pytest.fixture(scope="module")
def continuum_planes():
    """16 continuum tessellations in 48^3 windows, a = 4, phi2 = 0.2; lines of the window
    estimator (margin of sigma = 0.35 at 2 sub-voxels), 64 directions x 8 lines each."""
    a, phi2, side, supersample = 4.0, 0.2, 48, 2
    rng = np.random.default_rng(2026)
    margin = default_margin(0.35, supersample)
    z, edges = chord_grids(24.0, 1.0, 1.0)
    lineal, density, mean = [], [], []
    for _ in range(16):
        tessellation = ColouredPlanes.draw(rng, side, a, phi2)
        lines = window_lines((side * supersample,) * 3, margin, rng, n_directions=64, lines_per_direction=8,
                             fine_step=0.1 * supersample)
        sampled = tessellation.runs(lines, supersample, 0)
        lineal.append(window_lineal_path(sampled.runs, sampled.line_lengths, z))
        p, chord = window_chord_density(sampled, edges)
        density.append(p)
        mean.append(chord)
    return a, phi2, z, edges, np.array(lineal), np.array(density), np.array(mean)


def _mean_sem(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return values.mean(axis=0), values.std(axis=0, ddof=1) / np.sqrt(values.shape[0])


def test_window_estimators_on_exact_plane_runs_are_unbiased(continuum_planes):
    """No digitization: L(z), p(z) (from the first bin on) and the mean chord a / phi2 of the
    exact runs within 3.5 SEM of the exact exponentials -- no systematic margin."""
    a, phi2, z, edges, lineal, density, mean = continuum_planes
    L, L_sem = _mean_sem(lineal)
    assert np.all(np.abs(L - (1 - phi2) * np.exp(-phi2 * z / a)) <= 3.5 * L_sem)
    p, p_sem = _mean_sem(density)
    assert np.all(np.abs(p - _exact_plane_chord_bins(edges, a, phi2)) <= 3.5 * p_sem)
    chord, chord_sem = _mean_sem(mean)
    assert abs(chord - a / phi2) <= 3.5 * chord_sem
