"""Overlapping disks (2D Boolean model) on a periodic square, digitized to pixels: the d = 2
case of :mod:`randmedia.generate.balls`, under the names the debye2020 rules use.

The model (Ma & Torquato 2020, Sec. VI A; Torquato, *Random Heterogeneous
Materials*, Ch. 3): disk centres form a Poisson point process of intensity
rho; the disks (radius R) are phase 2, the rest is the void phase 1 with
volume fraction phi1 = exp(-rho * pi R^2), i.e. rho = -ln(1 - phi2) / (pi R^2)
(:func:`randmedia.theory.balls.poisson_intensity` with ``dim=2``).

Digitization: pixel (row i, column j) of an L x L image covers
[j, j+1) x [i, i+1) and is set to phase 2 when its *centre* (j + 1/2, i + 1/2)
lies in at least one disk (periodic images included). The image is therefore
the continuum indicator function sampled exactly on a lattice, and its
periodic autocorrelation at a lattice displacement v is an unbiased estimate
of the continuum S2(|v|) of the torus model -- no discretization error enters
the two-point function, only in quantities that need the interface.

The d-generic painter draws the same random numbers and paints the same pixels as the
former 2D-only one (the images of every seed are unchanged).
"""

from __future__ import annotations

import numpy as np

from randmedia.generate.balls import digitize_balls, overlapping_ball_centers, overlapping_balls_image

__all__ = ["digitize_disks", "overlapping_disk_centers", "overlapping_disks_image"]


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
    return overlapping_ball_centers(rng, side, radius, phi2, 2)


def digitize_disks(centers: np.ndarray, radius: float, shape: tuple[int, int]) -> np.ndarray:
    """uint8 image of ``shape`` (rows, columns): 1 where a pixel centre lies in a disk.

    Parameters
    ----------
    centers : array_like, shape (n, 2)
        Disk centres (x, y) in pixel units; periodic images are painted.
    radius : float
        Disk radius (> 0), in pixels.
    shape : tuple of int
        Image shape (rows ny, columns nx).

    Returns
    -------
    ndarray of uint8, shape ``shape``
        1 = disk phase 2, 0 = void phase 1.
    """
    if len(shape) != 2:
        raise ValueError(f"expected a 2D image shape (ny, nx), got {shape}")
    return digitize_balls(centers, radius, shape)


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
    return overlapping_balls_image(rng, side, radius, phi2, 2)
