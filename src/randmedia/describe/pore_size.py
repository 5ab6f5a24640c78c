"""Pore-size functions of periodic digitized 2D media.

Ma & Torquato 2020, Sec. II C: F(delta) is the probability that a disk of
radius delta centred at a random point of the pore (void) space lies entirely
in the void, i.e. that the point's distance to the interface is at least
delta; P(delta) = -dF/ddelta (Eq. 17), P(0) = s/phi1, and
<delta^n> = n integral delta^(n-1) F(delta) ddelta (Eq. 18).

Estimator (our choice; the paper does not describe one): distances are taken
to the *sub-pixel* interface of the Ma-Torquato level-set medium
(:class:`randmedia.describe.chords.LevelSet`, the same medium the chords and
surface functions use) -- not to pixel centres, whose distance transform is
biased by about half a pixel. The interface is the marching-squares polyline
of :func:`randmedia.describe.surface.interface_segments`; a point's distance
is the exact Euclidean distance to the nearest segment, found among the
``k_candidates`` segments with the nearest midpoints (periodic k-d tree).
Beyond the candidates the error is at most (l/2)^2 / (2 delta) for segments
of length l <= sqrt(2)/supersample pixels (< 0.02 px for delta >= 0.5 px).
Query points: one uniformly random point per pixel (stratified sampling),
kept when it lies in the void of the level set. A regular lattice of query
points would alias with the pixel lattice imprinted on the interface
(distances to a digitized straight edge come in whole pixels): on overlapping
disks its P(delta) histogram oscillates by +-60 % between 0.25 px bins.

The interface extraction is 2D; F, P and the moments are dimension-generic.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from scipy.spatial import cKDTree

from randmedia.describe.chords import LevelSet
from randmedia.describe.surface import interface_segments
from randmedia.io import VariableSpec
from randmedia.progress import Progress
from randmedia.stats import standard_error


def _point_segment_distance(px, py, ax, ay, bx, by):
    """Distance from points (px, py) to segments a-b (all arrays broadcast together)."""
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    with np.errstate(invalid="ignore", divide="ignore"):
        t = ((px - ax) * dx + (py - ay) * dy) / length2
    t = np.where(length2 > 0, np.clip(t, 0.0, 1.0), 0.0)
    return np.hypot(px - ax - t * dx, py - ay - t * dy)


def void_distances(level_set: LevelSet, rng: np.random.Generator, *, k_candidates: int = 4,
                   chunk: int = 200_000) -> np.ndarray:
    """Distance (pixels) to the interface from the void query points: one uniformly random
    point in every pixel (stratified sampling), kept when it lies in the level set's void.

    Parameters
    ----------
    level_set : LevelSet
        Level-set medium whose phase (fine > threshold) is the void.
    rng : numpy.random.Generator
        Source of the query points.
    k_candidates : int, optional
        Segments (nearest midpoints) checked per point.
    chunk : int, optional
        Points per k-d tree query.

    Returns
    -------
    ndarray, shape (n_void_points,)
        Distances (pixels); inf for every point if the level set has no interface.
    """
    ny, nx = level_set.shape
    box = np.array([nx, ny], dtype=float)
    rows, cols = np.mgrid[0:ny, 0:nx]
    x = cols.ravel() + rng.random(rows.size)
    y = rows.ravel() + rng.random(rows.size)
    void = level_set.value_at(x, y) > level_set.threshold
    points = np.column_stack([x[void], y[void]])
    segments = interface_segments(level_set)
    if segments.shape[0] == 0:
        return np.full(points.shape[0], np.inf)
    mids = 0.5 * (segments[:, :2] + segments[:, 2:])
    wrapped = np.mod(mids, box)
    tree = cKDTree(wrapped, boxsize=box)
    k = min(k_candidates, segments.shape[0])
    out = np.empty(points.shape[0])
    for start in range(0, points.shape[0], chunk):
        p = points[start:start + chunk]
        _, index = tree.query(p, k=k)
        index = index.reshape(p.shape[0], k)
        # minimum-image displacement of the point from each candidate's midpoint
        rel = p[:, None, :] - mids[index]
        rel -= box * np.round(rel / box)
        a = segments[index, :2] - mids[index]
        b = segments[index, 2:] - mids[index]
        dist = _point_segment_distance(rel[..., 0], rel[..., 1], a[..., 0], a[..., 1],
                                       b[..., 0], b[..., 1])
        out[start:start + chunk] = dist.min(axis=1)
    return out


def pixel_centre_distances(image: np.ndarray) -> np.ndarray:
    """Distance from every void pixel centre to the nearest phase-2 pixel centre (periodic
    Euclidean distance transform of the pixel image, by 3 x 3 tiling). A *diagnostic*, not
    our estimator: a void pixel next to the solid gets 1 although its centre is 1/2 pixel
    from the pixel boundary, so the mean overestimates <delta> by about half a pixel
    (on overlapping disks, R = 10 px: +0.5 px against the exact Eq. 37)."""
    from scipy.ndimage import distance_transform_edt

    image = np.asarray(image)
    ny, nx = image.shape
    if not (image == 1).any():
        raise ValueError("image has no phase-2 pixel: pore sizes are unbounded")
    distance = distance_transform_edt(np.tile(image == 0, (3, 3)))[ny:2 * ny, nx:2 * nx]
    return distance[image == 0]


def _histogram_density(distances: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Probability density of ``distances`` on the equal bins ``edges`` (bin averages of P)."""
    return np.histogram(distances, bins=edges)[0] / (distances.size * (edges[1] - edges[0]))


