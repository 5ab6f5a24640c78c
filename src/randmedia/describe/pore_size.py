"""Pore-size functions of periodic digitized 2D and 3D media.

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

3D (voxel images): the same estimator with a sphere of radius delta, one random query
point per voxel (kept when the trilinear ``LevelSet.value_at`` puts it in the void), the
interface the marching-tetrahedra triangles of
:func:`randmedia.describe.isosurface.interface_triangles` and the exact point-to-triangle
distance to the ``k_candidates`` triangles with the nearest centroids (periodic k-d tree).
If a point's nearest interface point lies inside a triangle whose points are all within rho
of its centroid, the nearest-centroid candidate is at most sqrt(delta^2 + rho^2) away, so
the error is at most rho^2 / (2 delta); rho <= (2/3) sqrt(3) h for triangles inside a
sub-voxel cube of side h (0.38 voxel at h = 1/4; measured on the exact geometry of
overlapping spheres, R = 3 voxels, h = 1/4: rho = 0.285 voxel). There, k = 4 candidates
give a longer distance than a 128-candidate search for 6.6 % of the points, by 4.5e-5
voxel on average and at most 0.027 voxel (at delta = 0.006 voxel; error x delta <= 0.0032
voxel^2 against the bound rho^2 / 2 = 0.04); k = 8: 1.9 %, at most 0.006 voxel; k = 16:
none (tested). The query points are classified by the trilinear
interpolant, the interface is the piecewise-linear one of the tetrahedra: a point in the
thin sliver between the two (O(h^2) thick) gets a distance of that order, not 0.
Units: voxel in 3D.

F, P and the moments are dimension-generic.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from numba import njit
from scipy.spatial import cKDTree

from randmedia.describe.chords import LevelSet
from randmedia.describe.isosurface import interface_triangles
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


@njit(cache=True)
def _point_segment_distance3(px, py, pz, a, b):
    """Distance from the point p to the segment [a, b] (3D; a point if a == b)."""
    dx, dy, dz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    ex, ey, ez = px - a[0], py - a[1], pz - a[2]
    length2 = dx * dx + dy * dy + dz * dz
    t = 0.0
    if length2 > 0.0:
        t = min(1.0, max(0.0, (ex * dx + ey * dy + ez * dz) / length2))
    qx, qy, qz = ex - t * dx, ey - t * dy, ez - t * dz
    return math.sqrt(qx * qx + qy * qy + qz * qz)


@njit(cache=True)
def _point_triangle_distance(px, py, pz, tri):
    """Exact distance from the point p to the triangle ``tri`` (3, 3) (closest point by the
    Voronoi regions of the vertices, edges and face; Ericson, Real-Time Collision Detection,
    Sec. 5.1.5). A degenerate triangle (zero area: marching tetrahedra emits them where the
    field equals the threshold at a grid node, with repeated vertices) is its three edges,
    whose closest point the Voronoi tests would divide by zero to find: the minimum of the
    point-segment distances."""
    ax, ay, az = tri[0, 0], tri[0, 1], tri[0, 2]
    abx, aby, abz = tri[1, 0] - ax, tri[1, 1] - ay, tri[1, 2] - az
    acx, acy, acz = tri[2, 0] - ax, tri[2, 1] - ay, tri[2, 2] - az
    nx = aby * acz - abz * acy
    ny = abz * acx - abx * acz
    nz = abx * acy - aby * acx
    if nx * nx + ny * ny + nz * nz == 0.0:
        return min(_point_segment_distance3(px, py, pz, tri[0], tri[1]),
                   _point_segment_distance3(px, py, pz, tri[0], tri[2]),
                   _point_segment_distance3(px, py, pz, tri[1], tri[2]))
    apx, apy, apz = px - ax, py - ay, pz - az
    d1 = abx * apx + aby * apy + abz * apz
    d2 = acx * apx + acy * apy + acz * apz
    if d1 <= 0.0 and d2 <= 0.0:  # vertex a
        return math.sqrt(apx * apx + apy * apy + apz * apz)
    bpx, bpy, bpz = px - tri[1, 0], py - tri[1, 1], pz - tri[1, 2]
    d3 = abx * bpx + aby * bpy + abz * bpz
    d4 = acx * bpx + acy * bpy + acz * bpz
    if d3 >= 0.0 and d4 <= d3:  # vertex b
        return math.sqrt(bpx * bpx + bpy * bpy + bpz * bpz)
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:  # edge ab
        v = d1 / (d1 - d3)
        qx, qy, qz = apx - v * abx, apy - v * aby, apz - v * abz
        return math.sqrt(qx * qx + qy * qy + qz * qz)
    cpx, cpy, cpz = px - tri[2, 0], py - tri[2, 1], pz - tri[2, 2]
    d5 = abx * cpx + aby * cpy + abz * cpz
    d6 = acx * cpx + acy * cpy + acz * cpz
    if d6 >= 0.0 and d5 <= d6:  # vertex c
        return math.sqrt(cpx * cpx + cpy * cpy + cpz * cpz)
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:  # edge ac
        w = d2 / (d2 - d6)
        qx, qy, qz = apx - w * acx, apy - w * acy, apz - w * acz
        return math.sqrt(qx * qx + qy * qy + qz * qz)
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and (d4 - d3) >= 0.0 and (d5 - d6) >= 0.0:  # edge bc
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        qx = bpx - w * (tri[2, 0] - tri[1, 0])
        qy = bpy - w * (tri[2, 1] - tri[1, 1])
        qz = bpz - w * (tri[2, 2] - tri[1, 2])
        return math.sqrt(qx * qx + qy * qy + qz * qz)
    total = va + vb + vc
    if total <= 0.0:  # degenerate (zero-area) triangle: its edges were handled above
        return math.sqrt(apx * apx + apy * apy + apz * apz)
    v = vb / total
    w = vc / total
    qx, qy, qz = apx - v * abx - w * acx, apy - v * aby - w * acy, apz - v * abz - w * acz
    return math.sqrt(qx * qx + qy * qy + qz * qz)


@njit(cache=True)
def _nearest_triangle_distance(points, triangles, index, out):
    """out[p] = min over the candidates c of the distance from the point to triangle
    index[p, c]; ``points`` (n, k, 3) holds the point's minimum-image displacement from each
    candidate's centroid and ``triangles`` (m, 3, 3) the vertices relative to their centroid."""
    for p in range(points.shape[0]):
        best = np.inf
        for c in range(index.shape[1]):
            d = _point_triangle_distance(points[p, c, 0], points[p, c, 1], points[p, c, 2],
                                         triangles[index[p, c]])
            if d < best:
                best = d
        out[p] = best


