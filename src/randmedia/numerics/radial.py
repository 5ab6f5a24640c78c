"""Radial bins of periodic lattice displacements, and the periodic autocorrelation by FFT.

Shared by the Yeong-Torquato construction (:mod:`randmedia.generate.yeong_torquato`, whose
energy sums the same bins) and the two-point descriptors (:mod:`randmedia.describe.two_phase`
and the estimators built on it), so that the construction and the measurement bin alike.

Periodic autocorrelation: on a periodic image I of N pixels,

    C(v) = (1/N) sum_x I(x) I(x + v)      for every lattice displacement v,

computed exactly as irfftn(|rfftn(I)|^2) / N.

Displacements are taken as their minimal periodic image (numpy's fftfreq convention), which
is correct for odd and even side lengths; only |v| < min(side)/2 is allowed, where the
minimal image is unique. Bins have width ``bin_width`` (pixels) centred on multiples of it,
so bin 0 holds v = 0 alone. Each bin is labelled by the mean |v| of the displacements in it;
:meth:`RadialBinning.average_of` gives the exact bin-average of a known radial function for
checking that labelling.

By default every displacement in a bin has the same weight. In a thin annulus
(width ~ the lattice spacing) the lattice points are not spread evenly over the
directions -- along the axes and diagonals they bunch in some bins and thin out
in the next (Gauss's circle problem) -- so a function that is not isotropic on
the lattice scale (e.g. the interface correlation of a level set that carries
the pixel grid's preferred directions) gets a bin-to-bin alternating bias.
``RadialBinning.build(..., angular=True)`` (2D) instead gives each displacement
the angular width it stands for in its bin (half the angles to its neighbours
in direction; displacements along one direction share it): the bin average is
then the trapezoid rule for the *direction* average, which is what a radial
function of an isotropic medium means. For a radial function both weightings
estimate the same thing; they differ only in how the bin's |v| are weighted,
and :meth:`average_of` and ``r_mean`` use the same weights.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["RadialBinning", "angular_bin_weights", "periodic_autocorrelation"]


@dataclass(frozen=True)
class RadialBinning:
    """Assignment of the periodic lattice displacements with |v| <= r_max to radial bins."""

    shape: tuple[int, ...]
    flat_index: np.ndarray  # indices (into the raveled autocorrelation) of kept displacements
    bin_of: np.ndarray  # bin number of each kept displacement
    distance: np.ndarray  # |v| of each kept displacement
    counts: np.ndarray  # displacements per bin
    r_mean: np.ndarray  # mean |v| per bin (weighted like the averages)
    weight: np.ndarray | None = None  # per kept displacement, summing to 1 per bin; None: equal

    @classmethod
    def build(cls, shape, r_max: float, bin_width: float = 1.0,
              angular: bool = False) -> "RadialBinning":
        """Bin the minimal-image lattice displacements with |v| <= ``r_max``.

        Parameters
        ----------
        shape : tuple of int
            Shape of the periodic lattice (the image).
        r_max : float
            Largest |v| kept (lattice units, e.g. pixels); must be < min(shape)/2.
        bin_width : float, optional
            Bin width; bin k holds |v| within bin_width/2 of k bin_width. Below 1, empty bins
            raise ValueError.
        angular : bool, optional
            Per-direction weights (2D only; module docstring) instead of equal weights.

        Returns
        -------
        RadialBinning
        """
        shape = tuple(int(n) for n in shape)
        if r_max <= 0 or bin_width <= 0:
            raise ValueError(f"r_max and bin_width must be > 0, got {r_max}, {bin_width}")
        if r_max >= min(shape) / 2:
            raise ValueError(
                f"r_max = {r_max:g} must be < min(shape)/2 = {min(shape) / 2:g} for a unique "
                "periodic distance"
            )
        # integer minimal-image components in numpy's fftfreq order (0, 1, .., -1); exact
        # integers, so a displacement at exactly r_max (e.g. (50, 0)) is not lost to rounding
        axes = np.meshgrid(*[np.rint(np.fft.fftfreq(n) * n) for n in shape], indexing="ij")
        distance = np.sqrt(sum(a * a for a in axes)).ravel()
        flat_index = np.flatnonzero(distance <= r_max)
        distance = distance[flat_index]
        bin_of = np.rint(distance / bin_width).astype(np.int64)
        counts = np.bincount(bin_of)
        if np.any(counts == 0):  # only possible for bin_width < 1 pixel
            raise ValueError(f"bin_width = {bin_width:g} leaves empty bins; use >= 1 pixel")
        if not angular:
            r_mean = np.bincount(bin_of, weights=distance) / counts
            return cls(shape, flat_index, bin_of, distance, counts, r_mean)
        if len(shape) != 2:
            raise ValueError(f"angular weights are defined for 2D lattices, got shape {shape}")
        components = [a.ravel()[flat_index] for a in axes]  # (row, column) = (y, x)
        weight = angular_bin_weights(np.arctan2(components[0], components[1]), bin_of)
        r_mean = np.bincount(bin_of, weights=weight * distance)
        return cls(shape, flat_index, bin_of, distance, counts, r_mean, weight)

    def displacements(self) -> np.ndarray:
        """Integer lattice vectors (minimal images) of the kept displacements, shape (m, d)."""
        index = np.unravel_index(self.flat_index, self.shape)
        return np.stack([np.where(i > n // 2, i - n, i) for i, n in zip(index, self.shape)], axis=1)

    def _bin_mean(self, values: np.ndarray) -> np.ndarray:
        if self.weight is None:
            return np.bincount(self.bin_of, weights=values, minlength=self.counts.size) / self.counts
        return np.bincount(self.bin_of, weights=self.weight * values, minlength=self.counts.size)

    def average(self, field: np.ndarray) -> np.ndarray:
        """Bin-average of a full-size displacement field (e.g. an autocorrelation)."""
        return self._bin_mean(field.ravel()[self.flat_index])

    def average_of(self, radial_function) -> np.ndarray:
        """Exact bin-average of f(|v|) over the displacements in each bin (same weights)."""
        return self._bin_mean(radial_function(self.distance))


def angular_bin_weights(theta: np.ndarray, bin_of: np.ndarray) -> np.ndarray:
    """Weights of points at angles ``theta`` (radians) in bins ``bin_of``: within a bin, each
    distinct direction gets half the angular gaps to its neighbouring directions (periodic in
    2 pi; a bin with one direction gets all of it), shared equally by the points along it;
    normalized to 1 per bin. The weighted bin mean is the trapezoid rule for the mean over
    directions."""
    theta = np.round(np.mod(theta, 2 * np.pi), 12)  # one value per lattice direction
    theta[theta >= np.round(2 * np.pi, 12)] = 0.0
    order = np.lexsort((theta, bin_of))
    b, t = bin_of[order], theta[order]
    new_group = np.r_[True, (b[1:] != b[:-1]) | (t[1:] != t[:-1])]
    group = np.cumsum(new_group) - 1
    g_bin, g_theta = b[new_group], t[new_group]
    g_size = np.bincount(group)
    # first and last group of each bin, for the wrap-around neighbours
    first = np.r_[True, g_bin[1:] != g_bin[:-1]]
    last = np.r_[g_bin[1:] != g_bin[:-1], True]
    first_of = np.maximum.accumulate(np.where(first, np.arange(g_bin.size), 0))
    last_of = np.empty_like(first_of)
    last_idx = np.flatnonzero(last)
    last_of[:] = np.repeat(last_idx, np.diff(np.r_[-1, last_idx]))
    nxt = np.where(last, g_theta[first_of] + 2 * np.pi, np.r_[g_theta[1:], 0.0])
    prv = np.where(first, g_theta[last_of] - 2 * np.pi, np.r_[0.0, g_theta[:-1]])
    width = np.where(first & last, 2 * np.pi, 0.5 * (nxt - prv))
    per_point = (width / g_size)[group]
    weight = np.empty_like(per_point)
    weight[order] = per_point
    return weight / np.bincount(bin_of, weights=weight)[bin_of]


def periodic_autocorrelation(indicator: np.ndarray) -> np.ndarray:
    """C(v) = (1/N) sum_x I(x) I(x+v) on the periodic lattice, for every v (FFT, exact)."""
    field = np.asarray(indicator, dtype=np.float64)
    spectrum = np.fft.rfftn(field)
    power = spectrum.real**2 + spectrum.imag**2
    return np.fft.irfftn(power, s=field.shape, axes=tuple(range(field.ndim))) / field.size
