"""Pore-size functions of a 3D *window* image (reduced-sample / minus-sampling estimator).

Ma & Torquato 2020, Sec. II C: F(delta) is the probability that the sphere of radius delta
around a random void point lies entirely in the void (the point's distance to the interface
is at least delta); P(delta) = -dF/ddelta (Eq. 17), <delta> = integral F ddelta (Eq. 18).
:mod:`randmedia.describe.pore_size` measures distances to the interface of a *periodic*
level set; in a window cut from a non-periodic medium (the Poisson-plane tessellations) the
wrapped interface and the missing outside make distances near the faces wrong. Here:

1. **Level set and interface**: the window level set of the surface functions and chords
   (:func:`randmedia.describe.window_surface.window_level_set`, same sigma), and its
   marching-tetrahedra triangles (:func:`randmedia.describe.isosurface.interface_triangles`)
   whose vertices all lie where the filtered field is that of the infinite medium, i.e. at
   least the kernel radius ``int(4 sigma m + 0.5)`` sub-voxels from every face (the cubes
   that wrap are dropped with them).
2. **Query points**: one uniformly random point per voxel of the interior box
   (:func:`~randmedia.numerics.gaussian.default_margin` sub-voxels from every face, one
   voxel more than the kernel radius), kept when the level set puts it in the void; its
   distance d to the nearest kept triangle (exact point-triangle distance to the
   ``k_candidates`` nearest centroids, as in the periodic estimator) and its distance b to the
   faces of the interior box.
3. **Reduced-sample estimator** (standard minus-sampling for spherical contact distributions):
   F(delta) = #{d >= delta, b >= delta} / #{b >= delta}. For b >= delta the sphere of radius
   delta lies in the interior box, where every piece of interface is among the kept
   triangles, so d >= delta is decided exactly; the price is fewer points at large delta
   (none once delta exceeds half the interior side). Each delta has its own denominator, so
   F need not be monotone; P is the bin difference of F (-dF/ddelta averaged over the bin,
   the periodic estimator's definition) and <delta> = integral of F over the grid (trapezoid;
   a lower bound if F(delta_max) > 0, attribute ``F_at_delta_max``).

Validated on overlapping spheres read as windows against the exact 3D F(delta) and the
periodic estimator (tests/test_window_pores.py).
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from scipy.spatial import cKDTree

from randmedia.describe.isosurface import interface_triangles
from randmedia.describe.pore_size import _nearest_triangle_distance, pore_functions_dataset
from randmedia.describe.window_surface import window_level_set
from randmedia.numerics.gaussian import default_margin, kernel_radius
from randmedia.progress import Progress


def window_void_distances(image: np.ndarray, rng: np.random.Generator, *, sigma: float, supersample: int,
                          margin: int | None = None, k_candidates: int = 4,
                          chunk: int = 200_000) -> tuple[np.ndarray, np.ndarray]:
    """Distances (voxels) of the void query points of a window to the interface (d) and to
    the faces of the interior box (b) (module docstring, steps 1-2).

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        Window image, void = 0.
    rng : numpy.random.Generator
        Source of the query points (3 uniforms per voxel of the whole window).
    sigma : float
        Gaussian width of the level set (voxels).
    supersample : int
        Sub-voxels per voxel.
    margin : int, optional
        Interior margin in sub-voxels; None: :func:`default_margin`.
    k_candidates : int, optional
        Triangles (nearest centroids) checked per point.
    chunk : int, optional
        Points per k-d tree query.

    Returns
    -------
    d, b : ndarray
        Per void query point of the interior box: distance to the interface (inf if there is
        none) and to the box's faces.
    """
    level_set = window_level_set(image, sigma, supersample)
    if margin is None:
        margin = default_margin(sigma, supersample)
    kernel = kernel_radius(sigma, supersample)
    if margin < kernel + 1:
        raise ValueError(f"margin {margin} sub-voxels must exceed the filter's kernel radius {kernel}")
    shape = np.array(image.shape[::-1], dtype=float)  # (x, y, z) in voxels
    low, high = np.full(3, margin / supersample), shape - margin / supersample
    if np.any(high <= low):
        raise ValueError(f"margin {margin} sub-voxels leaves no interior in {image.shape}")
    layers, rows, cols = np.mgrid[0:image.shape[0], 0:image.shape[1], 0:image.shape[2]]
    x = cols.ravel() + rng.random(cols.size)
    y = rows.ravel() + rng.random(cols.size)
    z = layers.ravel() + rng.random(cols.size)
    points = np.column_stack([x, y, z])
    inside = np.all((points >= low) & (points <= high), axis=1)
    points = points[inside]
    void = level_set.value_at(points[:, 0], points[:, 1], points[:, 2]) > level_set.threshold
    points = np.ascontiguousarray(points[void])
    to_faces = np.minimum(points - low, high - points).min(axis=1)
    triangles = interface_triangles(level_set)
    exact_low = (kernel + 0.5) / supersample
    exact_high = shape - exact_low
    keep = np.all((triangles >= exact_low) & (triangles <= exact_high), axis=(1, 2))
    triangles = triangles[keep]
    if triangles.shape[0] == 0:
        return np.full(points.shape[0], np.inf), to_faces
    centroids = triangles.mean(axis=1)
    relative = np.ascontiguousarray(triangles - centroids[:, None, :])
    tree = cKDTree(centroids)
    k = min(k_candidates, triangles.shape[0])
    out = np.empty(points.shape[0])
    for start in range(0, points.shape[0], chunk):
        p = points[start:start + chunk]
        _, index = tree.query(p, k=k)
        index = np.ascontiguousarray(index.reshape(p.shape[0], k), dtype=np.int64)
        rel = np.ascontiguousarray(p[:, None, :] - centroids[index])
        _nearest_triangle_distance(rel, relative, index, out[start:start + chunk])
    return out, to_faces


def reduced_sample_F(distances: np.ndarray, to_faces: np.ndarray, deltas: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """F(delta) = #{d >= delta, b >= delta} / #{b >= delta} and the denominators (nan where
    no point is farther than delta from the faces)."""
    at_risk = to_faces.size - np.searchsorted(np.sort(to_faces), deltas, side="left")
    open_ = to_faces.size - np.searchsorted(np.sort(np.minimum(distances, to_faces)), deltas, side="left")
    with np.errstate(invalid="ignore", divide="ignore"):
        F = np.where(at_risk > 0, open_ / at_risk, np.nan)
    return F, at_risk


def window_pore_size_functions(images, rng: np.random.Generator, *, sigma: float, supersample: int,
                               delta_max: float, delta_bin: float, margin: int | None = None,
                               k_candidates: int = 4, log=None) -> xr.Dataset:
    """F(delta), P(delta) and <delta> of the void of a stack of 3D windows (module
    docstring): the pore-size file of :func:`randmedia.describe.pore_size.pore_functions_dataset`
    (voxels), with attributes ``estimator`` = "window", ``margin`` (sub-voxels),
    ``F_at_delta_max`` (sample mean) and per sample ``n_points_at_delta_max_samples`` (query
    points at least delta_max from the faces).

    Parameters
    ----------
    images : array_like, shape (n_samples, nz, ny, nx)
        Window images, void = 0.
    rng : numpy.random.Generator
        Source of the query points.
    sigma : float
        Gaussian width of the level set (voxels).
    supersample : int
        Sub-voxels per voxel.
    delta_max, delta_bin : float
        Largest delta of the grid and its step (voxels), 0 < delta_bin < delta_max.
    margin : int, optional
        Interior margin in sub-voxels; None: :func:`default_margin`.
    k_candidates : int, optional
        Passed to :func:`window_void_distances`.
    log : logging.Logger, optional
        Progress log.

    Returns
    -------
    xarray.Dataset
    """
    images = np.asarray(images)
    if images.ndim != 4:
        raise ValueError(f"expected windows of shape (n_samples, nz, ny, nx), got {images.shape}")
    if delta_bin <= 0 or delta_max <= delta_bin:
        raise ValueError(f"need 0 < delta_bin < delta_max, got {delta_bin}, {delta_max}")
    if margin is None:
        margin = default_margin(sigma, supersample)
    edges = np.arange(0.0, delta_max + 0.5 * delta_bin, delta_bin)
    n = images.shape[0]
    F = np.empty((n, edges.size))
    at_max = np.empty(n, dtype=np.int64)
    max_delta = np.empty(n)
    n_points = np.empty(n, dtype=np.int64)
    progress = Progress(n, "window pore sizes", log, unit="images")
    for k, image in enumerate(images):
        distances, to_faces = window_void_distances(image, rng, sigma=sigma, supersample=supersample,
                                                    margin=margin, k_candidates=k_candidates)
        F[k], at_risk = reduced_sample_F(distances, to_faces, edges)
        if np.isnan(F[k]).any():
            raise ValueError(f"window {k}: no void point farther than delta = "
                             f"{edges[np.isnan(F[k])][0]:g} voxels from the interior's faces; lower delta_max")
        at_max[k] = at_risk[-1]
        max_delta[k] = float(np.max(np.minimum(distances, to_faces)))
        n_points[k] = distances.size
        progress.step()
    P = -np.diff(F, axis=1) / delta_bin
    mean_delta = np.trapezoid(F, edges, axis=1)
    attrs = {"sigma": float(sigma), "supersample": int(supersample), "level_set_model": "pixels",
             "delta_bin_width": float(delta_bin), "k_candidates": int(k_candidates), "dimension": 3,
             "estimator": "window", "margin": int(margin), "F_at_delta_max": float(F[:, -1].mean())}
    extra = {"n_points_at_delta_max_samples": ("sample", at_max, {"units": "1", "long_name":
             "void query points at least delta_max from the interior's faces"})}
    out = pore_functions_dataset(F, P, mean_delta, max_delta, n_points, edges, unit="voxel", attrs=attrs,
                                 extra=extra)
    out["mean_delta_samples"].attrs["long_name"] = ("mean pore size <delta> (Eq. 18) per sample: integral "
                                                    "of the reduced-sample F up to delta_max")
    out["max_delta_samples"].attrs["long_name"] = ("largest distance to the interface certified inside "
                                                   "the interior box (min of d and b) per sample")
    return out
