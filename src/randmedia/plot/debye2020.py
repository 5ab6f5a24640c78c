"""Figures 1-12 of Ma & Torquato, PRE 102, 043310 (2020), and two validation figures.

:data:`FIGURES` (end of the module) maps each figure to its function: ``figNN(inputs,
settings, log)`` reads the rule's input files (``inputs``: name -> path or list of paths),
takes the config values it uses from ``settings`` and returns the matplotlib figure; the
rules ``debye2020_figNN`` run it through ``workflow/scripts/debye2020/figure.py``
(convention: :mod:`randmedia.plot.rule`). Validation figures beyond the paper are keyed by
name: ``overlapping_disks_s2``, ``overlapping_disks_level_set``.
"""

from __future__ import annotations

import numpy as np

from randmedia.describe.chords import CHORDS
from randmedia.describe.pore_size import PORES
from randmedia.describe.surface import SURFACE
from randmedia.describe.two_phase import TWO_POINT
from randmedia.generate import PHASE_IMAGE
from randmedia.io import read_dataset
from randmedia.plot.style import band, figure, legend_below
from randmedia.theory.overlapping import s2_void


def _by_phi2(paths, spec, attrs=("phi2",)) -> dict:
    """{phi2: dataset} of files (images or descriptors) that each hold one volume fraction."""
    found = {}
    for path in paths:
        ds = read_dataset(path, spec, attrs=list(attrs))
        found[float(ds.attrs["phi2"])] = ds
    return found


def overlapping_disks_s2(inputs, settings, log):
    """Validation figure: simulated S2 of overlapping disks (input ``s2``) against Eqs. (32)-(33).

    Top: S2^(1)(r) (mean +- SEM over samples) and the exact curve, with the
    long-range limit phi1^2. Bottom: deviation in units of the SEM, with the
    +-3 SEM band used by the comparison (up to ``compare_r_max``).

    Parameters
    ----------
    inputs : dict
        ``s2``: path of the two-point descriptor file.
    settings : dict
        ``radius`` (disk radius R, pixels), ``phi2``, ``compare_r_max`` (pixels).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    s2 = read_dataset(inputs["s2"], TWO_POINT, attrs=["r_max", "bin_width"])
    radius, phi2, compare_r_max = settings["radius"], settings["phi2"], settings["compare_r_max"]
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
    return fig


#: phase 1 (void) dark, phase 2 (solid) yellow, as in the paper's Fig. 1
PHASE_COLOURS = ("#3b0f70", "#fde725")


def fig01(inputs, settings, log):
    """Fig. 1: one construction per volume fraction (input ``samples``), phase 2 (solid) in yellow.

    Parameters
    ----------
    inputs : dict
        ``samples``: phase-image files, one per phi2.
    settings : dict
        ``a`` (pixels, for the label).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    from matplotlib.colors import ListedColormap

    from randmedia.plot.style import PAGE_WIDTH

    images_by_phi2 = {phi2: ds["phase"].values
                      for phi2, ds in _by_phi2(inputs["samples"], PHASE_IMAGE).items()}
    a = settings["a"]
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
    return fig


def fig02(inputs, settings, log):
    """Fig. 2: S2(r) of the constructions (input ``s2``; dashed, mean over samples) and targets
    (solid).

    Parameters
    ----------
    inputs : dict
        ``s2``: two-point descriptor files, one per phi2.
    settings : dict
        ``lc``: largest r drawn (pixels).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    s2_by_phi2 = _by_phi2(inputs["s2"], TWO_POINT, attrs=("phi2", "a"))
    lc = settings["lc"]
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
    return fig


def fig06(inputs, settings, log):
    """Fig. 6: (a) L(z) per phi2 (input ``chords``) with the fit of Eq. (29) (input ``fits``);
    (b) fitted L_w against phi2.

    Parameters
    ----------
    inputs : dict
        ``chords``: chord descriptor files, one per phi2; ``fits``: the fit dataset (``L_w``).
    settings : dict
        ``a`` (pixels; distances are drawn in units of a).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    chords_by_phi2 = _by_phi2(inputs["chords"], CHORDS)
    fits = read_dataset(inputs["fits"])
    a = settings["a"]
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
    return fig


