"""Equilibrium hard disks: closed forms Ma & Torquato 2020 use in Sec. VI B.

Identical disks of radius R (phase 2, volume fraction phi2) in equilibrium
along the fluid branch; phase 1 is the matrix (void).

* s = 2 phi2 / R                                                    Eq. (40)
  (exact for non-overlapping disks: perimeter 2 pi R per disk, rho = phi2/(pi R^2));
  :func:`randmedia.theory.hard_spheres.specific_surface` with ``dim=2``
* L(z) = phi1 exp(-(2 phi2 / (pi phi1)) z / R)                      Eq. (42)
  (Lu & Torquato, PRE A 45, 922 (1992): the matrix lineal-path function of
  equilibrium hard disks in the approximation the paper uses)
* p(z) = (2 phi2 / (pi phi1 R)) exp(-(2 phi2 / (pi phi1)) z / R)    Eq. (43)
  = (l_C / phi1) L''(z) of Eq. (42) by Eq. (19); its mean chord
  pi phi1 R / (2 phi2) = pi phi1 / s agrees with Eq. (20).

The pore-size density of Eq. (41) (scaled-particle theory) lives in
:mod:`randmedia.theory.scaled_particle`.
"""

from __future__ import annotations

import numpy as np

from randmedia.numerics.checks import check_fraction, check_positive


def chord_rate(radius: float, phi2: float) -> float:
    """lambda = 2 phi2 / (pi phi1 R): the decay rate of Eqs. (42)-(43), 1 / mean chord."""
    check_positive(radius, "radius")
    check_fraction(phi2)
    return 2.0 * phi2 / (np.pi * (1.0 - phi2) * radius)


def lineal_path_void(z, radius: float, phi2: float) -> np.ndarray:
    """Eq. (42): L(z) = phi1 exp(-2 phi2 z / (pi phi1 R)).

    Parameters
    ----------
    z : float or array_like
        Segment lengths, >= 0 (same length unit as ``radius``).
    radius : float
        Disk radius R, > 0.
    phi2 : float
        Volume fraction of the disks, in (0, 1).

    Returns
    -------
    numpy.ndarray
        L(z) of the matrix (void) phase, same shape as ``z``.
    """
    z = np.asarray(z, dtype=float)
    if np.any(z < 0):
        raise ValueError("segment lengths must be >= 0")
    return (1.0 - phi2) * np.exp(-chord_rate(radius, phi2) * z)


def chord_density_void(z, radius: float, phi2: float) -> np.ndarray:
    """Eq. (43): p(z) = (2 phi2 / (pi phi1 R)) exp(-2 phi2 z / (pi phi1 R)).

    Parameters
    ----------
    z : float or array_like
        Chord lengths, >= 0 (same length unit as ``radius``).
    radius : float
        Disk radius R, > 0.
    phi2 : float
        Volume fraction of the disks, in (0, 1).

    Returns
    -------
    numpy.ndarray
        p(z) of the matrix chords (units 1/length), same shape as ``z``.
    """
    z = np.asarray(z, dtype=float)
    if np.any(z < 0):
        raise ValueError("chord lengths must be >= 0")
    rate = chord_rate(radius, phi2)
    return rate * np.exp(-rate * z)
