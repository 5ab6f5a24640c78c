"""Protocol of the 3D Debye study (issue 13, beyond the papers; docs/debye3d.md).

Systems: Yeong-Torquato constructions of the Debye S2 (Ma & Torquato 2020, Eq. 21) on
periodic N^3 voxels (kind ``yt``), Poisson-plane tessellations with independently coloured
cells -- exactly the same S2, a different microstructure, observed in a non-periodic window
(``planes``) -- and digitized overlapping spheres (``spheres``), whose descriptors are known
exactly in 3D (:mod:`randmedia.theory.overlapping`) and validate every estimator first.

This module turns a system's parameters (one entry of the workflow's system table,
:func:`randmedia.config.debye3d_systems`) and its sample images into the descriptor datasets: which estimator, which exact reference, which
ranges (in units of the system's length: a for the Debye media, R for the spheres).
"""

from __future__ import annotations

import functools
from typing import Callable, Mapping

import numpy as np
import xarray as xr

from randmedia.config import debye3d_system_length, debye3d_window_margin
from randmedia.describe.two_phase import s2_discrepancy, two_point_function
from randmedia.describe.window import window_binning, window_s2_samples
from randmedia.generate.voxel_images import VOXEL_IMAGE
from randmedia.io import read_dataset
from randmedia.numerics.radial import RadialBinning
from randmedia.stats import standard_error
from randmedia.theory import overlapping
from randmedia.theory.debye import debye_s2

#: the three kinds of 3D media (module docstring)
KINDS = ("yt", "planes", "spheres")


def read_voxel_images(paths) -> tuple[np.ndarray, bool]:
    """Stack the ``phase`` images of the sample files; (images (n, nz, ny, nx) uint8, periodic).
    All files must agree on being periodic cells or windows."""
    images, periodic = [], set()
    for path in paths:
        ds = read_dataset(path, VOXEL_IMAGE, attrs=["periodic"])
        images.append(ds["phase"].values)
        periodic.add(bool(ds.attrs["periodic"]))
    if len(periodic) != 1:
        raise ValueError(f"samples mix periodic cells and windows: {list(map(str, paths))}")
    return np.stack(images), periodic.pop()


def exact_void_s2(params: Mapping) -> Callable[[np.ndarray], np.ndarray]:
    """S2 of the void (phase 1) that the system has exactly: Debye, phi1^2 + phi1 phi2 e^(-r/a)
    (Eq. 21 with chi_V unchanged by swapping the phases), or overlapping spheres (Eq. 32, d = 3)."""
    phi2 = float(params["phi2"])
    if params["kind"] == "spheres":
        return functools.partial(overlapping.s2_void, radius=float(params["radius"]), phi2=phi2, dim=3)

    def debye_void(r):
        return debye_s2(r, 1.0 - phi2, float(params["a"]))

    return debye_void


