"""Validation figure of the equilibrium hard-disk / hard-sphere chains."""

from __future__ import annotations

import numpy as np

from randmedia.plot.style import PAGE_WIDTH, figure, save_figure
from randmedia.theory.balls import ball_volume
from randmedia.theory.hard_spheres import compressibility_factor, contact_value


def eos_validation_figure(frame, pooled: dict, settings, *, dim: int, phi: float,
                          eos_names: dict, sample_msd: float, title: str, pdf_path) -> None:
    """(a) g(r) near contact from the pooled pair counts, the fitted polynomial and the EOS
    contact values; (b) per-sample contact-value pressure with the EOS values; (c) MSD
    between consecutive samples of each chain against the required minimum; (d) when the
    frame has bond order (3D): global Q6 and crystal-like fraction per sample.

    Parameters
    ----------
    frame : pandas.DataFrame
        One row per sample: ``sample``, ``reduced_pressure``, ``msd_since_previous`` (units of
        D^2) and, in 3D, ``global_q6`` and ``crystalline_fraction``.
    pooled : dict
        Pooled pair counts near contact: ``histogram``, ``box``, ``diameter``, ``n_particles``,
        ``measurements``, ``coefficients`` (polynomial in r/D - 1) and ``contact_value``.
    settings : randmedia.generate.hard_particles.settings.MCSettings
        The chain's settings; ``contact_range`` is the histogram's range beyond r = D (units of D).
    dim : int
        Dimension, 2 or 3.
    phi : float
        Packing fraction of the chain.
    eos_names : dict
        Equation-of-state name -> legend label, for the reference lines.
    sample_msd : float
        Required minimum MSD between samples (units of D^2).
    title : str
        Figure title.
    pdf_path : str or os.PathLike
        Output ``.pdf`` path; the PNG is written beside it.
    """
    bond_order = "global_q6" in frame
    if bond_order:
        fig, axes = figure(2, 2, width=PAGE_WIDTH, aspect=0.6)
    else:
        fig, axes = figure(3, 1, width=PAGE_WIDTH, aspect=0.95)
    axes = np.ravel(axes)
    ax_g, ax_z, ax_m = axes[:3]
    hist = pooled["histogram"].astype(float)
    edges = 1.0 + np.linspace(0.0, settings.contact_range, len(hist) + 1)
    box, n = pooled["box"] / pooled["diameter"], pooled["n_particles"]
    shell = float(ball_volume(1.0, dim)) * (edges[1:] ** dim - edges[:-1] ** dim)
    expected = n * (n - 1) / (2.0 * np.prod(box)) * pooled["measurements"] * shell
    centres = 0.5 * (edges[1:] + edges[:-1])
    ax_g.errorbar(centres, hist / expected, yerr=np.sqrt(hist) / expected, fmt="o", ms=2.5,
                  label="Monte Carlo")
    r = np.linspace(1.0, edges[-1], 100)
    ax_g.plot(r, np.polynomial.polynomial.polyval(r - 1.0, pooled["coefficients"]), "k-", lw=0.8,
              label=f"fit: $g(D^+)$ = {pooled['contact_value']:.3f}")
    for i, (name, label) in enumerate(eos_names.items()):
        ax_g.axhline(contact_value(phi, dim, name), color=f"C{i + 1}", ls="--", lw=0.8,
                     label=label)
    ax_g.set_xlabel("$r/D$")
    ax_g.set_ylabel("$g(r)$")
    ax_g.legend(fontsize=6)

    z = frame["reduced_pressure"].to_numpy(float)
    ax_z.plot(frame["sample"], z, "o", ms=2.5, label="per sample")
    sem = z.std(ddof=1) / np.sqrt(len(z)) if len(z) > 1 else np.nan
    ax_z.axhspan(z.mean() - sem, z.mean() + sem, color="C0", alpha=0.25,
                 label=f"mean {z.mean():.4f} $\\pm$ {sem:.4f}")
    for i, (name, label) in enumerate(eos_names.items()):
        ax_z.axhline(compressibility_factor(phi, dim, name), color=f"C{i + 1}", ls="--", lw=0.8,
                     label=f"{label}: {compressibility_factor(phi, dim, name):.4f}")
    ax_z.set_xlabel("sample")
    ax_z.set_ylabel(r"$\beta p/\rho$")
    fig.suptitle(title, fontsize=9)
    ax_z.legend(fontsize=6)

    ax_m.plot(frame["sample"], frame["msd_since_previous"], "o", ms=2.5)
    ax_m.axhline(sample_msd, color="k", ls=":", lw=0.8, label="required")
    ax_m.set_xlabel("sample")
    ax_m.set_ylabel(r"MSD since previous sample $/D^2$", fontsize=7)
    ax_m.set_ylim(bottom=0)
    ax_m.legend(fontsize=6)
    if bond_order:
        ax_q = axes[3]
        ax_q.plot(frame["sample"], frame["global_q6"], "o", ms=2.5, label="global $Q_6$")
        ax_q.plot(frame["sample"], frame["crystalline_fraction"], "s", ms=2.5,
                  label="crystal-like fraction")
        ax_q.axhline(1.0 / np.sqrt(pooled["n_particles"]), color="k", ls=":", lw=0.8,
                     label="$N^{-1/2}$")
        ax_q.set_yscale("symlog", linthresh=1e-3)
        ax_q.set_ylim(0, 1)
        ax_q.set_xlabel("sample")
        ax_q.set_title("fcc 0.575, bcc 0.511", fontsize=7)
        ax_q.legend(fontsize=6)
    fig.tight_layout()
    save_figure(fig, pdf_path)
