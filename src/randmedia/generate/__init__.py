"""Generators of configurations: digitized two-phase images and particle positions.

File contract of a digitized two-phase medium (one netCDF file per sample):
variable ``phase`` with dims (``y``, ``x``), uint8, 1 = phase 2 (the disks;
the yellow "solid" phase of Ma & Torquato 2020, Fig. 1), 0 = phase 1 (void).
"""

from __future__ import annotations

from typing import Mapping

import numpy as np
import xarray as xr

from randmedia.io import VariableSpec

#: what a reader of a phase image requires (see :func:`randmedia.io.read_dataset`)
PHASE_IMAGE = {"phase": VariableSpec(("y", "x"), "1")}


def phase_image_dataset(image: np.ndarray, attrs: Mapping) -> xr.Dataset:
    """Wrap a 2D 0/1 image as the contract's Dataset, with ``attrs`` (e.g. phi2)."""
    image = np.asarray(image)
    if image.ndim != 2 or not np.isin(image, (0, 1)).all():
        raise ValueError(f"expected a 2D image of 0/1 values, got shape {image.shape}")
    return xr.Dataset(
        {"phase": (("y", "x"), image.astype(np.uint8),
                   {"units": "1", "long_name": "phase indicator: 1 = phase 2 (solid), 0 = phase 1 (void)",
                    "flag_values": np.array([0, 1], dtype=np.uint8),
                    "flag_meanings": "phase1_void phase2_solid"})},
        attrs=dict(attrs),
    )
