"""The one matplotlib style of every figure, and saving to PDF + PNG atomically."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # headless: rule jobs and CI have no display

import matplotlib.pyplot as plt  # noqa: E402

from randmedia.io import atomic_output  # noqa: E402

#: single-column width of a Physical Review figure, inches
COLUMN_WIDTH = 3.4
#: double-column width, inches
PAGE_WIDTH = 7.0

STYLE = {
    "font.size": 9,
    "axes.labelsize": 9,
    "axes.titlesize": 9,
    "legend.fontsize": 8,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.top": True,
    "ytick.right": True,
    "lines.linewidth": 1.2,
    "lines.markersize": 3.5,
    "errorbar.capsize": 1.5,
    "legend.frameon": False,
    "figure.dpi": 150,
    "savefig.dpi": 300,
    "savefig.bbox": "tight",
    "mathtext.fontset": "cm",
    "font.family": "serif",
    "pdf.fonttype": 42,
}


def figure(ncols: int = 1, nrows: int = 1, *, width: float = COLUMN_WIDTH, aspect: float = 0.75,
           **subplot_kwargs):
    """A new figure in the project style; returns (fig, axes).

    Parameters
    ----------
    ncols, nrows : int
        Grid of axes (default 1 x 1).
    width : float
        Figure width in inches (default :data:`COLUMN_WIDTH`).
    aspect : float
        Height / width of one panel; the figure height is width * aspect * nrows / ncols.
    **subplot_kwargs
        Passed to :func:`matplotlib.pyplot.subplots` (e.g. ``sharex``, ``gridspec_kw``).

    Returns
    -------
    tuple
        (fig, axes) as returned by :func:`matplotlib.pyplot.subplots`.
    """
    plt.rcParams.update(STYLE)
    height = width * aspect * nrows / ncols
    return plt.subplots(nrows, ncols, figsize=(width, height), **subplot_kwargs)


def save_figure(fig, pdf_path: str | os.PathLike) -> tuple[Path, Path]:
    """Save ``fig`` as ``X.pdf`` and ``X.png`` (atomically) and close it."""
    pdf_path = Path(pdf_path)
    if pdf_path.suffix != ".pdf":
        raise ValueError(f"{pdf_path}: figure path must end in .pdf (the PNG goes beside it)")
    png_path = pdf_path.with_suffix(".png")
    with atomic_output(pdf_path) as tmp:
        # no creation date, so that identical figures are identical files
        fig.savefig(tmp, format="pdf", metadata={"CreationDate": None})
    with atomic_output(png_path) as tmp:
        fig.savefig(tmp, format="png")
    plt.close(fig)
    return pdf_path, png_path
