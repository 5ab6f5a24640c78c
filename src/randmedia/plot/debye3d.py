"""Figures of the 3D Debye study (issue 13, beyond the papers; docs/debye3d.md).

Registry :data:`FIGURES` (convention: :mod:`randmedia.plot.rule`): ``media`` (a mid-plane
slice of one sample per volume fraction, constructions above Poisson planes), ``s2`` (the
autocovariance of every system against its exact form), ``surface`` (F_sv, F_ss against the
conjectures Eqs. 44-45), ``pores`` (F(delta)), ``chords`` (L(z), p(z) against exponentials).
"""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import NullFormatter
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


def _by_kind(paths, kind="yt"):
    """Descriptor datasets: (those of ``kind`` sorted by phi2, the spheres')."""
    debye, spheres = [], []
    for path in paths:
        ds = xr.load_dataset(path)
        if ds.attrs["kind"] == "spheres":
            spheres.append(ds)
        elif ds.attrs["kind"] == kind:
            debye.append(ds)
    return sorted(debye, key=lambda ds: float(ds.attrs["phi2"])), spheres


def surface(inputs, settings, log):
    """F_sv(r) a and F_ss(r) a^2 of the constructions against the conjectures Eqs. (44)-(45)
    (dashed), the Poisson-plane windows of the same phi2 (open markers) with their exact
    functions (dotted, :mod:`randmedia.theory.poisson_planes`), and the overlapping spheres'
    F_sv / s, F_ss / s^2 against exact (validation).

    Parameters
    ----------
    inputs : dict
        ``descriptors``: surface files of the periodic systems.
    settings : dict
        unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from randmedia.theory import overlapping, poisson_planes
    from randmedia.theory.debye_formulas import debye_surface_surface, debye_surface_void

    yt, spheres = _by_kind(inputs["descriptors"])
    planes = {float(ds.attrs["phi2"]): ds for ds in _by_kind(inputs["descriptors"], "planes")[0]}
    fig, axes = figure(ncols=3, nrows=1, width=PAGE_WIDTH, aspect=0.9)
    for ds in yt:
        a, phi2 = float(ds.attrs["length_scale"]), float(ds.attrs["phi2"])
        r = ds["r"].values
        keep = r > 0
        fine = np.linspace(max(r[keep][0], 0.05 * a), r[-1], 200)
        line = axes[0].errorbar(r[keep] / a, a * ds["F_sv"].values[keep], yerr=a * ds["F_sv_sem"].values[keep],
                                fmt="o", ms=1.5, lw=0.5, label=f"$\\phi_2$ = {phi2:g}")
        colour = line[0].get_color()
        axes[0].plot(fine / a, a * debye_surface_void(fine, phi2, a, dim=3), "--", lw=0.8, color=colour)
        axes[1].errorbar(r[keep] / a, a * a * ds["F_ss"].values[keep], yerr=a * a * ds["F_ss_sem"].values[keep],
                         fmt="o", ms=1.5, lw=0.5, color=colour)
        axes[1].plot(fine / a, a * a * debye_surface_surface(fine, phi2, a, dim=3), "--", lw=0.8, color=colour)
        if phi2 in planes:  # same S2, another medium: open markers
            other = planes[phi2]
            rp = other["r"].values
            kept = rp > 0
            axes[0].plot(rp[kept] / a, a * other["F_sv"].values[kept], "o", ms=2, mfc="none", mew=0.4,
                         color=colour)
            axes[1].plot(rp[kept] / a, a * a * other["F_ss"].values[kept], "o", ms=2, mfc="none", mew=0.4,
                         color=colour)
            axes[0].plot(fine / a, a * poisson_planes.surface_void(fine, phi2, a, dim=3), ":", lw=0.8, color=colour)
            axes[1].plot(fine / a, a * a * poisson_planes.surface_surface(fine, phi2, a, dim=3), ":", lw=0.8,
                         color=colour)
    for ds in spheres:
        radius, phi2 = float(ds.attrs["length_scale"]), float(ds.attrs["phi2"])
        s_exact = float(ds.attrs["s_exact"])
        r = ds["r"].values
        keep = r > 0
        axes[2].errorbar(r[keep] / radius, ds["F_sv"].values[keep] / s_exact, fmt="o", ms=1.5, lw=0.5,
                         yerr=ds["F_sv_sem"].values[keep] / s_exact, label="$F_{sv}/s$")
        axes[2].errorbar(r[keep] / radius, ds["F_ss"].values[keep] / s_exact**2, fmt="s", ms=1.5, lw=0.5,
                         yerr=ds["F_ss_sem"].values[keep] / s_exact**2, label="$F_{ss}/s^2$")
        fine = np.linspace(r[keep][0], r[-1], 300)
        axes[2].plot(fine / radius, overlapping.surface_void(fine, radius, phi2, dim=3) / s_exact, "k-", lw=0.7)
        axes[2].plot(fine / radius, overlapping.surface_surface(fine, radius, phi2, dim=3) / s_exact**2,
                     "k-", lw=0.7)
        axes[2].set_ylim(0, 3)
    # long descriptions as panel titles: y-labels this long overlapped the next panel
    axes[0].set_ylabel(r"$a F_{sv}(r)$")
    axes[0].set_title("dashed: Eq. 44; open, dotted: planes", fontsize=6)
    axes[1].set_ylabel(r"$a^2 F_{ss}(r)$")
    axes[1].set_title("dashed: Eq. 45; open, dotted: planes", fontsize=6)
    axes[1].set_yscale("log")
    axes[1].yaxis.set_minor_formatter(NullFormatter())
    axes[2].set_ylabel("overlapping spheres")
    axes[2].set_title("lines: exact", fontsize=6)
    fig.subplots_adjust(wspace=0.4)  # room for the middle and right panels' y-labels
    for ax, label in zip(axes, ("r / a", "r / a", "r / R")):
        ax.set_xlabel(label)
    if axes[0].has_data():  # in room made below the lowest curve (phi2 = 0.1, a F_sv >= 0.19)
        axes[0].set_ylim(bottom=0)
        axes[0].legend(fontsize=5, loc="lower center", ncol=3, columnspacing=0.6, handlelength=1.0,
                       handletextpad=0.3)
    if axes[2].has_data():
        axes[2].legend(fontsize=5)
    return fig


def pores(inputs, settings, log):
    """F(delta) of the constructions per phi2 (against delta / a; dashed: the Poisson-plane
    windows of the same phi2, reduced-sample estimator) and of the overlapping spheres against
    their exact F (Eq. 36, d = 3).

    Parameters
    ----------
    inputs : dict
        ``descriptors``: pore-size files (constructions, Poisson planes, spheres).
    settings : dict
        unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from randmedia.theory import overlapping

    yt, spheres = _by_kind(inputs["descriptors"])
    planes = {float(ds.attrs["phi2"]): ds for ds in _by_kind(inputs["descriptors"], "planes")[0]}
    fig, axes = figure(ncols=2, nrows=1, width=PAGE_WIDTH, aspect=0.7)
    for ds in yt:
        a, phi2 = float(ds.attrs["length_scale"]), float(ds.attrs["phi2"])
        delta = ds["delta"].values
        line = axes[0].errorbar(delta / a, ds["F"].values, yerr=ds["F_sem"].values, fmt="-", lw=0.8,
                                label=f"$\\phi_2$ = {phi2:g}")
        if phi2 in planes:  # same S2, another medium (window estimator): dashed
            other = planes[phi2]
            axes[0].plot(other["delta"].values / a, other["F"].values, "--", lw=0.7, color=line[0].get_color())
    for ds in spheres:
        radius, phi2 = float(ds.attrs["length_scale"]), float(ds.attrs["phi2"])
        delta = ds["delta"].values
        axes[1].errorbar(delta / radius, ds["F"].values, yerr=ds["F_sem"].values, fmt="o", ms=1.5,
                         lw=0.5, label="ours")
        axes[1].plot(delta / radius, overlapping.pore_size_complementary_cdf(delta, radius, phi2, dim=3),
                     "k-", lw=0.7, label="exact")
    axes[0].set_xlabel(r"$\delta / a$")
    axes[0].set_ylabel(r"$F(\delta)$")
    axes[0].set_title("dashed: Poisson planes", fontsize=6)
    axes[1].set_xlabel(r"$\delta / R$")
    axes[1].set_ylabel(r"$F(\delta)$, overlapping spheres")
    for ax in axes:
        ax.set_yscale("log")
        ax.set_ylim(1e-4, 1.1)
        if ax.has_data():
            ax.legend(fontsize=5)
    return fig


