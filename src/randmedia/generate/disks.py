"""Overlapping disks (2D Boolean model) on a periodic square, digitized to pixels.

The model (Ma & Torquato 2020, Sec. VI A; Torquato, *Random Heterogeneous
Materials*, Ch. 3): disk centres form a Poisson point process of intensity
rho; the disks (radius R) are phase 2, the rest is the void phase 1 with
volume fraction phi1 = exp(-rho * pi R^2), i.e. rho = -ln(1 - phi2) / (pi R^2).

Digitization: pixel (row i, column j) of an L x L image covers
[j, j+1) x [i, i+1) and is set to phase 2 when its *centre* (j + 1/2, i + 1/2)
lies in at least one disk (periodic images included). The image is therefore
the continuum indicator function sampled exactly on a lattice, and its
periodic autocorrelation at a lattice displacement v is an unbiased estimate
of the continuum S2(|v|) of the torus model -- no discretization error enters
the two-point function, only in quantities that need the interface.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


def poisson_intensity(phi2: float, radius: float) -> float:
    """Number density rho giving expected disk-phase fraction phi2 (2D)."""
    if not 0.0 < phi2 < 1.0:
        raise ValueError(f"phi2 must lie in (0, 1), got {phi2}")
    if radius <= 0:
        raise ValueError(f"radius must be > 0, got {radius}")
    return -math.log1p(-phi2) / (math.pi * radius * radius)


def overlapping_disk_centers(
    rng: np.random.Generator, side: float, radius: float, phi2: float
) -> np.ndarray:
    """Poisson disk centres in the periodic square [0, side)^2, shape (n, 2) as (x, y).

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the Poisson count and the uniform positions.
    side : float
        Side L of the periodic square (> 0), in pixels.
    radius : float
        Disk radius R, in pixels.
    phi2 : float
        Expected disk-phase fraction, in (0, 1).

    Returns
    -------
    ndarray, shape (n, 2)
        Centres (x, y) in [0, side), in pixels; n is Poisson with mean rho side^2.
    """
    if side <= 0:
        raise ValueError(f"side must be > 0, got {side}")
    count = rng.poisson(poisson_intensity(phi2, radius) * side * side)
    return rng.uniform(0.0, side, size=(count, 2))


@njit(cache=True)
def _paint_disks(centers, radius, out):
    ny, nx = out.shape
    r2 = radius * radius
    for k in range(centers.shape[0]):
        cx = centers[k, 0]
        cy = centers[k, 1]
        i_lo = int(math.floor(cy - 0.5 - radius))
        i_hi = int(math.ceil(cy - 0.5 + radius))
        j_lo = int(math.floor(cx - 0.5 - radius))
        j_hi = int(math.ceil(cx - 0.5 + radius))
        for i in range(i_lo, i_hi + 1):
            dy = i + 0.5 - cy
            if dy * dy > r2:
                continue
            row = i % ny
            for j in range(j_lo, j_hi + 1):
                dx = j + 0.5 - cx
                if dx * dx + dy * dy <= r2:
                    out[row, j % nx] = 1


def digitize_disks(centers: np.ndarray, radius: float, shape: tuple[int, int]) -> np.ndarray:
    """uint8 image of ``shape`` (rows, columns): 1 where a pixel centre lies in a disk.

    Parameters
    ----------
    centers : array_like, shape (n, 2)
        Disk centres (x, y) in pixel units; periodic images are painted.
    radius : float
        Disk radius, in pixels.
    shape : tuple of int
        Image shape (rows ny, columns nx).

    Returns
    -------
    ndarray of uint8, shape ``shape``
        1 = disk phase 2, 0 = void phase 1.
    """
    centers = np.ascontiguousarray(centers, dtype=np.float64).reshape(-1, 2)
    out = np.zeros(shape, dtype=np.uint8)
    _paint_disks(centers, float(radius), out)
    return out


def overlapping_disks_image(
    rng: np.random.Generator, side: int, radius: float, phi2: float
) -> np.ndarray:
    """One periodic side x side image of overlapping disks (1 = disk phase 2).

    Parameters
    ----------
    rng : numpy.random.Generator
        Random stream of :func:`overlapping_disk_centers`.
    side : int
        Image side L in pixels (also the periodic square side).
    radius : float
        Disk radius R, in pixels.
    phi2 : float
        Expected disk-phase fraction, in (0, 1).

    Returns
    -------
    ndarray of uint8, shape (side, side)
        Axes (y, x); 1 = disk phase 2, 0 = void phase 1.
    """
    centers = overlapping_disk_centers(rng, side, radius, phi2)
    return digitize_disks(centers, radius, (side, side))
