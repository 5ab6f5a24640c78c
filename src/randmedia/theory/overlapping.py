"""Exact two-point function of overlapping disks / spheres (Boolean model).

Ma & Torquato, PRE 102, 043310 (2020), Sec. VI A:

* Eq. (32): S2^(1)(r) = exp(-rho v2(r; R)) for the void phase 1;
* Eq. (33): the union area of two disks of radius R at centre distance r,
  v2/v1 = 2 Theta(r - 2R) + (2/pi)[pi + x sqrt(1 - x^2) - arccos(x)] Theta(2R - r),
  x = r / (2R), v1 = pi R^2;
* phi1 = exp(-rho v1) = exp(-eta).

The d = 3 union volume (Torquato, *Random Heterogeneous Materials*, Eq. 3.16)
v2/v1 = 1 + (3/4)(r/R) - (1/16)(r/R)^3 for r < 2R serves the sphere models.
"""

from __future__ import annotations

import numpy as np


def union_volume_ratio(r, radius: float, dim: int = 2) -> np.ndarray:
    """v2(r; R) / v1(R): union of two d-balls of radius R, centres r apart (Eq. 33 for d=2)."""
    r = np.asarray(r, dtype=float)
    if radius <= 0:
        raise ValueError(f"radius must be > 0, got {radius}")
    if np.any(r < 0):
        raise ValueError("distances must be >= 0")
    overlapping = r < 2.0 * radius
    if dim == 2:
        x = np.clip(r / (2.0 * radius), 0.0, 1.0)
        inside = (2.0 / np.pi) * (np.pi + x * np.sqrt(1.0 - x * x) - np.arccos(x))
    elif dim == 3:
        y = r / radius
        inside = 1.0 + 0.75 * y - y**3 / 16.0
    else:
        raise ValueError(f"dim must be 2 or 3, got {dim}")
    return np.where(overlapping, inside, 2.0)


def s2_void(r, radius: float, phi2: float, dim: int = 2) -> np.ndarray:
    """Eq. (32): S2 of the void phase, exp(-eta v2/v1) with eta = -ln(1 - phi2)."""
    if not 0.0 < phi2 < 1.0:
        raise ValueError(f"phi2 must lie in (0, 1), got {phi2}")
    eta = -np.log1p(-phi2)
    return np.exp(-eta * union_volume_ratio(r, radius, dim))
