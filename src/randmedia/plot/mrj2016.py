"""Figures 1-13 of Klatt & Torquato, PRE 94, 022152 (2016), with the paper's axes.

:data:`FIGURES` (end of the module) maps each figure number to its function:
``figNN(inputs, settings, log)`` takes ``inputs`` (name -> file: ``config_{system}``
for a configuration, ``{kind}_{system}`` for a merged descriptor file), the config
values the figure reads (``settings``) and a logger, and returns the matplotlib
figure; the rule ``mrj2016_figNN`` runs it through ``workflow/scripts/mrj2016/figure.py``
(convention: :mod:`randmedia.plot.rule`). A system missing from ``inputs`` is left
out of the figure (and logged). Not reproduced: the
phi = 0.50 liquid of Ref. [39] (Fig. 3) and the MD packings of Ref. [29]
(Figs. 7, 10) -- external data we do not generate.
"""

from __future__ import annotations

import math

import numpy as np

from randmedia.io import read_dataset
from randmedia.plot.style import COLUMN_WIDTH, band, figure, legend_below

COLOURS = {"overlapping": "0.25", "equilibrium": "C0", "mrj": "C3", "mrj_large": "C3",
           "mrj_md": "C1", "fcc": "C2", "bcc": "C4"}
LABELS = {"overlapping": "overlapping spheres", "equilibrium": "equilibrium liquid",
          "mrj": "MRJ packings", "mrj_large": "MRJ packings",
          "mrj_md": "MD-like packings (LS; cf. Ref. [29])", "fcc": "fcc", "bcc": "bcc"}
#: the systems of Figs. 7 and 8 (the paper's: TJ and MD packings of Ref. [29], liquid, lattices)
POINT_SYSTEMS = ("overlapping", "equilibrium", "mrj", "mrj_md", "fcc", "bcc")
RADIUS = 0.5  # sphere radius in units of D


def _load(inputs, name, log=None):
    path = inputs.get(name)
    if path is None:
        if log is not None:
            log.warning("%s not available: left out of the figure", name)
        return None
    return read_dataset(path)


def _count(n: int, noun: str) -> str:
    """``"1 sample"``, ``"4 samples"``."""
    return f"{n} {noun}" + ("" if n == 1 else "s")


def _phi_label(ds):
    return rf"$\phi = {float(np.mean(ds['eta'].values)):.3f}$"


def _overlapping_curves(r, phi):
    """Exact S2 (sphere phase), F_sv/s (matrix void), F_ss/s^2 of overlapping spheres."""
    from randmedia.theory import overlapping as theory

    s = theory.specific_surface(RADIUS, phi, 3)
    s2 = 1.0 - 2.0 * (1.0 - phi) + theory.s2_void(r, RADIUS, phi, 3)
    with np.errstate(divide="ignore", invalid="ignore"):
        fss = theory.surface_surface(r, RADIUS, phi, 3) / s**2
    return s, s2, theory.surface_void(r, RADIUS, phi, 3) / s, fss


# --------------------------------------------------------------------------- Figs. 3-5, 12, 13


