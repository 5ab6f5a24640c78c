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
