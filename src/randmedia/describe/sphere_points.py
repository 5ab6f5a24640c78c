"""Local number variance in spherical caps and the geodesic pair correlation (sphere2019).

Windows. A cap of base radius a about the unit vector c contains the points p with
p.c / R >= cos(phi), phi = arcsin(a/R) (Fig. 1; upper hemisphere, a <= R). The cap
radii are the grid a_k = R k / n_a, k = 1..n_a
(:func:`randmedia.theory.sphere_caps.cap_grid`).

Number variance, Eq. (2): sigma^2(a) = <n(a)^2> - <n(a)>^2, pooled over every
(configuration, window) pair. The same estimator serves both ensembles; they differ
in the data (fixed N: canonical; Poisson N: grand canonical, Eq. 5) and in the
density rho used for sigma^2/(rho s): N/(4 pi R^2) or the sample mean <N>/(4 pi R^2).

Window centres (the three variants the workflow uses):

* fixed patterns (lattices; Sec. III): ``n_centres`` uniformly random centres
  (the paper: about 10^4);
* ensembles of configurations (uniform, Poisson, fluid frames): ``n_centres`` fresh
  random centres per configuration ("random centres", the better-converged variant);
* the paper's protocol for the fluids (Sec. V): the caps about the three orthogonal
  origins +x, +y, +z in *every* production sweep, counted during the Monte Carlo run
  (:mod:`randmedia.generate.sphere_mc`) and summarized by :func:`axis_count_variance`.

Errors. The data are split into ``n_blocks`` blocks: groups of centres for a single
pattern, contiguous runs of configurations (or of sweeps, for the Monte Carlo time
series -- blocks much longer than the correlation time make them independent). The
value is the pooled estimate; its standard error and the leave-one-block-out curves
(kept for the exponent fits, :mod:`randmedia.fit.power_law`) come from the jackknife
over blocks (a variance is a nonlinear statistic, so the jackknife rather than the
spread of per-block variances).

Geodesic pair correlation g2(x), x = R psi the great-circle distance: ordered pair
counts per bin over N(N - 1) times the fraction of the sphere the bin covers,
(cos psi_lo - cos psi_hi)/2, summed over configurations (so uniform points, canonical
or Poisson, give g2 = 1); this is the g2 of Eqs. (4)-(5)
(:func:`randmedia.theory.sphere_caps.variance_from_g2`).

:func:`window_average_variance` evaluates Eq. (3) for one configuration exactly
(the average over *all* window positions); the random-centre estimator converges
to it, which the tests use to validate both.
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np
import xarray as xr
from numba import njit, prange

from randmedia.io import VariableSpec
from randmedia.theory.sphere_caps import (cap_area, cap_grid, cap_intersection_fraction,  # noqa: F401
                                          first_cap_containing,
                                          check_radius, cos_thresholds)

#: what a reader of a cap-variance descriptor file requires
CAP_VARIANCE = {
    "sigma2": VariableSpec(("variant", "a"), "1"),
    "sigma2_sem": VariableSpec(("variant", "a"), "1"),
    "sigma2_jackknife": VariableSpec(("variant", "block", "a"), "1"),
    "cap_area": VariableSpec(("a",), "1"),
    "g2": VariableSpec(("x",), "1"),
    "g2_sem": VariableSpec(("x",), "1"),
    "sigma2_from_g2": VariableSpec(("a",), "1"),
}

VARIANTS = ("random_centres", "three_origins")

#: cap counts (frames x centres x caps) per numba call, bounding the memory of a batch
_BATCH_ELEMENTS = 4_000_000


# --------------------------------------------------------------------------- windows


def random_centres(rng: np.random.Generator, n: int) -> np.ndarray:
    """``n`` independent uniform unit vectors (window centres)."""
    g = rng.standard_normal((n, 3))
    return g / np.linalg.norm(g, axis=1)[:, None]


@njit(cache=True, parallel=True)
def _cap_counts(points, n_points, centres, radius, thresholds, out):
    """out[f, m, k]: points of frame f (its first n_points[f] rows) in cap k about centres[f, m]."""
    n_frames, n_centres = centres.shape[0], centres.shape[1]
    n_caps = thresholds.size
    for job in prange(n_frames * n_centres):
        f, m = job // n_centres, job % n_centres
        hist = np.zeros(n_caps + 1, dtype=np.int64)
        cx, cy, cz = centres[f, m, 0], centres[f, m, 1], centres[f, m, 2]
        for i in range(n_points[f]):
            value = (points[f, i, 0] * cx + points[f, i, 1] * cy + points[f, i, 2] * cz) / radius
            hist[first_cap_containing(thresholds, value)] += 1
        running = 0
        for c in range(n_caps):
            running += hist[c]
            out[f, m, c] = running


def _stack(frames: Sequence[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Frames as one zero-padded (F, N_max, 3) array and their point numbers."""
    n_points = np.array([np.asarray(f).reshape(-1, 3).shape[0] for f in frames], dtype=np.int64)
    stacked = np.zeros((len(frames), max(1, int(n_points.max(initial=0))), 3))
    for k, frame in enumerate(frames):
        stacked[k, : n_points[k]] = np.asarray(frame, dtype=np.float64).reshape(-1, 3)
    return stacked, n_points