def triangle_centroid_radius(triangles: np.ndarray) -> float:
    """rho: the largest distance from a triangle's centroid to one of its points (vertices),
    the bound of :func:`void_distances` in 3D (voxels)."""
    if triangles.shape[0] == 0:
        return 0.0
    centroids = triangles.mean(axis=1, keepdims=True)
    return float(np.sqrt(((triangles - centroids) ** 2).sum(axis=2)).max())


def _void_distances_3d(level_set: LevelSet, rng: np.random.Generator, k_candidates: int,
                       chunk: int) -> np.ndarray:
    """:func:`void_distances` of a 3D level set (module docstring)."""
    nz, ny, nx = level_set.shape
    box = np.array([nx, ny, nz], dtype=float)
    layers, rows, cols = np.mgrid[0:nz, 0:ny, 0:nx]
    x = cols.ravel() + rng.random(cols.size)
    y = rows.ravel() + rng.random(cols.size)
    z = layers.ravel() + rng.random(cols.size)
    void = level_set.value_at(x, y, z) > level_set.threshold
    points = np.column_stack([x[void], y[void], z[void]])
    triangles = interface_triangles(level_set)
    if triangles.shape[0] == 0:
        return np.full(points.shape[0], np.inf)
    centroids = triangles.mean(axis=1)
    relative = np.ascontiguousarray(triangles - centroids[:, None, :])
    tree = cKDTree(np.mod(centroids, box), boxsize=box)
    k = min(k_candidates, triangles.shape[0])
    out = np.empty(points.shape[0])
    for start in range(0, points.shape[0], chunk):
        p = points[start:start + chunk]
        _, index = tree.query(p, k=k)
        index = np.ascontiguousarray(index.reshape(p.shape[0], k), dtype=np.int64)
        # minimum-image displacement of the point from each candidate's centroid
        rel = p[:, None, :] - centroids[index]
        rel -= box * np.round(rel / box)
        _nearest_triangle_distance(np.ascontiguousarray(rel), relative, index,
                                   out[start:start + chunk])
    return out


