"""Figures 1-8 of *Hyperuniformity on spherical surfaces*, PRE 100, 022107 (2019).

:data:`FIGURES` (end of the module) maps each figure number to its function: ``figNN(inputs,
settings, log)`` reads the rule's input files (``inputs``: name -> list of paths), takes the
config values it uses from ``settings`` and returns the matplotlib figure -- Figs. 5-8, drawn
also for the second reading of Eq. (12b) (input ``alpha_cubed``), return both as
``{"pdf": ..., "alpha_cubed_pdf": ...}``; the rules ``sphere2019_figNN`` run it through
``workflow/scripts/sphere2019/figure.py`` (convention: :mod:`randmedia.plot.rule`).

Descriptor files (:mod:`randmedia.describe.sphere_points`) carry sigma^2(a) for one
or two window-centre variants, its jackknife SEM, g2 and sigma^2 from g2; every
curve is drawn with a +-1 SEM band. Sphere renderings are orthographic views of
the near hemisphere, points shaded by depth.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from randmedia.describe.sphere_points import CAP_VARIANCE
from randmedia.generate.sphere_surface import SPHERE_CONFIG, frames_of
from randmedia.io import read_dataset
from randmedia.plot.style import PAGE_WIDTH, band, figure, legend_below
from randmedia.theory.sphere_caps import poisson_variance, uniform_variance

VIEW = (np.deg2rad(20.0), np.deg2rad(30.0))  # elevation, azimuth of the viewer


def _view_matrix(elevation: float, azimuth: float) -> np.ndarray:
    """Rows: screen x, screen y, towards the viewer."""
    ca, sa, ce, se = np.cos(azimuth), np.sin(azimuth), np.cos(elevation), np.sin(elevation)
    towards = np.array([ce * ca, ce * sa, se])
    right = np.array([-sa, ca, 0.0])
    up = np.cross(towards, right)
    return np.vstack([right, up, towards])


def render_sphere(ax, points: np.ndarray, radius: float, *, size: float = 4.0, colour="C0",
                  title: str | None = None, diameter: float | None = None) -> None:
    """Orthographic view of the points on the near hemisphere of the sphere of radius R;
    with ``diameter``, particles are drawn as disks of that diameter (length unit of R),
    foreshortened towards the rim.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Axes to draw into (turned off; limits set to the unit disk).
    points : numpy.ndarray
        Points on the sphere, shape (n, 3), in the length unit of ``radius``.
    radius : float
        Sphere radius R.
    size : float
        Marker area of the scatter points (points^2, scaled down with depth; default 4).
    colour : str
        Matplotlib colour of the points (default ``"C0"``).
    title : str or None
        Axes title; None for none.
    diameter : float or None
        Particle diameter (length unit of R) to draw disks instead of points; None: points.
    """
    from matplotlib.collections import EllipseCollection
    from matplotlib.colors import to_rgba

    unit = np.asarray(points, float) / radius
    view = _view_matrix(*VIEW) @ unit.T
    front = view[2] > 0
    depth = view[2, front]
    order = np.argsort(depth)
    ax.add_patch(_circle((0, 0), 1.0, facecolor="0.96", edgecolor="0.3", lw=0.6))
    x, y = view[0, front][order], view[1, front][order]
    if diameter is None:
        ax.scatter(x, y, s=size * (0.35 + 0.65 * depth[order]), c=colour, linewidths=0, zorder=3)
    else:
        width = np.full(x.size, diameter / radius)
        shade = np.array([to_rgba(colour, 0.45 + 0.55 * d) for d in depth[order]])
        ax.add_collection(EllipseCollection(
            width, width * depth[order], np.degrees(np.arctan2(y, x)) + 90.0, units="xy",
            offsets=np.column_stack([x, y]), offset_transform=ax.transData, facecolors=shade,
            edgecolors="k", linewidths=0.3, zorder=3))
    ax.set_xlim(-1.05, 1.05)
    ax.set_ylim(-1.05, 1.05)
    ax.set_aspect("equal")
    ax.axis("off")
    if title:
        ax.set_title(title)


def _circle(centre, radius, **kwargs):
    from matplotlib.patches import Circle

    return Circle(centre, radius, **kwargs)


def _scaled(ds: xr.Dataset, variant: str = "random_centres"):
    rho = float(ds.attrs["density"])
    s = ds["cap_area"].values
    sigma2 = ds["sigma2"].sel(variant=variant).values
    sem = ds["sigma2_sem"].sel(variant=variant).values
    return ds["a"].values, sigma2 / (rho * s), sem / (rho * s), rho


def _plain_log_ticks(ax) -> None:
    """Log axes with plain-number major labels and no minor labels."""
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(ScalarFormatter())
        axis.set_minor_formatter(NullFormatter())


def _first_frames(paths) -> list[np.ndarray]:
    """The first frame of each configuration file."""
    return [frames_of(read_dataset(path, SPHERE_CONFIG))[0] for path in paths]


def _cap_variances(paths) -> list[xr.Dataset]:
    """The descriptor files of the point patterns (sigma^2(a) in caps)."""
    return [read_dataset(path, CAP_VARIANCE, attrs=["R", "density"]) for path in paths]


# --------------------------------------------------------------------------- Fig. 1


def fig01(inputs, settings, log):
    """Fig. 1: the spherical-cap window of arc length x, area s and base radius a (no inputs).

    Parameters
    ----------
    inputs : dict
        Unused (schematic).
    settings : dict
        Unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from matplotlib.patches import Arc, Polygon

    fig, ax = figure(aspect=0.9)
    radius, phi = 1.0, np.deg2rad(50.0)
    t = np.linspace(0, 2 * np.pi, 400)
    ax.fill(np.cos(t), np.sin(t), color="#5b7db1", alpha=0.85, lw=0)
    # the cap (white): the part of the disk above height cos(phi), seen side on
    cap_t = np.linspace(np.pi / 2 - phi, np.pi / 2 + phi, 200)
    ax.add_patch(Polygon(np.column_stack([np.cos(cap_t), np.sin(cap_t)]), closed=True,
                         facecolor="white", edgecolor="k", lw=1.0, zorder=2))
    # base of the cap drawn as an ellipse (the cap boundary circle in perspective)
    a = radius * np.sin(phi)
    h_base = radius * np.cos(phi)
    e = np.linspace(0, 2 * np.pi, 200)
    ax.plot(a * np.cos(e), h_base + 0.18 * a * np.sin(e), "k-", lw=0.8, zorder=3)
    ax.plot(np.cos(t), np.sin(t), "k-", lw=1.0)
    ax.plot([0, a], [h_base, h_base], "k--", lw=0.8, zorder=4)
    ax.text(a / 2, h_base + 0.012, r"$a$", ha="center", va="bottom", fontsize=7, zorder=5)  # under the rim
    ax.plot([0, 0], [0, radius], "k:", lw=0.8)
    ax.plot([0, a], [0, h_base], "k:", lw=0.8)
    ax.add_patch(Arc((0, 0), 0.5, 0.5, theta1=90 - np.rad2deg(phi), theta2=90, lw=0.8))
    ax.text(0.08, 0.3, r"$\phi$", ha="left")
    ax.text(0.35, -0.15, r"$R$", ha="center")
    ax.plot([0, 0], [0, 0], "k.", ms=4)
    # arc length x from the pole to the cap edge
    arc_t = np.linspace(np.pi / 2 - phi, np.pi / 2, 60)
    ax.plot(1.07 * np.cos(arc_t), 1.07 * np.sin(arc_t), color="C3", lw=1.2)
    ax.text(1.12 * np.cos(np.pi / 2 - phi / 2), 1.12 * np.sin(np.pi / 2 - phi / 2), r"$x = R\phi$",
            color="C3", ha="left", va="bottom")
    ax.text(-0.18, 0.9, r"$s$", ha="center", va="center", zorder=5)
    ax.annotate("", xy=(0, radius + 0.03), xytext=(0, h_base - 0.0),
                arrowprops=dict(arrowstyle="<->", lw=0.6), zorder=5)
    ax.text(0.03, (radius + h_base) / 2 + 0.02, r"$h$", ha="left", va="center", fontsize=7)
    ax.set_xlim(-1.25, 1.45)
    ax.set_ylim(-1.1, 1.35)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(r"cap of base radius $a = R\sin\phi$, area $s = 2\pi R h$, $0 \leq \phi \leq \pi/2$")
    return fig


