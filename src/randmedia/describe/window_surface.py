"""Specific surface and surface correlation functions of a 3D *window* image (minus-sampling).

Ma & Torquato 2020, Sec. II B: the interface indicator M(x) = |grad I(x)| (Eq. 9), the
specific surface s = <M> (Eq. 10), F_sv(r) = <M(x) I_void(x + r)> (Eq. 11) and
F_ss(r) = <M(x) M(x + r)> (Eq. 15); phase 1 (image value 0) is the void.

:mod:`randmedia.describe.surface` estimates them for *periodic* images: its Gaussian filter,
its marching-tetrahedra interface and its FFT correlations all wrap around the faces. On a
window cut from a non-periodic medium (the Poisson-plane tessellations of
:mod:`randmedia.generate.poisson_planes`) that wrapping invents a seam on every face: the
filter blends opposite faces, the level set gets a sheet of interface there that is not in
the medium, and wrapped pairs (x, x + v mod L) are really ~L apart. This module is the
window counterpart -- standard minus-sampling:

1. **Level set of the window.** The "pixels" model of
   :class:`randmedia.describe.chords.LevelSet` (the voxel indicator of the void, repeated
   ``supersample``^3 times, Gaussian-filtered on the sub-voxel grid) with a *non-wrapping*
   boundary mode, ``mode="reflect"`` (scipy's half-sample symmetric reflection: it keeps the
   filtered field's sum equal to the indicator's, so the whole-window threshold still means
   "the window's void fraction"); threshold: the quantile of the whole fine window that keeps
   the window's void fraction, the same rule as ``LevelSet.build``. Done here, in this
   module (a :class:`LevelSet` is constructed from the filtered field): ``chords.py`` is
   not touched, so the periodic path (which feeds the 2D paper workflow) is unchanged by
   construction.
2. **Interior mask.** w = 1 on the box of sub-voxels at least ``margin`` sub-voxels from
   every face. Default margin rule (:func:`randmedia.numerics.gaussian.default_margin`): the filter's truncation
   radius, ``int(4 sigma m + 0.5)`` sub-voxels (scipy's ``truncate=4``), plus one voxel
   (m sub-voxels). Inside that box the filtered field is *exactly* the field the infinite
   medium would give (the truncated kernel never reaches a face, so the boundary mode
   plays no part), and the extra voxel keeps out every triangle of a cube that wraps (seam
   triangles lie within one sub-voxel of a face) and its cloud-in-cell deposit (one more
   sub-voxel). This is more than the ~3 sigma + 1 voxel that a 1e-3 field error would need.
   M is :func:`randmedia.describe.isosurface.surface_density` of the marching-tetrahedra
   triangles of the whole window, restricted to w. The only remaining dependence on the
   outside of w is the threshold (a single number from the whole window).
3. **Estimators.** s = sum w M / sum w; for a, b in {M, void}:
   F_ab(v) = sum_x w(x) a(x) w(x + v) b(x + v) / sum_x w(x) w(x + v), by FFT of the interior
   box zero-padded by r_max per axis (no wrapped pair reaches |v_i| <= r_max), the pair
   count sum w w = prod_i (L_i - |v_i|) with L the interior side in sub-voxels. E F_ab(v) is
   the stationary F_ab(|v|) of the level-set medium for any stationary medium. Radially
   averaged with lattice weights over the same displacements and bins as the periodic 3D
   estimator (:func:`randmedia.describe.surface.surface_binning`, bins in sub-voxel units;
   laid out on the padded grid by :func:`randmedia.describe.window.window_binning`), so
   labels are identical and paired comparisons bin by bin are possible.
4. **Tuning** (:func:`tune_sigma_window`): the Brent search of
   :func:`randmedia.describe.surface.tune_sigma` with the interior s plugged in; the margin
   is fixed over the search (default: the rule at the bracket's upper sigma) so the
   function searched is continuous in sigma.

The price of minus-sampling: a 48^3 window with sigma ~ 0.45 voxel, 4 sub-voxels per
voxel, loses 11 sub-voxels = 2.75 voxels per face (interior 42.5^3, 71 % of the volume),
and r_max must stay below half the interior side. Validation and the seam measured:
docs/debye3d.md, 'Window surface functions'.
"""

from __future__ import annotations

import numpy as np
import scipy.fft
import xarray as xr
from scipy.ndimage import gaussian_filter

