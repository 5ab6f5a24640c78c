"""Poisson-plane (d = 3) and Poisson-line (d = 2) tessellations with independently coloured
cells: a second microstructure with *exactly* the Debye two-point function.

Model. An isotropic, stationary Poisson process of hyperplanes cuts R^d into
convex cells; every cell independently is phase 2 with probability phi2.

Derivation of S2 (Ma & Torquato 2020, Eq. 21, in any d). Parametrize a
hyperplane by its unit normal u and signed offset t, {x : u.(x - c) = t}. The
planes that hit the ball B(c, R) are a Poisson number with mean M, each with u
uniform on the unit sphere S^(d-1) and t uniform on [-R, R] (the restriction
of the isotropic stationary process to the ball). A segment of length r in
direction e inside the ball is crossed by the plane (u, t) iff t lies between
u.(x0 - c) and u.(x0 - c) + r u.e, which has probability r |u.e| / (2R); with
kappa_d = E|u.e| = Gamma(d/2) / (sqrt(pi) Gamma((d+1)/2)) (2/pi for d = 2,
1/2 for d = 3), the crossings of the segment are a thinned Poisson process:
Poisson with mean

    lambda_L r,    lambda_L = M kappa_d / (2R)   (crossings per unit length).

Cells are intersections of half-spaces, so two points lie in the same cell
iff no plane separates them, i.e. iff no plane crosses the segment between
them:  P(same cell) = exp(-lambda_L r). Two points in one cell share its
colour; in different cells their colours are independent. Hence

    S2(r) = P(same) phi2 + [1 - P(same)] phi2^2 = phi2^2 + phi1 phi2 exp(-lambda_L r),

which is Eq. (21) with a = 1 / lambda_L: M = 2R / (a kappa_d). The plane
area per volume is S_V = lambda_L / kappa_d (Cauchy-Crofton; 3D: P_L = S_V/2),
and a plane piece is an interface iff the two cells it separates differ in
colour (probability 2 phi1 phi2), so the specific surface is
s = 2 phi1 phi2 / (a kappa_d): 4 phi1 phi2 / a in 3D and pi phi1 phi2 / a in
2D (Eq. 22), both equal to -S2'(0) d omega_d / omega_(d-1) (Eq. 7). These exact
formulas (kappa_d, S_V, s) live in :mod:`randmedia.theory.plane_process` (the generator takes
kappa_d from there), the tessellation's exact descriptors in
:mod:`randmedia.theory.poisson_planes`.

Digitization. Voxel (k, i, j) of an image of shape (nz, ny, nx) takes the
colour of the cell containing its centre (j + 1/2, i + 1/2, k + 1/2); the image
is the continuum indicator sampled on a lattice, so every voxel pair at
lattice displacement v has exactly P(both phase 2) = S2(|v|).

Periodicity: none. A Poisson plane process is not periodic (a plane with an
irrational normal is dense on the torus; planes with integer normals make
parallel sheets that do not separate the torus, so cells must be the arcs
between the sheets of a direction, which adds the wrap-around term
exp(-mu (1 - f)), and a finite set of directions is anisotropic: with the 13
directions |n| <= sqrt 3 at L = 128, a = 4, P(same cell) / exp(-r/a) is 1.25-1.46
at r = 4a; see docs/debye3d.md). The image is the
exact restriction of the stationary process to the window [0, L)^d: the
planes hitting the ball that circumscribes the window, about its centre.
Consequence for periodic estimators: pairs that wrap around the window are
~independent (their true distance is > L/2 along a wrapped axis), so the periodic
autocorrelation of such an image is *not* Debye; its exact expectation is
:func:`randmedia.describe.window.periodic_estimator_expectation`, and
:func:`randmedia.describe.window.window_s2_samples` is the unbiased
(minus-sampling) estimator for windows. Descriptors that assume periodicity
(level-set filters, distance transforms, chords) must stay a margin away from
the window faces.

Cell labels. Each plane gets a random 64-bit key; a voxel's label is the XOR of
the keys of the planes it lies above (u.(x - c) > t), a 64-bit hash of its cell's
sign vector. Labels are then made consecutive (in order of first appearance) and each label gets
an independent colour, so the colours of distinct cells are exactly independent
unless two of the window's cells share a hash (probability <= n_cells^2 / 2^65,
< 10^-7 for 10^6 cells).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from randmedia.numerics.checks import check_fraction, check_positive
from randmedia.theory.plane_process import crossing_fraction


@dataclass(frozen=True)
class Planes:
    """Hyperplanes {x : normal.(x - centre) = offset} hitting the ball B(centre, radius)."""

    normal: np.ndarray  # (m, d) unit normals, (x, y[, z]) components
    offset: np.ndarray  # (m,)
    centre: np.ndarray  # (d,)
    radius: float


def poisson_planes(rng: np.random.Generator, shape: tuple[int, ...], a: float) -> Planes:
    """The isotropic Poisson hyperplanes (lambda_L = 1/a) that hit the window
    [0, nx) x [0, ny) (x [0, nz)) of an image of ``shape`` (axes (y, x) or (z, y, x)):
    a Poisson number with mean M = 2R / (a kappa_d) of planes hitting the circumscribed
    ball (radius R) about the window's centre, normals uniform on S^(d-1), offsets
    uniform on [-R, R].

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the count, normals and offsets.
    shape : tuple of int
        Image shape (ny, nx) or (nz, ny, nx), in pixels; d = len(shape).
    a : float
        Correlation length a (> 0), in pixels.

    Returns
    -------
    Planes
        Normals (m, d) in (x, y[, z]) order, offsets (m,), the window centre (d,) and the
        circumscribed radius R, in pixels.
    """
    shape = tuple(int(n) for n in shape)
    dim = len(shape)
    check_positive(a, "a")
    kappa = crossing_fraction(dim)
    if min(shape) < 1:
        raise ValueError(f"image shape must be positive, got {shape}")
    sides = np.array(shape[::-1], dtype=float)  # (nx, ny[, nz])
    centre = sides / 2.0
    radius = float(np.linalg.norm(centre))
    count = int(rng.poisson(2.0 * radius / (a * kappa)))
    normal = rng.standard_normal((count, dim))
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    offset = rng.uniform(-radius, radius, size=count)
    return Planes(normal, offset, centre, radius)


@njit(cache=True)
def _cell_hash(normal, offset, keys, centre, out):
    """out[k, i, j] = XOR of keys[m] over the planes m with f_m(j, i, k) > 0, where
    f_m = normal.(x - centre) - offset at the voxel centre x = (j + 1/2, i + 1/2, k + 1/2);
    normal and centre are 3-vectors (a 2D image is one layer with normal_z = 0).

    Along an image row f_m is linear in j, so plane m covers one interval of the row
    ([j0, nx) or [0, j1)): the row costs O(planes + nx) with an XOR difference array
    instead of O(planes nx). The interval ends are located from -c/n_x and then
    corrected with f_m itself, so the side of a voxel is the sign of f_m as evaluated."""
    nz, ny, nx = out.shape
    m_planes = offset.shape[0]
    base = np.empty(m_planes)  # f_m at voxel (0, 0, 0)
    for m in range(m_planes):
        base[m] = (normal[m, 0] * (0.5 - centre[0]) + normal[m, 1] * (0.5 - centre[1])
                   + normal[m, 2] * (0.5 - centre[2])) - offset[m]
    toggle = np.zeros(nx + 1, dtype=np.uint64)
    for k in range(nz):
        for i in range(ny):
            toggle[:] = 0
            for m in range(m_planes):
                c = base[m] + normal[m, 1] * i + normal[m, 2] * k
                slope = normal[m, 0]
                if slope == 0.0:
                    if c > 0.0:
                        toggle[0] ^= keys[m]
                        toggle[nx] ^= keys[m]
                    continue
                # first j with f > 0 (slope > 0) or first j with f <= 0 (slope < 0)
                root = -c / slope
                if root < -1.0:
                    j = 0
                elif root > nx + 1.0:
                    j = nx
                else:
                    j = min(max(int(math.floor(root)) + 1, 0), nx)
                if slope > 0.0:
                    while j > 0 and c + slope * (j - 1) > 0.0:
                        j -= 1
                    while j < nx and not c + slope * j > 0.0:
                        j += 1
                    lo, hi = j, nx  # f > 0 on [j, nx)
                else:
                    while j > 0 and not c + slope * (j - 1) > 0.0:
                        j -= 1
                    while j < nx and c + slope * j > 0.0:
                        j += 1
                    lo, hi = 0, j  # f > 0 on [0, j)
                if lo < hi:
                    toggle[lo] ^= keys[m]
                    toggle[hi] ^= keys[m]
            h = np.uint64(0)
            for j in range(nx):
                h ^= toggle[j]
                out[k, i, j] = h


@njit(cache=True)
def _first_appearance_labels(hashes, labels):
    """labels[x] = index of hashes[x] among the distinct values in order of first appearance
    (open-addressing hash table on the uint64 values, whose low bits are uniformly random;
    doubled when half full). Returns the number of distinct values."""
    size = 1 << 12
    table_key = np.zeros(size, dtype=np.uint64)
    table_label = np.full(size, -1, dtype=np.int64)
    count = 0
    previous = np.uint64(0)
    previous_label = -1
    for x in range(hashes.size):
        h = hashes[x]
        if previous_label >= 0 and h == previous:  # runs along a row share one cell
            labels[x] = previous_label
            continue
        mask = np.uint64(size - 1)
        slot = h & mask
        while table_label[slot] >= 0 and table_key[slot] != h:
            slot = (slot + np.uint64(1)) & mask
        if table_label[slot] < 0:
            table_key[slot] = h
            table_label[slot] = count
            count += 1
        label = table_label[slot]
        if 2 * count > size:  # grow: reinsert every entry into a table twice as large
            size *= 2
            mask = np.uint64(size - 1)
            new_key = np.zeros(size, dtype=np.uint64)
            new_label = np.full(size, -1, dtype=np.int64)
            for old in range(table_label.size):
                if table_label[old] >= 0:
                    s = table_key[old] & mask
                    while new_label[s] >= 0:
                        s = (s + np.uint64(1)) & mask
                    new_key[s] = table_key[old]
                    new_label[s] = table_label[old]
            table_key = new_key
            table_label = new_label
        labels[x] = label
        previous = h
        previous_label = label
    return count


def cell_labels(planes: Planes, shape: tuple[int, ...], rng: np.random.Generator) -> np.ndarray:
    """Cell index (0 .. n_cells - 1, int64, in order of first appearance in the raveled
    image) of every voxel centre of an image of ``shape``.

    Parameters
    ----------
    planes : Planes
        Hyperplanes of :func:`poisson_planes` for the same ``shape``.
    shape : tuple of int
        Image shape (ny, nx) or (nz, ny, nx).
    rng : numpy.random.Generator
        Source of the 64-bit plane keys (module docstring).

    Returns
    -------
    ndarray of int64, shape ``shape``
        Cell label of every voxel.
    """
    shape = tuple(int(n) for n in shape)
    dim = len(shape)
    if planes.normal.shape[1] != dim:
        raise ValueError(f"planes are {planes.normal.shape[1]}-dimensional, image shape {shape}")
    normal = np.zeros((planes.normal.shape[0], 3))
    normal[:, :dim] = planes.normal
    centre = np.full(3, 0.5)
    centre[:dim] = planes.centre
    keys = rng.integers(0, np.iinfo(np.uint64).max, size=planes.offset.size, dtype=np.uint64,
                        endpoint=True)
    hashes = np.empty((1,) * (3 - dim) + shape, dtype=np.uint64)
    _cell_hash(normal, np.ascontiguousarray(planes.offset, dtype=np.float64), keys, centre, hashes)
    labels = np.empty(hashes.size, dtype=np.int64)
    _first_appearance_labels(hashes.reshape(-1), labels)
    return labels.reshape(shape)


def poisson_plane_image(rng: np.random.Generator, shape: tuple[int, ...], a: float,
                        phi2: float) -> np.ndarray:
    """uint8 image (1 = phase 2) of a Poisson-plane (3D) / Poisson-line (2D) tessellation with
    independently coloured cells in the window of ``shape``: S2 = phi2^2 + phi1 phi2 e^(-r/a)
    exactly for every voxel pair (non-periodic; see the module docstring).

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the planes, the keys and the cell colours.
    shape : tuple of int
        Image shape (ny, nx) or (nz, ny, nx), in pixels.
    a : float
        Correlation length a of the Debye S2 (> 0), in pixels.
    phi2 : float
        Probability that a cell is phase 2, in (0, 1).

    Returns
    -------
    ndarray of uint8, shape ``shape``
        1 = phase 2, 0 = phase 1.
    """
    check_fraction(phi2)
    check_positive(a, "a")
    planes = poisson_planes(rng, shape, a)
    labels = cell_labels(planes, shape, rng)
    colour = (rng.random(int(labels.max()) + 1) < phi2).astype(np.uint8)
    return colour[labels]