def fig07(inputs, settings, log):
    """Fig. 7: p(z) by direct chord sampling (input ``chords``), with Eq. (31) from the fitted
    L_w (input ``fits``).

    Parameters
    ----------
    inputs : dict
        ``chords``: chord descriptor files, one per phi2; ``fits``: the fit dataset (``L_w``).
    settings : dict
        ``a`` (pixels).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    chords_by_phi2 = _by_phi2(inputs["chords"], CHORDS)
    fits = read_dataset(inputs["fits"])
    a = settings["a"]
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
    return fig


# --------------------------------------------------------------------------- Sec. V A-B


def _panels(n: int, *, width: float | None = None):
    """A row of n panels (a), (b), ... in the page width."""
    from randmedia.plot.style import PAGE_WIDTH

    fig, axes = figure(ncols=n, nrows=1, width=width or PAGE_WIDTH, aspect=0.9,
                       gridspec_kw={"wspace": 0.55})
    return fig, np.atleast_1d(axes)


def _plain_log_axis(ax) -> None:
    """Log y axis labelled at decades only (no crowded minor-tick labels)."""
    from matplotlib.ticker import NullFormatter

    ax.set_yscale("log")
    ax.yaxis.set_minor_formatter(NullFormatter())


def fig03(inputs, settings, log):
    """Fig. 3: F_sv(r) of the Debye media per phi2 (input ``surface``: mean +- SEM band over
    samples, level sets tuned to the exact s) and the parameter-free Eq. (24).

    Parameters
    ----------
    inputs : dict
        ``surface``: surface descriptor files, one per phi2.
    settings : dict
        ``a`` (pixels).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    from randmedia.theory.debye_formulas import debye_surface_void

    surface_by_phi2 = _by_phi2(inputs["surface"], SURFACE)
    a = settings["a"]
    fig, axes = _panels(len(surface_by_phi2))
    for label, ax, (phi2, ds) in zip("abcdefghij", axes, sorted(surface_by_phi2.items())):
        r = ds["r"].values
        keep = r >= 0.5  # the r = 0 bin is the interface deposit's own overlap with the void
        band(ax, r[keep] / a, a * ds["F_sv"].values[keep], a * ds["F_sv_sem"].values[keep], "C0",
             "simulation", lw=1.0)
        fine = np.linspace(0, r.max(), 300)
        ax.plot(fine / a, a * debye_surface_void(fine, phi2, a), "k--", lw=0.9, label="Eq. (24)")
        ax.set_xlabel(r"$r/a$")
        ax.set_title(rf"({label}) $\phi_2 = {phi2:g}$")
        ax.set_xlim(0, r.max() / a)
    axes[0].set_ylabel(r"$a\,F_{sv}(r)$")
    legend_below(axes[0], fontsize=7)  # wider than a panel of five
    return fig


