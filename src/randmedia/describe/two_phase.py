"""Two-point descriptors of periodic digitized two-phase media (2D and 3D alike).

Two-point function S2 (Ma & Torquato 2020, Eq. 1 with n = 2): the probability
that both ends of a segment of length r fall in the chosen phase. On a
periodic image I (1 in the phase, 0 elsewhere) of N pixels the estimator is
the exact circular autocorrelation

    C(v) = (1/N) sum_x I(x) I(x + v)      for every lattice displacement v,

computed as irfftn(|rfftn(I)|^2) / N
(:func:`randmedia.numerics.radial.periodic_autocorrelation`), then averaged radially over
*all* displacements v with |v| in a bin (every direction, not only the axes), with the bins
of :class:`randmedia.numerics.radial.RadialBinning` (minimal periodic images, |v| <
min(side)/2; bins of width ``bin_width`` centred on multiples of it, so bin 0 holds v = 0
alone and S2(0) = phi; each bin labelled by the mean |v| of its displacements; equal or, in
2D, angular weights -- see that module). The Yeong-Torquato construction
(:mod:`randmedia.generate.yeong_torquato`) sums the same bins.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from randmedia.io import VariableSpec
from randmedia.numerics.radial import RadialBinning, periodic_autocorrelation
from randmedia.stats import standard_error


def two_point_function(
    images, phase: int, r_max: float, bin_width: float = 1.0
) -> xr.Dataset:
    """S2(r) of ``phase`` for a stack of periodic images, with mean and SEM over samples.

    ``images`` has shape (n_samples, *image_shape) -- always with the sample axis,
    so a single 3D image is ``image[np.newaxis]``. Returns a
    Dataset with coordinate ``r`` (mean pair distance of each bin, pixels) and
    variables ``S2_samples`` (sample, r), ``S2`` and ``S2_sem`` (r; SEM over
    samples with ddof = 1, NaN for one sample), ``phi_samples`` (sample) and
    ``n_vectors`` (r; displacements in each bin).

    Parameters
    ----------
    images : array_like, shape (n_samples, *image_shape)
        Periodic 2D or 3D images of phase labels.
    phase : int
        Label of the phase.
    r_max : float
        Largest distance (pixels), < min(image_shape)/2.
    bin_width : float, optional
        Bin width (pixels).
    """
    images = np.asarray(images)
    if images.ndim not in (3, 4):
        raise ValueError(f"expected images of shape (n_samples, ny, nx[, nz]), got {images.shape}")
    binning = RadialBinning.build(images.shape[1:], r_max, bin_width)
    curves = np.empty((images.shape[0], binning.counts.size))
    fractions = np.empty(images.shape[0])
    for k, image in enumerate(images):
        indicator = image == phase
        curves[k] = binning.average(periodic_autocorrelation(indicator))
        fractions[k] = indicator.mean()
    n = curves.shape[0]
    sem = standard_error(curves)
    r_attrs = {"units": "pixel", "long_name": "mean distance of the pixel pairs in the bin"}
    return xr.Dataset(
        {
            "S2_samples": (("sample", "r"), curves,
                           {"units": "1", "long_name": f"two-point function of phase {phase} per sample"}),
            "S2": ("r", curves.mean(axis=0),
                   {"units": "1", "long_name": f"two-point function of phase {phase}, sample mean"}),
            "S2_sem": ("r", sem,
                       {"units": "1", "long_name": "standard error of the mean of S2 over samples"}),
            "phi_samples": ("sample", fractions,
                            {"units": "1", "long_name": f"volume fraction of phase {phase} per sample"}),
            "n_vectors": ("r", binning.counts,
                          {"units": "1", "long_name": "lattice displacements averaged in the bin"}),
        },
        coords={
            "r": ("r", binning.r_mean, r_attrs),
            "sample": ("sample", np.arange(n), {"units": "1", "long_name": "sample index"}),
        },
        attrs={"phase": phase, "bin_width": bin_width, "r_max": r_max},
    )


#: what a reader of a two-point-function file requires
TWO_POINT = {
    "S2": VariableSpec(("r",), "1"),
    "S2_sem": VariableSpec(("r",), "1"),
    "S2_samples": VariableSpec(("sample", "r"), "1"),
    "r": VariableSpec(("r",), "pixel"),
}


def s2_discrepancy(s2: xr.Dataset, target_s2, image_shape) -> np.ndarray:
    """Delta S2 per sample (Ma & Torquato 2020, Sec. IV): mean over the bins r > 0 of an
    S2 dataset from :func:`two_point_function` of |S2 - target|, the target being the exact
    bin average of ``target_s2`` over the same displacements -- the bins and target the
    Yeong-Torquato construction uses when the dataset's r_max is its l_c.

    Parameters
    ----------
    s2 : xarray.Dataset
        Output of :func:`two_point_function` (attributes ``r_max``, ``bin_width``).
    target_s2 : callable
        Target S2 as a function of distance (pixels), vectorized.
    image_shape : tuple of int
        Shape of the images.

    Returns
    -------
    ndarray, shape (n_samples,)
        Delta S2 per sample.
    """
    binning = RadialBinning.build(image_shape, float(s2.attrs["r_max"]),
                                  float(s2.attrs["bin_width"]))
    target = binning.average_of(target_s2)
    return np.abs(s2["S2_samples"].values[:, 1:] - target[1:]).mean(axis=1)