def cap_counts_frames(frames: Sequence[np.ndarray], centres: np.ndarray, a, radius: float) -> np.ndarray:
    """counts[f, m, k]: points of frames[f] in the cap of base radius a_k about the unit vector
    centres[f, m] (one numba call for all frames).

    Parameters
    ----------
    frames : sequence of ndarray, each (N_f, 3)
        Points on the sphere of radius R, per frame (N_f may differ).
    centres : ndarray, shape (len(frames), n_centres, 3)
        Unit vectors of the cap centres, per frame.
    a : array_like, shape (K,)
        Increasing cap base radii a_k, 0 < a <= R (length unit of R).
    radius : float
        Sphere radius R.

    Returns
    -------
    ndarray of int64, shape (len(frames), n_centres, K)
        Cumulative counts (cap k contains caps < k).
    """
    thresholds = np.ascontiguousarray(cos_thresholds(a, radius))
    points, n_points = _stack(frames)
    centres = np.ascontiguousarray(centres, dtype=np.float64)
    if centres.ndim != 3 or centres.shape[0] != len(frames) or centres.shape[2] != 3:
        raise ValueError(f"centres must have shape (frames, n, 3), got {centres.shape}")
    out = np.zeros((len(frames), centres.shape[1], thresholds.size), dtype=np.int64)
    _cap_counts(points, n_points, centres, float(radius), thresholds, out)
    return out


def cap_counts(points: np.ndarray, centres: np.ndarray, a, radius: float) -> np.ndarray:
    """counts[m, k]: number of ``points`` (on the sphere of radius R) in the cap of base
    radius a_k about the unit vector centres[m].

    Parameters
    ----------
    points : ndarray, shape (N, 3)
        Points on the sphere of radius R.
    centres : ndarray, shape (n_centres, 3)
        Unit vectors of the cap centres.
    a : array_like, shape (K,)
        Increasing cap base radii a_k, 0 < a <= R (length unit of R).
    radius : float
        Sphere radius R.

    Returns
    -------
    ndarray of int64, shape (n_centres, K)
        Cumulative counts, as :func:`cap_counts_frames`.
    """
    centres = np.asarray(centres, dtype=np.float64).reshape(1, -1, 3)
    return cap_counts_frames([points], centres, a, radius)[0]


# --------------------------------------------------------------------------- variance + jackknife


def jackknife_variance(sum_n: np.ndarray, sum_n2: np.ndarray, windows: np.ndarray):
    """Pooled sigma^2 = <n^2> - <n>^2 from per-block sums (B, K) of n and n^2 over ``windows``
    (B,) windows each; returns (sigma^2 (K,), jackknife SEM (K,), leave-one-out curves (B, K)).

    Parameters
    ----------
    sum_n, sum_n2 : ndarray, shape (B, K)
        Per-block sums of the counts n and n^2, B >= 2 blocks, K cap radii.
    windows : ndarray, shape (B,)
        Windows per block.

    Returns
    -------
    sigma2 : ndarray, shape (K,)
        Pooled variance.
    sem : ndarray, shape (K,)
        Jackknife standard error.
    leave_out : ndarray, shape (B, K)
        Leave-one-block-out variances.
    """
    sum_n, sum_n2 = np.asarray(sum_n, float), np.asarray(sum_n2, float)
    windows = np.asarray(windows, float)
    if sum_n.ndim != 2 or sum_n.shape != sum_n2.shape or windows.shape != (sum_n.shape[0],):
        raise ValueError("need block sums of shape (B, K) and window numbers of shape (B,)")
    n_blocks = sum_n.shape[0]
    if n_blocks < 2:
        raise ValueError("the jackknife needs at least 2 blocks")
    total_w, total_1, total_2 = windows.sum(), sum_n.sum(axis=0), sum_n2.sum(axis=0)
    value = total_2 / total_w - (total_1 / total_w) ** 2
    w_out = (total_w - windows)[:, None]
    leave_out = (total_2 - sum_n2) / w_out - ((total_1 - sum_n) / w_out) ** 2
    sem = np.sqrt((n_blocks - 1) / n_blocks * np.sum((leave_out - leave_out.mean(axis=0)) ** 2, axis=0))
    return value, sem, leave_out


