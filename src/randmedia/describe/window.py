"""Two-point function of a *non-periodic* window image (2D and 3D alike), and what the
periodic estimator measures on one.

The periodic estimator of :mod:`randmedia.describe.two_phase` treats an image as
one cell of a periodic medium. A window cut from a non-periodic medium (e.g.
:mod:`randmedia.generate.poisson_planes`) has a seam on its faces: a pair
(x, x + v mod L) that wraps around axis i is really |v_i - sign(v_i) L_i| apart
along that axis.

* Exact expectation of the periodic estimator on a window of a stationary
  isotropic medium with two-point function S2 (:func:`periodic_estimator_expectation`).
  Of the L_i lattice coordinates along axis i, exactly |v_i| wrap (axes
  independently), so

      E C(v) = sum over subsets W of the axes
               prod_{i in W} (|v_i| / L_i) prod_{i not in W} (1 - |v_i| / L_i) S2(|v^W|),

  v^W_i = v_i - sign(v_i) L_i for i in W, v_i otherwise. For a Debye medium with
  L >> a the wrapped terms are ~phi2^2, so the seam lowers the measured chi_V by
  the fraction of wrapping pairs, 1 - prod_i (1 - |v_i|/L_i) (~ |v|_1 / L).

* Unbiased window (minus-sampling) estimator (:func:`window_s2_samples`):
  C_w(v) = sum over pairs with both ends inside the window of I(x) I(x + v),
  divided by their number prod_i (L_i - |v_i|); E C_w(v) = S2(|v|) for any
  stationary medium. Computed by FFT of the image zero-padded to L_i + r_max per
  axis (no wrapped pairs reach |v_i| <= r_max), radially averaged over all
  displacements with the bins of :class:`randmedia.numerics.radial.RadialBinning`
  (the same bins and labels as the periodic estimator for the same r_max), each
  displacement with equal weight.
"""

from __future__ import annotations

import itertools
import math
from typing import Callable

import numpy as np
import scipy.fft

from randmedia.numerics.radial import RadialBinning


def periodic_estimator_expectation(s2: Callable[[np.ndarray], np.ndarray],
                                   binning: RadialBinning) -> np.ndarray:
    """Per bin of ``binning`` (built on the window's shape): the exact expectation of the
    periodic estimator (:func:`randmedia.describe.two_phase.two_point_function`) on a
    window of a stationary isotropic medium with two-point function ``s2(r)``."""
    vectors = binning.displacements().astype(float)  # (m, d), minimal images on the shape
    sides = np.asarray(binning.shape, dtype=float)
    wrap = np.abs(vectors) / sides  # fraction of coordinates that wrap, per axis
    expected = np.zeros(len(vectors))
    for subset in itertools.product((False, True), repeat=len(sides)):
        weight = np.ones(len(vectors))
        true = vectors.copy()
        for axis, wrapped in enumerate(subset):
            if wrapped:
                weight *= wrap[:, axis]
                true[:, axis] -= np.sign(vectors[:, axis]) * sides[axis]
            else:
                weight *= 1.0 - wrap[:, axis]
        expected += weight * np.asarray(s2(np.sqrt((true * true).sum(axis=1))), dtype=float)
    return np.bincount(binning.bin_of, weights=expected, minlength=binning.counts.size) / binning.counts


def window_binning(shape, r_max: float, bin_width: float = 1.0) -> RadialBinning:
    """Bins of the window estimator for an image of ``shape``: those of the periodic estimator
    for the same r_max (same displacements, counts and labels), laid out on the zero-padded
    grid. Requires r_max < min(shape)/2, like the periodic estimator.

    Parameters
    ----------
    shape : tuple of int
        Shape of the window image.
    r_max : float
        Largest distance (pixels), 0 < r_max < min(shape)/2.
    bin_width : float, optional
        Bin width (pixels).

    Returns
    -------
    RadialBinning
        Built on the padded shape (``binning.shape``).
    """
    shape = tuple(int(n) for n in shape)
    if not 0 < r_max < min(shape) / 2:
        raise ValueError(f"r_max = {r_max:g} must lie in (0, min(shape)/2 = {min(shape) / 2:g})")
    padded = tuple(scipy.fft.next_fast_len(n + int(math.floor(r_max)), real=True) for n in shape)
    return RadialBinning.build(padded, r_max, bin_width)


def window_s2_samples(images, phase: int, r_max: float, bin_width: float = 1.0) -> np.ndarray:
    """Window S2 of ``phase`` per sample and bin, shape (n_samples, n_bins), for a stack of
    images (n_samples, *shape); bins and labels as ``window_binning(shape, r_max).r_mean``.

    Parameters
    ----------
    images : array_like, shape (n_samples, *shape)
        Non-periodic 2D or 3D window images of phase labels.
    phase : int
        Label of the phase.
    r_max : float
        Largest distance (pixels), < min(shape)/2.
    bin_width : float, optional
        Bin width (pixels).

    Returns
    -------
    ndarray, shape (n_samples, n_bins)
        Window estimate of S2.
    """
    images = np.asarray(images)
    if images.ndim not in (3, 4):
        raise ValueError(f"expected images of shape (n_samples, [nz,] ny, nx), got {images.shape}")
    shape = images.shape[1:]
    binning = window_binning(shape, r_max, bin_width)
    padded = binning.shape
    # number of pairs at each displacement: prod_i (L_i - |v_i|), minimal images on the padded grid
    pairs = np.ones(padded)
    for axis, (n, p) in enumerate(zip(shape, padded)):
        lag = np.abs(np.rint(np.fft.fftfreq(p) * p))
        count = np.maximum(n - lag, 1.0)  # displacements beyond the window are never binned
        pairs = pairs * count.reshape([-1 if k == axis else 1 for k in range(len(shape))])
    axes = tuple(range(len(shape)))
    curves = np.empty((images.shape[0], binning.counts.size))
    for k, image in enumerate(images):
        spectrum = scipy.fft.rfftn((image == phase).astype(np.float64), s=padded, axes=axes)
        power = spectrum.real**2 + spectrum.imag**2
        sums = scipy.fft.irfftn(power, s=padded, axes=axes)
        curves[k] = binning.average(sums / pairs)
    return curves
