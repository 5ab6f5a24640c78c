"""File contract of a digitized 3D two-phase medium (issue 13, beyond the papers).

One netCDF file per sample: variable ``phase`` with dims (``z``, ``y``, ``x``), uint8,
1 = phase 2 (solid), 0 = phase 1 (void) -- the 3D counterpart of the 2D contract
:data:`randmedia.generate.PHASE_IMAGE` (which the 2D paper rules keep reading).
Attribute ``periodic`` (1/0) says whether the image is a periodic cell (Yeong-Torquato
constructions, overlapping spheres) or a window of a non-periodic medium (Poisson-plane
tessellations, :mod:`randmedia.generate.poisson_planes`), whose descriptors must not wrap.
"""

from __future__ import annotations

from typing import Mapping

import numpy as np
import xarray as xr

from randmedia.io import VariableSpec

#: what a reader of a 3D phase image requires (see :func:`randmedia.io.read_dataset`)
VOXEL_IMAGE = {"phase": VariableSpec(("z", "y", "x"), "1")}


def voxel_image_dataset(image: np.ndarray, attrs: Mapping, *, periodic: bool) -> xr.Dataset:
    """Wrap a 3D 0/1 image (axes z, y, x) as the contract's Dataset, with ``attrs``.

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        0/1 voxel image, 1 = phase 2.
    attrs : Mapping
        Global attributes (e.g. phi2, a, sample).
    periodic : bool
        Whether the image is a periodic cell (attribute ``periodic`` = 1) or a window.

    Returns
    -------
    xarray.Dataset
        Variable ``phase`` (z, y, x), uint8.
    """
    image = np.asarray(image)
    if image.ndim != 3 or not np.isin(image, (0, 1)).all():
        raise ValueError(f"expected a 3D image of 0/1 values, got shape {image.shape}")
    return xr.Dataset(
        {"phase": (("z", "y", "x"), image.astype(np.uint8),
                   {"units": "1", "long_name": "phase indicator: 1 = phase 2 (solid), 0 = phase 1 (void)",
                    "flag_values": np.array([0, 1], dtype=np.uint8),
                    "flag_meanings": "phase1_void phase2_solid"})},
        attrs={**dict(attrs), "periodic": int(bool(periodic))},
    )
