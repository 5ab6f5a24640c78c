"""Truncation of the Gaussian filters of the level sets, and the interior margin it implies.

The level sets of :mod:`randmedia.describe.window_surface` (and the chords and pore sizes
measured on them) filter a window with :func:`scipy.ndimage.gaussian_filter`, whose kernel
stops at ``TRUNCATE`` standard deviations: ``int(TRUNCATE sigma m + 0.5)`` sub-voxels for a
width of ``sigma`` voxels on a grid of ``m`` sub-voxels per voxel. At least that far from
every face the filtered field of a window equals that of the infinite medium; one voxel more
keeps out the triangles and deposits of the marching cubes that touch a face (the rule of
:func:`default_margin`). Kept here, below the descriptors, because the config validation
needs the same number before any job runs (:func:`randmedia.config.debye3d_window_margin`).
"""

from __future__ import annotations

__all__ = ["TRUNCATE", "default_margin", "kernel_radius"]

#: scipy.ndimage.gaussian_filter's default kernel truncation, in standard deviations
TRUNCATE = 4.0


def kernel_radius(sigma: float, supersample: int) -> int:
    """Radius (sub-voxels) of the truncated Gaussian kernel, as scipy computes it:
    ``int(TRUNCATE sigma m + 0.5)``.

    Parameters
    ----------
    sigma : float
        Gaussian width (voxels).
    supersample : int
        Sub-voxels per voxel, m.

    Returns
    -------
    int
        Kernel radius in sub-voxels.
    """
    return int(TRUNCATE * float(sigma) * supersample + 0.5)


def default_margin(sigma: float, supersample: int) -> int:
    """Interior margin in sub-voxels for a Gaussian of width ``sigma`` voxels on ``supersample``
    sub-voxels per voxel: the truncated kernel's radius (:func:`kernel_radius`) plus one voxel
    (``supersample`` sub-voxels)."""
    return kernel_radius(sigma, supersample) + int(supersample)
