"""Lineal-path function and chord-length density of a 3D *window* image (minus-sampling).

Ma & Torquato 2020, Sec. II D-E: L(z) is the probability that a segment of length z lies
entirely in the phase, p(z) the density of chord lengths. :mod:`randmedia.describe.chords`
walks lines through *periodic* images; on a window cut from a non-periodic medium (the
Poisson-plane tessellations of :mod:`randmedia.generate.poisson_planes`) a wrapped line
would cross a seam that is not in the medium. Here the lines are clipped to the window:

1. **Level set.** The level set of the window surface functions
   (:func:`randmedia.describe.window_surface.window_level_set`: voxel indicator repeated
   ``supersample``^3 times, Gaussian-filtered with a non-wrapping boundary, threshold at the
   window's void fraction), so chords and F_sv, F_ss see one medium; lines are walked only
   inside the interior box :func:`~randmedia.numerics.gaussian.default_margin`
   sub-voxels from every face, where the filtered field is that of the infinite medium.
2. **Lines.** Directions: the stratified spherical Fibonacci set turned by one random
   rotation per image (:func:`randmedia.describe.chords.sphere_line_directions`, as in the
   periodic estimator). Per direction, ``lines_per_direction`` lines whose foot points are
   uniform on the square of side the box diagonal perpendicular to the direction, centred
   on the box; a line that misses the box is drawn again. The line is the box's chord along
   it, of length T_i (different for every line), walked in steps ``step`` with the phase
   changes placed midway (:func:`randmedia.describe.chords._walk3`).
3. **Estimators** (ratio estimators, consistent for any stationary medium because every
   segment position and every line direction sees the same L(z), whatever the weighting of
   directions): L(z) = sum_k max(0, l_k - z) / sum_i max(0, T_i - z) over all runs k (those
   cut by the box too) and lines i. For p(z), the forward ends of the chords (phase ->
   other phase along the line) are points of intensity lambda per unit line length, and a
   chord of length l ending in [l, T_i] is seen complete (both ends on the interface), so
   lambda p(l) dl = sum over complete chords in dl of 1 / U(l), U(l) = sum_i max(0, T_i - l)
   (Miles-Lantuejoul with every line's own length), with lambda = (interface ends) / sum_i T_i;
   the mean chord is phi_line / lambda (phi_line: the phase's fraction of the line length;
   lambda = s/4 in 3D, so this is Eq. 20). Unlike the periodic estimator, which normalizes
   p over the complete chords seen (lines of 4 image sides, chords << T), this normalization
   needs no chord to be seen whole: in a 128^3 window (lines ~84 voxels) the void chords at
   phi2 = 0.1, a = 4 (mean 40 voxels) are often longer than the line, and normalizing over
   the seen chords gave a mean chord of 30.4 +- 0.7 against 40 (docs/debye3d.md).

Validated on the exact case that needs no digitization argument: Poisson-plane
tessellations with independently coloured cells have L(z) = phi1 e^(-phi2 z / a) and
p(z) = (phi2 / a) e^(-phi2 z / a) exactly (planes cross a line as a Poisson process of rate
1/a; a void run ends at a crossing into a solid cell, probability phi2) -- the exponential
forms conjectured for Debye random media in Sec. VII --, on the exact runs of such a
continuum tessellation along the lines of :func:`window_lines` (the estimators alone, no
digitization: unbiased with no margin; paired with the level set on the same lines, the
digitization's short-chord excess), and on overlapping spheres read as a window
(tests/test_window_chords.py, docs/debye3d.md).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import xarray as xr

from randmedia.describe.chords import (_inside3, _walk3, chord_functions_dataset, chord_grids, segments_in_phase,
                                       sphere_line_directions)
from randmedia.describe.window_surface import window_level_set
from randmedia.numerics.gaussian import default_margin


class WindowRuns(NamedTuple):
    """Runs of a phase along the lines through one window (:func:`sample_window_chords`)."""

    runs: np.ndarray
    complete: np.ndarray
    run_line_length: np.ndarray
    line_lengths: np.ndarray
    interface_ends: int


def box_chord(point: np.ndarray, direction: np.ndarray, low: np.ndarray, high: np.ndarray) -> tuple[float, float]:
    """Entry and exit parameters (t_in, t_out) of the line point + t direction through the box
    [low, high] (slab method); t_out <= t_in when the line misses the box."""
    t_in, t_out = -math.inf, math.inf
    for axis in range(3):
        if direction[axis] == 0.0:
            if not low[axis] <= point[axis] <= high[axis]:
                return 0.0, 0.0
            continue
        t1 = (low[axis] - point[axis]) / direction[axis]
        t2 = (high[axis] - point[axis]) / direction[axis]
        t_in, t_out = max(t_in, min(t1, t2)), min(t_out, max(t1, t2))
    return t_in, t_out


def _perpendicular_basis(direction: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors perpendicular to ``direction`` and to each other."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(direction[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(direction, helper)
    u /= np.linalg.norm(u)
    return u, np.cross(direction, u)


class WindowLines(NamedTuple):
    """Lines through the interior box of a window (:func:`window_lines`), in the coordinates of
    the level set's sub-voxel grid (a point x there is x / supersample in voxels)."""

    starts: np.ndarray  # (n, 3) entry points (x, y, z) on the interior box
    directions: np.ndarray  # (n, 3) unit vectors
    n_steps: np.ndarray  # (n,) walking steps of length fine_step inside the box
    fine_step: float  # step (sub-voxels)

    @property
    def lengths(self) -> np.ndarray:
        """Walked length T_i of every line (sub-voxels)."""
        return self.n_steps * self.fine_step


