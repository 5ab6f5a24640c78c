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

def refuse_invalid(what: str, checks: Mapping[str, bool], values) -> None:
    """Raise ValueError naming every field of ``values`` whose check in ``checks`` (field
    name -> condition that must hold) fails; the parameter classes of the generators call
    it from ``__post_init__``.

    Parameters
    ----------
    what : str
        Name of the checked object in the error message (e.g. "inflation-LP parameters").
    checks : Mapping[str, bool]
        Field name -> whether its condition holds.
    values : object
        The checked object (usually the dataclass instance), shown in the message.

    Raises
    ------
    ValueError
        If any check is False.
    """
    bad = [name for name, ok in checks.items() if not ok]
    if bad:
        raise ValueError(f"invalid {what}: {bad} ({values})")


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


# --------------------------------------------------------------------------- particle configurations

#: what a reader of a periodic particle configuration requires (DESIGN.md contract:
#: results/mrj2016/configs/{system}/sample{k}.nc); positions and box in units of D
PARTICLE_CONFIG = {
    "position": VariableSpec(("particle", "xyz"), "D"),
    "box": VariableSpec(("xyz", "vec"), "D"),
}


def particle_config_dataset(positions: np.ndarray, box: np.ndarray, diameter: float,
                            attrs: Mapping, *, units: str = "D") -> xr.Dataset:
    """Wrap sphere centres in a periodic cell as the contract's Dataset.

    ``positions`` (n, d) are wrapped into the cell whose lattice vectors are the
    *columns* of ``box`` (d, d); ``diameter`` is the sphere diameter (attr
    ``diameter``), in the same ``units`` (D = 1 for the mrj2016 systems). The
    spatial dimension is named ``xyz`` whatever d (a 2D file has xyz of length 2).

    Parameters
    ----------
    positions : ndarray, shape (n, d)
        Sphere centres (Cartesian), in ``units``; wrapped into the cell on output.
    box : ndarray, shape (d, d)
        Periodic cell, column k = lattice vector k, in ``units``.
    diameter : float
        Sphere diameter (> 0), in ``units``; stored as attr ``diameter``.
    attrs : Mapping
        Extra global attributes (``diameter``, ``n_particles`` and ``dimension`` are added).
    units : str, optional
        Length unit written to the variables (default "D").

    Returns
    -------
    xarray.Dataset
        Variables ``position`` (particle, xyz) and ``box`` (xyz, vec), coords ``xyz``, ``vec``.
    """
    from randmedia.periodic import Cell

    positions = np.asarray(positions, dtype=np.float64)
    cell = Cell(box)
    if positions.ndim != 2 or positions.shape[1] != cell.dim:
        raise ValueError(f"positions must have shape (n, {cell.dim}), got {positions.shape}")
    if not diameter > 0:
        raise ValueError(f"diameter must be > 0, got {diameter}")
    axes = "xyz"[: cell.dim]
    return xr.Dataset(
        {
            "position": (("particle", "xyz"), cell.wrap(positions),
                         {"units": units, "long_name": "sphere centre (Cartesian, wrapped into the cell)"}),
            "box": (("xyz", "vec"), cell.box,
                    {"units": units, "long_name": "periodic cell: column k is lattice vector k"}),
        },
        coords={
            "xyz": ("xyz", list(axes), {"units": "1", "long_name": "Cartesian axis"}),
            "vec": ("vec", np.arange(cell.dim), {"units": "1", "long_name": "lattice vector index"}),
        },
        attrs={**dict(attrs), "diameter": float(diameter), "n_particles": positions.shape[0],
               "dimension": cell.dim},
    )
