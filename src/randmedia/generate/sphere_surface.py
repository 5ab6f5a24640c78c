"""Point patterns on the sphere of radius R (sphere2019, Secs. III-IV and the Appendix).

File contract (DESIGN.md, ``results/sphere2019/configs/{system}.nc``): variable
``position`` with dims (``frame``, ``particle``, ``xyz``), points on the sphere of
radius attr ``R``; frames with fewer points than the longest are padded with NaN
rows; variable ``n_points`` (frame) says how many rows of each frame are points.
:func:`points_dataset` builds it, :func:`frames_of` reads the frames back.

Patterns
--------
* :func:`icosahedral_grid` -- Tegmark's icosahedron pixelization (ApJ 470, L81,
  1996), the "triangular lattice" of Fig. 2(a). The sphere is inscribed in a
  regular icosahedron (faces tangent to it). Each face, seen in its tangent plane
  (gnomonic coordinates), is split into six right triangles C-M-V (C: face centre,
  M: an edge midpoint, V: a corner). On each face a regular triangular grid with
  2n points per edge (spacing = edge / (2n - 1), n = ``resolution``) is laid out;
  its points are moved by the inverse of an *area-equalizing* map of the face onto
  itself and then projected centrally onto the sphere. Points on edges and corners
  are shared between faces and kept once, giving N = 40 n (n - 1) + 12 pixels.

  Area equalization (Tegmark's construction). In a sixth, with v the coordinate
  along C->M (0 <= v <= h) and u perpendicular to it towards V (0 <= u <= sqrt3 v),
  t = u / v, the solid angle per unit plane area at (u, v) is (1 + u^2 + v^2)^(-3/2).
  The map (v, t) -> (v', t') with

      (sqrt3/2) v'^2 = k Omega(v)       Omega(v): solid angle of {C, (0, v), (sqrt3 v, v)}
      t' = t sqrt((1 + 4 v^2) / (1 + v^2 + t^2 v^2))

  has planar Jacobian v' dv' dt' = k (solid angle) dv dt, i.e. it is exactly
  equal-area (t'/sqrt3 is the solid-angle fraction of the strip at height v
  between u = 0 and u = t v); k makes the sixth map onto itself (v'(h) = h).
  Omega(v) is computed with the Van Oosterom & Strackee formula. Grid points
  (equal-area plane) are mapped back by inverting v'(v) by bisection and t'(t) in
  closed form, t = t' sqrt((1 + v^2) / (1 + 4 v^2 - t'^2 v^2)). Pixels (spherical
  Voronoi cells) then have equal areas up to the edge and corner cells (tested).
* :func:`fibonacci_grid` -- the Swinbank & Purser (QJRMS 132, 1769, 2006)
  Fibonacci grid, Fig. 2(b): z_i = (2i + 1 - N)/N, longitude 2 pi i / Phi
  (Phi the golden ratio), i = 0..N-1 (for odd N = 2n + 1 exactly their
  sin(lat) = 2k/(2n + 1), k = -n..n).
* :func:`uniform_points` -- canonical: N independent uniform points (normalized
  Gaussian vectors, Appendix 1).
* :func:`poisson_points` -- grand canonical: Poisson point process of mean <N>
  by the Appendix's spherical-rectangle subdivision: rectangles
  theta_1 < theta <= theta_2, phi_1 < phi <= phi_2 (equal steps in theta and
  phi, so rectangles have *unequal* areas mu = R^2 (cos theta_1 - cos theta_2)
  (phi_2 - phi_1)); each gets k ~ Poiss(<N> mu / (4 pi R^2)) points uniform in
  area (cos theta uniform in its band, phi uniform).
"""

from __future__ import annotations

import itertools
import math
from typing import Mapping, Sequence

import numpy as np
import xarray as xr

from randmedia.io import VariableSpec
from randmedia.theory.sphere_caps import check_radius

#: what a reader of a sphere configuration file requires (DESIGN.md contract)
SPHERE_CONFIG = {
    "position": VariableSpec(("frame", "particle", "xyz"), "1"),
    "n_points": VariableSpec(("frame",), "1"),
}

GOLDEN_RATIO = (1.0 + math.sqrt(5.0)) / 2.0