def chords(inputs, settings, log):
    """L(z) and p(z) of the constructions against the exponential forms with the exact slope,
    phi1 e^(-phi2 z / a) and (phi2 / a) e^(-phi2 z / a) (dashed; L'(0) = -s/4 with the 3D
    s = 4 phi1 phi2 / a), with the Poisson-plane windows of the same phi2 (open markers; exactly
    exponential), and the overlapping spheres' L(z) against exact (Eq. 38, d = 3).

    Parameters
    ----------
    inputs : dict
        ``descriptors``: chords files (constructions, Poisson planes, spheres).
    settings : dict
        unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from randmedia.theory import overlapping

    yt, spheres = _by_kind(inputs["descriptors"])
    planes = {float(ds.attrs["phi2"]): ds for ds in _by_kind(inputs["descriptors"], "planes")[0]}
    fig, axes = figure(ncols=3, nrows=1, width=PAGE_WIDTH, aspect=0.9)
    for ds in yt:
        a, phi2 = float(ds.attrs["length_scale"]), float(ds.attrs["phi2"])
        z, zc = ds["z"].values, ds["z_chord"].values
        line = axes[0].errorbar(z / a, ds["L"].values, yerr=ds["L_sem"].values, fmt="-", lw=0.8,
                                label=f"$\\phi_2$ = {phi2:g}")
        colour = line[0].get_color()
        axes[0].plot(z / a, (1 - phi2) * np.exp(-phi2 * z / a), "--", lw=0.7, color=colour)
        axes[1].errorbar(zc / a, a * ds["p"].values, yerr=a * ds["p_sem"].values, fmt="o", ms=1.5,
                         lw=0.5, color=colour)
        axes[1].plot(zc / a, phi2 * np.exp(-phi2 * zc / a), "--", lw=0.7, color=colour)
        if phi2 in planes:  # same S2, another medium (exactly exponential): open markers
            other = planes[phi2]
            zp, zcp = other["z"].values, other["z_chord"].values
            axes[0].plot(zp[::4] / a, other["L"].values[::4], "o", ms=2, mfc="none", mew=0.4, color=colour)
            axes[1].plot(zcp / a, a * other["p"].values, "o", ms=2, mfc="none", mew=0.4, color=colour)
    for ds in spheres:
        radius, phi2 = float(ds.attrs["length_scale"]), float(ds.attrs["phi2"])
        z = ds["z"].values
        axes[2].errorbar(z / radius, ds["L"].values, yerr=ds["L_sem"].values, fmt="o", ms=1.5, lw=0.5,
                         label="ours")
        axes[2].plot(z / radius, overlapping.lineal_path_void(z, radius, phi2, dim=3), "k-", lw=0.7,
                     label="exact")
    axes[0].set_ylabel("L(z)")
    axes[0].set_title("dashed: exponential; open: Poisson planes", fontsize=6)
    axes[1].set_ylabel("a p(z)")
    axes[1].set_title("dashed: exponential; open: Poisson planes", fontsize=6)
    axes[2].set_ylabel("L(z), spheres")
    for ax, label in zip(axes, ("z / a", "z / a", "z / R")):
        ax.set_xlabel(label)
        ax.set_yscale("log")
        ax.yaxis.set_minor_formatter(NullFormatter())
        if ax.has_data():
            ax.legend(fontsize=5)
    axes[0].set_ylim(1e-3, 1)
    axes[1].set_ylim(1e-3, 1)
    fig.subplots_adjust(wspace=0.4)  # room for the middle and right panels' y-labels
    return fig


#: figure key -> function (see :mod:`randmedia.plot.rule`)
FIGURES = {"media": media, "s2": s2, "surface": surface, "pores": pores, "chords": chords}