from randmedia.describe.chords import LevelSet
from randmedia.describe.isosurface import interface_triangles, surface_density
from randmedia.describe.surface import curve_variables, tune_sigma
from randmedia.describe.window import window_binning
from randmedia.numerics.gaussian import TRUNCATE, default_margin
from randmedia.numerics.radial import RadialBinning
from randmedia.progress import Progress

#: boundary mode of the window filter (non-wrapping)
BOUNDARY_MODE = "reflect"


def window_level_set(image: np.ndarray, sigma: float, supersample: int) -> LevelSet:
    """Level set of the void (image value 0) of a non-periodic 3D window: "pixels" model,
    Gaussian filter with ``mode="reflect"``, threshold keeping the window's void fraction.

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        Window image, void = 0.
    sigma : float
        Gaussian width (voxels), > 0.
    supersample : int
        Sub-voxels per voxel along each axis.

    Returns
    -------
    LevelSet
        ``phase``-region = void; ``fine`` of shape (n * supersample per axis).
    """
    indicator = (np.asarray(image) == 0).astype(np.float64)
    if indicator.ndim != 3:
        raise ValueError(f"expected a 3D image, got shape {indicator.shape}")
    if sigma <= 0 or supersample < 1:
        raise ValueError(f"need sigma > 0 and supersample >= 1, got {sigma}, {supersample}")
    fine = np.kron(indicator, np.ones((supersample,) * 3))
    fine = gaussian_filter(fine, sigma * supersample, mode=BOUNDARY_MODE, truncate=TRUNCATE)
    fraction = indicator.mean()
    threshold = 0.5 if fraction in (0.0, 1.0) else float(np.quantile(fine, 1.0 - fraction))
    return LevelSet(fine, threshold, int(supersample), float(sigma), "pixels", None)


def _interior(field: np.ndarray, margin: int) -> np.ndarray:
    if margin <= 0:
        return field
    if 2 * margin >= min(field.shape):
        raise ValueError(f"margin {margin} sub-voxels leaves no interior in {field.shape}")
    return field[margin:-margin, margin:-margin, margin:-margin]


def interior_fields(image: np.ndarray, sigma: float, supersample: int,
                    margin: int | None = None) -> tuple[np.ndarray, np.ndarray, int]:
    """Interface density M (1/voxel) and void indicator of the window's level set on the
    interior box (``margin`` sub-voxels from every face; None: :func:`default_margin`).

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        Window image, void = 0.
    sigma : float
        Gaussian width (voxels).
    supersample : int
        Sub-voxels per voxel.
    margin : int, optional
        Margin in sub-voxels.

    Returns
    -------
    density : ndarray
        M on the interior box (Ma & Torquato 2020, Eq. 9; 1/voxel).
    void : ndarray of bool
        Void indicator of the level-set medium on the interior box.
    margin : int
        The margin used (sub-voxels).
    """
    if margin is None:
        margin = default_margin(sigma, supersample)
    level_set = window_level_set(image, sigma, supersample)
    triangles = interface_triangles(level_set)
    density = surface_density(triangles, level_set.fine.shape, level_set.spacing)
    return _interior(density, margin), _interior(level_set.inside(), margin), int(margin)


def window_specific_surface(image: np.ndarray, sigma: float, supersample: int,
                            margin: int | None = None) -> float:
    """s = sum w M / sum w of one window (Ma & Torquato 2020, Eq. 10), 1/voxel.

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        Window image, void = 0.
    sigma : float
        Gaussian width (voxels).
    supersample : int
        Sub-voxels per voxel.
    margin : int, optional
        Margin in sub-voxels; None: :func:`default_margin`.

    Returns
    -------
    float
        Interior specific surface (1/voxel).
    """
    density, _, _ = interior_fields(image, sigma, supersample, margin)
    return float(density.mean())