# --------------------------------------------------------------------------- file contract


def points_dataset(frames: Sequence[np.ndarray], radius: float, attrs: Mapping,
                   extra: Mapping | None = None) -> xr.Dataset:
    """Wrap point sets on the sphere of radius R as the contract's Dataset.

    ``frames``: sequence of (n_f, 3) arrays (or one (F, N, 3) array), every point at
    distance R from the origin (checked to 1e-9 R). Shorter frames are padded
    with NaN rows. ``extra``: further data variables (name -> (dims, values, attrs)).

    Parameters
    ----------
    frames : sequence of ndarray, each shape (n_f, 3)
        Point sets on the sphere (Cartesian), in the length unit of ``radius``.
    radius : float
        Sphere radius R; stored as attr ``R``.
    attrs : Mapping
        Extra global attributes (``R``, ``n_frames``, ``mean_n_points`` and ``density`` are added).
    extra : Mapping, optional
        Further data variables, name -> (dims, values, attrs).

    Returns
    -------
    xarray.Dataset
        ``position`` (frame, particle, xyz) NaN-padded, ``n_points`` (frame), coord ``xyz``.
    """
    check_radius(radius)
    frames = [np.asarray(f, dtype=np.float64) for f in frames]
    if not frames:
        raise ValueError("no frames to store")
    for k, f in enumerate(frames):
        if f.ndim != 2 or f.shape[1] != 3:
            raise ValueError(f"frame {k} has shape {f.shape}, expected (n, 3)")
        if f.size and np.max(np.abs(np.linalg.norm(f, axis=1) - radius)) > 1e-9 * radius:
            raise ValueError(f"frame {k}: points are not on the sphere of radius {radius}")
    n_max = max(max(f.shape[0] for f in frames), 1)
    position = np.full((len(frames), n_max, 3), np.nan)
    for k, f in enumerate(frames):
        position[k, : f.shape[0]] = f
    counts = np.array([f.shape[0] for f in frames], dtype=np.int64)
    data = {
        "position": (("frame", "particle", "xyz"), position,
                     {"units": "1", "long_name": "point on the sphere (Cartesian; length unit of R, "
                      "d_LJ for the fluids); NaN rows pad shorter frames"}),
        "n_points": (("frame",), counts, {"units": "1", "long_name": "number of points in the frame"}),
    }
    data.update(extra or {})
    return xr.Dataset(
        data,
        coords={"xyz": ("xyz", ["x", "y", "z"], {"units": "1", "long_name": "Cartesian axis"})},
        attrs={**dict(attrs), "R": float(radius), "n_frames": len(frames),
               "mean_n_points": float(counts.mean()),
               "density": float(counts.mean() / (4.0 * np.pi * radius**2))},
    )


def frames_of(ds: xr.Dataset) -> list[np.ndarray]:
    """The frames of a configuration Dataset, NaN padding removed."""
    position = ds["position"].values
    counts = ds["n_points"].values
    frames = []
    for k in range(position.shape[0]):
        frame = position[k, : int(counts[k])]
        if np.isnan(frame).any() or not np.isnan(position[k, int(counts[k]):]).all():
            raise ValueError(f"frame {k}: NaN rows do not match n_points = {counts[k]}")
        frames.append(frame)
    return frames


# --------------------------------------------------------------------------- icosahedral grid


def icosahedron() -> tuple[np.ndarray, np.ndarray]:
    """Unit vectors of the 12 vertices and the 20 faces (vertex index triples, outward
    counter-clockwise) of a regular icosahedron."""
    vertices = []
    for s1, s2 in itertools.product((-1.0, 1.0), repeat=2):
        vertices += [(0.0, s1, s2 * GOLDEN_RATIO), (s1, s2 * GOLDEN_RATIO, 0.0),
                     (s2 * GOLDEN_RATIO, 0.0, s1)]
    vertices = np.array(vertices) / math.hypot(1.0, GOLDEN_RATIO)
    edge = np.min([np.linalg.norm(p - q) for p, q in itertools.combinations(vertices, 2)])
    adjacent = np.abs(np.linalg.norm(vertices[:, None] - vertices[None], axis=2) - edge) < 1e-9
    faces = []
    for i, j, k in itertools.combinations(range(12), 3):
        if adjacent[i, j] and adjacent[j, k] and adjacent[i, k]:
            if np.dot(np.cross(vertices[j] - vertices[i], vertices[k] - vertices[i]), vertices[i]) < 0:
                j, k = k, j
            faces.append((i, j, k))
    return vertices, np.array(faces, dtype=np.int64)