def fig04(inputs, settings, log):
    """Fig. 4: F_ss(r) of the Debye media per phi2 (input ``surface``: mean +- SEM band) and
    Eq. (26); log scale, since F_ss diverges as s/(pi r) at r -> 0 (bins below 1 pixel,
    smeared by the interface deposit, are not drawn).

    Parameters
    ----------
    inputs : dict
        ``surface``: surface descriptor files, one per phi2.
    settings : dict
        ``a`` (pixels).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    from randmedia.theory.debye_formulas import debye_surface_surface

    surface_by_phi2 = _by_phi2(inputs["surface"], SURFACE)
    a = settings["a"]
    fig, axes = _panels(len(surface_by_phi2))
    for label, ax, (phi2, ds) in zip("abcdefghij", axes, sorted(surface_by_phi2.items())):
        r = ds["r"].values
        keep = r >= 1.0
        band(ax, r[keep] / a, a * a * ds["F_ss"].values[keep], a * a * ds["F_ss_sem"].values[keep],
             "C0", "simulation", lw=1.0)
        fine = np.linspace(0.5, r.max(), 300)
        ax.plot(fine / a, a * a * debye_surface_surface(fine, phi2, a), "k--", lw=0.9, label="Eq. (26)")
        _plain_log_axis(ax)
        ax.set_xlabel(r"$r/a$")
        ax.set_title(rf"({label}) $\phi_2 = {phi2:g}$")
        ax.set_xlim(0, r.max() / a)
    axes[0].set_ylabel(r"$a^2 F_{ss}(r)$")
    legend_below(axes[0], fontsize=7)  # wider than a panel of five
    return fig


def fig05(inputs, settings, log):
    """Fig. 5: (a) P(delta) phi1/s against delta/a per phi2 (input ``pores``; simulation: mean
    +- SEM band; Eq. (27) with our fitted p1 (input ``fits``): dashed; with the paper's cubic
    p1: dotted); (b) <delta>/a against phi2 with Eq. (28) (paper's coefficients and ours).

    Parameters
    ----------
    inputs : dict
        ``pores``: pore-size descriptor files, one per phi2; ``fits``: the fit dataset.
    settings : dict
        ``a`` (pixels).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    from randmedia.theory.debye_formulas import (debye_mean_pore_size, debye_specific_surface, pore_p1,
                                                 pore_size_density)

    pores_by_phi2 = _by_phi2(inputs["pores"], PORES)
    fits = read_dataset(inputs["fits"])
    a = settings["a"]
    fig, (left, right) = figure(ncols=2, nrows=1, width=2 * 3.4, aspect=0.75)
    for i, (phi2, ds) in enumerate(sorted(pores_by_phi2.items())):
        x = ds["delta_bin"].values
        scale = (1 - phi2) / debye_specific_surface(a, phi2)
        colour = f"C{i}"
        band(left, x / a, scale * ds["P"].values, scale * ds["P_sem"].values, colour,
             rf"$\phi_2 = {phi2:g}$", lw=1.0)
        p0 = np.pi * phi2 / a
        p1 = float(fits["p1"].sel(phi2=phi2))
        left.plot(x / a, scale * pore_size_density(x, p0, p1, p0), "--", color=colour, lw=0.8)
        left.plot(x / a, scale * pore_size_density(x, p0, float(pore_p1(phi2, a)), p0), ":",
                  color=colour, lw=0.8)
    _plain_log_axis(left)
    left.set_ylim(1e-3, 2)
    reach = [ds["delta_bin"].values[ds["P"].values * (1 - phi2) / debye_specific_surface(a, phi2) > 1e-3].max()
             for phi2, ds in pores_by_phi2.items()]
    left.set_xlim(0, 1.1 * max(reach) / a)
    left.set_xlabel(r"$\delta/a$")
    left.set_ylabel(r"$P(\delta)\,\phi_1/s$")
    legend_below(left, ncol=3, fontsize=7, title="simulation (band); Eq. (27): "
                 "our $p_1$ (dashed), paper's $p_1$ (dotted)", title_fontsize=6)  # the curves fill the panel
    left.set_title("(a)")
    phi2 = fits["phi2"].values
    right.errorbar(phi2, fits["mean_delta"].values / a, yerr=fits["mean_delta_sem"].values / a,
                   fmt="o", mfc="none", label="simulation")
    fine = np.linspace(0.05, 0.95, 200)
    right.plot(fine, [debye_mean_pore_size(p, a) / a for p in fine], "k-", lw=0.9,
               label="Eq. (28), paper's coefficients")
    own = fits["p1_coefficients"].values
    if np.all(np.isfinite(own)) and np.all(pore_p1(fine, a, own) > 0):
        right.plot(fine, [debye_mean_pore_size(p, a, own) / a for p in fine], "C1--", lw=0.9,
                   label="Eq. (28), our cubic")
    _plain_log_axis(right)
    right.set_xlabel(r"$\phi_2$")
    right.set_ylabel(r"$\langle\delta\rangle/a$")
    right.legend(loc="upper right", fontsize=7)
    right.set_title("(b)")
    return fig


# --------------------------------------------------------------------------- Sec. VI


def fig08(inputs, settings, log):
    """Fig. 8: one image per particle-dispersion model at the comparison phi2 (phase 2 yellow):
    input ``samples``, one file per model, titled by ``settings["titles"]``.

    Parameters
    ----------
    inputs : dict
        ``samples``: phase-image files, one per model.
    settings : dict
        ``titles``: one panel title per file.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    from matplotlib.colors import ListedColormap

    images = {}
    for title, path in zip(settings["titles"], inputs["samples"]):
        ds = read_dataset(path, PHASE_IMAGE, attrs=["phi2"])
        images[rf"{title}, $\phi_2 = {float(ds.attrs['phi2']):g}$"] = ds["phase"].values
    fig, axes = _panels(len(images), width=2 * 3.4)
    cmap = ListedColormap(PHASE_COLOURS)
    for label, ax, (title, image) in zip("abcdefghij", axes, images.items()):
        ax.imshow(image, cmap=cmap, vmin=0, vmax=1, interpolation="nearest", origin="lower")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(f"({label}) {title}")
    return fig


#: line style of each model in Figs. 9-12
MODEL_STYLE = {"debye": ("C0", "-", "Debye random media"),
               "overlapping_disks": ("C1", "--", "overlapping disks"),
               "hard_disks": ("C2", "-.", "equilibrium hard disks")}


def _fig09_two_point(models: dict):
    """Fig. 9: (a) chi_V(r), (b) F_sv(r)/F_sv(inf), (c) F_ss(r)/F_ss(inf) against r s for the
    three models. ``models`` maps a key of :data:`MODEL_STYLE` to a dict with ``s`` (exact) and
    callables or arrays: ``chi`` (r) -> chi_V, ``fsv``, ``fss`` and optionally ``simulated``
    (an xr surface dataset, drawn as points with SEM bars)."""
    fig, axes = _panels(3)
    for key, model in models.items():
        colour, style, name = MODEL_STYLE[key]
        s = model["s"]
        phi1 = model["phi1"]
        x = np.linspace(1e-3, 6.0, 800)  # r s
        r = x / s
        axes[0].plot(x, model["chi"](r), style, color=colour, lw=1.0, label=name)
        axes[1].plot(x, model["fsv"](r) / (s * phi1), style, color=colour, lw=1.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            axes[2].plot(x, model["fss"](r) / s**2, style, color=colour, lw=1.0)
        sim = model.get("simulated")
        if sim is not None:
            rs = sim["r"].values * s
            keep = (rs <= 6.0) & (sim["r"].values >= 1.0)
            step = max(1, keep.sum() // 40)
            sel = np.nonzero(keep)[0][::step]
            axes[1].errorbar(rs[sel], sim["F_sv"].values[sel] / (s * phi1),
                             yerr=sim["F_sv_sem"].values[sel] / (s * phi1), fmt="o", ms=2,
                             mfc="none", color=colour, lw=0.6)
            axes[2].errorbar(rs[sel], sim["F_ss"].values[sel] / s**2,
                             yerr=sim["F_ss_sem"].values[sel] / s**2, fmt="o", ms=2, mfc="none",
                             color=colour, lw=0.6)
            if "S2_void_samples" in sim:  # chi_V per sample with its own void fraction
                chi = (sim["S2_void_samples"].values
                       - sim["phi_void_samples"].values[:, None] ** 2).mean(axis=0)
                axes[0].plot(rs[sel], chi[sel], "o", ms=2, mfc="none", color=colour)
    axes[0].set_ylabel(r"$\chi_V(r)$")
    axes[1].set_ylabel(r"$F_{sv}(r)/F_{sv}(\infty)$")
    axes[2].set_ylabel(r"$F_{ss}(r)/F_{ss}(\infty)$")
    axes[2].set_ylim(0, 4)
    for label, ax in zip("abc", axes):
        ax.set_xlabel(r"$r s$")
        ax.set_xlim(0, 6)
        ax.set_title(f"({label})")
    legend_below(axes[2], ncol=1, title="lines: exact / formula / simulation\npoints: level-set images",
                 title_fontsize=6)
    return fig


def _fig10_to_12(models: dict, *, quantity: str):
    """Figs. 10-12 against distance x s: ``quantity`` "pore" (P(delta)/s), "lineal" (L(z)) or
    "chord" (p(z)/s). ``models`` maps a key of :data:`MODEL_STYLE` to a dict with ``s`` and
    ``curve``: a callable of the distance (the analytic result) or a tuple (x, y, y_sem) of a
    simulation in pixels; optional ``check`` (x, y, y_sem): our image estimate, drawn as points."""
    labels = {"pore": (r"$\delta s$", r"$P(\delta)/s$"), "lineal": (r"$z s$", r"$L(z)$"),
              "chord": (r"$z s$", r"$p(z)/s$")}
    scale_y = quantity != "lineal"
    fig, ax = figure()
    for key, model in models.items():
        colour, style, name = MODEL_STYLE[key]
        s = model["s"]
        for part in ("curve", "check"):
            entry = model.get(part)
            if entry is None:
                continue
            factor = 1.0 / s if scale_y else 1.0
            if callable(entry):
                x = np.linspace(0.0, 10.0, 400)
                ax.plot(x, entry(x / s) * factor, style, color=colour, lw=1.0, label=name)
            elif part == "curve":
                x, y, err = entry
                ax.fill_between(x * s, (y - err) * factor, (y + err) * factor, color=colour,
                                alpha=0.3, lw=0)
                ax.plot(x * s, y * factor, style, color=colour, lw=1.0, label=name)
            else:
                x, y, err = entry
                step = max(1, x.size // 40)
                ax.errorbar(x[::step] * s, y[::step] * factor, yerr=err[::step] * factor, fmt="o",
                            ms=2, mfc="none", color=colour, lw=0.6)
    _plain_log_axis(ax)
    x_max = {"pore": 5.0, "lineal": 10.0, "chord": 10.0}[quantity]
    ax.set_xlim(0, x_max)
    ax.set_ylim(1e-4, 2.0 if quantity == "lineal" else 3.0)
    ax.set_xlabel(labels[quantity][0])
    ax.set_ylabel(labels[quantity][1])
    # off the curves: P(delta) falls steeply from the top left (upper right free), L(z) and p(z)
    # fall as straight lines across the log axis (lower left free)
    ax.legend(loc="upper right" if quantity == "pore" else "lower left", fontsize=7,
              title="points: our image estimates", title_fontsize=6)
    return fig


def overlapping_disks_level_set(inputs, settings, log):
    """Validation figure: F_sv, F_ss (Eqs. 35-36) and F(delta), P(delta) (Eq. 37) of digitized
    overlapping disks on tuned level sets (inputs ``surface``, ``pores``), against the exact
    results; bottom row: deviations in units of the SEM with the +-3 band. F_ss is drawn from
    r = 1 px (the bins below are smeared by the interface deposit), F and P while the exact
    F >= 1e-3.

    Parameters
    ----------
    inputs : dict
        ``surface``, ``pores``: descriptor files of the digitized disks.
    settings : dict
        ``radius`` (disk radius R, pixels), ``phi2``.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    from randmedia.theory.overlapping import (pore_size_complementary_cdf, pore_size_density,
                                              surface_surface, surface_void)

    surface = read_dataset(inputs["surface"], SURFACE, attrs=["sigma"])
    pores = read_dataset(inputs["pores"], PORES)
    radius, phi2 = settings["radius"], settings["phi2"]
    fig, axes = figure(nrows=2, ncols=4, width=7.4, aspect=0.5, sharex="col",
                       gridspec_kw={"height_ratios": [2, 1], "wspace": 0.5, "hspace": 0.08})
    r = surface["r"].values
    delta, centres = pores["delta"].values, pores["delta_bin"].values
    reach = delta[pore_size_complementary_cdf(delta, radius, phi2) >= 1e-3].max()
    panels = [
        ("F_sv", surface, r, r >= 0.5, lambda x: surface_void(x, radius, phi2), r"$R\,F_{sv}$", radius),
        ("F_ss", surface, r, r >= 1.0, lambda x: surface_surface(x, radius, phi2), r"$R^2 F_{ss}$",
         radius**2),
        ("F", pores, delta, delta <= reach, lambda x: pore_size_complementary_cdf(x, radius, phi2),
         r"$F(\delta)$", 1.0),
        ("P", pores, centres, centres <= reach, lambda x: pore_size_density(x, radius, phi2),
         r"$R\,P(\delta)$", radius),
    ]
    for column, (name, ds, x, keep, exact, ylabel, scale) in enumerate(panels):
        top, bottom = axes[0, column], axes[1, column]
        mean, sem = ds[name].values, ds[f"{name}_sem"].values
        top.errorbar(x[keep] / radius, scale * mean[keep], yerr=scale * sem[keep], fmt="o", ms=1.2,
                     mfc="none", color="C0", lw=0.4, label="level sets")
        fine = np.linspace(x[keep].min(), x[keep].max(), 1000)
        with np.errstate(divide="ignore", invalid="ignore"):
            top.plot(fine / radius, scale * exact(fine), "k-", lw=0.7, label="exact")
            deviation = (mean - exact(x)) / sem
        if name in ("F", "P"):
            _plain_log_axis(top)
            top.set_ylim(3e-4 * scale * np.nanmax(mean[keep]), 2 * scale * np.nanmax(mean[keep]))
        if name == "F_ss":
            top.set_ylim(0, 4 * scale * mean[keep][-1])
        top.set_ylabel(ylabel)
        bottom.axhspan(-3, 3, color="0.9")
        bottom.plot(x[keep] / radius, deviation[keep], "o", ms=1.2, mfc="none", color="C0")
        bottom.set_ylim(-8, 8)
        bottom.set_xlabel(r"$r/R$" if name.startswith("F_s") else r"$\delta/R$")
    axes[0, 0].legend(loc="lower right", fontsize=6)
    axes[1, 0].set_ylabel("dev./SEM")
    fig.suptitle(rf"Overlapping disks, $\phi_2 = {phi2:g}$, $R = {radius:g}$ px, "
                 rf"{surface.sizes['sample']} images: level sets ($\sigma = "
                 rf"{float(surface.attrs['sigma']):.3f}$ px) against Eqs. (35)-(37)", fontsize=8)
    return fig


def _hard_disk_pore_density(radius: float, phi2: float):
    """P(delta) of Eq. (41) (scaled-particle theory, randmedia.theory.scaled_particle)."""
    from randmedia.theory import scaled_particle

    return lambda delta: scaled_particle.eq41_pore_size_density(delta, phi2, radius)


#: reading of the Sec. VI inputs by kind (the part of the input name after the model:
#: media_surface, disks_chords, hard_pores, ...): (variables, attributes)
_SECTION6_SPECS = {"surface": (SURFACE, ["phi2", "length_scale"]), "pores": (PORES, ["phi2"]),
                   "chords": (CHORDS, ["phi2"])}


def _section6(number: int, inputs, settings):
    """Figs. 9-12 from the rule's inputs ``{model}_{kind}`` (models media, disks, hard; kinds
    surface, pores, chords) and settings ``a``, ``radius``, ``phi2``."""
    data = {}
    for name, path in inputs.items():
        spec, attrs = _SECTION6_SPECS[name.split("_", 1)[1]]
        data[name] = read_dataset(path, spec, attrs=attrs)
    return _section6_figure(number, a=settings["a"], radius=settings["radius"],
                            phi2=settings["phi2"], **data)


def fig09(inputs, settings, log):
    """Fig. 9: chi_V(r), F_sv(r), F_ss(r) of the three models at the comparison phi2, against r s.

    Parameters
    ----------
    inputs : dict
        ``{model}_{kind}`` descriptor files (models ``media``, ``disks``, ``hard``; kinds
        ``surface``, ``pores``, ``chords``).
    settings : dict
        ``a`` (pixels), ``radius`` (pixels), ``phi2``.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    return _section6(9, inputs, settings)


def fig10(inputs, settings, log):
    """Fig. 10: P(delta) of the three models, against delta s.

    Parameters
    ----------
    inputs : dict
        ``{model}_{kind}`` descriptor files (models ``media``, ``disks``, ``hard``; kinds
        ``surface``, ``pores``, ``chords``).
    settings : dict
        ``a`` (pixels), ``radius`` (pixels), ``phi2``.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    return _section6(10, inputs, settings)


def fig11(inputs, settings, log):
    """Fig. 11: L(z) of the three models, against z s.

    Parameters
    ----------
    inputs : dict
        ``{model}_{kind}`` descriptor files (models ``media``, ``disks``, ``hard``; kinds
        ``surface``, ``pores``, ``chords``).
    settings : dict
        ``a`` (pixels), ``radius`` (pixels), ``phi2``.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    return _section6(11, inputs, settings)


def fig12(inputs, settings, log):
    """Fig. 12: p(z) of the three models, against z s.

    Parameters
    ----------
    inputs : dict
        ``{model}_{kind}`` descriptor files (models ``media``, ``disks``, ``hard``; kinds
        ``surface``, ``pores``, ``chords``).
    settings : dict
        ``a`` (pixels), ``radius`` (pixels), ``phi2``.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (saved by the caller, :func:`randmedia.plot.rule.draw_rule_figure`).
    """
    return _section6(12, inputs, settings)


def _section6_figure(number: int, *, a: float, media_surface=None, media_pores=None,
                     media_chords=None, disks_surface=None, disks_pores=None, disks_chords=None,
                     hard_surface=None, hard_pores=None, radius: float, phi2: float):
    """Figs. 9-12 (Sec. VI): Debye media (our simulation, and Eqs. 21, 24, 26 in Fig. 9),
    overlapping disks (exact Eqs. 32-39; our level-set estimates as points) and equilibrium
    hard disks (Fig. 9: our images; Figs. 10-12: Eqs. 41-43, our image estimate of P as points),
    all at ``phi2``, distances scaled by each model's exact s (Eqs. 22, 34, 40)."""
    from randmedia.theory import debye_formulas as debye, hard_disks, hard_spheres, overlapping

    phi1 = 1.0 - phi2
    models = {}
    s_debye = debye.debye_specific_surface(a, phi2)
    s_disks = overlapping.specific_surface(radius, phi2, dim=2)
    if number == 9:
        models["debye"] = {
            "s": s_debye, "phi1": phi1, "simulated": media_surface,
            "chi": lambda r: phi1 * phi2 * np.exp(-r / a),
            "fsv": lambda r: debye.debye_surface_void(r, phi2, a),
            "fss": lambda r: debye.debye_surface_surface(r, phi2, a)}
        models["overlapping_disks"] = {
            "s": s_disks, "phi1": phi1, "simulated": disks_surface,
            "chi": lambda r: overlapping.s2_void(r, radius, phi2) - phi1**2,
            "fsv": lambda r: overlapping.surface_void(r, radius, phi2),
            "fss": lambda r: overlapping.surface_surface(r, radius, phi2)}
        if hard_surface is not None:
            hr, hphi2 = float(hard_surface.attrs["length_scale"]), float(hard_surface.attrs["phi2"])
            s_hard = hard_spheres.specific_surface(hr, hphi2, 2)
            rr = hard_surface["r"].values

            def tabulated(name, hs=hard_surface, grid=rr):
                return lambda r: np.interp(r, grid, hs[name].values, left=np.nan, right=np.nan)

            models["hard_disks"] = {
                "s": s_hard, "phi1": 1.0 - hphi2, "simulated": None,
                "chi": lambda r, f=tabulated("S2_void"), p=1.0 - hphi2: f(r) - p * p,
                "fsv": tabulated("F_sv"), "fss": tabulated("F_ss")}
        return _fig09_two_point(models)
    quantity = {10: "pore", 11: "lineal", 12: "chord"}[number]
    if quantity == "pore":
        debye_curve = (media_pores["delta_bin"].values, media_pores["P"].values, media_pores["P_sem"].values)
        disks_curve = lambda d: overlapping.pore_size_density(d, radius, phi2)  # noqa: E731
        disks_check = (disks_pores["delta_bin"].values, disks_pores["P"].values, disks_pores["P_sem"].values)
    elif quantity == "lineal":
        debye_curve = (media_chords["z"].values, media_chords["L"].values, media_chords["L_sem"].values)
        disks_curve = lambda z: overlapping.lineal_path_void(z, radius, phi2)  # noqa: E731
        disks_check = (disks_chords["z"].values, disks_chords["L"].values, disks_chords["L_sem"].values)
    else:
        debye_curve = (media_chords["z_chord"].values, media_chords["p"].values, media_chords["p_sem"].values)
        disks_curve = lambda z: overlapping.chord_density_void(z, radius, phi2)  # noqa: E731
        disks_check = (disks_chords["z_chord"].values, disks_chords["p"].values,
                       disks_chords["p_sem"].values)
    models["debye"] = {"s": s_debye, "curve": debye_curve}
    models["overlapping_disks"] = {"s": s_disks, "curve": disks_curve, "check": disks_check}
    if hard_surface is not None:
        hr, hphi2 = float(hard_surface.attrs["length_scale"]), float(hard_surface.attrs["phi2"])
        entry = {"s": hard_spheres.specific_surface(hr, hphi2, 2)}
        if quantity == "pore":
            entry["curve"] = _hard_disk_pore_density(hr, hphi2)
            entry["check"] = (hard_pores["delta_bin"].values, hard_pores["P"].values,
                              hard_pores["P_sem"].values)
        elif quantity == "lineal":
            entry["curve"] = lambda z: hard_disks.lineal_path_void(z, hr, hphi2)
        else:
            entry["curve"] = lambda z: hard_disks.chord_density_void(z, hr, hphi2)
        models["hard_disks"] = entry
    return _fig10_to_12(models, quantity=quantity)


FIGURES = {1: fig01, 2: fig02, 3: fig03, 4: fig04, 5: fig05, 6: fig06, 7: fig07, 8: fig08, 9: fig09,
           10: fig10, 11: fig11, 12: fig12,
           "overlapping_disks_s2": overlapping_disks_s2,
           "overlapping_disks_level_set": overlapping_disks_level_set}