def void_distances(level_set: LevelSet, rng: np.random.Generator, *, k_candidates: int = 4,
                   chunk: int = 200_000) -> np.ndarray:
    """Distance (pixels) to the interface from the void query points: one uniformly random
    point in every pixel (stratified sampling), kept when it lies in the level set's void.
    A 3D level set: one point per voxel, distances (voxels) to the marching-tetrahedra
    triangles (module docstring).

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
    if level_set.fine.ndim == 3:
        return _void_distances_3d(level_set, rng, k_candidates, chunk)
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
    Euclidean distance transform of the pixel image, by 3 x 3 tiling; a 3D image: voxel
    centres, 3 x 3 x 3 tiling). A *diagnostic*, not
    our estimator: a void pixel next to the solid gets 1 although its centre is 1/2 pixel
    from the pixel boundary, so the mean overestimates <delta> by about half a pixel
    (on overlapping disks, R = 10 px: +0.5 px against the exact Eq. 37)."""
    from scipy.ndimage import distance_transform_edt

    image = np.asarray(image)
    if not (image == 1).any():
        raise ValueError("image has no phase-2 pixel: pore sizes are unbounded")
    if image.ndim == 3:
        centre = tuple(slice(n, 2 * n) for n in image.shape)
        distance = distance_transform_edt(np.tile(image == 0, (3, 3, 3)))[centre]
        return distance[image == 0]
    ny, nx = image.shape
    distance = distance_transform_edt(np.tile(image == 0, (3, 3)))[ny:2 * ny, nx:2 * nx]
    return distance[image == 0]