def _correlation_figure(inputs, settings, log, *, which):
    """Three stacked panels (overlapping, equilibrium, MRJ) of one correlation function."""
    phi_over = settings["overlapping_phi"]
    systems = [("overlapping", None), ("equilibrium", _load(inputs, "correlation_equilibrium", log)),
               ("mrj", _load(inputs, "correlation_mrj", log))]
    fig, axes = figure(nrows=3, ncols=1, aspect=0.62, sharex=True)
    r_fine = np.linspace(1e-3, 3.0, 1500)
    ylabel = {"S2": r"$S_2(r)$", "Fsv": r"$F_{sv}(r)/s$", "Fss": r"$F_{ss}(r)/s^2$",
              "Fsv2": r"$F^*_{sv}(r)/s$", "Fss2": r"$F^*_{ss}(r)/s^2$"}[which]
    variable = {"S2": "S2", "Fsv": "F_sv_over_s", "Fss": "F_ss_over_s2",
                "Fsv2": "F_sv_two_body_over_s", "Fss2": "F_ss_two_body_over_s2"}[which]
    for ax, (system, ds) in zip(axes, systems):
        colour = COLOURS[system]
        if system == "overlapping":
            s, s2, fsv, fss = _overlapping_curves(r_fine, phi_over)
            curve = {"S2": s2, "Fsv": fsv, "Fss": fss, "Fsv2": np.full_like(r_fine, phi_over),
                     "Fss2": np.ones_like(r_fine)}[which]
            ax.plot(r_fine, curve, color=colour, label=f"{LABELS[system]} (exact)")
            phi, label = phi_over, rf"$\phi = {phi_over:g}$"
        elif ds is None:
            ax.text(0.5, 0.5, f"{LABELS[system]}: not computed", transform=ax.transAxes, ha="center")
            continue
        else:
            r = ds["r"].values
            keep = r > 0 if which in ("Fss", "Fsv2", "Fss2") else slice(None)
            band(ax, r[keep], ds[f"{variable}_mean"].values[keep], ds[f"{variable}_sem"].values[keep],
                  colour, label=f"{LABELS[system]} ({_count(ds.sizes['sample'], 'sample')})")
            phi, label = float(np.mean(ds["phi"].values)), _phi_label(ds)
            s = 6.0 * phi
            if which == "Fsv2":  # slope at r = 0 from the contact number (Eq. B3)
                z = float(np.mean(ds["z_B3"].values))
                if z > 0.1:
                    x = np.linspace(0, 0.6, 20)
                    ax.plot(x, z * x / 8.0, "--", color="C2", lw=0.9, label=rf"slope $s\bar z/(8D)$, $\bar z = {z:.2f}$")
            if which == "Fss2":  # value at r = 0 from the contact number (Eq. B4)
                z = float(np.mean(ds["z_B4"].values))
                if z > 0.1:
                    ax.axhline(z / (4.0 * s), color="C2", ls="--", lw=0.9,
                               label=rf"$\bar z/(4Ds)$, $\bar z = {z:.2f}$")
        limits = {"S2": [phi, phi**2], "Fsv": [0.5, 1.0 - phi], "Fss": [1.0], "Fsv2": [phi], "Fss2": [1.0]}[which]
        for value in limits:
            ax.axhline(value, color="0.5", ls=":", lw=0.8)
        if which == "S2":  # slope -s/4 at r = 0
            x = np.linspace(0, 0.5, 10)
            ax.plot(x, phi - s * x / 4.0, ":", color="0.5", lw=0.8)
        if which in ("Fss", "Fss2"):
            ax.set_ylim(0.0, 3.0 if which == "Fss" else 1.6)
        ax.text(0.97, 0.92, label, transform=ax.transAxes, ha="right", va="top")
        ax.set_ylabel(ylabel)
        # F*_ss/s^2 (Fig. 13) keeps its plateau at 1 in the upper half: legend upper left, inset low
        ax.legend(loc="upper left" if which == "Fss2" else "lower right", fontsize=6)
    axes[-1].set_xlabel(r"$r/D$")
    axes[-1].set_xlim(0, 3.0)
    inset_at = {"Fss": 2.0, "Fss2": 1.0}.get(which)
    if inset_at is not None:
        for ax, (system, ds) in zip(axes[1:], systems[1:]):
            if ds is None:
                continue
            r = ds["r"].values
            near = (r > inset_at - 0.15) & (r < inset_at + 0.15)
            if near.sum() < 3:
                continue
            inset = ax.inset_axes([0.45, 0.08, 0.3, 0.4] if which == "Fss2" else [0.45, 0.45, 0.3, 0.4])
            band(inset, r[near], ds[f"{variable}_mean"].values[near], ds[f"{variable}_sem"].values[near],
                  COLOURS[system])
            inset.axvline(inset_at, color="0.5", ls=":", lw=0.6)
            inset.tick_params(labelsize=5)
    return fig