# --------------------------------------------------------------------------- Figs. 2 and 3


def fig02(inputs, settings, log):
    """Fig. 2: (a) icosahedral (Tegmark) grid, (b) Fibonacci grid (inputs ``configs`` and
    ``descriptors``, in this order), (c) sigma^2/(rho s) vs a rho^(1/2), inset sigma^2 vs a.

    Parameters
    ----------
    inputs : dict
        ``configs``: [icosahedral, Fibonacci] configuration files; ``descriptors``: their descriptor files, same order.
    settings : dict
        Unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    ico_points, fib_points = _first_frames(inputs["configs"])
    ico, fib = _cap_variances(inputs["descriptors"])
    fig, axes = figure(ncols=3, nrows=1, width=PAGE_WIDTH, aspect=1.0,
                       gridspec_kw={"width_ratios": [1, 1, 1.25], "wspace": 0.3})
    render_sphere(axes[0], ico_points, float(ico.attrs["R"]), size=3.0,
                  title=f"(a) icosahedral, N = {len(ico_points)}")
    render_sphere(axes[1], fib_points, float(fib.attrs["R"]), size=3.0, colour="C1",
                  title=f"(b) Fibonacci, N = {len(fib_points)}")
    ax = axes[2]
    inset = ax.inset_axes([0.45, 0.45, 0.5, 0.45])
    for ds, name, colour in ((ico, "icosahedral", "C0"), (fib, "Fibonacci", "C1")):
        a, scaled, sem, rho = _scaled(ds)
        band(ax, a * np.sqrt(rho), scaled, sem, colour, name, alpha=0.25)
        sigma2 = ds["sigma2"].sel(variant="random_centres").values
        inset.plot(a, sigma2, color=colour)
    ax.set_xlabel(r"$a\rho^{1/2}$")
    ax.set_ylabel(r"$\sigma_n^2(a)/(\rho s)$")
    ax.set_ylim(bottom=0)
    ax.legend(loc="center left", bbox_to_anchor=(0.3, 0.25))
    inset.set_xlabel(r"$a$", fontsize=7, labelpad=1)
    inset.set_ylabel(r"$\sigma_n^2$", fontsize=7, labelpad=1)
    inset.tick_params(labelsize=6)
    ax.set_title("(c)")  # as (a) and (b); inside the axes it lay on the curves at small a
    return fig


def fig03(inputs, settings, log):
    """Fig. 3: (a) Poisson and (b) uniform configurations (inputs ``configs`` and ``descriptors``,
    in this order); (c) sigma^2/(rho s) vs a/R with Eq. (6) (uniform, canonical) and Eq. (7)
    (Poisson, grand canonical).

    Parameters
    ----------
    inputs : dict
        ``configs``: [Poisson, uniform] configuration files; ``descriptors``: their descriptor files, same order.
    settings : dict
        Unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from matplotlib.gridspec import GridSpec

    poisson_points, uniform_points = _first_frames(inputs["configs"])
    poisson, uniform = _cap_variances(inputs["descriptors"])
    fig, _ = figure(width=PAGE_WIDTH, aspect=0.42)
    fig.clf()
    grid = GridSpec(2, 3, figure=fig, width_ratios=[1, 1, 1.3], wspace=0.35)
    radius = float(uniform.attrs["R"])
    render_sphere(fig.add_subplot(grid[:, 0]), poisson_points, float(poisson.attrs["R"]), size=2.0,
                  colour="C2", title=rf"(a) Poisson, $\langle N\rangle$ = {poisson.attrs['mean_n_points']:.0f}")
    render_sphere(fig.add_subplot(grid[:, 1]), uniform_points, radius, size=2.0, colour="C0",
                  title=f"(b) uniform, N = {len(uniform_points)}")
    top, bottom = fig.add_subplot(grid[0, 2]), fig.add_subplot(grid[1, 2])
    for ax, ds, theory, label, colour in (
            (top, uniform, uniform_variance, "uniform (canonical), Eq. (6)", "C0"),
            (bottom, poisson, poisson_variance, "Poisson (grand canonical), Eq. (7)", "C2")):
        a, scaled, sem, rho = _scaled(ds)
        R = float(ds.attrs["R"])
        band(ax, a / R, scaled, sem, colour, "simulation", alpha=0.25)
        fine = np.linspace(a[0], R, 200)
        s = 2 * np.pi * R**2 * (1 - np.sqrt(1 - (fine / R) ** 2))
        ax.plot(fine / R, theory(fine, R, rho) / (rho * s), "k--", lw=0.8, label=label)
        ax.set_ylabel(r"$\sigma_n^2/(\rho s)$")
        ax.legend(loc="lower left", fontsize=6)
        ax.set_ylim(0.4, 1.15)
    top.tick_params(labelbottom=False)
    bottom.set_xlabel(r"$a/R$")
    top.set_title("(c)")
    return fig