def pore_size_functions(images, rng: np.random.Generator, *, sigma: float, supersample: int,
                        delta_max: float, delta_bin: float, model: str = "pixels",
                        k_candidates: int = 4, log=None) -> xr.Dataset:
    """F(delta), P(delta) and <delta> of the void (image value 0) of a stack of periodic
    images, on their level sets of width ``sigma``; per sample, mean and SEM.

    F is evaluated on the grid delta = 0, delta_bin, ..., and P as the histogram density
    of the distances on the bins between those points (labelled by their centres), so
    that P is the exact bin average of -dF/ddelta of the sample.

    Parameters
    ----------
    images : array_like, shape (n_samples, ny, nx)
        Periodic images, void = 0 and phase 2 = 1.
    rng : numpy.random.Generator
        Source of the query points (:func:`void_distances`).
    sigma : float
        Gaussian width of the level set (pixels).
    supersample : int
        Sub-pixels per pixel along each axis (:class:`~randmedia.describe.chords.LevelSet`).
    delta_max, delta_bin : float
        Largest delta of the grid and its step (pixels), 0 < delta_bin < delta_max.
    model : {"pixels", "bilinear"}, optional
        Level-set model (:data:`~randmedia.describe.chords.LEVEL_SET_MODELS`).
    k_candidates : int, optional
        Passed to :func:`void_distances`.
    log : logging.Logger, optional
        Progress log (:class:`randmedia.progress.Progress`).

    Returns
    -------
    xarray.Dataset
        ``F`` on ``delta`` (grid points), ``P`` (1/pixel) on ``delta_bin`` (bin centres), each
        per sample with mean and SEM; per-sample ``mean_delta_samples``, ``max_delta_samples``
        (pixels), ``n_points_samples`` and the pixel-centre diagnostics.
    """
    images = np.asarray(images)
    if images.ndim != 3:
        raise ValueError(f"expected images of shape (n_samples, ny, nx), got {images.shape}")
    if delta_bin <= 0 or delta_max <= delta_bin:
        raise ValueError(f"need 0 < delta_bin < delta_max, got {delta_bin}, {delta_max}")
    edges = np.arange(0.0, delta_max + 0.5 * delta_bin, delta_bin)
    n = images.shape[0]
    F = np.empty((n, edges.size))
    P = np.empty((n, edges.size - 1))
    mean_delta = np.empty(n)
    max_delta = np.empty(n)
    n_points = np.empty(n, dtype=np.int64)
    mean_pixel_centre = np.empty(n)
    P_pixel_centre = np.empty((n, edges.size - 1))
    progress = Progress(n, "pore sizes", log, unit="images")
    for k, image in enumerate(images):
        distances = np.sort(void_distances(LevelSet.build(image, 0, sigma, supersample, model), rng,
                                           k_candidates=k_candidates))
        count = distances.size
        F[k] = 1.0 - np.searchsorted(distances, edges, side="left") / count
        P[k] = _histogram_density(distances, edges)
        mean_delta[k] = distances.mean()
        max_delta[k] = distances[-1]
        n_points[k] = count
        centre_distances = pixel_centre_distances(image)
        mean_pixel_centre[k] = centre_distances.mean()
        P_pixel_centre[k] = _histogram_density(centre_distances, edges)
        progress.step()
    centres = 0.5 * (edges[1:] + edges[:-1])
    return xr.Dataset(
        {
            "F_samples": (("sample", "delta"), F, {"units": "1", "long_name":
                          "complementary cumulative pore-size distribution per sample"}),
            "F": ("delta", F.mean(axis=0), {"units": "1", "long_name": "F(delta), sample mean"}),
            "F_sem": ("delta", standard_error(F), {"units": "1", "long_name":
                      "standard error of F over samples"}),
            "P_samples": (("sample", "delta_bin"), P, {"units": "1/pixel", "long_name":
                          "pore-size probability density per sample (bin average)"}),
            "P": ("delta_bin", P.mean(axis=0), {"units": "1/pixel", "long_name":
                  "pore-size probability density, sample mean"}),
            "P_sem": ("delta_bin", standard_error(P), {"units": "1/pixel", "long_name":
                      "standard error of P over samples"}),
            "mean_delta_samples": ("sample", mean_delta, {"units": "pixel", "long_name":
                                   "mean pore size <delta> (Eq. 18) per sample"}),
            "max_delta_samples": ("sample", max_delta, {"units": "pixel", "long_name":
                                  "largest pore size found per sample"}),
            "n_points_samples": ("sample", n_points, {"units": "1", "long_name":
                                 "void query points per sample"}),
            "mean_delta_pixel_centres_samples": ("sample", mean_pixel_centre, {"units": "pixel",
                "long_name": "diagnostic: mean distance from void pixel centres to the nearest "
                             "phase-2 pixel centre (biased by about +1/2 pixel)"}),
            "P_pixel_centres_samples": (("sample", "delta_bin"), P_pixel_centre, {"units": "1/pixel",
                "long_name": "second reading: histogram density of the pixel-centre distances "
                             "(void pixel centre to nearest phase-2 pixel centre) per sample"}),
        },
        coords={
            "delta": ("delta", edges, {"units": "pixel", "long_name": "pore radius delta"}),
            "delta_bin": ("delta_bin", centres, {"units": "pixel", "long_name":
                          "pore radius, bin centre"}),
            "sample": ("sample", np.arange(n), {"units": "1", "long_name": "sample index"}),
        },
        attrs={"sigma": float(sigma), "supersample": int(supersample), "level_set_model": model,
               "delta_bin_width": float(delta_bin), "k_candidates": int(k_candidates)},
    )


#: what a reader of a pore-size file requires
PORES = {
    "F": VariableSpec(("delta",), "1"),
    "F_sem": VariableSpec(("delta",), "1"),
    "F_samples": VariableSpec(("sample", "delta"), "1"),
    "P": VariableSpec(("delta_bin",), "1/pixel"),
    "P_sem": VariableSpec(("delta_bin",), "1/pixel"),
    "P_samples": VariableSpec(("sample", "delta_bin"), "1/pixel"),
    "mean_delta_samples": VariableSpec(("sample",), "pixel"),
}
