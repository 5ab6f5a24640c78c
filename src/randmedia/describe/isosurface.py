"""The interface of a 3D level-set medium as triangles (marching tetrahedra), its area density
and its Euler characteristic.

The 3D counterpart of the marching squares of :mod:`randmedia.describe.surface`
(Ma & Torquato 2020, Eqs. 9-11 and 15 need the interface indicator M = |grad I|, whose
mean is the specific surface s; in 3D the specific surface of a Debye medium is
s = 4 phi1 phi2 / a, the value behind the conjectures Eqs. 44-45).

Grid: the sub-voxel grid of a :class:`randmedia.describe.chords.LevelSet` built from a 3D
image, ``fine`` of shape (nz m, ny m, nx m), node (k, i, j) at the sub-voxel centre
((j + 1/2) h, (i + 1/2) h, (k + 1/2) h) in voxels, h = 1/m, periodic. The medium is the
region fine > threshold.

Marching tetrahedra: every cube of 8 neighbouring nodes is split into the 6 tetrahedra
{c0, c0 + e_a, c0 + e_a + e_b, c0 + e_x + e_y + e_z} around its main diagonal (one per
order (a, b, c) of the axes; the Kuhn / Freudenthal triangulation). Each face of a cube
is then cut along its diagonal from the face's lowest corner to its highest, in both cubes
that share it, so the tetrahedra of neighbouring cubes match and the surface is closed
with no ambiguous case. On every tetrahedron edge whose ends lie on both sides of the
threshold the crossing is placed by linear interpolation; a tetrahedron with one (or
three) nodes inside gives one triangle, with two inside a quadrilateral split into two
triangles. The result is *exactly* the level set of the piecewise-linear interpolant of
``fine`` on the tetrahedra (``LevelSet.value_at`` is trilinear, which differs from it
inside a cube by O(h^2 |curvature of the field|)).

Euler characteristic: every surface edge lies in one face shared by two tetrahedra (or is
the diagonal of a split quadrilateral), so the triangle mesh is a closed combinatorial
surface: E = 3F/2 and chi(surface) = V - F/2, V the crossed tetrahedron edges (every node
has 7 edges going up: 3 axes, 3 face diagonals, the main diagonal). The region is a
compact 3-manifold with boundary, so chi(region) = chi(surface)/2, on the 3-torus as in
R^3 -- and the complement has the same chi (chi(T^3) = 0). Equivalently (Gauss-Bonnet)
chi(region) = (1/4 pi) x the integrated Gaussian curvature of the interface: local and
additive, whatever wraps around the torus.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: the 6 tetrahedra of a cube: corners as (dx, dy, dz) bit masks c = dx + 2 dy + 4 dz;
#: each is (0, e_a, e_a + e_b, 7) for one order (a, b, c) of the axes
_AXIS_BIT = (1, 2, 4)
TETRAHEDRA = np.array([(0, _AXIS_BIT[a], _AXIS_BIT[a] | _AXIS_BIT[b], 7)
                       for a in range(3) for b in range(3) if a != b], dtype=np.int64)
#: the 7 tetrahedron edges leaving a node towards higher coordinates, (dx, dy, dz)
UP_EDGES = np.array([(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1), (0, 1, 1),
                     (1, 1, 1)], dtype=np.int64)


@njit(cache=True)
def _crossing(va, vb, pa, pb, out, row):
    """The point of the edge a-b where the linear interpolant vanishes (va > 0 >= vb or the
    reverse), written to out[row]."""
    t = va / (va - vb)
    for c in range(3):
        out[row, c] = pa[c] + t * (pb[c] - pa[c])


@njit(cache=True)
def _march_tetrahedra(values, spacing, tetrahedra, out, fill):
    """Marching tetrahedra on a periodic grid of (value - threshold), axes (z, y, x); returns
    the triangle count. With ``fill`` the triangles are written to ``out`` (n, 3, 3): three
    vertices (x, y, z) in voxels."""
    nz, ny, nx = values.shape
    count = 0
    v = np.empty(8)
    p = np.empty((8, 3))
    q = np.empty((4, 3))  # crossings of the current tetrahedron
    for k in range(nz):
        k1 = (k + 1) % nz
        z0 = (k + 0.5) * spacing
        for i in range(ny):
            i1 = (i + 1) % ny
            y0 = (i + 0.5) * spacing
            for j in range(nx):
                j1 = (j + 1) % nx
                v[0] = values[k, i, j]
                v[1] = values[k, i, j1]
                v[2] = values[k, i1, j]
                v[3] = values[k, i1, j1]
                v[4] = values[k1, i, j]
                v[5] = values[k1, i, j1]
                v[6] = values[k1, i1, j]
                v[7] = values[k1, i1, j1]
                n_in = 0
                for c in range(8):
                    if v[c] > 0:
                        n_in += 1
                if n_in == 0 or n_in == 8:
                    continue
                x0 = (j + 0.5) * spacing
                for c in range(8):
                    p[c, 0] = x0 + (c & 1) * spacing
                    p[c, 1] = y0 + ((c >> 1) & 1) * spacing
                    p[c, 2] = z0 + ((c >> 2) & 1) * spacing
                for t in range(tetrahedra.shape[0]):
                    inside = 0
                    for a in range(4):
                        if v[tetrahedra[t, a]] > 0:
                            inside += 1
                    if inside == 0 or inside == 4:
                        continue
                    if inside == 2:
                        # quadrilateral: inside nodes a, b; outside c, d; crossings on
                        # a-c, a-d, b-d, b-c in cyclic order, split along (a-c, b-d)
                        if fill:
                            na = -1
                            nb = -1
                            nc = -1
                            nd = -1
                            for a in range(4):
                                corner = tetrahedra[t, a]
                                if v[corner] > 0:
                                    if na < 0:
                                        na = corner
                                    else:
                                        nb = corner
                                else:
                                    if nc < 0:
                                        nc = corner
                                    else:
                                        nd = corner
                            _crossing(v[na], v[nc], p[na], p[nc], q, 0)
                            _crossing(v[na], v[nd], p[na], p[nd], q, 1)
                            _crossing(v[nb], v[nd], p[nb], p[nd], q, 2)
                            _crossing(v[nb], v[nc], p[nb], p[nc], q, 3)
                            for c in range(3):
                                out[count, 0, c] = q[0, c]
                                out[count, 1, c] = q[1, c]
                                out[count, 2, c] = q[2, c]
                                out[count + 1, 0, c] = q[0, c]
                                out[count + 1, 1, c] = q[2, c]
                                out[count + 1, 2, c] = q[3, c]
                        count += 2
                    else:
                        # one node on its own side: crossings on its three edges
                        if fill:
                            lone = -1
                            for a in range(4):
                                corner = tetrahedra[t, a]
                                if (v[corner] > 0) == (inside == 1):
                                    lone = corner
                            row = 0
                            for a in range(4):
                                corner = tetrahedra[t, a]
                                if corner != lone:
                                    _crossing(v[lone], v[corner], p[lone], p[corner], q, row)
                                    row += 1
                            for r in range(3):
                                for c in range(3):
                                    out[count, r, c] = q[r, c]
                        count += 1
    return count


def interface_triangles(level_set) -> np.ndarray:
    """The interface of a 3D level set as triangles (marching tetrahedra, module docstring).

    Parameters
    ----------
    level_set : LevelSet
        A level set of a 3D image (``fine`` of shape (nz m, ny m, nx m)).

    Returns
    -------
    ndarray, shape (n, 3, 3)
        Triangle vertices (x, y, z) in voxels; coordinates may exceed the image by one
        sub-voxel where a cube wraps around the periodic boundary.
    """
    fine = np.asarray(level_set.fine)
    if fine.ndim != 3:
        raise ValueError(f"expected a 3D level set, got fine of shape {fine.shape}")
    return triangles_of_field(fine - level_set.threshold, level_set.spacing)


def triangles_of_field(values: np.ndarray, spacing: float) -> np.ndarray:
    """Marching tetrahedra on a periodic 3D grid of values; the surface is where they pass 0
    (region: values > 0). Node (k, i, j) sits at ((j + 1/2), (i + 1/2), (k + 1/2)) x spacing.

    Parameters
    ----------
    values : ndarray, shape (nz, ny, nx)
        Field minus threshold on the periodic grid.
    spacing : float
        Grid spacing (voxels).

    Returns
    -------
    ndarray, shape (n, 3, 3)
        Triangles, vertices (x, y, z).
    """
    values = np.ascontiguousarray(values, dtype=np.float64)
    dummy = np.empty((0, 3, 3))
    count = _march_tetrahedra(values, float(spacing), TETRAHEDRA, dummy, False)
    out = np.empty((count, 3, 3))
    _march_tetrahedra(values, float(spacing), TETRAHEDRA, out, True)
    return out


def triangle_areas(triangles: np.ndarray) -> np.ndarray:
    """Areas of triangles (n, 3, 3) (voxel^2)."""
    triangles = np.asarray(triangles, dtype=np.float64)
    cross = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    return 0.5 * np.sqrt(np.einsum("ij,ij->i", cross, cross))


@njit(cache=True)
def trilinear_stencil(fx, fy, fz, nz, ny, nx):
    """The eight periodic grid nodes around the point (fx, fy, fz) in node units (node
    (k, i, j) at (j, i, k)) and its fractions past the lower ones:
    (k0, k1, i0, i1, j0, j1, tx, ty, tz); the 3D analogue of ``chords.bilinear_stencil``."""
    j0 = int(math.floor(fx))
    i0 = int(math.floor(fy))
    k0 = int(math.floor(fz))
    tx = fx - j0
    ty = fy - i0
    tz = fz - k0
    return (k0 % nz, (k0 + 1) % nz, i0 % ny, (i0 + 1) % ny, j0 % nx, (j0 + 1) % nx, tx, ty, tz)


@njit(cache=True)
def _deposit_point(grid, x, y, z, weight, spacing):
    nz, ny, nx = grid.shape
    k0, k1, i0, i1, j0, j1, tx, ty, tz = trilinear_stencil(x / spacing - 0.5, y / spacing - 0.5,
                                                           z / spacing - 0.5, nz, ny, nx)
    w0 = weight * (1 - tz)
    w1 = weight * tz
    grid[k0, i0, j0] += w0 * (1 - ty) * (1 - tx)
    grid[k0, i0, j1] += w0 * (1 - ty) * tx
    grid[k0, i1, j0] += w0 * ty * (1 - tx)
    grid[k0, i1, j1] += w0 * ty * tx
    grid[k1, i0, j0] += w1 * (1 - ty) * (1 - tx)
    grid[k1, i0, j1] += w1 * (1 - ty) * tx
    grid[k1, i1, j0] += w1 * ty * (1 - tx)
    grid[k1, i1, j1] += w1 * ty * tx


@njit(cache=True)
def _deposit_triangles(triangles, spacing, grid):
    """Add each triangle's area to ``grid`` (periodic, node (k, i, j) at the sub-voxel centre):
    the triangle is cut into n^2 congruent triangles (each edge in n pieces, n the smallest
    integer with longest edge / n <= spacing / 2), each deposited at its centroid with
    trilinear (cloud-in-cell) weights."""
    half = 0.5 * spacing
    for t in range(triangles.shape[0]):
        ax = triangles[t, 0, 0]
        ay = triangles[t, 0, 1]
        az = triangles[t, 0, 2]
        ux = triangles[t, 1, 0] - ax
        uy = triangles[t, 1, 1] - ay
        uz = triangles[t, 1, 2] - az
        wx = triangles[t, 2, 0] - ax
        wy = triangles[t, 2, 1] - ay
        wz = triangles[t, 2, 2] - az
        cx = uy * wz - uz * wy
        cy = uz * wx - ux * wz
        cz = ux * wy - uy * wx
        area = 0.5 * math.sqrt(cx * cx + cy * cy + cz * cz)
        if area == 0.0:
            continue
        longest = max(math.sqrt(ux * ux + uy * uy + uz * uz),
                      math.sqrt(wx * wx + wy * wy + wz * wz),
                      math.sqrt((wx - ux) ** 2 + (wy - uy) ** 2 + (wz - uz) ** 2))
        n = max(1, int(math.ceil(longest / half)))
        weight = area / (n * n)
        for a in range(n):
            for b in range(n - a):
                # upward piece with corners (a, b), (a + 1, b), (a, b + 1)
                sa = (a + 1.0 / 3.0) / n
                sb = (b + 1.0 / 3.0) / n
                _deposit_point(grid, ax + sa * ux + sb * wx, ay + sa * uy + sb * wy,
                               az + sa * uz + sb * wz, weight, spacing)
                if a + b <= n - 2:  # downward piece (a + 1, b), (a, b + 1), (a + 1, b + 1)
                    sa = (a + 2.0 / 3.0) / n
                    sb = (b + 2.0 / 3.0) / n
                    _deposit_point(grid, ax + sa * ux + sb * wx, ay + sa * uy + sb * wy,
                                   az + sa * uz + sb * wz, weight, spacing)


def surface_density(triangles: np.ndarray, shape, spacing: float) -> np.ndarray:
    """M on the sub-voxel grid (1/voxel): deposited triangle area per sub-voxel volume. Its
    mean is exactly the total area per volume (the specific surface s, Ma & Torquato 2020,
    Eq. 10), up to rounding.

    Parameters
    ----------
    triangles : ndarray, shape (n, 3, 3)
        Interface triangles (x, y, z) in voxels (:func:`interface_triangles`).
    shape : tuple of int
        Shape (nz, ny, nx) of the sub-voxel grid.
    spacing : float
        Sub-voxel spacing (voxels).

    Returns
    -------
    ndarray, shape ``shape``
        M per sub-voxel (1/voxel).
    """
    grid = np.zeros(tuple(int(n) for n in shape))
    _deposit_triangles(np.ascontiguousarray(triangles, dtype=np.float64), float(spacing), grid)
    return grid / spacing**3


@njit(cache=True)
def _crossed_edges(values, edges):
    """Number of tetrahedron edges (7 per node, towards higher coordinates) with ends on both
    sides of 0 (> 0 against <= 0), periodic."""
    nz, ny, nx = values.shape
    count = 0
    for k in range(nz):
        for i in range(ny):
            for j in range(nx):
                here = values[k, i, j] > 0
                for e in range(edges.shape[0]):
                    there = values[(k + edges[e, 2]) % nz, (i + edges[e, 1]) % ny,
                                   (j + edges[e, 0]) % nx] > 0
                    if here != there:
                        count += 1
    return count


def euler_characteristic_3d(values: np.ndarray, n_triangles: int | None = None) -> int:
    """Euler characteristic of the region values > 0 of a periodic 3D grid, in the
    piecewise-linear reading of marching tetrahedra: chi = (V - F/2) / 2, V the crossed
    tetrahedron edges, F the triangles (module docstring). The region {values <= 0} has the
    same chi on the torus.

    Parameters
    ----------
    values : ndarray, shape (nz, ny, nx)
        Field minus threshold.
    n_triangles : int, optional
        Triangle count of :func:`triangles_of_field` on the same values, if known.

    Returns
    -------
    int
        Euler characteristic of the whole grid (a number, not per volume).
    """
    values = np.ascontiguousarray(values, dtype=np.float64)
    if n_triangles is None:
        n_triangles = _march_tetrahedra(values, 1.0, TETRAHEDRA, np.empty((0, 3, 3)), False)
    crossed = _crossed_edges(values, UP_EDGES)
    twice = 2 * crossed - n_triangles  # 2 chi(surface) = 2V - F, and chi = chi(surface) / 2
    if twice % 4:
        raise RuntimeError(f"inconsistent surface: 2V - F = {twice} is not a multiple of 4")
    return twice // 4