def window_correlations(fields: dict, pairs, binning: RadialBinning) -> dict:
    """Minus-sampling correlations F_ab(v) = sum_x a(x) b(x + v) / prod_i (L_i - |v_i|) of the
    named fields on one box of shape (L_z, L_y, L_x) (zero padding to ``binning.shape``,
    nothing wraps), bin-averaged with ``binning`` (from :func:`window_binning` on the box)."""
    shape = next(iter(fields.values())).shape
    padded = binning.shape
    if any(p < n + 1 for n, p in zip(shape, padded)):
        raise ValueError(f"binning shape {padded} is not a padding of the box {shape}")
    pair_count = np.ones(padded)
    for axis, (n, p) in enumerate(zip(shape, padded)):
        lag = np.abs(np.rint(np.fft.fftfreq(p) * p))
        count = np.maximum(n - lag, 1.0)  # displacements beyond the box are never binned
        pair_count = pair_count * count.reshape([-1 if k == axis else 1 for k in range(len(shape))])
    axes = tuple(range(len(shape)))
    spectra = {name: scipy.fft.rfftn(np.asarray(f, dtype=np.float64), s=padded, axes=axes)
               for name, f in fields.items()}
    out = {}
    for a, b in pairs:
        sums = scipy.fft.irfftn(np.conj(spectra[a]) * spectra[b], s=padded, axes=axes)
        out[(a, b)] = binning.average(sums / pair_count)
    return out


def window_surface_binning(interior_shape, supersample: int, r_max: float,
                           bin_width: float) -> RadialBinning:
    """Bins of the window surface functions: the displacements and bins of the periodic
    ``surface_binning(..., "lattice")`` for the same r_max (sub-voxel units), laid out on the
    interior box zero-padded by r_max.

    Parameters
    ----------
    interior_shape : tuple of int
        Interior box in sub-voxels.
    supersample : int
        Sub-voxels per voxel.
    r_max, bin_width : float
        Largest distance and bin width (voxels); r_max < half the interior side.

    Returns
    -------
    RadialBinning
        On the padded grid; ``r_mean / supersample`` in voxels.
    """
    return window_binning(interior_shape, r_max * supersample, bin_width * supersample)


def window_descriptors(image: np.ndarray, sigma: float, supersample: int, r_max: float,
                       bin_width: float, margin: int | None = None) -> dict:
    """s, F_sv, F_ss, S2 of the void and the void fraction of one window's level set on its
    interior (module docstring; Ma & Torquato 2020, Eqs. 10, 11, 15).

    Parameters
    ----------
    image : ndarray, shape (nz, ny, nx)
        Window image, void = 0.
    sigma : float
        Gaussian width (voxels).
    supersample : int
        Sub-voxels per voxel.
    r_max, bin_width : float
        Largest distance and bin width (voxels).
    margin : int, optional
        Margin in sub-voxels; None: :func:`default_margin`.

    Returns
    -------
    dict
        ``s``, ``phi_void`` (floats), ``F_sv``, ``F_ss``, ``S2_void`` (per bin), ``r`` (bin
        mean distance, voxels), ``margin`` (sub-voxels).
    """
    density, void, margin = interior_fields(image, sigma, supersample, margin)
    binning = window_surface_binning(density.shape, supersample, r_max, bin_width)
    correlations = window_correlations({"M": density, "void": void},
                                       [("M", "void"), ("M", "M"), ("void", "void")], binning)
    return {"s": float(density.mean()), "phi_void": float(void.mean()),
            "F_sv": correlations[("M", "void")], "F_ss": correlations[("M", "M")],
            "S2_void": correlations[("void", "void")], "r": binning.r_mean / supersample,
            "margin": margin}