def _triangle_solid_angle(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Solid angle of the planar triangle abc seen from the origin (Van Oosterom & Strackee)."""
    na, nb, nc = (np.linalg.norm(v, axis=-1) for v in (a, b, c))
    numerator = np.abs(np.einsum("...i,...i", a, np.cross(b, c)))
    denominator = (na * nb * nc + np.einsum("...i,...i", a, b) * nc
                   + np.einsum("...i,...i", a, c) * nb + np.einsum("...i,...i", b, c) * na)
    return 2.0 * np.arctan2(numerator, denominator)


def _sixth_solid_angle(v, t) -> np.ndarray:
    """Omega(v, t): solid angle of {C, (0, v), (t v, v)} in the tangent plane z = 1."""
    v, t = np.broadcast_arrays(np.asarray(v, dtype=float), np.asarray(t, dtype=float))
    zero = np.zeros_like(v)
    one = np.ones_like(v)
    apex = np.stack([zero, zero, one], axis=-1)
    foot = np.stack([zero, v, one], axis=-1)
    corner = np.stack([t * v, v, one], axis=-1)
    return _triangle_solid_angle(apex, foot, corner)


def _bisect(function, target, lo, hi, iterations: int = 60):
    """Vectorized bisection for an increasing ``function`` with function(lo) <= target <= function(hi)."""
    lo = np.broadcast_to(np.asarray(lo, dtype=float), np.shape(target)).copy()
    hi = np.broadcast_to(np.asarray(hi, dtype=float), np.shape(target)).copy()
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        below = function(mid) < target
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return 0.5 * (lo + hi)


def equal_area_to_gnomonic(v_eq, t_eq, h: float) -> tuple[np.ndarray, np.ndarray]:
    """Inverse of the area-equalizing map of a sixth (module docstring): equal-area
    coordinates (v', t') -> gnomonic (v, t). h: centre-to-edge-midpoint distance of
    the face in the tangent plane z = 1.

    Parameters
    ----------
    v_eq, t_eq : array_like
        Equal-area coordinates (v', t') of a sixth, 0 <= v' <= h (broadcast together).
    h : float
        Centre-to-edge-midpoint distance of the face in the tangent plane z = 1.

    Returns
    -------
    v, t : ndarray
        Gnomonic coordinates (t = 0 where v = 0).
    """
    root3 = math.sqrt(3.0)
    v_eq, t_eq = np.broadcast_arrays(np.asarray(v_eq, float), np.asarray(t_eq, float))
    total = _sixth_solid_angle(h, root3)
    v = _bisect(lambda x: _sixth_solid_angle(x, root3), total * (v_eq / h) ** 2, 0.0, h)
    t = t_eq * np.sqrt((1.0 + v * v) / (1.0 + 4.0 * v * v - t_eq**2 * v * v))
    return v, np.where(v > 0, t, 0.0)


def gnomonic_to_equal_area(v, t, h: float) -> tuple[np.ndarray, np.ndarray]:
    """The area-equalizing map of a sixth, (v, t) -> (v', t') (module docstring).

    Parameters
    ----------
    v, t : array_like
        Gnomonic coordinates of a sixth, 0 <= v <= h, t = u / v (broadcast together).
    h : float
        Centre-to-edge-midpoint distance of the face in the tangent plane z = 1.

    Returns
    -------
    v_eq, t_eq : ndarray
        Equal-area coordinates (v', t').
    """
    root3 = math.sqrt(3.0)
    v, t = np.broadcast_arrays(np.asarray(v, float), np.asarray(t, float))
    v_eq = h * np.sqrt(_sixth_solid_angle(v, root3) / _sixth_solid_angle(h, root3))
    t_eq = t * np.sqrt((1.0 + 4.0 * v * v) / (1.0 + v * v + t * t * v * v))
    return v_eq, t_eq


def _face_frame(vertices: np.ndarray, face: np.ndarray):
    """Centre direction, in-plane corner positions (tangent plane at distance 1) of a face."""
    centre = vertices[face].sum(axis=0)
    centre /= np.linalg.norm(centre)
    corners = vertices[face] / (vertices[face] @ centre)[:, None]  # gnomonic projection
    return centre, corners


def _unadjust(points: np.ndarray, centre: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """Move points of the planar face (equal-area plane) to their gnomonic positions."""
    moved = np.empty_like(points)
    midpoints = 0.5 * (corners[[0, 1, 2]] + corners[[1, 2, 0]])  # edges 01, 12, 20
    rel = points - centre
    # the sixth of a point: nearest edge midpoint, then the nearer corner of that edge
    edge_of = np.argmin(np.linalg.norm(points[:, None] - midpoints[None], axis=2), axis=1)
    h = np.linalg.norm(midpoints[0] - centre)
    for e in range(3):
        towards_m = (midpoints[e] - centre) / h
        for corner in (corners[e], corners[(e + 1) % 3]):
            perp = corner - midpoints[e]
            perp /= np.linalg.norm(perp)
            mask = edge_of == e
            mask &= (rel @ perp) >= -1e-15
            v_eq = rel[mask] @ towards_m
            u_eq = np.maximum(rel[mask] @ perp, 0.0)
            with np.errstate(invalid="ignore", divide="ignore"):
                t_eq = np.where(v_eq > 0, u_eq / v_eq, 0.0)
            v, t = equal_area_to_gnomonic(v_eq, np.minimum(t_eq, math.sqrt(3.0)), h)
            moved[mask] = centre + v[:, None] * towards_m + (t * v)[:, None] * perp
    return moved


def icosahedral_grid(resolution: int, radius: float = 1.0) -> np.ndarray:
    """Tegmark's icosahedron pixel centres on the sphere of radius R: N = 40 n (n-1) + 12 points
    (n = ``resolution`` >= 1); see the module docstring."""
    if not (isinstance(resolution, (int, np.integer)) and resolution >= 1):
        raise ValueError(f"icosahedral resolution must be an integer >= 1, got {resolution!r}")
    check_radius(radius)
    vertices, faces = icosahedron()
    subdivisions = 2 * resolution - 1
    grid = np.array([(i, j, subdivisions - i - j) for i in range(subdivisions + 1)
                     for j in range(subdivisions + 1 - i)])
    # All faces are congruent: move the grid once on face 0 and keep the moved points as
    # barycentric weights of the face corners (P = w @ corners), valid on every face.
    centre, corners = _face_frame(vertices, faces[0])
    moved = _unadjust((grid / subdivisions) @ corners, centre, corners)
    weights = moved @ np.linalg.inv(corners)
    edge_owner: dict[tuple[int, int], int] = {}
    vertex_owner: dict[int, int] = {}
    for f, face in enumerate(faces):
        for p, q in ((0, 1), (1, 2), (2, 0)):
            edge_owner.setdefault(tuple(sorted((face[p], face[q]))), f)
        for p in face:
            vertex_owner.setdefault(int(p), f)
    points = []
    for f, face in enumerate(faces):
        keep = np.ones(len(grid), dtype=bool)
        for g, bary in enumerate(grid):
            zero = np.flatnonzero(bary == 0)
            if zero.size == 1:  # on the edge opposite the zero weight: one face owns it
                others = tuple(sorted(int(face[k]) for k in range(3) if k != zero[0]))
                keep[g] = edge_owner[others] == f
            elif zero.size == 2:  # a corner: one face owns it
                keep[g] = vertex_owner[int(face[np.flatnonzero(bary)[0]])] == f
        gnomonic = weights[keep] @ _face_frame(vertices, face)[1]
        points.append(gnomonic / np.linalg.norm(gnomonic, axis=1)[:, None])
    points = np.concatenate(points)
    expected = 40 * resolution * (resolution - 1) + 12
    if points.shape[0] != expected:  # pragma: no cover - construction invariant
        raise AssertionError(f"icosahedral grid has {points.shape[0]} points, expected {expected}")
    return radius * points


# --------------------------------------------------------------------------- other patterns


def fibonacci_grid(n_points: int, radius: float = 1.0) -> np.ndarray:
    """Swinbank-Purser Fibonacci grid of N points on the sphere of radius R."""
    if not (isinstance(n_points, (int, np.integer)) and n_points >= 1):
        raise ValueError(f"number of Fibonacci points must be an integer >= 1, got {n_points!r}")
    check_radius(radius)
    i = np.arange(n_points)
    z = (2.0 * i + 1.0 - n_points) / n_points
    longitude = 2.0 * np.pi * np.mod(i / GOLDEN_RATIO, 1.0)
    rho = np.sqrt(1.0 - z * z)
    return radius * np.column_stack([rho * np.cos(longitude), rho * np.sin(longitude), z])


def uniform_points(n_points: int, radius: float, rng: np.random.Generator) -> np.ndarray:
    """N independent points uniform on the sphere of radius R (canonical ensemble).

    Parameters
    ----------
    n_points : int
        Number of points N (>= 0).
    radius : float
        Sphere radius R.
    rng : numpy.random.Generator
        Source of the Gaussian vectors.

    Returns
    -------
    ndarray, shape (n_points, 3)
        Points on the sphere, in the unit of ``radius``.
    """
    if not (isinstance(n_points, (int, np.integer)) and n_points >= 0):
        raise ValueError(f"number of points must be an integer >= 0, got {n_points!r}")
    check_radius(radius)
    g = rng.standard_normal((n_points, 3))
    return radius * g / np.linalg.norm(g, axis=1)[:, None]


def spherical_rectangles(n_theta: int, n_phi: int) -> np.ndarray:
    """Rectangles (theta1, theta2, phi1, phi2) with equal steps in theta and phi (Appendix 2)."""
    if n_theta < 1 or n_phi < 1:
        raise ValueError(f"need n_theta, n_phi >= 1, got {n_theta}, {n_phi}")
    theta = np.linspace(0.0, np.pi, n_theta + 1)
    phi = np.linspace(0.0, 2.0 * np.pi, n_phi + 1)
    return np.array([(theta[i], theta[i + 1], phi[j], phi[j + 1])
                     for i in range(n_theta) for j in range(n_phi)])


def poisson_points(mean_points: float, radius: float, rng: np.random.Generator, *,
                   n_theta: int = 8, n_phi: int = 16) -> np.ndarray:
    """A Poisson point process on the sphere of radius R with mean <N> = ``mean_points``,
    generated rectangle by rectangle as in the paper's Appendix (module docstring).

    Parameters
    ----------
    mean_points : float
        Mean number of points <N> (> 0).
    radius : float
        Sphere radius R.
    rng : numpy.random.Generator
        Source of the counts and positions.
    n_theta, n_phi : int, optional
        Rectangles in theta and in phi (equal steps; defaults 8 and 16).

    Returns
    -------
    ndarray, shape (N, 3)
        Points on the sphere (unit of ``radius``), N Poisson with mean ``mean_points``;
        grouped by rectangle.
    """
    if not (mean_points > 0 and math.isfinite(mean_points)):
        raise ValueError(f"mean number of Poisson points must be > 0, got {mean_points!r}")
    check_radius(radius)
    rectangles = spherical_rectangles(n_theta, n_phi)
    cos1, cos2 = np.cos(rectangles[:, 0]), np.cos(rectangles[:, 1])
    fraction = (cos1 - cos2) * (rectangles[:, 3] - rectangles[:, 2]) / (4.0 * np.pi)
    counts = rng.poisson(mean_points * fraction)
    owner = np.repeat(np.arange(rectangles.shape[0]), counts)
    z = cos2[owner] + (cos1[owner] - cos2[owner]) * rng.random(owner.size)
    phi = rectangles[owner, 2] + (rectangles[owner, 3] - rectangles[owner, 2]) * rng.random(owner.size)
    rho = np.sqrt(np.clip(1.0 - z * z, 0.0, None))
    return radius * np.column_stack([rho * np.cos(phi), rho * np.sin(phi), z])
