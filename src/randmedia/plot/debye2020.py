"""Figures of the debye2020 pipeline."""

from __future__ import annotations

import numpy as np
import xarray as xr

from randmedia.plot.style import figure, save_figure
from randmedia.theory.overlapping import s2_void


def overlapping_disks_s2(s2: xr.Dataset, *, radius: float, phi2: float, compare_r_max: float,
                         pdf_path) -> None:
    """Validation figure: simulated S2 of overlapping disks against Eqs. (32)-(33).

    Top: S2^(1)(r) (mean +- SEM over samples) and the exact curve, with the
    long-range limit phi1^2. Bottom: deviation in units of the SEM, with the
    +-3 SEM band used by the comparison (up to ``compare_r_max``).
    """
    r = s2["r"].values
    x = r / radius
    fig, (top, bottom) = figure(nrows=2, ncols=1, aspect=0.55, sharex=True,
                                gridspec_kw={"height_ratios": [2.2, 1]})
    fine = np.linspace(0.0, x.max(), 600)
    exact_fine = s2_void(fine * radius, radius, phi2)
    phi1 = 1.0 - phi2
    top.plot(fine, exact_fine, "k-", label="exact, Eqs. (32)-(33)")
    top.errorbar(x, s2["S2"].values, yerr=s2["S2_sem"].values, fmt="o", mfc="none", color="C0",
                 label=f"{s2.sizes['sample']} digitized images")
    top.axhline(phi1**2, color="0.5", ls=":", lw=0.8, label=r"$\phi_1^2$")
    top.set_ylabel(r"$S_2^{(1)}(r)$")
    top.legend(loc="upper right")
    top.set_title(rf"Overlapping disks, $\phi_2 = {phi2:g}$, $R = {radius:g}$ px")

    deviation = (s2["S2"].values - s2_void(r, radius, phi2)) / s2["S2_sem"].values
    bottom.axhspan(-3, 3, color="0.9")
    bottom.axhline(0, color="k", lw=0.6)
    bottom.plot(x, deviation, "o", mfc="none", color="C0")
    bottom.axvline(compare_r_max / radius, color="0.5", ls="--", lw=0.8)
    bottom.set_xlabel(r"$r/R$")
    bottom.set_ylabel("(ours $-$ exact)/SEM")
    bottom.set_xlim(0, x.max())
    save_figure(fig, pdf_path)


#: phase 1 (void) dark, phase 2 (solid) yellow, as in the paper's Fig. 1
PHASE_COLOURS = ("#3b0f70", "#fde725")


def fig01_media(images_by_phi2: dict, *, a: float, pdf_path) -> None:
    """Fig. 1: one construction per volume fraction, phase 2 (solid) in yellow."""
    from matplotlib.colors import ListedColormap

    from randmedia.plot.style import PAGE_WIDTH

    n = len(images_by_phi2)
    fig, axes = figure(ncols=n, nrows=1, width=PAGE_WIDTH, aspect=1.0)
    axes = np.atleast_1d(axes)
    cmap = ListedColormap(PHASE_COLOURS)
    for label, ax, (phi2, image) in zip("abcdefghij", axes, sorted(images_by_phi2.items())):
        ax.imshow(image, cmap=cmap, vmin=0, vmax=1, interpolation="nearest", origin="lower")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(rf"({label}) $\phi_2 = {phi2:g}$")
    axes[0].set_ylabel(rf"$N = {image.shape[0]}$, $a = {a:g}$ pixels")
    save_figure(fig, pdf_path)


def fig02_s2(s2_by_phi2: dict, *, lc: float, pdf_path) -> None:
    """Fig. 2: S2(r) of the constructions (dashed, mean over samples) and targets (solid)."""
    fig, ax = figure()
    for i, (phi2, s2) in enumerate(sorted(s2_by_phi2.items(), reverse=True)):
        keep = s2["r"].values <= lc
        r = s2["r"].values[keep]
        fine = np.linspace(0.0, r.max(), 400)
        target = phi2 * phi2 + phi2 * (1 - phi2) * np.exp(-fine / float(s2.attrs["a"]))
        ax.plot(fine, target, "k-", lw=1.0, label="target, Eq. (21)" if i == 0 else None)
        ax.plot(r, s2["S2"].values[keep], "--", color=f"C{i}", lw=1.2,
                label=rf"$\phi_2 = {phi2:g}$")
    ax.set_xlabel(r"$r$ (pixels)")
    ax.set_ylabel(r"$S_2(r)$")
    ax.set_xlim(0, lc)
    ax.set_ylim(0, None)
    ax.legend(loc="upper right", ncol=2)
    save_figure(fig, pdf_path)


def fig06_lineal_path(chords_by_phi2: dict, fits, *, a: float, pdf_path) -> None:
    """Fig. 6: (a) L(z) per phi2 with the fit of Eq. (29); (b) fitted L_w against phi2."""
    fig, (left, right) = figure(ncols=2, nrows=1, width=2 * 3.4, aspect=0.75)
    for i, (phi2, ds) in enumerate(sorted(chords_by_phi2.items())):
        z = ds["z"].values
        lw = float(fits["L_w"].sel(phi2=phi2))
        left.plot(z / a, ds["L"].values, "-", color=f"C{i}", label=rf"$\phi_2 = {phi2:g}$")
        left.plot(z / a, (1 - phi2) * np.exp(-z / lw), ":", color=f"C{i}", lw=0.9)
    left.set_yscale("log")
    left.set_ylim(1e-3, 1)
    left.set_xlabel(r"$z/a$")
    left.set_ylabel(r"$L(z)$")
    left.legend(loc="lower left", title="simulation (solid)\nEq. (29) fit (dotted)", fontsize=7,
                title_fontsize=7)
    left.set_title("(a)")
    right.errorbar(fits["phi2"].values, fits["L_w"].values / a, yerr=fits["L_w_err"].values / a,
                   fmt="o-", mfc="none")
    right.set_xlabel(r"$\phi_2$")
    right.set_ylabel(r"$L_w/a$")
    right.set_title("(b)")
    save_figure(fig, pdf_path)


def fig07_chord_density(chords_by_phi2: dict, fits, *, a: float, pdf_path) -> None:
    """Fig. 7: p(z) by direct chord sampling, with Eq. (31) from the fitted L_w."""
    fig, ax = figure()
    for i, (phi2, ds) in enumerate(sorted(chords_by_phi2.items())):
        z = ds["z_chord"].values
        lw = float(fits["L_w"].sel(phi2=phi2))
        ax.plot(z / a, a * ds["p"].values, "o", ms=2, mfc="none", color=f"C{i}",
                label=rf"$\phi_2 = {phi2:g}$")
        ax.plot(z / a, a * a / (phi2 * lw * lw) * np.exp(-z / lw), "-", color=f"C{i}", lw=0.9)
    ax.set_yscale("log")
    ax.set_ylim(1e-4, None)
    ax.set_xlabel(r"$z/a$")
    ax.set_ylabel(r"$a\, p(z)$")
    ax.legend(loc="lower left", title="chord sampling (points)\nEq. (31) with fitted $L_w$ (lines)",
              fontsize=7, title_fontsize=7)
    save_figure(fig, pdf_path)