def fig03(inputs, settings, log):
    """Fig. 3: S2(r).

    Parameters
    ----------
    inputs : dict
        ``correlation_equilibrium``, ``correlation_mrj``: merged correlation files (optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    return _correlation_figure(inputs, settings, log, which="S2")


def fig04(inputs, settings, log):
    """Fig. 4: F_sv(r)/s.

    Parameters
    ----------
    inputs : dict
        ``correlation_equilibrium``, ``correlation_mrj``: merged correlation files (optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    return _correlation_figure(inputs, settings, log, which="Fsv")


def fig05(inputs, settings, log):
    """Fig. 5: F_ss(r)/s^2 (insets at r = 2D).

    Parameters
    ----------
    inputs : dict
        ``correlation_equilibrium``, ``correlation_mrj``: merged correlation files (optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    return _correlation_figure(inputs, settings, log, which="Fss")


def fig12(inputs, settings, log):
    """Fig. 12: two-body F*_sv(r)/s with the contact slope (Eq. B3).

    Parameters
    ----------
    inputs : dict
        ``correlation_equilibrium``, ``correlation_mrj``: merged correlation files (optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    return _correlation_figure(inputs, settings, log, which="Fsv2")


def fig13(inputs, settings, log):
    """Fig. 13: two-body F*_ss(r)/s^2 with the contact value (Eq. B4; insets at r = D).

    Parameters
    ----------
    inputs : dict
        ``correlation_equilibrium``, ``correlation_mrj``: merged correlation files (optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    return _correlation_figure(inputs, settings, log, which="Fss2")


# --------------------------------------------------------------------------- Fig. 6


def fig06(inputs, settings, log):
    """Fig. 6: spectral densities -- overlapping (bottom), liquid (centre), MRJ (top).

    Parameters
    ----------
    inputs : dict
        ``spectral_{system}``, ``correlation_{system}`` for ``mrj_large`` (else ``mrj``) and
        ``equilibrium`` (optional).
    settings : dict
        ``spectral`` (its ``k_max``, units of 1/D) and ``overlapping_phi``: sphere volume fraction
        of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from randmedia.describe.spectral import form_factor_zeros, overlapping_spectral_density

    k_max = settings["spectral"]["k_max"]
    fig, axes = figure(nrows=3, ncols=1, aspect=0.62, sharex=True)
    zeros = form_factor_zeros(k_max)
    # the paper's top panel is its N = 10 000 MRJ packings; without them (mrj2016.mrj.mrj_large
    # .n_samples = 0) the N = 2000 packings, labelled with their N, so the panel is never empty
    mrj = "mrj_large" if any(f"{kind}_mrj_large" in inputs for kind in ("spectral", "correlation")) else "mrj"
    panels = [(mrj, axes[0]), ("equilibrium", axes[1])]
    for system, ax in panels:
        title = LABELS[system]
        spec = _load(inputs, f"spectral_{system}", log)
        corr = _load(inputs, f"correlation_{system}", log)
        colour = COLOURS[system]
        if corr is not None:
            k = corr["k_ft"].values
            reliable = k >= corr.attrs["k_min_reliable"]
            ax.plot(k[reliable], corr["chi_ft_mean"].values[reliable], color=colour,
                    label=r"$\mathcal{F}[\chi_V(r)]$ (Eq. 11)")
        if spec is not None:
            good = np.isfinite(spec["chi_mean"].values)
            kk = np.nanmean(spec["k_mean"].values, axis=0)[good]
            ax.errorbar(kk, spec["chi_mean"].values[good], yerr=spec["chi_sem"].values[good], fmt="x",
                        ms=2.5, color="k", lw=0.6, label=r"$|\tilde J(\mathbf{k})|^2/V$ (Eq. 14)")
            title = (rf"{LABELS[system]}" "\n" rf"$\phi = {float(np.mean(spec['eta'].values)):.3f}$, "
                     rf"$N = {float(np.mean(spec['n'].values)):.0f}$, " + _count(spec.sizes["sample"], "sample"))
            if system == "equilibrium":
                s0 = _liquid_s0(float(np.mean(spec["eta"].values)), log)
                if s0 is not None:
                    phi = float(np.mean(spec["eta"].values))
                    ax.axhline(phi * math.pi / 6.0 * s0, color=colour, ls="--", lw=0.8,
                               label=r"$\phi v_D S(0)$ (EOS, Eq. 32)")
        ax.set_ylabel(r"$\tilde\chi_V(k)/D^3$")
        ax.legend(loc="upper right", fontsize=6, title=title, title_fontsize=6)
    phi = settings["overlapping_phi"]
    k = np.linspace(0.05, k_max, 500)
    axes[2].plot(k, overlapping_spectral_density(k, phi), color=COLOURS["overlapping"],
                 label="overlapping spheres (exact, Eq. 11)")
    axes[2].axhline(float(overlapping_spectral_density([0.0], phi)[0]), color="0.5", ls="--", lw=0.8,
                    label=r"$\tilde\chi_V(0)$")
    axes[2].set_ylabel(r"$\tilde\chi_V(k)/D^3$")
    # below the top of the curve (the horizontal line of chi_V(0) runs along the top)
    axes[2].legend(loc="center right", fontsize=6, title=rf"$\phi = {phi:g}$", title_fontsize=6)
    for ax in axes[:2]:
        for z in zeros:
            ax.axvline(z, color="0.5", ls="--", lw=0.6)
        ax.set_ylim(bottom=0)
    axes[-1].set_xlabel(r"$kD$")
    axes[-1].set_xlim(0, k_max)
    return fig


def _liquid_s0(phi, log):
    """S(0) = rho k_B T kappa_T of the hard-sphere liquid (Eq. 32) from the equation of state."""
    from randmedia.theory.hard_spheres import structure_factor_zero

    return float(structure_factor_zero(phi, 3))


def _liquid_pore_theory(phi, log):
    """(F(delta), E_V(r)) callables of the liquid by scaled-particle theory (Refs. [39,77,78])."""
    from randmedia.theory import scaled_particle

    return (lambda delta: scaled_particle.pore_size_ccdf(delta, phi, 3),
            lambda r: scaled_particle.exclusion_probability(r, phi, 3))


# --------------------------------------------------------------------------- Figs. 7, 8


def fig07(inputs, settings, log):
    """Fig. 7: complementary cumulative pore-size distribution F(delta) (inset: MRJ by phi).

    Parameters
    ----------
    inputs : dict
        ``points_{system}`` for the systems of POINT_SYSTEMS (each optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (exact curves).
    log : logging.Logger
        Logger for missing systems and for a skipped MRJ inset.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from randmedia.theory.overlapping import pore_size_complementary_cdf

    fig, ax = figure(aspect=0.8)
    phi_over = settings["overlapping_phi"]
    delta = np.linspace(0, 1.0, 400)
    ax.plot(delta, pore_size_complementary_cdf(delta, RADIUS, phi_over, 3), color=COLOURS["overlapping"],
            lw=0.9, label="overlapping (exact)")
    mrj = None
    for system in POINT_SYSTEMS:
        ds = _load(inputs, f"points_{system}", log)
        if ds is None:
            continue
        if system == "mrj":
            mrj = ds
        if system == "equilibrium":
            theory = _liquid_pore_theory(float(np.mean(ds["eta"].values)), log)
            if theory is not None:
                ax.plot(delta, theory[0](delta), "--", color=COLOURS[system], lw=0.9,
                        label="liquid (scaled-particle theory)")
        d, F = ds["delta"].values, ds["F_mean"].values
        step = max(1, len(d) // 60)
        phi = (settings["overlapping_phi"] if system == "overlapping" else float(np.mean(ds["eta"].values)))
        ax.plot(d[::step], np.where(F[::step] > 0, F[::step], np.nan), "o", ms=2.2, mfc="none",
                color=COLOURS[system], label=rf"{LABELS[system]}, $\phi = {phi:.3f}$")
    ax.set_yscale("log")
    ax.set_ylim(1e-6, 1.2)
    ax.set_xlim(0, 0.8)
    ax.set_xlabel(r"$\delta/D$")
    ax.set_ylabel(r"$F(\delta)$")
    legend_below(ax)  # the curves fill the lower left, the inset the upper right
    if mrj is not None and mrj.sizes["sample"] >= 4:
        eta = mrj["eta"].values
        mean = float(eta.mean())
        high, low = eta > mean + 0.001, eta < mean - 0.001
        rule = r"$\bar\phi \pm 0.001$"
        if high.sum() < 2 or low.sum() < 2:  # our phi spread is narrower: split at the median
            high, low = eta > np.median(eta), eta < np.median(eta)
            rule = "median"
        if high.sum() < 2 or low.sum() < 2:
            log.info("MRJ packing fractions too uniform to split: no inset")
            return fig
        inset = ax.inset_axes([0.66, 0.64, 0.3, 0.31])  # above the overlapping spheres' curve
        d = mrj["delta"].values
        for group, style, name in ((high, "-", ">"), (low, "--", "<")):
            F = mrj["F"].values[group].mean(axis=0)
            inset.plot(d, np.where(F > 0, F, np.nan), style, color=COLOURS["mrj"], lw=0.8,
                       label=rf"$\phi {name}$ ({rule}, {group.sum()})")
        inset.set_yscale("log")
        inset.set_xlim(0.2, 0.45)
        inset.set_ylim(1e-7, 1e-2)
        inset.tick_params(labelsize=5)
        inset.legend(fontsize=4.5)
    return fig


def fig08(inputs, settings, log):
    """Fig. 8: exclusion probability E_V(r) of the centres at unit density (r in lambda).

    Parameters
    ----------
    inputs : dict
        ``points_{system}`` for the systems of POINT_SYSTEMS (each optional).
    settings : dict
        ``overlapping_phi``: sphere volume fraction of the overlapping spheres (their density).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from randmedia.theory.balls import poisson_intensity
    from randmedia.theory.overlapping import exclusion_probability

    fig, ax = figure(aspect=0.8)
    x = np.linspace(0, 1.6, 400)
    ax.plot(x, exclusion_probability(x, 1.0, 3), color=COLOURS["overlapping"], lw=0.9,
            label="Poisson (exact)")
    for system in POINT_SYSTEMS:
        ds = _load(inputs, f"points_{system}", log)
        if ds is None:
            continue
        rho = (poisson_intensity(settings["overlapping_phi"], RADIUS, 3) if system == "overlapping"
               else float(np.mean(ds["rho"].values)))
        lam = rho ** (-1.0 / 3.0)
        if system == "equilibrium":
            theory = _liquid_pore_theory(float(np.mean(ds["eta"].values)), log)
            if theory is not None:
                ax.plot(x, theory[1](x * lam), "--", color=COLOURS[system], lw=0.9,
                        label="liquid (scaled-particle theory)")
        r, E = ds["r"].values, ds["E_V_mean"].values
        step = max(1, len(r) // 80)
        phi = settings["overlapping_phi"] if system == "overlapping" else float(np.mean(ds["eta"].values))
        ax.plot(r[::step] / lam, np.where(E[::step] > 0, E[::step], np.nan), "o", ms=2.2, mfc="none",
                color=COLOURS[system], label=rf"{LABELS[system]}, $\phi = {phi:.3f}$")
        if system in ("fcc", "bcc"):
            ax.axvline(float(ds["covering_radius"].values.max()) / lam, color=COLOURS[system], ls=":", lw=0.8)
    ax.set_yscale("log")
    ax.set_ylim(1e-8, 1.5)
    ax.set_xlim(0, 1.6)
    ax.set_xlabel(r"$r/\lambda$")
    ax.set_ylabel(r"$E_V(r)$")
    legend_below(ax)
    return fig


# --------------------------------------------------------------------------- Figs. 9, 10


def fig09(inputs, settings, log):
    """Fig. 9: number distributions rescaled by sigma_N against the standard normal.

    Parameters
    ----------
    inputs : dict
        ``windows_{system}`` for overlapping, equilibrium, mrj (optional).
    settings : dict
        ``windows`` (its ``fit_r_min``, units of D: radii drawn as filled Gaussian-regime markers)
        and ``overlapping_phi`` (for the exact Poisson distribution).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from scipy.stats import norm, poisson

    from randmedia.theory.balls import poisson_intensity

    fig, axes = figure(nrows=3, ncols=1, aspect=0.62, sharex=True)
    x = np.linspace(-4, 4, 300)
    for label, ax, system in zip("abc", axes, ("overlapping", "equilibrium", "mrj")):
        ds = _load(inputs, f"windows_{system}", log)
        ax.plot(x, norm.pdf(x), "k-", lw=1.0)
        ax.set_ylabel(r"$\sigma_N f_R(N)$")
        ax.text(0.02, 0.9, f"({label}) {LABELS[system]}", transform=ax.transAxes, fontsize=7)
        if ds is None:
            continue
        lam = float(np.mean(ds["rho"].values)) ** (-1.0 / 3.0)
        cmap = __import__("matplotlib").colormaps["viridis"]
        radii = ds["R_f"].values
        for j, R in enumerate(radii):
            p = ds["count_probability"].values[j]
            if not np.isfinite(p).all() or p.sum() == 0:
                continue
            n = ds["N"].values
            mean = float((n * p).sum())
            sigma = math.sqrt(float(((n - mean) ** 2 * p).sum()))
            if sigma == 0:
                continue
            colour = cmap(j / max(1, len(radii) - 1))
            keep = p > 0
            gauss = R >= settings["windows"]["fit_r_min"]
            marker = "o" if (gauss or system == "overlapping") else "s"
            ax.plot((n[keep] - mean) / sigma, sigma * p[keep], marker, ms=2.2, color=colour,
                    mfc=colour if (gauss and system != "overlapping") else "none",
                    label=rf"$R = {R:g}D = {R / lam:.2f}\lambda$")
            if system == "overlapping":  # exact Poisson distribution
                mu = poisson_intensity(settings["overlapping_phi"], RADIUS, 3) * 4 * math.pi * R**3 / 3
                nn = np.arange(max(0, int(mu - 5 * math.sqrt(mu))), int(mu + 5 * math.sqrt(mu)) + 2)
                ax.plot((nn - mu) / math.sqrt(mu), math.sqrt(mu) * poisson.pmf(nn, mu), "--",
                        color=colour, lw=0.7)
        ax.legend(fontsize=5, loc="upper right")
    axes[-1].set_xlabel(r"$(N - \langle N\rangle_R)/\sigma_N(R)$")
    axes[-1].set_xlim(-4, 4)
    return fig


def fig10(inputs, settings, log):
    """Fig. 10: number variance sigma_N^2(R) against R/lambda with the fits b2 R^2 + b3 R^3 and R^2.

    Parameters
    ----------
    inputs : dict
        ``windows_{system}`` for overlapping, equilibrium, mrj (optional).
    settings : dict
        ``windows`` (its ``fit_r_min``, units of D: start of the fitted curves).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from randmedia.fit.number_variance import MODELS

    fig, ax = figure(aspect=0.85)
    r_top, low, high = 1.0, np.inf, 0.0
    for system in ("overlapping", "equilibrium", "mrj"):
        ds = _load(inputs, f"windows_{system}", log)
        if ds is None:
            continue
        lam = ds.attrs["lambda"]
        R = ds["R"].values / lam
        var, sem = ds["number_variance"].values, ds["number_variance_sem"].values
        ok = np.isfinite(var) & (var > 0)
        sem = np.where(np.isfinite(sem), sem, 0.0)
        lower = np.minimum(sem, 0.9 * var)  # keep error bars on the log axis
        ax.errorbar(R[ok], var[ok], yerr=[lower[ok], sem[ok]], fmt="o", ms=2, mfc="none", lw=0.5,
                    color=COLOURS[system], label=LABELS[system])
        r_top = max(r_top, R[ok].max())
        low, high = min(low, var[ok].min()), max(high, (var + sem)[ok].max())
        rmin = settings["windows"]["fit_r_min"] / lam
        xf = np.linspace(rmin, max(R.max(), 2 * rmin), 100)
        for model, style in (("b2_b3", "-"), ("b2", "--")):
            if system == "overlapping" or f"fit_{model}" not in ds:
                continue
            if system == "mrj" and model == "b2_b3":
                continue
            coef = ds[f"fit_{model}"].values
            y = sum(c * xf**p for c, p in zip(coef, MODELS[model]))
            text = " ".join(f"{c:+.3g} R^{p}" for c, p in zip(coef, MODELS[model])).lstrip("+")
            ax.plot(xf, y, style, color=COLOURS[system], lw=0.9, label=f"fit ${text}$")
    x = np.logspace(-1, np.log10(r_top), 200)
    ax.plot(x, 4 * math.pi * x**3 / 3, color=COLOURS["overlapping"], lw=0.9,
            label=r"Poisson, $\propto R^3$ (exact)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    if np.isfinite(low):
        ax.set_ylim(0.5 * low, 2 * high)
    ax.set_xlim(0.9 * min(0.2, x[0]), 1.1 * r_top)
    ax.set_xlabel(r"$R/\lambda$")
    ax.set_ylabel(r"$\sigma_N^2(R)$")
    ax.legend(fontsize=6, loc="upper left")
    return fig


# --------------------------------------------------------------------------- Figs. 1, 2, 11


def render_spheres(positions, box, side: float, pixels: int = 360, diameter: float = 1.0):
    """Shaded orthographic image (z-buffer of sphere caps) of the spheres centred in the cube
    [0, side]^3 (periodic images included), viewed along -z; returns (shade, hit, side).

    Parameters
    ----------
    positions : numpy.ndarray
        Sphere centres, shape (n, 3), in the units of ``box``.
    box : array_like
        Periodic cell, as accepted by :class:`randmedia.periodic.Cell`.
    side : float
        Edge of the rendered cube; clipped to the cell's smallest face distance.
    pixels : int
        Image size in pixels per edge (default 360).
    diameter : float
        Sphere diameter D (default 1).

    Returns
    -------
    tuple
        (shade, hit, side): shade, float array (pixels, pixels) of grey levels in [0, 1];
        hit, bool array (pixels, pixels), True where a sphere is seen; side, the edge used.
        Both arrays are oriented for ``imshow`` (first row at the top, y = side).
    """
    from randmedia.periodic import Cell, padded_images

    cell = Cell(box)
    side = min(side, float(cell.face_distances.min()))
    points, _ = padded_images(cell, positions, side * 0.999)
    inside = np.all((points >= 0) & (points < side), axis=1)
    centres = points[inside]
    R = diameter / 2.0
    scale = pixels / side
    depth = np.full((pixels, pixels), -np.inf)
    shade = np.zeros((pixels, pixels))
    light = np.array([-0.4, 0.5, 0.77])
    light /= np.linalg.norm(light)
    for cx, cy, cz in centres[np.argsort(centres[:, 2])]:
        i0, i1 = max(0, int((cx - R) * scale)), min(pixels, int((cx + R) * scale) + 2)
        j0, j1 = max(0, int((cy - R) * scale)), min(pixels, int((cy + R) * scale) + 2)
        if i0 >= i1 or j0 >= j1:
            continue
        gx, gy = np.meshgrid((np.arange(i0, i1) + 0.5) / scale - cx, (np.arange(j0, j1) + 0.5) / scale - cy,
                             indexing="ij")
        h2 = R * R - gx * gx - gy * gy
        hit = h2 > 0
        h = np.sqrt(np.where(hit, h2, 0.0))
        z = cz + h
        patch = depth[i0:i1, j0:j1]
        front = hit & (z > patch)
        lambert = np.clip((gx * light[0] + gy * light[1] + h * light[2]) / R, 0, 1)
        patch[front] = z[front]
        shade[i0:i1, j0:j1][front] = (0.25 + 0.75 * lambert[front]) * (0.55 + 0.45 * (cz / side))
    return shade.T[::-1], np.isfinite(depth).T[::-1], side


def fig01(inputs, settings, log):
    """Fig. 1: renderings of (a) overlapping spheres, (b) the liquid, (c) an MRJ packing.

    Parameters
    ----------
    inputs : dict
        ``config_{system}`` for overlapping, equilibrium, mrj (optional).
    settings : dict
        ``figures`` (its ``render_side``: side of the rendered cube in D, default 8).
    log : logging.Logger
        Logger; systems missing from ``inputs`` are reported on it.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    from randmedia.plot.style import PAGE_WIDTH
    from randmedia.studies.mrj2016 import load_configuration

    fig, axes = figure(ncols=3, nrows=1, width=PAGE_WIDTH, aspect=1.0)
    side = float(settings["figures"].get("render_side", 8.0))
    base = {"overlapping": np.array([0.55, 0.55, 0.6]), "equilibrium": np.array([0.25, 0.45, 0.85]),
            "mrj": np.array([0.85, 0.3, 0.25])}
    for label, ax, system in zip("abc", axes, ("overlapping", "equilibrium", "mrj")):
        ax.set_axis_off()
        ax.set_title(f"({label}) {LABELS[system]}", fontsize=8)
        path = inputs.get(f"config_{system}")
        if path is None:
            log.warning("configuration of %s not available", system)
            continue
        positions, box, diameter = load_configuration(path)
        shade, hit, used = render_spheres(positions, box, side, diameter=diameter)
        image = np.ones(shade.shape + (3,))
        image[hit] = shade[hit, None] * base[system][None, :]
        ax.imshow(np.clip(image, 0, 1), extent=(0, used, 0, used))
    return fig


def _disk_configuration(rng, n, side, diameter):
    """Random sequential addition of n non-overlapping disks (for the schematic only)."""
    centres = []
    while len(centres) < n:
        c = rng.uniform(0, side, 2)
        if all(np.hypot(*(c - o)) >= diameter for o in centres):
            centres.append(c)
    return np.array(centres)


def fig02(inputs, settings, log):
    """Fig. 2: events behind the descriptors of Table I: (a) two-phase medium, (b) point process.

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
    from matplotlib.patches import Circle, FancyArrowPatch

    from randmedia.plot.style import PAGE_WIDTH

    fig, axes = figure(ncols=2, nrows=1, width=PAGE_WIDTH * 0.8, aspect=1.0)
    rng = np.random.default_rng(2016)
    side = 6.0
    centres = _disk_configuration(rng, 18, side, 1.0)
    for ax in axes:
        ax.set_xlim(0, side)
        ax.set_ylim(0, side)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
    a, b = axes
    for c in centres:
        a.add_patch(Circle(c, 0.5, facecolor="#f4c542", edgecolor="k", lw=0.6))
        b.plot(*c, "k.", ms=4)
    # (a) phi: random point in a sphere; s: point on an interface; S2, F_sv, F_ss: pairs at distance r
    inner = np.all((centres > 1.0) & (centres < side - 1.0), axis=1)
    c0 = centres[inner][0]
    a.plot(*(c0 + [0.1, 0.1]), "o", color="C3", ms=3)
    a.text(c0[0] + 0.15, c0[1] + 0.15, r"$\phi$", fontsize=7, color="C3")
    c1 = centres[inner][1]
    p = c1 + 0.5 * np.array([np.cos(0.6), np.sin(0.6)])
    q = p + 1.3 * np.array([np.cos(2.2), np.sin(2.2)])
    a.plot(*np.array([p, q]).T, "--", color="C0", lw=0.9)
    a.plot(*p, "s", color="C0", ms=3)
    a.plot(*q, "o", color="C0", ms=3)
    a.text(*(0.5 * (p + q) + [0.1, 0.05]), r"$r$", color="C0", fontsize=7)
    # pore: largest ball around a matrix point touching the nearest sphere
    gap = np.array([side / 2, side / 2])
    distance = np.min(np.hypot(*(centres - gap).T)) - 0.5
    if distance > 0:
        a.add_patch(Circle(gap, distance, facecolor="none", edgecolor="C2", lw=0.9))
        a.plot(*gap, "o", color="C2", ms=2)
        a.text(gap[0] + 0.05, gap[1] + 0.05, r"$\delta$", color="C2", fontsize=7)
    a.set_title(r"(a) two-phase medium: $\phi$, $s$, $S_2$, $F_{sv}$, $F_{ss}$, $F(\delta)$", fontsize=7)
    # (b) exclusion: empty ball; number of points in a ball of radius R
    window = np.array([2.0, 2.5])
    b.add_patch(Circle(window, 1.3, facecolor="none", edgecolor="C0", lw=0.9))
    inside = np.hypot(*(centres - window).T) < 1.3
    b.plot(*centres[inside].T, "o", color="C0", ms=3)
    b.add_patch(FancyArrowPatch(window, window + [1.3, 0], arrowstyle="-|>", mutation_scale=5, color="C0"))
    b.text(window[0] + 0.4, window[1] + 0.1, r"$R$", color="C0", fontsize=7)
    empty = gap
    r_empty = np.min(np.hypot(*(centres - empty).T))
    b.add_patch(Circle(empty, r_empty, facecolor="none", edgecolor="C2", ls="--", lw=0.9))
    b.text(empty[0], empty[1] + 0.05, r"$E_V(r)$", color="C2", fontsize=7, ha="center")
    b.set_title(r"(b) point process: $E_V(r)$, $f_R(N)$, $\sigma_N^2(R)$", fontsize=7)
    return fig


def fig11(inputs, settings, log):
    """Fig. 11: section through B_R(c_j) and the test sphere B_r(x) (Eqs. A2-A5).

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
    from matplotlib.patches import Arc, Circle

    fig, ax = figure(aspect=0.8, width=COLUMN_WIDTH * 0.8)
    R, r, delta = 1.0, 0.8, 1.1
    cj, x = np.array([0.0, 0.0]), np.array([delta, 0.0])
    ax.add_patch(Circle(cj, R, facecolor="none", edgecolor="k", lw=1.0))
    ax.add_patch(Circle(x, r, facecolor="none", edgecolor="k", ls="--", lw=1.0))
    cos_w = (delta**2 + r**2 - R**2) / (2 * r * delta)
    omega = math.degrees(math.acos(cos_w))
    # arc of the test sphere inside B_R(c_j): angles 180 - omega .. 180 + omega about x
    ax.add_patch(Arc(x, 2 * r, 2 * r, theta1=180 - omega, theta2=180 + omega, color="C3", lw=2.0, ls="--"))
    top = x + r * np.array([-cos_w, math.sin(math.acos(cos_w))])
    ax.plot(*np.array([cj, x]).T, "k-", lw=0.7)
    ax.plot(*np.array([x, top]).T, "k-", lw=0.7)
    ax.plot(*np.array([x, x + [-r, 0]]).T, "k:", lw=0.7)
    ax.add_patch(Arc(x, 0.5, 0.5, theta1=180 - omega, theta2=180, lw=0.7))
    ax.text(*(x + [-0.38, 0.1]), r"$\omega$", fontsize=8)
    for point, name, offset in ((cj, r"$\mathbf{c}_j$", (-0.2, -0.15)), (x, r"$\mathbf{x}$", (0.05, -0.15))):
        ax.plot(*point, "ko", ms=2.5)
        ax.text(point[0] + offset[0], point[1] + offset[1], name, fontsize=8)
    ax.text(0.5 * delta, 0.05, r"$\delta$", fontsize=8)
    ax.text(*(0.5 * (x + top) + [0.05, 0.0]), r"$r$", fontsize=8)
    ax.text(-0.7, 0.75, r"$B_R(\mathbf{c}_j)$", fontsize=8)
    ax.text(x[0] + 0.45, 0.65, r"$B_r(\mathbf{x})$", fontsize=8)
    ax.set_xlim(-1.2, 2.1)
    ax.set_ylim(-1.15, 1.15)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return fig


FIGURES = {1: fig01, 2: fig02, 3: fig03, 4: fig04, 5: fig05, 6: fig06, 7: fig07, 8: fig08, 9: fig09,
           10: fig10, 11: fig11, 12: fig12, 13: fig13}