def s2_dataset(images: np.ndarray, periodic: bool, params: Mapping) -> xr.Dataset:
    """S2 of the void phase (image value 0) out to ``params["s2_r_max"]`` voxels, per sample,
    mean and SEM, with the exact bin average ``S2_exact``; periodic estimator for periodic
    cells, window estimator for windows (:mod:`randmedia.describe.window`). For the
    constructions also Delta S2 of phase 2 per sample over 0 < r <= l_c (Sec. IV).

    Parameters
    ----------
    images : ndarray, shape (n_samples, nz, ny, nx)
        0/1 images, 1 = phase 2.
    periodic : bool
        Periodic cells (True) or windows of a non-periodic medium.
    params : Mapping
        The system's parameters: ``kind``, ``phi2``, ``a`` or ``radius``, ``s2_r_max``
        (voxels), and ``lc`` for the constructions.

    Returns
    -------
    xarray.Dataset
        ``S2``, ``S2_sem``, ``S2_samples``, ``S2_exact`` on ``r`` (voxels), ``phi_samples``;
        ``delta_S2`` per sample for the constructions.
    """
    r_max = float(params["s2_r_max"])
    exact = exact_void_s2(params)
    shape = images.shape[1:]
    if periodic:
        s2 = two_point_function(images, phase=0, r_max=r_max)
        binning = RadialBinning.build(shape, r_max)
    else:
        binning = window_binning(shape, r_max)
        curves = window_s2_samples(images, 0, r_max)
        s2 = xr.Dataset(
            {"S2_samples": (("sample", "r"), curves, {"units": "1", "long_name":
                            "window two-point function of phase 0 per sample"}),
             "S2": ("r", curves.mean(axis=0), {"units": "1", "long_name":
                    "window two-point function of phase 0, sample mean"}),
             "S2_sem": ("r", standard_error(curves), {"units": "1", "long_name":
                        "standard error of the mean of S2 over samples"}),
             "phi_samples": ("sample", (images == 0).mean(axis=(1, 2, 3)),
                             {"units": "1", "long_name": "volume fraction of phase 0 per sample"})},
            coords={"r": ("r", binning.r_mean, {"units": "pixel", "long_name":
                          "mean distance of the voxel pairs in the bin"}),
                    "sample": ("sample", np.arange(images.shape[0]), {"units": "1",
                               "long_name": "sample index"})},
            attrs={"phase": 0, "bin_width": 1.0, "r_max": r_max, "estimator": "window"})
    s2["S2_exact"] = ("r", binning.average_of(exact), {"units": "1", "long_name":
                      "exact S2 of the void, averaged over the bin's displacements"})
    s2["r"].attrs["units"] = "voxel"
    if params["kind"] == "yt":
        phase2 = two_point_function(images, phase=1, r_max=float(params["lc"]))
        target = functools.partial(debye_s2, phi2=float(params["phi2"]), a=float(params["a"]))
        s2["delta_S2"] = ("sample", s2_discrepancy(phase2, target, shape), {"units": "1",
                          "long_name": "mean |S2 - target| over bins 0 < r <= l_c (the constructed range)"})
    s2.attrs.update({key: value for key, value in params.items()
                     if isinstance(value, (int, float, str)) and not isinstance(value, bool)})
    s2.attrs["periodic"] = int(periodic)
    return s2


#: kinds whose periodic level-set descriptors (surface functions, pores, chords) are computed.
#: The Poisson-plane windows are not periodic and these estimators wrap around the image (the
#: seam adds ~6 phi1 phi2 / L of interface per volume); they get S2, the surface functions and
#: the chords by the window (minus-sampling) estimators (:func:`window_surface_dataset`,
#: :func:`chords_dataset`).
LEVEL_SET_KINDS = ("yt", "spheres")
#: kinds observed in non-periodic windows
WINDOW_KINDS = ("planes",)


def is_window(params: Mapping) -> bool:
    """Whether the system's samples are windows of a non-periodic medium (:data:`WINDOW_KINDS`)."""
    return params["kind"] in WINDOW_KINDS


def exact_specific_surface(params: Mapping) -> float:
    """The exact specific surface of the system: 4 phi1 phi2 / a for the Debye media (3D,
    Eq. 7 with Eq. 21) and that of overlapping spheres (Eq. 34 in 3D)."""
    from randmedia.theory.debye_formulas import debye_specific_surface

    if params["kind"] == "spheres":
        return float(overlapping.specific_surface(float(params["radius"]), float(params["phi2"]), dim=3))
    return float(debye_specific_surface(float(params["a"]), float(params["phi2"]), dim=3))


