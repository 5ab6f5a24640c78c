"""Overlapping d-balls (the Boolean model, d = 2 and 3) on a periodic grid, digitized.

The model (Ma & Torquato 2020, Sec. VI A for d = 2; Klatt & Torquato 2016,
Sec. III A for d = 3; Torquato, *Random Heterogeneous Materials*, Ch. 3):
centres form a Poisson point process of intensity rho; the balls (radius R)
are phase 2, the rest is the void phase 1 with phi1 = exp(-rho v1(R)),
v1 = omega_d R^d (Eq. 8), i.e. rho = -ln(1 - phi2) / v1
(:func:`randmedia.theory.balls.poisson_intensity`).

Digitization: voxel (layer k, row i, column j) of an image of shape
(nz, ny, nx) covers [j, j+1) x [i, i+1) x [k, k+1) and is phase 2 when its
*centre* (j + 1/2, i + 1/2, k + 1/2) lies in at least one ball (periodic
images included). The image is the continuum indicator sampled on the
lattice, so its periodic autocorrelation at a lattice displacement v is an
unbiased estimate of S2(|v|) of the periodic model (Eqs. 32-33 in d = 2,
:func:`randmedia.theory.overlapping.s2_void` with ``dim=3``) for
|v| <= L - 2R.

One kernel for both dimensions: a 2D image is painted as one layer (nz = 1)
through the plane of the centres (dz = 0), which is exactly the 2D rule.
:mod:`randmedia.generate.disks` gives the 2D case the names the debye2020 rules use.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.numerics.checks import check_dim, check_positive
from randmedia.theory.balls import poisson_intensity


def overlapping_ball_centers(rng: np.random.Generator, side: float, radius: float, phi2: float,
                             dim: int) -> np.ndarray:
    """Poisson centres in the periodic cube [0, side)^d, shape (n, d) as (x, y[, z]); the
    number is Poisson with mean rho side^d (not fixed).

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the Poisson count and the uniform positions.
    side : float
        Side L of the periodic cube (> 0), in pixels.
    radius : float
        Ball radius R, in pixels.
    phi2 : float
        Expected ball-phase fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    ndarray, shape (n, d)
        Centres (x, y[, z]) in [0, side), in pixels; n is Poisson distributed.
    """
    check_positive(side, "side")
    mean = poisson_intensity(phi2, radius, dim)
    for _ in range(dim):  # rho * side * side (* side)
        mean = mean * side
    count = rng.poisson(mean)
    return rng.uniform(0.0, side, size=(count, dim))


@njit(cache=True)
def _paint_balls(centers, radius, out, planar):
    """Set out[k, i, j] = 1 where the voxel centre lies within ``radius`` of a centre
    (periodic). ``centers`` is (n, 3) as (x, y, z); ``planar``: one layer through the
    centres' plane (d = 2: dz = 0 and the z loop has the single layer 0)."""
    nz, ny, nx = out.shape
    r2 = radius * radius
    for m in range(centers.shape[0]):
        cx = centers[m, 0]
        cy = centers[m, 1]
        cz = centers[m, 2]
        if planar:
            k_lo = 0
            k_hi = 0
        else:
            k_lo = int(math.floor(cz - 0.5 - radius))
            k_hi = int(math.ceil(cz - 0.5 + radius))
        i_lo = int(math.floor(cy - 0.5 - radius))
        i_hi = int(math.ceil(cy - 0.5 + radius))
        j_lo = int(math.floor(cx - 0.5 - radius))
        j_hi = int(math.ceil(cx - 0.5 + radius))
        for k in range(k_lo, k_hi + 1):
            dz2 = 0.0
            if not planar:
                dz = k + 0.5 - cz
                dz2 = dz * dz
                if dz2 > r2:
                    continue
            layer = k % nz
            for i in range(i_lo, i_hi + 1):
                dy = i + 0.5 - cy
                dyz2 = dy * dy + dz2  # + 0.0 in 2D: exactly dy * dy
                if dyz2 > r2:
                    continue
                row = i % ny
                for j in range(j_lo, j_hi + 1):
                    dx = j + 0.5 - cx
                    if dx * dx + dyz2 <= r2:
                        out[layer, row, j % nx] = 1


def digitize_balls(centers: np.ndarray, radius: float, shape: tuple[int, ...]) -> np.ndarray:
    """uint8 image of ``shape`` ((ny, nx) or (nz, ny, nx)): 1 where a voxel centre lies in a
    ball about one of ``centers`` ((n, d) as (x, y[, z]), periodic).

    Parameters
    ----------
    centers : array_like, shape (n, d)
        Ball centres (x, y[, z]) in pixel units; periodic images are painted.
    radius : float
        Ball radius (> 0), in pixels.
    shape : tuple of int
        Image shape (ny, nx) for d = 2 or (nz, ny, nx) for d = 3; d = len(shape).

    Returns
    -------
    ndarray of uint8, shape ``shape``
        1 = ball phase 2, 0 = void phase 1.
    """
    shape = tuple(int(n) for n in shape)
    dim = len(shape)
    check_dim(dim)
    check_positive(radius, "radius")
    centers = np.asarray(centers, dtype=np.float64).reshape(-1, dim)
    padded = np.zeros((centers.shape[0], 3))
    padded[:, :dim] = centers
    out = np.zeros((1,) * (3 - dim) + shape, dtype=np.uint8)
    _paint_balls(padded, float(radius), out, dim == 2)
    return out.reshape(shape)


def overlapping_balls_image(rng: np.random.Generator, side: int, radius: float, phi2: float,
                            dim: int) -> np.ndarray:
    """One periodic side^d image of overlapping balls (1 = ball phase 2); axes (y, x) or
    (z, y, x).

    Parameters
    ----------
    rng : numpy.random.Generator
        Random stream of :func:`overlapping_ball_centers`.
    side : int
        Image side L in pixels (also the periodic cube side).
    radius : float
        Ball radius R, in pixels.
    phi2 : float
        Expected ball-phase fraction, in (0, 1).
    dim : int
        Dimension d, 2 or 3.

    Returns
    -------
    ndarray of uint8, shape (side,) * dim
        1 = ball phase 2, 0 = void phase 1.
    """
    centers = overlapping_ball_centers(rng, side, radius, phi2, dim)
    return digitize_balls(centers, radius, (side,) * dim)