def window_surface_functions(images, *, sigma: float, supersample: int, r_max: float,
                             bin_width: float, margin: int | None = None,
                             log=None) -> xr.Dataset:
    """F_sv(r), F_ss(r) (Ma & Torquato 2020, Eqs. 11, 15; void = image value 0) and s
    (Eq. 10) of a stack of non-periodic 3D window images by minus-sampling on the interior
    of each window's level set; per sample, mean and SEM. Variable names and units as
    :func:`randmedia.describe.surface.surface_functions` for 3D (no Euler characteristic
    or wrapping flags: those need the whole torus).

    Parameters
    ----------
    images : array_like, shape (n_samples, nz, ny, nx)
        Window images, void = 0.
    sigma : float
        Gaussian width of the level sets (voxels).
    supersample : int
        Sub-voxels per voxel along each axis.
    r_max, bin_width : float
        Largest distance and bin width (voxels; ``bin_width`` a multiple of 1/supersample).
    margin : int, optional
        Interior margin in sub-voxels; None: :func:`default_margin` (kernel radius + 1 voxel).
    log : logging.Logger, optional
        Progress log.

    Returns
    -------
    xarray.Dataset
        ``F_sv`` (1/voxel), ``F_ss`` (1/voxel^2), ``S2_void`` with ``*_samples``, ``*_sem`` on
        ``r`` (voxels); ``s_samples``, ``phi_void_samples``; attrs include
        ``estimator="window"``, ``margin`` (sub-voxels) and ``margin_voxels``.
    """
    images = np.asarray(images)
    if images.ndim != 4:
        raise ValueError(f"expected images of shape (n_samples, nz, ny, nx), got {images.shape}")
    if margin is None:
        margin = default_margin(sigma, supersample)
    progress = Progress(images.shape[0], "window surface functions", log, unit="images")
    results = []
    for image in images:
        results.append(window_descriptors(image, sigma, supersample, r_max, bin_width, margin))
        progress.step()

    def stack(name):
        return np.array([res[name] for res in results])

    unit = "voxel"
    data = curve_variables({name: stack(name) for name in ("F_sv", "F_ss", "S2_void")}, unit)
    data["s_samples"] = ("sample", stack("s"), {"units": f"1/{unit}", "long_name":
                         "specific surface of the level-set medium (interface area per volume) "
                         "on the window's interior"})
    data["phi_void_samples"] = ("sample", stack("phi_void"), {"units": "1", "long_name":
                                "void fraction of the level-set medium on the window's interior"})
    attrs = {"sigma": float(sigma), "supersample": int(supersample), "level_set_model": "pixels",
             "bin_width": float(bin_width), "bin_weighting": "lattice", "r_max": float(r_max),
             "dimension": 3, "estimator": "window", "margin": int(margin),
             "margin_voxels": margin / supersample, "boundary_mode": BOUNDARY_MODE}
    return xr.Dataset(
        data,
        coords={
            "r": ("r", results[0]["r"], {"units": unit, "long_name": "mean distance of the "
                                         "displacements in the bin (weighted like the averages)"}),
            "sample": ("sample", np.arange(len(results)), {"units": "1", "long_name": "sample index"}),
        },
        attrs=attrs,
    )


def mean_window_specific_surface(images, sigma: float, supersample: int,
                                 margin: int | None = None) -> float:
    """Sample mean of :func:`window_specific_surface` (1/voxel).

    Parameters
    ----------
    images : array_like, shape (n_samples, nz, ny, nx)
        Window images, void = 0.
    sigma : float
        Gaussian width (voxels).
    supersample : int
        Sub-voxels per voxel.
    margin : int, optional
        Margin in sub-voxels; None: :func:`default_margin` at this sigma.

    Returns
    -------
    float
        Mean interior s.
    """
    return float(np.mean([window_specific_surface(image, sigma, supersample, margin)
                          for image in images]))


def tune_sigma_window(images, s_target: float, *, supersample: int, margin: int | None = None,
                      bracket=(0.1, 3.0), xtol: float = 2e-3, log=None) -> tuple[float, float]:
    """The sigma at which the windows' interior level sets have, on average, the specific
    surface ``s_target`` (Ma & Torquato 2020, Sec. V A): :func:`randmedia.describe.surface.tune_sigma`
    (Brent) with :func:`mean_window_specific_surface` plugged in.

    Parameters
    ----------
    images : array_like, shape (n_samples, nz, ny, nx)
        Window images, void = 0.
    s_target : float
        Target specific surface (1/voxel; 4 phi1 phi2 / a for a Debye medium).
    supersample : int
        Sub-voxels per voxel.
    margin : int, optional
        Margin in sub-voxels, fixed over the search; None: :func:`default_margin` at
        ``bracket[1]`` (valid for every sigma searched).
    bracket : tuple of float, optional
        (lo, hi) of sigma searched (voxels).
    xtol : float, optional
        Tolerance on sigma (voxels).
    log : logging.Logger, optional
        Progress log.

    Returns
    -------
    sigma : float
        Tuned width (voxels).
    s : float
        Mean interior s at ``sigma``.
    """
    images = np.asarray(images)
    if margin is None:
        margin = default_margin(bracket[1], supersample)

    def specific_surface(stack, sigma):
        return mean_window_specific_surface(stack, sigma, supersample, margin)

    return tune_sigma(images, s_target, supersample=supersample, bracket=bracket, xtol=xtol,
                      log=log, specific_surface=specific_surface)