def level_set_datasets(images: np.ndarray, params: Mapping, interface: Mapping,
                       rng: np.random.Generator, log=None) -> tuple[xr.Dataset, xr.Dataset]:
    """F_sv, F_ss, s and wrapping (surface) and F, P, <delta> (pores) of the void of one
    system's periodic 3D images, on Ma-Torquato level sets whose Gaussian width is tuned so
    that their mean specific surface is the exact one (as for the 2D media, Sec. V A).

    Parameters
    ----------
    images : ndarray, shape (n_samples, nz, ny, nx)
        Periodic 0/1 images, void = 0.
    params : Mapping
        The system's parameters (:func:`randmedia.config.debye3d_systems`).
    interface : Mapping
        The config section ``debye3d.interface`` (model, supersample, sigma_bracket,
        r_max_over_length, bin_width, bin_weighting, delta_bin, delta_max_over_length,
        k_candidates).
    rng : numpy.random.Generator
        Source of the pore-size query points.
    log : logging.Logger, optional
        Progress log.

    Returns
    -------
    surface, pores : xarray.Dataset
        :func:`randmedia.describe.surface.surface_functions` and
        :func:`randmedia.describe.pore_size.pore_size_functions` outputs, with attributes
        ``sigma``, ``s_exact``, ``s_tuned``, ``length_scale``, ``kind``, ``phi2``.
    """
    from randmedia.describe.pore_size import pore_size_functions
    from randmedia.describe.surface import surface_functions, tune_sigma

    length = debye3d_system_length(params)
    s_exact = exact_specific_surface(params)
    sigma, s_tuned = tune_sigma(images, s_exact, supersample=interface["supersample"],
                                model=interface["model"], bracket=tuple(interface["sigma_bracket"]),
                                log=log)
    common = dict(sigma=sigma, supersample=interface["supersample"], model=interface["model"])
    surface = surface_functions(images, r_max=interface["r_max_over_length"] * length,
                                bin_width=interface["bin_width"],
                                bin_weighting=interface["bin_weighting"], log=log, **common)
    pores = pore_size_functions(images, rng, delta_max=interface["delta_max_over_length"] * length,
                                delta_bin=interface["delta_bin"],
                                k_candidates=interface["k_candidates"], log=log, **common)
    attrs = {"kind": params["kind"], "phi2": float(params["phi2"]), "length_scale": length,
             "s_exact": s_exact, "s_tuned": s_tuned, "image_side": int(images.shape[-1])}
    for ds in (surface, pores):
        ds.attrs.update(attrs)
    return surface, pores


#: window pore sizes stop at this fraction of the interior side (reduced-sample estimator:
#: at delta = side / 4 the query points farther than delta from the faces fill 1/8 of it)
WINDOW_DELTA_FRACTION = 0.25


def window_pores_dataset(images: np.ndarray, params: Mapping, interface: Mapping, level_set: Mapping,
                         rng: np.random.Generator, log=None) -> xr.Dataset:
    """F, P, <delta> of the void of one system's 3D windows by the reduced-sample estimator
    (:func:`randmedia.describe.window_pores.window_pore_size_functions`) on the level set of the
    window surface functions (``level_set``: its file's attributes ``sigma``, ``supersample``,
    ``margin``);
    delta up to ``interface["delta_max_over_length"]`` lengths, at most
    :data:`WINDOW_DELTA_FRACTION` of the interior side.

    Parameters
    ----------
    images : ndarray, shape (n_samples, nz, ny, nx)
        0/1 window images, void = 0.
    params : Mapping
        The system's parameters (:func:`randmedia.config.debye3d_systems`).
    interface : Mapping
        The config section ``debye3d.interface`` (delta_bin, delta_max_over_length,
        k_candidates).
    level_set : Mapping
        The window surface file's attributes.
    rng : numpy.random.Generator
        Source of the query points.
    log : logging.Logger, optional
        Progress log.

    Returns
    -------
    xarray.Dataset
        With attributes ``kind``, ``phi2``, ``length_scale``, ``s_exact``, ``image_side``.
    """
    from randmedia.describe.window_pores import window_pore_size_functions
    from randmedia.numerics.gaussian import default_margin

    length = debye3d_system_length(params)
    sigma, supersample = float(level_set["sigma"]), int(level_set["supersample"])
    margin = int(level_set.get("margin", default_margin(sigma, supersample)))
    interior = min(images.shape[1:]) - 2 * margin / supersample
    delta_bin = float(interface["delta_bin"])
    delta_max = min(interface["delta_max_over_length"] * length, WINDOW_DELTA_FRACTION * interior)
    delta_max = delta_bin * max(2, int(delta_max / delta_bin))
    pores = window_pore_size_functions(images, rng, sigma=sigma, supersample=supersample, delta_max=delta_max,
                                       delta_bin=delta_bin, margin=margin, k_candidates=interface["k_candidates"],
                                       log=log)
    pores.attrs.update({"kind": params["kind"], "phi2": float(params["phi2"]), "length_scale": length,
                        "s_exact": exact_specific_surface(params), "image_side": int(images.shape[-1])})
    return pores