# --------------------------------------------------------------------------- Figs. 4-8

LABELS = {
    "lj": "LJ", "udd": r"$U_{dd}$ (normal dipoles)", "uddpar": r"$U_{dd\parallel}$ ($1/r^3$)",
    "uddpar_cubed": r"$U_{dd\parallel}$ ($(\alpha/r)^3$)", "udc": r"$U_{dc}$ ($1/r^2$)", "ucc": r"$U_{cc}$ ($1/r$)",
}


def _fluid_label(ds: xr.Dataset, with_coupling: bool = False) -> str:
    label = LABELS[ds.attrs["potential"]]
    if with_coupling and ds.attrs["potential"] != "lj":
        symbol = {"udd": r"\alpha", "uddpar": r"\alpha", "uddpar_cubed": r"\alpha", "udc": r"\gamma", "ucc": r"\beta"}[ds.attrs["potential"]]
        label += rf", ${symbol} = {ds.attrs['coupling']:g}$"
    return label


def _fluids(paths) -> dict[str, xr.Dataset]:
    """{system: descriptor file} of the fluids, in the order of ``paths``."""
    by_system = {}
    for path in paths:
        ds = read_dataset(path, CAP_VARIANCE, attrs=["system", "R", "density", "potential", "coupling"])
        by_system[ds.attrs["system"]] = ds
    return by_system