def _histogram_density(distances: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Probability density of ``distances`` on the equal bins ``edges`` (bin averages of P)."""
    return np.histogram(distances, bins=edges)[0] / (distances.size * (edges[1] - edges[0]))


def pore_size_functions(images, rng: np.random.Generator, *, sigma: float, supersample: int,
                        delta_max: float, delta_bin: float, model: str = "pixels",
                        k_candidates: int = 4, log=None) -> xr.Dataset:
    """F(delta), P(delta) and <delta> of the void (image value 0) of a stack of periodic
    2D or 3D images, on their level sets of width ``sigma``; per sample, mean and SEM
    (Ma & Torquato 2020, Eqs. 17-18; in 3D the unit is the voxel, attribute ``dimension``).

    F is evaluated on the grid delta = 0, delta_bin, ..., and P as the histogram density
    of the distances on the bins between those points (labelled by their centres), so
    that P is the exact bin average of -dF/ddelta of the sample.

    Parameters
    ----------
    images : array_like, shape (n_samples, ny, nx) or (n_samples, nz, ny, nx)
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
    if images.ndim not in (3, 4):
        raise ValueError(f"expected images of shape (n_samples, ny, nx) or (n_samples, nz, ny, "
                         f"nx), got {images.shape}")
    three_d = images.ndim == 4
    unit = cell = "voxel" if three_d else "pixel"
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
    attrs = {"sigma": float(sigma), "supersample": int(supersample), "level_set_model": model,
             "delta_bin_width": float(delta_bin), "k_candidates": int(k_candidates)}
    if three_d:
        attrs["dimension"] = 3
    diagnostics = {
        "mean_delta_pixel_centres_samples": ("sample", mean_pixel_centre, {"units": unit,
            "long_name": f"diagnostic: mean distance from void {cell} centres to the nearest "
                         f"phase-2 {cell} centre (biased by about +1/2 {cell})"}),
        "P_pixel_centres_samples": (("sample", "delta_bin"), P_pixel_centre, {"units": f"1/{unit}",
            "long_name": f"second reading: histogram density of the {cell}-centre distances "
                         f"(void {cell} centre to nearest phase-2 {cell} centre) per sample"}),
    }
    return pore_functions_dataset(F, P, mean_delta, max_delta, n_points, edges, unit=unit, attrs=attrs,
                                  extra=diagnostics)


def pore_functions_dataset(F: np.ndarray, P: np.ndarray, mean_delta: np.ndarray, max_delta: np.ndarray,
                           n_points: np.ndarray, edges: np.ndarray, *, unit: str, attrs: dict,
                           extra: dict | None = None) -> xr.Dataset:
    """The pore-size file from per-sample F on the grid ``edges`` (shape (n, grid)), P on the
    bins between them (shape (n, bins)), <delta>, the largest distance and the query-point
    count: sample means and SEMs; ``extra`` variables (on ``sample``/``delta_bin``) are added
    as given; ``unit`` is "pixel" or "voxel"."""
    n = F.shape[0]
    centres = 0.5 * (edges[1:] + edges[:-1])
    return xr.Dataset(
        {
            "F_samples": (("sample", "delta"), F, {"units": "1", "long_name":
                          "complementary cumulative pore-size distribution per sample"}),
            "F": ("delta", F.mean(axis=0), {"units": "1", "long_name": "F(delta), sample mean"}),
            "F_sem": ("delta", standard_error(F), {"units": "1", "long_name":
                      "standard error of F over samples"}),
            "P_samples": (("sample", "delta_bin"), P, {"units": f"1/{unit}", "long_name":
                          "pore-size probability density per sample (bin average)"}),
            "P": ("delta_bin", P.mean(axis=0), {"units": f"1/{unit}", "long_name":
                  "pore-size probability density, sample mean"}),
            "P_sem": ("delta_bin", standard_error(P), {"units": f"1/{unit}", "long_name":
                      "standard error of P over samples"}),
            "mean_delta_samples": ("sample", mean_delta, {"units": unit, "long_name":
                                   "mean pore size <delta> (Eq. 18) per sample"}),
            "max_delta_samples": ("sample", max_delta, {"units": unit, "long_name":
                                  "largest pore size found per sample"}),
            "n_points_samples": ("sample", n_points, {"units": "1", "long_name":
                                 "void query points per sample"}),
            **(extra or {}),
        },
        coords={
            "delta": ("delta", edges, {"units": unit, "long_name": "pore radius delta"}),
            "delta_bin": ("delta_bin", centres, {"units": unit, "long_name":
                          "pore radius, bin centre"}),
            "sample": ("sample", np.arange(n), {"units": "1", "long_name": "sample index"}),
        },
        attrs=attrs,
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

#: what a reader of a 3D pore-size file requires
PORES_3D = {
    "F": VariableSpec(("delta",), "1"),
    "F_sem": VariableSpec(("delta",), "1"),
    "F_samples": VariableSpec(("sample", "delta"), "1"),
    "P": VariableSpec(("delta_bin",), "1/voxel"),
    "P_sem": VariableSpec(("delta_bin",), "1/voxel"),
    "P_samples": VariableSpec(("sample", "delta_bin"), "1/voxel"),
    "mean_delta_samples": VariableSpec(("sample",), "voxel"),
}