def chords_dataset(images: np.ndarray, params: Mapping, chords: Mapping,
                   rng: np.random.Generator, level_set: Mapping | None = None) -> xr.Dataset:
    """L(z) and p(z) of the void of one system's 3D images along lines in many directions:
    through the periodic images (:func:`randmedia.describe.chords.lineal_path_and_chords`) or,
    for window systems (Poisson planes), along lines clipped to the window's interior
    (:func:`randmedia.describe.window_chords.window_lineal_path_and_chords`, "pixels" level
    set only). On the level set of the surface functions when ``chords["sigma"]`` is "tuned"
    (``level_set``: its ``sigma``, ``supersample``, ``level_set_model`` -- the surface file's
    attributes).

    Parameters
    ----------
    images : ndarray, shape (n_samples, nz, ny, nx)
        0/1 images, void = 0.
    params : Mapping
        The system's parameters (:func:`randmedia.config.debye3d_systems`).
    chords : Mapping
        The config section ``debye3d.chords`` (z_max_over_length, sigma and the sampling
        keywords).
    rng : numpy.random.Generator
        Source of the directions and origins.
    level_set : Mapping, optional
        Required when ``chords["sigma"]`` is "tuned".

    Returns
    -------
    xarray.Dataset
        With attributes ``kind``, ``phi2``, ``length_scale``, ``s_exact``.
    """
    from randmedia.describe.chords import lineal_path_and_chords
    from randmedia.describe.window_chords import window_lineal_path_and_chords

    sampling = dict(chords)
    length = debye3d_system_length(params)
    z_max = sampling.pop("z_max_over_length") * length
    if sampling["sigma"] == "tuned":
        if level_set is None:
            raise ValueError("chords sigma 'tuned' needs the surface functions' level set")
        sampling.update(sigma=float(level_set["sigma"]), supersample=int(level_set["supersample"]),
                        model=str(level_set["level_set_model"]))
    if is_window(params):
        model = sampling.pop("model", "pixels")
        if model != "pixels":
            raise ValueError(f"debye3d chords of window system {params['kind']!r}: the window estimator "
                             f"walks the 'pixels' level set only, got model {model!r}")
        sampling["supersample"] = int(sampling.get("supersample", 1))
        margin = int(level_set["margin"]) if level_set is not None and "margin" in level_set else None
        out = window_lineal_path_and_chords(images, 0, rng, z_max=z_max, margin=margin, **sampling)
        sampling["model"] = model
    else:
        out = lineal_path_and_chords(images, 0, rng, z_max=z_max, **sampling)
    out.attrs.update({"kind": params["kind"], "phi2": float(params["phi2"]), "length_scale": length,
                      "s_exact": exact_specific_surface(params), "sigma": float(sampling["sigma"]),
                      "level_set_model": str(sampling.get("model", "bilinear")),
                      "supersample": int(sampling.get("supersample", 1))})
    return out


def window_surface_dataset(images: np.ndarray, params: Mapping, interface: Mapping,
                           log=None) -> xr.Dataset:
    """F_sv, F_ss and s of the void of one system's non-periodic 3D windows by minus-sampling
    on the interior of level sets whose Gaussian width is tuned to the exact s
    (:mod:`randmedia.describe.window_surface`; "pixels" model, the interface section's
    supersample, r range and bin width).

    Parameters
    ----------
    images : ndarray, shape (n_samples, nz, ny, nx)
        0/1 window images, void = 0.
    params : Mapping
        The system's parameters (:func:`randmedia.config.debye3d_systems`).
    interface : Mapping
        The config section ``debye3d.interface``.
    log : logging.Logger, optional
        Progress log.

    Returns
    -------
    xarray.Dataset
        :func:`randmedia.describe.window_surface.window_surface_functions` output with the
        attributes of :func:`level_set_datasets`.
    """
    from randmedia.describe.window_surface import tune_sigma_window, window_surface_functions

    length = debye3d_system_length(params)
    s_exact = exact_specific_surface(params)
    margin = debye3d_window_margin(interface)
    sigma, s_tuned = tune_sigma_window(images, s_exact, supersample=interface["supersample"], margin=margin,
                                       bracket=tuple(interface["sigma_bracket"]), log=log)
    surface = window_surface_functions(images, sigma=sigma, supersample=interface["supersample"],
                                       r_max=interface["r_max_over_length"] * length,
                                       bin_width=interface["bin_width"], margin=margin, log=log)
    surface.attrs.update({"kind": params["kind"], "phi2": float(params["phi2"]), "length_scale": length,
                          "s_exact": s_exact, "s_tuned": s_tuned, "image_side": int(images.shape[-1]),
                          "sigma": float(sigma), "level_set_model": "pixels"})
    return surface
