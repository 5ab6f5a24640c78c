"""Point-process and pore-space statistics of periodic sphere configurations (3D).

Klatt & Torquato, PRE 94, 022152 (2016), Secs. II B, V and VI:

* **Nearest-centre distances** of uniform random points (Monte Carlo). With
  d the distance from a random point to the nearest sphere centre,
  the exclusion probability is E_V(r) = P(d > r) (Sec. II B 1), and for
  spheres of radius R the pore size of a matrix point (d > R) is delta = d - R,
  so F(delta) = P(d > R + delta | d > R) = E_V(R + delta) / E_V(R) (Eqs. 17, 20;
  E_V(R) = 1 - phi). Moments <delta>, <delta^2> are sample means over the
  matrix points (Eqs. 18-19; raw second moment, Sec. V B). The paper draws
  10^7 matrix points per sample. Distances are histogrammed in fine bins
  whose edges include every r where a value is reported, so E_V at an edge is
  an exact count, not an interpolation.
* **Covering radius**: the largest distance of a point of space to the nearest
  centre = max over the Voronoi vertices of their distance to the generators
  (Sec. V C); computed exactly per sample from the Voronoi diagram of the
  centres padded by their periodic images.
* **Window counts** (Sec. VI): the number N(R) of centres in a ball of radius R
  around a uniform random point, for nested radii around the same centres
  (Sec. VI A: "a score of test balls with different radii R"). The number of
  throws for radius R follows the paper's rule (Sec. VI B): the expected
  volume fraction covered by the test balls stays below phi_B,
  n(R) = min(n_max, floor(phi_B V / v(R))); the first n(R) centres are used.
  N(R) is pooled over all throws of all samples: the number variance
  sigma^2_N(R) is the pooled sample variance (ddof 1), its SEM a delete-one-
  sample jackknife (throws in one sample are correlated; samples are not).
  R <= h_w, so a ball contains each centre at most once.

Neighbour search: a periodic cell list in fractional coordinates (any
triclinic cell; :class:`randmedia.cell_list.SortedCells` and its image-cell
walk), numba kernels. For the nearest centre the search grows in cell shells
until the distance found is within the radius the shell guarantees, so it is
exact without a cutoff; window counts visit every cell of a fixed range that a
lower bound of its distance does not rule out. The two walks share the query
location, the image cells and the distance; they differ in which cells they
visit (growing shells with a stopping rule vs. one culled range), so they stay two.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.cell_list import SortedCells, cell_coordinate, image_cell, periodic_cell
from randmedia.periodic import Cell, padded_images
from randmedia.stats import standard_error


# --------------------------------------------------------------------------- cell walks

#: the centres sorted into fractional cells (:class:`randmedia.cell_list.SortedCells`)
CellList = SortedCells


@njit(cache=True, inline="always")
def _locate(q, box, n_cells, qc):
    """Cartesian point qc of the fractional query q, its cell (c0, c1, c2) and its position
    (t0, t1, t2) inside that cell, in cell widths along each axis."""
    for i in range(3):
        qc[i] = box[i, 0] * q[0] + box[i, 1] * q[1] + box[i, 2] * q[2]
    c0 = cell_coordinate(q[0], n_cells[0])
    c1 = cell_coordinate(q[1], n_cells[1])
    c2 = cell_coordinate(q[2], n_cells[2])
    return c0, c1, c2, q[0] * n_cells[0] - c0, q[1] * n_cells[1] - c1, q[2] * n_cells[2] - c2


@njit(cache=True, inline="always")
def _distance2(cart, p, sh0, sh1, sh2):
    """Squared length of the displacement cart[p] + sh of stored centre p from the query."""
    x = cart[p, 0] + sh0
    y = cart[p, 1] + sh1
    z = cart[p, 2] + sh2
    return x * x + y * y + z * z


@njit(cache=True)
def _shell_min(qc, cart, start, n_cells, box, c0, c1, c2, s, best):
    """Minimum squared distance from the point qc (Cartesian) to centres in the cells at
    Chebyshev distance s from cell (c0, c1, c2); periodic images by whole-cell shifts."""
    for d0 in range(-s, s + 1):
        s0, w0 = periodic_cell(c0 + d0, n_cells[0])
        for d1 in range(-s, s + 1):
            s1, w1 = periodic_cell(c1 + d1, n_cells[1])
            for d2 in range(-s, s + 1):
                if max(abs(d0), abs(d1), abs(d2)) != s:
                    continue
                s2, w2 = periodic_cell(c2 + d2, n_cells[2])
                flat, sh0, sh1, sh2 = image_cell(box, s0, s1, s2, w0, w1, w2, n_cells, qc)
                for p in range(start[flat], start[flat + 1]):
                    r2 = _distance2(cart, p, sh0, sh1, sh2)
                    if r2 < best:
                        best = r2
    return best


@njit(cache=True)
def _nearest(queries, cart, start, n_cells, box, widths, out):
    """out[m] = distance from query m to its nearest centre: shells of cells around the
    query cell, grown until the best distance is within the radius they guarantee."""
    qc = np.empty(3)
    min_width = min(widths[0], min(widths[1], widths[2]))
    for m in range(queries.shape[0]):
        c0, c1, c2, t0, t1, t2 = _locate(queries[m], box, n_cells, qc)
        # distance from the query to the faces of its own cell
        margin = min(min(t0, 1.0 - t0) * widths[0], min(t1, 1.0 - t1) * widths[1],
                     min(t2, 1.0 - t2) * widths[2])
        best = np.inf
        s = 0
        while True:
            best = _shell_min(qc, cart, start, n_cells, box, c0, c1, c2, s, best)
            # every centre outside the shells 0..s is farther than margin + s * min_width
            guaranteed = margin + s * min_width
            if best <= guaranteed * guaranteed:
                break
            s += 1
        out[m] = math.sqrt(best)


def nearest_distances(cells: CellList, points) -> np.ndarray:
    """Distance from each point to the nearest centre (exact, periodic, any cell shape)."""
    queries = cells.query_fractional(points)
    out = np.empty(len(queries))
    _nearest(queries, cells.cart, cells.start, cells.n_cells, cells.box,
             np.ascontiguousarray(cells.cell_width), out)
    return out


# --------------------------------------------------------------------------- pore sizes, E_V


def distance_bins(bin_width: float, d_max: float) -> np.ndarray:
    """Edges 0, w, 2w, ..., >= d_max of the nearest-distance histogram."""
    if not bin_width > 0 or not d_max > bin_width:
        raise ValueError(f"need 0 < bin_width < d_max, got {bin_width}, {d_max}")
    n = int(math.ceil(d_max / bin_width - 1e-9))
    return np.arange(n + 1) * bin_width


def nearest_distance_statistics(positions, box, diameter: float, rng: np.random.Generator,
                                n_matrix_points: int, edges: np.ndarray,
                                batch: int = 1_000_000) -> dict:
    """Monte Carlo of one sample: uniform points until ``n_matrix_points`` lie in the matrix.

    Returns the histogram of nearest-centre distances of *all* points over
    ``edges`` (last bin open: distances beyond edges[-1] are counted in
    ``overflow``), the number of points, the number of matrix points (d > R),
    sums of delta = d - R and delta^2 over matrix points, and max d.

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    diameter : float
        Sphere diameter D; matrix points have d > D/2.
    rng : numpy.random.Generator
        Source of the uniform points.
    n_matrix_points : int
        Matrix points to draw.
    edges : ndarray
        Histogram bin edges of d (e.g. :func:`distance_bins`).
    batch : int, optional
        Largest number of points drawn at once.

    Returns
    -------
    dict
        ``hist`` (int, len(edges) - 1), ``n_points``, ``n_matrix``, ``overflow``,
        ``sum_delta``, ``sum_delta2``, ``max_distance`` (lengths in the units of ``box``).
    """
    cell = Cell(box)
    cells = CellList(positions, box)
    radius = diameter / 2.0
    hist = np.zeros(len(edges) - 1, dtype=np.int64)
    total = matrix = overflow = 0
    sum_delta = sum_delta2 = 0.0
    max_d = 0.0
    fraction = 0.5  # running estimate of the matrix fraction, sizes the batches
    while matrix < n_matrix_points:
        need = n_matrix_points - matrix
        # draw in batches; the last batch stops exactly at the wanted matrix count
        size = int(min(batch, 1.1 * need / max(fraction, 0.01) + 1000))
        points = cell.random_points(rng, size)
        d = nearest_distances(cells, points)
        in_matrix = np.flatnonzero(d > radius)
        if len(in_matrix) > need:
            d = d[: in_matrix[need - 1] + 1]
            in_matrix = in_matrix[:need]
        fraction = max(len(in_matrix), 1) / len(d)
        total += len(d)
        delta = d[in_matrix] - radius
        matrix += len(delta)
        sum_delta += float(delta.sum())
        sum_delta2 += float((delta * delta).sum())
        max_d = max(max_d, float(d.max()))
        counts, _ = np.histogram(d, bins=edges)
        hist += counts
        overflow += int(np.count_nonzero(d >= edges[-1]))
    return {"hist": hist, "n_points": total, "n_matrix": matrix, "overflow": overflow,
            "sum_delta": sum_delta, "sum_delta2": sum_delta2, "max_distance": max_d}


def exclusion_from_histogram(hist, n_points, overflow=0) -> np.ndarray:
    """E_V at each edge: fraction of points with d >= edge (the last bin is open).

    Parameters
    ----------
    hist : array_like, shape (..., n_bins)
        Counts of nearest-centre distances per bin (:func:`nearest_distance_statistics`).
    n_points : array_like, shape (...)
        Number of points behind each histogram.
    overflow : array_like, shape (...), optional
        Points with d >= the last edge.

    Returns
    -------
    ndarray, shape (..., n_bins + 1)
        E_V at the bin edges.
    """
    hist = np.asarray(hist, dtype=float)
    n_points = np.asarray(n_points, dtype=float)
    beyond = np.flip(np.cumsum(np.flip(hist, axis=-1), axis=-1), axis=-1)  # d >= edge_i, i < n
    beyond = np.concatenate([beyond, np.zeros(hist.shape[:-1] + (1,))], axis=-1)
    beyond += np.asarray(overflow, dtype=float)[..., None]
    return beyond / n_points[..., None]


def covering_radius(positions, box, pad: float | None = None) -> float:
    """Exact covering radius of a periodic point set: max distance of a Voronoi vertex to its generators.

    The centres are padded by their periodic images within ``pad`` of the cell
    (default: 2 mean spacings); a vertex inside the cell is genuine if its
    empty sphere is smaller than ``pad`` (checked; otherwise retried with 2 pad).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Points (sphere centres), in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    pad : float, optional
        Padding width (units of ``box``); None: 2 (V / n)^(1/3). Capped at the smallest face
        distance.

    Returns
    -------
    float
        Covering radius R_c (units of ``box``).
    """
    from scipy.spatial import Voronoi, cKDTree

    cell = Cell(box)
    positions = np.asarray(positions, dtype=float)
    spacing = (cell.volume / len(positions)) ** (1.0 / 3.0)
    pad = 2.0 * spacing if pad is None else float(pad)
    while True:
        pad = min(pad, cell.face_distances.min())
        points, _ = padded_images(cell, positions, pad)
        vertices = Voronoi(points).vertices
        f = cell.fractional(vertices)
        inside = np.all((f >= 0) & (f < 1), axis=1)
        distance, _ = cKDTree(points).query(vertices[inside])
        radius = float(distance.max())
        if radius < pad or pad >= cell.face_distances.min():
            return radius
        pad *= 2.0


# --------------------------------------------------------------------------- window counts


def throws_per_radius(volume: float, radii, phi_B: float, max_windows: int) -> np.ndarray:
    """Paper's rule (Sec. VI B): n(R) = min(max_windows, floor(phi_B V / v(R))), at least 1.

    Parameters
    ----------
    volume : float
        Cell volume V.
    radii : array_like
        Window radii R (same length unit as V^(1/3)).
    phi_B : float
        Largest expected fraction of V covered by the test balls, in (0, 1].
    max_windows : int
        Upper bound n_max on the throws.

    Returns
    -------
    ndarray of int64
        n(R), same shape as ``radii``.
    """
    radii = np.asarray(radii, dtype=float)
    if not 0 < phi_B <= 1:
        raise ValueError(f"phi_B must lie in (0, 1], got {phi_B}")
    ball = 4.0 * math.pi * radii**3 / 3.0
    n = np.floor(phi_B * volume / ball)
    return np.clip(n, 1, max_windows).astype(np.int64)


@njit(cache=True)
def _gap(d, t):
    """Distance (in cell widths, along one axis) between a query at t in [0, 1) of cell 0 and cell d."""
    if d > 0:
        return d - t
    if d < 0:
        return t - d - 1.0
    return 0.0


@njit(cache=True)
def _window_counts(queries, cart, start, n_cells, box, widths, lam_min, radii2, lut, lut_scale,
                   n_radius_of_window, out):
    """out[m, i] = number of centres within radii[i] of window m, for i < n_radius_of_window[m].

    Cells are skipped when a lower bound of their distance to the window centre
    exceeds the largest radius: |B f|^2 >= lam_min |f|^2 for the fractional gap f
    (lam_min = smallest eigenvalue of B^T B; exact culling for orthogonal cells).
    The radius index of a squared distance comes from a lookup table on d^2
    (``lut[int(d2 * lut_scale)]`` is the first index whose radius^2 may exceed d2),
    corrected by a few comparisons.
    """
    qc = np.empty(3)
    for m in range(queries.shape[0]):
        n_r = n_radius_of_window[m]
        if n_r == 0:
            continue
        r_max2 = radii2[n_r - 1]
        r_max = math.sqrt(r_max2)
        c0, c1, c2, t0, t1, t2 = _locate(queries[m], box, n_cells, qc)
        e0 = int(math.ceil(r_max / widths[0]))
        e1 = int(math.ceil(r_max / widths[1]))
        e2 = int(math.ceil(r_max / widths[2]))
        hist = np.zeros(n_r + 1, dtype=np.int64)
        for d0 in range(-e0, e0 + 1):
            g0 = _gap(d0, t0) / n_cells[0]
            b0 = lam_min * g0 * g0
            if b0 >= r_max2:
                continue
            s0, w0 = periodic_cell(c0 + d0, n_cells[0])
            for d1 in range(-e1, e1 + 1):
                g1 = _gap(d1, t1) / n_cells[1]
                b1 = b0 + lam_min * g1 * g1
                if b1 >= r_max2:
                    continue
                s1, w1 = periodic_cell(c1 + d1, n_cells[1])
                for d2 in range(-e2, e2 + 1):
                    g2 = _gap(d2, t2) / n_cells[2]
                    if b1 + lam_min * g2 * g2 >= r_max2:
                        continue
                    s2, w2 = periodic_cell(c2 + d2, n_cells[2])
                    flat, sh0, sh1, sh2 = image_cell(box, s0, s1, s2, w0, w1, w2, n_cells, qc)
                    for p in range(start[flat], start[flat + 1]):
                        r2 = _distance2(cart, p, sh0, sh1, sh2)
                        if r2 < r_max2:
                            # first radius index i with r2 < radii2[i] (radii ascending)
                            i = lut[int(r2 * lut_scale)]
                            while radii2[i] <= r2:
                                i += 1
                            hist[i] += 1
        running = 0
        for i in range(n_r):
            running += hist[i]
            out[m, i] = running


def _radius_lookup(radii2, size: int = 4096):
    """lut[j] = first index i with radii2[i] > j / scale (j = 0..size), scale = size / radii2[-1]."""
    scale = size / radii2[-1]
    lut = np.searchsorted(radii2, np.arange(size + 1) / scale, side="right").astype(np.int64)
    return np.minimum(lut, len(radii2) - 1), scale


def window_counts(positions, box, centres, radii, n_per_radius) -> np.ndarray:
    """N(R) of centres within each radius (ascending, <= h_w) of each window centre.

    Window m is evaluated for the radii i with m < n_per_radius[i] (nested
    throws); other entries are -1. Returns an int array (n_windows, n_radii).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    centres : array_like, shape (n_windows, 3)
        Window centres.
    radii : array_like, shape (n_radii,)
        Strictly ascending positive radii, the largest <= h_w.
    n_per_radius : array_like of int, shape (n_radii,)
        Throws per radius, non-increasing, at most ``n_windows``.

    Returns
    -------
    ndarray of int64, shape (n_windows, n_radii)
        N(R) per window, -1 where not evaluated.
    """
    cells = CellList(positions, box)
    radii = np.asarray(radii, dtype=float)
    n_per_radius = np.asarray(n_per_radius, dtype=np.int64)
    if np.any(np.diff(radii) <= 0) or radii[0] <= 0:
        raise ValueError("radii must be positive and strictly ascending")
    if radii[-1] > cells.cell.half_width * (1 + 1e-12):
        raise ValueError(f"window radius {radii[-1]:g} exceeds h_w = {cells.cell.half_width:g}")
    centres = np.asarray(centres, dtype=float)
    n_windows = len(centres)
    if n_per_radius.max() > n_windows:
        raise ValueError("more throws requested than window centres given")
    # number of leading radii each window is used for
    windows = np.arange(n_windows)
    n_radius_of_window = (n_per_radius[None, :] > windows[:, None]).sum(axis=1)
    if np.any(np.diff(n_per_radius) > 0):
        raise ValueError("throws must not increase with the radius (nested windows)")
    out = np.full((n_windows, len(radii)), -1, dtype=np.int64)
    radii2 = radii * radii
    lut, scale = _radius_lookup(radii2)
    _window_counts(cells.query_fractional(centres), cells.cart, cells.start, cells.n_cells,
                   cells.box, np.ascontiguousarray(cells.cell_width),
                   float(np.linalg.eigvalsh(cells.box.T @ cells.box).min()), radii2, lut, scale,
                   n_radius_of_window.astype(np.int64), out)
    return out


def window_moments(counts) -> dict:
    """Per radius: number of throws and the power sums of N, N^2, N^3, N^4 (window_counts array)."""
    counts = np.asarray(counts)
    valid = counts >= 0
    c = np.where(valid, counts, 0).astype(np.float64)
    return {"n_throws": valid.sum(axis=0), "sum_N": c.sum(axis=0), "sum_N2": (c**2).sum(axis=0),
            "sum_N3": (c**3).sum(axis=0), "sum_N4": (c**4).sum(axis=0)}


def pooled_shape(n_throws, sum_N, sum_N2, sum_N3, sum_N4):
    """Skewness and excess kurtosis of the pooled N(R) over samples (axis 0), from power sums.

    Parameters
    ----------
    n_throws, sum_N, sum_N2, sum_N3, sum_N4 : array_like, shape (n_samples, n_radii)
        Per-sample throws and power sums of N (:func:`window_moments`).

    Returns
    -------
    skewness, excess_kurtosis : ndarray, shape (n_radii,)
        Of the pooled N(R) (not finite where the variance is 0).
    """
    n, s1, s2, s3, s4 = (np.asarray(a, dtype=float).sum(axis=0) for a in
                         (n_throws, sum_N, sum_N2, sum_N3, sum_N4))
    with np.errstate(invalid="ignore", divide="ignore"):
        m = s1 / n
        c2 = s2 / n - m**2
        c3 = s3 / n - 3 * m * s2 / n + 2 * m**3
        c4 = s4 / n - 4 * m * s3 / n + 6 * m**2 * s2 / n - 3 * m**4
        return c3 / c2**1.5, c4 / c2**2 - 3.0


def pooled_number_variance(n_throws, sum_N, sum_N2):
    """Pooled mean and variance over samples (axis 0) and delete-one-sample jackknife SEMs.

    Inputs have shape (n_samples, n_radii). Returns (mean, variance, mean_sem, variance_sem).

    Parameters
    ----------
    n_throws, sum_N, sum_N2 : array_like, shape (n_samples, n_radii)
        Per-sample throws and power sums of N and N^2 (:func:`window_moments`).

    Returns
    -------
    mean, variance, mean_sem, variance_sem : ndarray, shape (n_radii,)
        Pooled mean and variance (ddof 1) of N(R) and their jackknife SEMs (NaN for one
        sample).
    """
    n, s1, s2 = (np.asarray(a, dtype=float) for a in (n_throws, sum_N, sum_N2))

    def estimate(nn, a, b):
        mean = a / nn
        with np.errstate(invalid="ignore", divide="ignore"):
            var = (b - a * a / nn) / (nn - 1)
        return mean, var

    mean, var = estimate(n.sum(0), s1.sum(0), s2.sum(0))
    k = n.shape[0]
    if k < 2:
        return mean, var, np.full_like(mean, np.nan), np.full_like(var, np.nan)
    loo_mean, loo_var = estimate(n.sum(0) - n, s1.sum(0) - s1, s2.sum(0) - s2)
    factor = (k - 1) / k
    mean_sem = np.sqrt(factor * ((loo_mean - loo_mean.mean(0)) ** 2).sum(0))
    var_sem = np.sqrt(factor * ((loo_var - loo_var.mean(0)) ** 2).sum(0))
    return mean, var, mean_sem, var_sem


def count_distribution(counts_column):
    """Histogram of the N of one radius over its valid throws: (values n, frequencies)."""
    c = np.asarray(counts_column)
    c = c[c >= 0]
    values = np.arange(c.min(), c.max() + 1) if c.size else np.array([], dtype=int)
    freq = np.bincount(c - c.min()).astype(float) if c.size else np.array([])
    return values, freq


__all__ = [
    "CellList", "nearest_distances", "distance_bins", "nearest_distance_statistics",
    "exclusion_from_histogram", "covering_radius", "throws_per_radius", "window_counts",
    "window_moments", "pooled_number_variance", "count_distribution", "standard_error",
]