def _both_readings(draw, printed, alpha_cubed, **kwargs) -> dict:
    """{output name: figure} of ``draw`` for Eq. (12b) as printed (output ``pdf``) and for its
    second reading (output ``alpha_cubed_pdf``)."""
    return {"pdf": draw(printed, **kwargs), "alpha_cubed_pdf": draw(alpha_cubed, **kwargs)}


def fig04(inputs, settings, log):
    """Fig. 4: sigma^2/(rho s) vs a rho^(1/2) of the R = 15 fluids (input ``descriptors``;
    a >= settings["a_min"]); inset: the normalized sigma^2*(a) = sigma^2(a)/sigma^2(R) vs a
    with references ~a and ~a^2.

    Parameters
    ----------
    inputs : dict
        ``descriptors``: descriptor files of the R = 15 fluids.
    settings : dict
        ``a_min``: smallest cap base radius drawn (length unit of R).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    descriptors, a_min = _fluids(inputs["descriptors"]), settings["a_min"]
    fig, ax = figure(aspect=0.8)
    # upper right, above the curves (the y range is raised to make room): in the lower left it
    # hid part of the U_cc curve and its labels crossed the main axes
    inset = ax.inset_axes([0.5, 0.62, 0.45, 0.33])
    for k, (system, ds) in enumerate(descriptors.items()):
        a, scaled, sem, rho = _scaled(ds)
        keep = a >= a_min
        band(ax, a[keep] * np.sqrt(rho), scaled[keep], sem[keep], f"C{k}", _fluid_label(ds), alpha=0.25)
        sigma2 = ds["sigma2"].sel(variant="random_centres").values
        inset.loglog(a[keep], sigma2[keep] / sigma2[-1], color=f"C{k}")
    if descriptors:
        a = next(iter(descriptors.values()))["a"].values
        a = a[a >= a_min]
        inset.loglog(a, (a / a[-1]), "k:", lw=0.8, label=r"$\propto a$")
        inset.loglog(a, (a / a[-1]) ** 2, "k--", lw=0.8, label=r"$\propto a^2$")
        inset.legend(fontsize=6, loc="lower right")
        R = float(next(iter(descriptors.values())).attrs["R"])
        ax.set_title(rf"$R = {R:g}$, $\rho = {rho:.3g}$")
    _plain_log_ticks(inset)
    inset.set_xlabel(r"$a$", fontsize=7, labelpad=1)
    inset.set_ylabel(r"$\sigma_n^{2*}(a)$", fontsize=7, labelpad=1)
    inset.tick_params(labelsize=6, which="both")
    ax.set_xlabel(r"$a\rho^{1/2}$")
    ax.set_ylabel(r"$\sigma_n^2(a)/(\rho s)$")
    ax.set_ylim(0, 1.8 * max((np.nanmax(line.get_ydata()) for line in ax.get_lines()), default=1.0))
    legend_below(ax)
    return fig


def fig05(inputs, settings, log):
    """Fig. 5: sigma^2/(rho s) vs a rho^(1/2) at R = 5 for U_dd|| with alpha = 1, 3, 6, for both
    readings of Eq. (12b).

    Parameters
    ----------
    inputs : dict
        ``descriptors``, ``alpha_cubed``: descriptor files of the R = 5 fluids for the two readings of Eq. (12b).
    settings : dict
        ``a_min``: smallest cap base radius drawn (length unit of R).
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    dict
        ``{"pdf": figure for Eq. (12b) as printed, "alpha_cubed_pdf": figure for its second reading}``.
    """
    return _both_readings(_fig05_alpha, _fluids(inputs["descriptors"]), _fluids(inputs["alpha_cubed"]),
                          a_min=settings["a_min"])


def _fig05_alpha(descriptors: dict[str, xr.Dataset], *, a_min: float = 1.0):
    """Fig. 5 from the descriptor files of the three fluids."""
    fig, ax = figure()
    for k, (system, ds) in enumerate(descriptors.items()):
        a, scaled, sem, rho = _scaled(ds)
        keep = a >= a_min
        band(ax, a[keep] * np.sqrt(rho), scaled[keep], sem[keep], f"C{k}", _fluid_label(ds, True),
             alpha=0.25)
    if descriptors:
        R = float(next(iter(descriptors.values())).attrs["R"])
        ax.set_title(rf"$U_{{dd\parallel}}$, $R = {R:g}$, $\rho = {rho:.3g}$")
    ax.set_xlabel(r"$a\rho^{1/2}$")
    ax.set_ylabel(r"$\sigma_n^2(a)/(\rho s)$")
    ax.set_ylim(bottom=0)
    legend_below(ax, fontsize=7)  # the curves of the three alpha span the panel
    return fig


def _snapshots(paths) -> dict[str, tuple[np.ndarray, float, str]]:
    """{panel label: (last frame, R, title)} of the configuration files."""
    panels = {}
    for label, path in zip("abcdefgh", paths):
        ds = read_dataset(path, SPHERE_CONFIG, attrs=["R", "coupling"])
        title = rf"({label}) $\alpha = {ds.attrs['coupling']:g}$, N = {int(ds['n_points'].values[-1])}"
        panels[label] = (frames_of(ds)[-1], float(ds.attrs["R"]), title)
    return panels


def fig06(inputs, settings, log):
    """Fig. 6: snapshots for alpha = 1, 3, 6 (input ``configs``; ``alpha_cubed`` for the second
    reading of Eq. 12b).

    Parameters
    ----------
    inputs : dict
        ``configs``, ``alpha_cubed``: configuration files (alpha = 1, 3, 6) for the two readings of Eq. (12b).
    settings : dict
        Unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    dict
        ``{"pdf": figure for Eq. (12b) as printed, "alpha_cubed_pdf": figure for its second reading}``.
    """
    return _both_readings(_fig06_snapshots, _snapshots(inputs["configs"]),
                          _snapshots(inputs["alpha_cubed"]))


def _fig06_snapshots(snapshots: dict[str, tuple[np.ndarray, float, str]]):
    """Fig. 6: one configuration per repulsion strength (points, R, label); particles drawn
    as disks of diameter d_LJ."""
    n = len(snapshots)
    fig, axes = figure(ncols=n, nrows=1, width=PAGE_WIDTH, aspect=1.0)
    for ax, (label, (points, radius, title)) in zip(np.atleast_1d(axes), snapshots.items()):
        render_sphere(ax, points, radius, colour="C3", title=title, diameter=1.0)
    return fig


def fig07(inputs, settings, log):
    """Fig. 7: geodesic g2(x) at R = 5 for increasing repulsion, for both readings of Eq. (12b).

    Parameters
    ----------
    inputs : dict
        ``descriptors``, ``alpha_cubed``: descriptor files of the fluids for the two readings of Eq. (12b).
    settings : dict
        Unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    dict
        ``{"pdf": figure for Eq. (12b) as printed, "alpha_cubed_pdf": figure for its second reading}``.
    """
    return _both_readings(_fig07_g2, _fluids(inputs["descriptors"]), _fluids(inputs["alpha_cubed"]))


def _fig07_g2(descriptors: dict[str, xr.Dataset]):
    """Fig. 7 from the descriptor files of the fluids."""
    fig, ax = figure()
    for k, (system, ds) in enumerate(descriptors.items()):
        band(ax, ds["x"].values, ds["g2"].values, np.nan_to_num(ds["g2_sem"].values), f"C{k}",
             _fluid_label(ds, True), alpha=0.25, lw=0.9)
    ax.axhline(1.0, color="0.5", lw=0.6, ls=":")
    ax.set_xlabel(r"$x$ (geodesic distance)")
    ax.set_ylabel(r"$g_2(x)$")
    radius = max((float(ds.attrs["R"]) for ds in descriptors.values()), default=1.0)
    ax.set_xlim(0, min(np.pi * radius, 8.0))
    ax.legend(loc="upper right", fontsize=7)
    return fig


def fig08(inputs, settings, log):
    """Fig. 8: sigma^2/(rho s) from g2 by Eq. (4) (solid) against the direct window counts
    (dotted), R = 5, for both readings of Eq. (12b).

    Parameters
    ----------
    inputs : dict
        ``descriptors``, ``alpha_cubed``: descriptor files of the fluids for the two readings of Eq. (12b).
    settings : dict
        Unused.
    log : logging.Logger
        The job's logger (unused).

    Returns
    -------
    dict
        ``{"pdf": figure for Eq. (12b) as printed, "alpha_cubed_pdf": figure for its second reading}``.
    """
    return _both_readings(_fig08_from_g2, _fluids(inputs["descriptors"]), _fluids(inputs["alpha_cubed"]))


def _fig08_from_g2(descriptors: dict[str, xr.Dataset], *, a_min: float = 0.0):
    """Fig. 8 from the descriptor files of the fluids."""
    fig, ax = figure()
    for k, (system, ds) in enumerate(descriptors.items()):
        a, scaled, sem, rho = _scaled(ds)
        keep = a >= a_min
        from_g2 = ds["sigma2_from_g2"].values / (rho * ds["cap_area"].values)
        ax.plot(a[keep] * np.sqrt(rho), from_g2[keep], color=f"C{k}", label=_fluid_label(ds, True))
        ax.plot(a[keep] * np.sqrt(rho), scaled[keep], color=f"C{k}", ls=":", lw=0.9)
    ax.plot([], [], "k-", label="from $g_2$, Eq. (4)")
    ax.plot([], [], "k:", label="window counts")
    ax.set_xlabel(r"$a\rho^{1/2}$")
    ax.set_ylabel(r"$\sigma_n^2(a)/(\rho s)$")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper right", fontsize=6)
    return fig


FIGURES = {1: fig01, 2: fig02, 3: fig03, 4: fig04, 5: fig05, 6: fig06, 7: fig07, 8: fig08}