def window_lines(field_shape: tuple[int, int, int], margin: int, rng: np.random.Generator, *,
                 n_directions: int, lines_per_direction: int, fine_step: float) -> WindowLines:
    """The lines of :func:`sample_window_chords` (module docstring, step 2) through the interior
    box ``margin`` <= x <= side - ``margin`` of a field of shape (nz, ny, nx): directions
    :func:`randmedia.describe.chords.sphere_line_directions` (one rotation drawn from ``rng``),
    then per direction ``lines_per_direction`` foot points uniform on the square of side the
    box diagonal perpendicular to it (two uniforms per try, redrawn until the line crosses the
    box for at least one step)."""
    shape_xyz = np.array(tuple(field_shape)[::-1], dtype=float)  # (x, y, z) extents in sub-voxels
    low, high = np.full(3, float(margin)), shape_xyz - margin
    if np.any(high - low <= 0):
        raise ValueError(f"margin {margin} sub-voxels leaves no interior in {tuple(field_shape)}")
    centre, half_diagonal = 0.5 * (low + high), 0.5 * float(np.linalg.norm(high - low))
    starts, directions, n_steps = [], [], []
    for direction in sphere_line_directions(n_directions, rng):
        direction = np.asarray(direction, dtype=float)
        u, v = _perpendicular_basis(direction)
        for _ in range(lines_per_direction):
            while True:
                a, b = (2.0 * rng.random(2) - 1.0) * half_diagonal
                foot = centre + a * u + b * v
                t_in, t_out = box_chord(foot, direction, low, high)
                steps = int((t_out - t_in) / fine_step)
                if steps >= 1:
                    break
            starts.append(foot + t_in * direction)
            directions.append(direction)
            n_steps.append(steps)
    return WindowLines(np.array(starts), np.array(directions), np.array(n_steps, dtype=np.int64),
                       float(fine_step))


