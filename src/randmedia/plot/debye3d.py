"""Figures of the 3D Debye study (issue 13, beyond the papers; docs/debye3d.md).

Registry :data:`FIGURES` (convention: :mod:`randmedia.plot.rule`): ``media`` (a mid-plane
slice of one sample per volume fraction, constructions above Poisson planes), ``s2`` (the
autocovariance of every system against its exact form).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from randmedia.generate.voxel_images import VOXEL_IMAGE
from randmedia.io import read_dataset
from randmedia.plot.style import PAGE_WIDTH, figure

#: void (phase 1) and solid (phase 2), as in the 2D paper's Fig. 1
PHASE_COLOURS = ("#3b0f70", "#fde725")


def _system_of(ds: xr.Dataset) -> tuple[str, float]:
    return str(ds.attrs["kind"]), float(ds.attrs["phi2"])


def media(inputs, settings, log):
    """Mid-plane slices (z = N/2) of sample 0 of every Debye system: constructions (top row)
    and Poisson-plane windows (bottom row, if any), one column per phi2.

    Parameters
    ----------
    inputs : dict
        ``samples``: voxel-image files (sample 0 of each system).
    settings : dict
        ``a`` (voxels, for the scale label).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.colors import ListedColormap

    slices = {}
    for path in inputs["samples"]:
        ds = read_dataset(path, VOXEL_IMAGE, attrs=["kind", "phi2"])
        image = ds["phase"].values
        slices[_system_of(ds)] = image[image.shape[0] // 2]
    kinds = [kind for kind in ("yt", "planes") if any(k == kind for k, _ in slices)]
    phis = sorted({phi for _, phi in slices})
    fig, axes = figure(ncols=len(phis), nrows=len(kinds), width=PAGE_WIDTH, aspect=1.0, squeeze=False)
    cmap = ListedColormap(PHASE_COLOURS)
    names = {"yt": "construction", "planes": "Poisson planes"}
    for row, kind in enumerate(kinds):
        for col, phi in enumerate(phis):
            ax = axes[row, col]
            ax.set_xticks([])
            ax.set_yticks([])
            if (kind, phi) not in slices:
                ax.set_visible(False)
                continue
            ax.imshow(slices[kind, phi], cmap=cmap, vmin=0, vmax=1, interpolation="nearest",
                      origin="lower")
            ax.set_title(f"{names[kind]}, $\\phi_2$ = {phi:g}", fontsize=7)
    fig.suptitle(f"3D Debye media, mid-plane slices (a = {settings['a']:g} voxels)", fontsize=8)
    return fig


def s2(inputs, settings, log):
    """chi_V(r) / (phi1 phi2) = (S2(r) - phi1^2) / (phi1 phi2) of the void, mean +- SEM, per
    system against exact: e^(-r/a) for the Debye media (constructions, Poisson planes) and
    the overlapping spheres' exact S2 (Eq. 32, d = 3), on a log scale against r / length.

    Parameters
    ----------
    inputs : dict
        ``s2``: S2 files of every system (:func:`randmedia.studies.debye3d.s2_dataset`).
    settings : dict
        unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, axes = figure(ncols=3, nrows=1, width=PAGE_WIDTH, aspect=0.9)
    panels = {"yt": axes[0], "planes": axes[1], "spheres": axes[2]}
    titles = {"yt": "constructions (periodic)", "planes": "Poisson planes (window estimator)",
              "spheres": "overlapping spheres"}
    for path in inputs["s2"]:
        ds = xr.load_dataset(path)
        kind, phi2 = str(ds.attrs["kind"]), float(ds.attrs["phi2"])
        length = float(ds.attrs["radius"] if kind == "spheres" else ds.attrs["a"])
        phi1 = 1.0 - phi2
        r = ds["r"].values
        scale = phi1 * phi2
        chi = (ds["S2"].values - phi1**2) / scale
        ax = panels[kind]
        keep = r > 0
        line = ax.errorbar(r[keep] / length, chi[keep], yerr=ds["S2_sem"].values[keep] / scale,
                           fmt="o", ms=2, lw=0.6, label=f"$\\phi_2$ = {phi2:g}")
        exact = (ds["S2_exact"].values - phi1**2) / scale
        ax.plot(r[keep] / length, exact[keep], "-", lw=0.8, color=line[0].get_color())
    for kind, ax in panels.items():
        ax.set_yscale("log")
        ax.set_ylim(1e-3, 1.2)
        ax.set_xlabel("r / R" if kind == "spheres" else "r / a")
        ax.set_title(titles[kind], fontsize=7)
        if ax.has_data():
            ax.legend(fontsize=5)
    axes[0].set_ylabel(r"$\chi_V(r) / (\phi_1\phi_2)$ (lines: exact)")
    return fig


#: figure key -> function (see :mod:`randmedia.plot.rule`)
FIGURES = {"media": media, "s2": s2}