def block_index(n_units: int, n_blocks: int) -> np.ndarray:
    """Block of each of ``n_units`` consecutive units: n_blocks contiguous, near-equal runs."""
    if n_units < n_blocks:
        raise ValueError(f"cannot split {n_units} units into {n_blocks} blocks")
    return (np.arange(n_units) * n_blocks) // n_units


def cap_variance(frames: Sequence[np.ndarray], radius: float, a, rng: np.random.Generator, *,
                 n_centres: int, n_blocks: int):
    """sigma^2(a) with ``n_centres`` fresh random centres per frame (module docstring).

    One frame: the centres are split into ``n_blocks`` groups; several frames: the
    frames are split into ``n_blocks`` contiguous blocks (at least ``n_blocks`` frames needed). Returns (sigma^2, SEM,
    leave-one-out curves (n_blocks, K), mean count (K,)).

    Parameters
    ----------
    frames : sequence of ndarray, each (N_f, 3)
        Configurations: points on the sphere of radius R.
    radius : float
        Sphere radius R.
    a : array_like, shape (K,)
        Increasing cap base radii a_k, 0 < a <= R (length unit of R).
    rng : numpy.random.Generator
        Source of the window centres.
    n_centres : int
        Random centres per frame (>= 1).
    n_blocks : int
        Jackknife blocks.

    Returns
    -------
    sigma2 : ndarray, shape (K,)
        Pooled number variance per cap radius.
    sem : ndarray, shape (K,)
        Jackknife standard error over blocks.
    leave_out : ndarray, shape (n_blocks, K)
        Leave-one-block-out variances.
    mean_count : ndarray, shape (K,)
        Mean number of points per cap.
    """
    a = np.asarray(a, dtype=float)
    if n_centres < 1:
        raise ValueError(f"n_centres must be >= 1, got {n_centres}")
    sum_n = np.zeros((n_blocks, a.size))
    sum_n2 = np.zeros((n_blocks, a.size))
    windows = np.zeros(n_blocks)
    if len(frames) == 1:
        counts = cap_counts(frames[0], random_centres(rng, n_centres), a, radius).astype(float)
        blocks = block_index(n_centres, n_blocks)
        np.add.at(sum_n, blocks, counts)
        np.add.at(sum_n2, blocks, counts**2)
        np.add.at(windows, blocks, 1.0)
    else:
        blocks = block_index(len(frames), n_blocks)
        batch = max(1, _BATCH_ELEMENTS // (n_centres * a.size))  # frames per numba call
        for start in range(0, len(frames), batch):
            part = frames[start:start + batch]
            centres = random_centres(rng, len(part) * n_centres).reshape(len(part), n_centres, 3)
            counts = cap_counts_frames(part, centres, a, radius).astype(float)
            where = blocks[start:start + len(part)]
            np.add.at(sum_n, where, counts.sum(axis=1))
            np.add.at(sum_n2, where, (counts**2).sum(axis=1))
            np.add.at(windows, where, float(n_centres))
    value, sem, leave_out = jackknife_variance(sum_n, sum_n2, windows)
    return value, sem, leave_out, sum_n.sum(axis=0) / windows.sum()


def axis_count_variance(axis_counts: np.ndarray, n_blocks: int):
    """The paper's three-origin estimator from per-sweep counts (sweeps, 3, K): every
    sweep and origin is a window; blocks are contiguous runs of sweeps. Same returns
    as :func:`cap_variance`."""
    counts = np.asarray(axis_counts, dtype=float)
    if counts.ndim != 3 or counts.shape[1] != 3:
        raise ValueError(f"axis counts must have shape (sweeps, 3, n_caps), got {counts.shape}")
    blocks = block_index(counts.shape[0], n_blocks)
    sum_n = np.zeros((n_blocks, counts.shape[2]))
    sum_n2 = np.zeros((n_blocks, counts.shape[2]))
    np.add.at(sum_n, blocks, counts.sum(axis=1))
    np.add.at(sum_n2, blocks, (counts**2).sum(axis=1))
    windows = np.bincount(blocks, minlength=n_blocks).astype(float) * 3
    value, sem, leave_out = jackknife_variance(sum_n, sum_n2, windows)
    return value, sem, leave_out, sum_n.sum(axis=0) / windows.sum()


# --------------------------------------------------------------------------- pair statistics


@njit(cache=True, parallel=True)
def _pair_histogram(points, n_points, radius, bin_width, n_bins, out):
    """out[f, b]: ordered pairs of frame f at geodesic distance in bin b. Work is split into
    (frame, row-chunk) jobs so that one large frame also runs in parallel."""
    n_frames = points.shape[0]
    n_chunks = 16
    partial = np.zeros((n_frames * n_chunks, n_bins), dtype=np.int64)
    r2 = radius * radius
    for job in prange(n_frames * n_chunks):
        f, chunk = job // n_chunks, job % n_chunks
        n = n_points[f]
        for i in range(chunk, n, n_chunks):  # interleaved rows balance the triangle
            for j in range(i + 1, n):
                c = (points[f, i, 0] * points[f, j, 0] + points[f, i, 1] * points[f, j, 1]
                     + points[f, i, 2] * points[f, j, 2]) / r2
                c = min(1.0, max(-1.0, c))
                b = int(math.acos(c) * radius / bin_width)
                if b < n_bins:
                    partial[job, b] += 2  # ordered pairs
    for job in range(n_frames * n_chunks):
        for b in range(n_bins):
            out[job // n_chunks, b] += partial[job, b]


def geodesic_g2(frames: Sequence[np.ndarray], radius: float, n_bins: int, n_blocks: int):
    """g2 on ``n_bins`` equal bins of geodesic distance x in [0, pi R] (module docstring).

    Returns (x_edges, g2, SEM over contiguous blocks of frames; NaN with one frame).

    Parameters
    ----------
    frames : sequence of ndarray, each (N_f, 3)
        Configurations: points on the sphere of radius R.
    radius : float
        Sphere radius R.
    n_bins : int
        Bins of x over [0, pi R] (>= 1).
    n_blocks : int
        Blocks of frames for the SEM (used when there are at least max(2, n_blocks) frames).

    Returns
    -------
    x_edges : ndarray, shape (n_bins + 1,)
        Bin edges (length unit of R).
    g2 : ndarray, shape (n_bins,)
        Pair correlation per bin.
    sem : ndarray, shape (n_bins,)
        Standard error over blocks (NaN without blocks).
    """
    check_radius(radius)
    if n_bins < 1:
        raise ValueError("n_bins must be >= 1")
    edges = np.linspace(0.0, np.pi * radius, n_bins + 1)
    shell = 0.5 * (np.cos(edges[:-1] / radius) - np.cos(edges[1:] / radius))
    use_blocks = len(frames) >= max(2, n_blocks)
    blocks = block_index(len(frames), n_blocks) if use_blocks else np.zeros(len(frames), int)
    n_groups = n_blocks if use_blocks else 1
    per_frame = np.zeros((len(frames), n_bins), dtype=np.int64)
    batch = max(1, _BATCH_ELEMENTS // (16 * n_bins))
    for start in range(0, len(frames), batch):
        points, _ = _stack(frames[start:start + batch])
        _pair_histogram(points, np.array([len(f) for f in frames[start:start + batch]], dtype=np.int64),
                        float(radius), float(edges[1]), n_bins, per_frame[start:start + batch])
    n_points = np.array([len(f) for f in frames], dtype=np.int64)
    counts = np.zeros((n_groups, n_bins))
    pairs = np.zeros(n_groups)
    np.add.at(counts, blocks, per_frame.astype(float))
    np.add.at(pairs, blocks, n_points * (n_points - 1.0))
    g2 = counts.sum(axis=0) / (pairs.sum() * shell)
    if use_blocks:
        per_block = counts / (pairs[:, None] * shell[None, :])
        sem = per_block.std(axis=0, ddof=1) / math.sqrt(n_groups)
    else:
        sem = np.full(n_bins, np.nan)
    return edges, g2, sem


def window_average_variance(points: np.ndarray, radius: float, a) -> np.ndarray:
    """Eq. (3): the variance over *all* window positions of one configuration,
    rho s [1 - rho s + (1/N) sum_{i != j} alpha2(x_ij; a)].

    Parameters
    ----------
    points : ndarray, shape (N, 3)
        One configuration on the sphere of radius R.
    radius : float
        Sphere radius R.
    a : array_like
        Cap base radii (length unit of R).

    Returns
    -------
    ndarray, shape (len(a),)
        sigma^2(a) averaged over all window positions.
    """
    points = np.asarray(points, dtype=float)
    n = points.shape[0]
    unit = points / radius
    cosine = np.clip(unit @ unit.T, -1.0, 1.0)
    upper = np.triu_indices(n, 1)
    x = radius * np.arccos(cosine[upper])
    rho = n / (4.0 * np.pi * radius**2)
    a = np.atleast_1d(np.asarray(a, dtype=float))
    s = cap_area(a, radius)
    pair_sum = np.array([2.0 * cap_intersection_fraction(x, ak, radius).sum() for ak in a])
    return rho * s * (1.0 - rho * s + pair_sum / n)


# --------------------------------------------------------------------------- descriptor file


def variance_dataset(a, radius: float, density: float, variants: dict, *, x_edges, g2, g2_sem,
                     sigma2_from_g2, attrs: dict) -> xr.Dataset:
    """The descriptor file of one system: for each variant in ``variants`` (name ->
    (sigma2, sem, leave_out (B, K), mean_count)), plus g2 and Eq. (4)/(5) from g2.

    Parameters
    ----------
    a : array_like, shape (K,)
        Increasing cap base radii a_k, 0 < a <= R (length unit of R).
    radius : float
        Sphere radius R.
    density : float
        Number density rho used for sigma^2 / (rho s).
    variants : dict
        Name (from :data:`VARIANTS`) -> (sigma2 (K,), sem (K,), leave_out (B, K),
        mean_count (K,)), e.g. of :func:`cap_variance`; the same B for all.
    x_edges : array_like, shape (n_bins + 1,)
        Bin edges of g2 (length unit of R).
    g2, g2_sem : array_like, shape (n_bins,)
        Geodesic g2 and its SEM (:func:`geodesic_g2`).
    sigma2_from_g2 : array_like, shape (K,)
        sigma^2 from g2 by Eq. (4) or (5).
    attrs : dict
        Attributes of the file (``R`` and ``density`` are added).

    Returns
    -------
    xarray.Dataset
        The descriptor file (:data:`CAP_VARIANCE`).
    """
    names = [v for v in VARIANTS if v in variants]
    if not names or set(variants) - set(VARIANTS):
        raise ValueError(f"variants must be among {VARIANTS}, got {sorted(variants)}")
    a = np.asarray(a, dtype=float)
    n_blocks = {np.asarray(variants[v][2]).shape[0] for v in names}
    if len(n_blocks) != 1:
        raise ValueError("all variants need the same number of jackknife blocks")
    stack = lambda k: np.stack([np.asarray(variants[v][k], float) for v in names])  # noqa: E731
    s = cap_area(a, radius)
    x_edges = np.asarray(x_edges, float)
    length = "length unit of R (d_LJ for the fluids)"
    return xr.Dataset(
        {
            "sigma2": (("variant", "a"), stack(0), {"units": "1", "long_name": "number variance sigma^2_n(a), Eq. (2)"}),
            "sigma2_sem": (("variant", "a"), stack(1), {"units": "1", "long_name": "jackknife standard error of sigma^2_n(a) over blocks"}),
            "sigma2_jackknife": (("variant", "block", "a"), stack(2), {"units": "1", "long_name": "leave-one-block-out sigma^2_n(a)"}),
            "mean_count": (("variant", "a"), stack(3), {"units": "1", "long_name": "mean number of points in the cap <n(a)>"}),
            "cap_area": (("a",), s, {"units": "1", "long_name": f"cap area s(a) ({length}, squared)"}),
            "scaled_sigma2": (("variant", "a"), stack(0) / (density * s), {"units": "1", "long_name": "sigma^2_n(a) / (rho s(a))"}),
            "g2": (("x",), np.asarray(g2, float), {"units": "1", "long_name": "geodesic pair correlation g2(x)"}),
            "g2_sem": (("x",), np.asarray(g2_sem, float), {"units": "1", "long_name": "standard error of g2 over blocks of frames"}),
            "x_edges": (("x_edge",), x_edges, {"units": "1", "long_name": f"bin edges of the geodesic distance x ({length})"}),
            "sigma2_from_g2": (("a",), np.asarray(sigma2_from_g2, float), {"units": "1", "long_name": "sigma^2_n(a) from g2 by Eq. (4) (canonical) or Eq. (5) (grand canonical)"}),
        },
        coords={
            "a": ("a", a, {"units": "1", "long_name": f"cap base radius a ({length})"}),
            "variant": ("variant", names, {"units": "1", "long_name": "window centres: random per configuration, or the three orthogonal origins per sweep"}),
            "block": ("block", np.arange(next(iter(n_blocks))), {"units": "1", "long_name": "jackknife block"}),
            "x": ("x", 0.5 * (x_edges[1:] + x_edges[:-1]), {"units": "1", "long_name": f"geodesic distance x, bin centre ({length})"}),
        },
        attrs={**attrs, "R": float(radius), "density": float(density)},
    )


def describe_configurations(ds: xr.Dataset, *, n_a: int, pattern_centres: int, frame_centres: int,
                            n_blocks: int, g2_bin_width_rho_half: float,
                            rng: np.random.Generator) -> xr.Dataset:
    """Every descriptor of one configuration file (``results/sphere2019/configs/{system}.nc``):
    sigma^2(a) with random centres (``pattern_centres`` on a single fixed pattern,
    ``frame_centres`` per frame otherwise), for a fluid also from the recorded three-origin
    counts (its own cap grid), g2 and sigma^2 from g2 by Eq. (4) or (5).

    Parameters
    ----------
    ds : xarray.Dataset
        Configuration file: attributes ``R``, ``ensemble``; frames; for a fluid also
        ``axis_counts`` on its own ``a`` grid and ``tau_caps``.
    n_a : int
        Cap radii of the grid a_k = R k / n_a (when the file has no ``axis_counts``).
    pattern_centres, frame_centres : int
        Random centres for a single pattern, and per frame for several frames.
    n_blocks : int
        Jackknife blocks.
    g2_bin_width_rho_half : float
        Width of the g2 bins in units of rho^(-1/2).
    rng : numpy.random.Generator
        Source of the window centres.

    Returns
    -------
    xarray.Dataset
        The descriptor file (:func:`variance_dataset`).
    """
    from randmedia.generate.sphere_surface import frames_of
    from randmedia.theory.sphere_caps import variance_from_g2

    radius = float(ds.attrs["R"])
    frames = frames_of(ds)
    counts = np.array([f.shape[0] for f in frames], dtype=float)
    density = counts.mean() / (4.0 * np.pi * radius**2)
    ensemble = str(ds.attrs["ensemble"])
    a = ds["a"].values if "axis_counts" in ds else cap_grid(radius, n_a)
    centres = pattern_centres if len(frames) == 1 else frame_centres
    variants = {"random_centres": cap_variance(frames, radius, a, rng, n_centres=centres,
                                               n_blocks=n_blocks)}
    if "axis_counts" in ds:
        variants["three_origins"] = axis_count_variance(ds["axis_counts"].values, n_blocks)
    n_bins = int(math.ceil(np.pi * radius * math.sqrt(density) / g2_bin_width_rho_half))
    edges, g2, g2_sem = geodesic_g2(frames, radius, n_bins, n_blocks)
    from_g2 = variance_from_g2(a, radius, density, edges, g2, n_particles=counts.mean(),
                               ensemble=ensemble)
    keep = ("kind", "system", "ensemble", "potential", "coupling", "temperature", "pattern",
            "n_particles", "equilibration_sweeps", "production_sweeps", "frame_interval",
            "count_interval", "step", "acceptance_equilibration", "acceptance_production",
            "tau_energy_sweeps", "energy_per_particle", "energy_per_particle_error",
            "energy_halves_z", "energy_drift_production", "energy_drift_equilibration")
    attrs = {k: ds.attrs[k] for k in keep if k in ds.attrs}
    attrs.update(n_frames=len(frames), mean_n_points=float(counts.mean()),
                 n_centres=centres, n_blocks=n_blocks)
    if "tau_caps" in ds:
        tau = ds["tau_caps"].values
        attrs.update(tau_caps_small_sweeps=float(tau[np.argmin(np.abs(a - 1.0))]),
                     tau_caps_half_R_sweeps=float(tau[np.argmin(np.abs(a - radius / 2))]),
                     tau_caps_R_sweeps=float(tau[-1]), mc_seconds=float(ds.attrs["seconds"]),
                     pair_evaluations_per_second=float(ds.attrs["pair_evaluations"])
                     / max(float(ds.attrs["seconds"]), 1e-9))
    return variance_dataset(a, radius, density, variants, x_edges=edges, g2=g2, g2_sem=g2_sem,
                            sigma2_from_g2=from_g2, attrs=attrs)