def sample_window_chords(image: np.ndarray, phase: int, rng: np.random.Generator, *, sigma: float,
                         supersample: int, margin: int | None = None, n_directions: int = 32,
                         lines_per_direction: int = 8, step: float = 0.1):
    """Runs of ``phase`` along lines clipped to the interior of a 3D window (module docstring).

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        Window image of phase labels (not periodic).
    phase : int
        Label of the phase.
    rng : numpy.random.Generator
        Source of the rotation (4 normals) and then of the foot points (2 uniforms per try).
    sigma : float
        Gaussian width of the level set (voxels).
    supersample : int
        Sub-voxels per voxel of the level set.
    margin : int, optional
        Interior margin in sub-voxels; None: :func:`default_margin`.
    n_directions, lines_per_direction : int, optional
        Stratified directions on the hemisphere, lines per direction.
    step : float, optional
        Step along a line (voxels).

    Returns
    -------
    WindowRuns
        ``runs`` (voxels), ``complete`` (both ends on the interface), ``run_line_length``
        (per run, the length T_i of its line), ``line_lengths`` (per line, T_i, voxels),
        ``interface_ends`` (runs that end on the interface, all lines).
    """
    image = np.asarray(image)
    if image.ndim != 3:
        raise ValueError(f"expected a 3D window image, got shape {image.shape}")
    if n_directions < 1 or lines_per_direction < 1 or step <= 0:
        raise ValueError("n_directions, lines_per_direction must be >= 1 and step > 0")
    level_set = window_level_set(image if phase == 0 else (image != phase).astype(np.uint8), sigma, supersample)
    field, threshold = level_set.fine, level_set.threshold
    if margin is None:
        margin = default_margin(sigma, supersample)
    lines = window_lines(field.shape, margin, rng, n_directions=n_directions,
                         lines_per_direction=lines_per_direction, fine_step=step * supersample)
    most_steps = int(lines.n_steps.max())
    buffer_runs = np.empty(most_steps // 2 + 2)
    buffer_complete = np.empty(most_steps // 2 + 2, dtype=np.bool_)
    runs, flags, run_lengths = [], [], []
    ends = 0
    for start, direction, n_steps in zip(lines.starts, lines.directions, lines.n_steps):
        count = _walk3(field, threshold, float(start[0]), float(start[1]), float(start[2]),
                       float(direction[0]), float(direction[1]), float(direction[2]),
                       int(n_steps), lines.fine_step, buffer_runs, buffer_complete)
        end = start + n_steps * lines.fine_step * direction
        ends += count - int(_inside3(field, threshold, float(end[0]), float(end[1]), float(end[2])))
        runs.append(buffer_runs[:count] / supersample)
        flags.append(buffer_complete[:count].copy())
        run_lengths.append(np.full(count, n_steps * lines.fine_step / supersample))
    return WindowRuns(np.concatenate(runs), np.concatenate(flags), np.concatenate(run_lengths),
                      lines.lengths / supersample, ends)


def window_chord_density(sampled: WindowRuns, edges: np.ndarray) -> tuple[np.ndarray, float]:
    """p(z) on bins ``edges`` and the mean chord, normalized by the intensity of chord ends
    (module docstring, step 3): lambda p = sum over complete chords in a bin of 1 / U(l) per
    bin width, U(l) = sum_i max(0, T_i - l); lambda = interface ends / sum_i T_i; mean chord
    phi_line / lambda."""
    total = float(sampled.line_lengths.sum())
    if sampled.interface_ends == 0:
        raise ValueError("no run of the phase ends on the interface: no chord statistics")
    intensity = sampled.interface_ends / total
    chords = sampled.runs[sampled.complete]
    usable = np.maximum(0.0, sampled.line_lengths[None, :] - chords[:, None]).sum(axis=1)
    hist, _ = np.histogram(chords, bins=edges, weights=1.0 / usable)
    density = hist / (intensity * np.diff(edges))
    mean_chord = float(sampled.runs.sum() / total / intensity)
    return density, mean_chord


def window_lineal_path(runs: np.ndarray, line_lengths: np.ndarray, z: np.ndarray) -> np.ndarray:
    """L(z) = sum_k max(0, l_k - z) / sum_i max(0, T_i - z) (lines of different lengths)."""
    z = np.asarray(z, dtype=float)
    usable = np.maximum(0.0, line_lengths[None, :] - z[:, None]).sum(axis=1)
    if np.any(usable <= 0):
        raise ValueError(f"no line longer than z = {float(z[usable <= 0][0])} voxels: lower z_max")
    return segments_in_phase(runs, z) / usable


def window_lineal_path_and_chords(images, phase: int, rng: np.random.Generator, *, z_max: float,
                                  sigma: float, supersample: int, dz: float = 0.5, chord_bin: float = 1.0,
                                  margin: int | None = None, **sampling) -> xr.Dataset:
    """L(z) and p(z) of ``phase`` for a stack of 3D windows, per sample, with mean and SEM
    (the chords file of :func:`randmedia.describe.chords.chord_functions_dataset`, lengths in
    voxels), plus attributes ``estimator`` = "window", ``margin`` (sub-voxels) and
    ``mean_line_length`` (voxels).

    Parameters
    ----------
    images : array_like, shape (n_samples, nz, ny, nx)
        Window images of phase labels.
    phase : int
        Label of the phase.
    rng : numpy.random.Generator
        Passed to :func:`sample_window_chords`.
    z_max : float
        Largest z of L(z) and upper end of the chord bins (voxels).
    sigma : float
        Gaussian width of the level set (voxels).
    supersample : int
        Sub-voxels per voxel.
    dz, chord_bin : float, optional
        Step of the z grid and width of the chord bins (voxels).
    margin : int, optional
        Interior margin in sub-voxels; None: :func:`default_margin`.
    **sampling
        ``n_directions``, ``lines_per_direction``, ``step`` of :func:`sample_window_chords`.

    Returns
    -------
    xarray.Dataset
    """
    images = np.asarray(images)
    if images.ndim != 4:
        raise ValueError(f"expected windows of shape (n_samples, nz, ny, nx), got {images.shape}")
    if margin is None:
        margin = default_margin(sigma, supersample)
    z, edges = chord_grids(z_max, dz, chord_bin)
    n = images.shape[0]
    lineal = np.empty((n, z.size))
    density = np.empty((n, edges.size - 1))
    mean_chord = np.empty(n)
    mean_line = np.empty(n)
    for k, image in enumerate(images):
        sampled = sample_window_chords(image, phase, rng, sigma=sigma, supersample=supersample,
                                       margin=margin, **sampling)
        lineal[k] = window_lineal_path(sampled.runs, sampled.line_lengths, z)
        density[k], mean_chord[k] = window_chord_density(sampled, edges)
        mean_line[k] = sampled.line_lengths.mean()
    out = chord_functions_dataset(lineal, density, mean_chord, z, edges, phase=phase, unit="voxel")
    out.attrs.update({"estimator": "window", "margin": int(margin), "mean_line_length": float(mean_line.mean())})
    return out
