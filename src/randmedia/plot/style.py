"""The one matplotlib style of every figure, its mean +- SEM band, and saving to PDF + PNG
atomically."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib
import numpy as np

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


def band(ax, x, mean, sem, colour=None, label=None, *, alpha: float = 0.3, **line_kwargs):
    """Draw a sample-mean curve and its mean +- SEM band (the band in the line's colour, no
    edge); every averaged curve of the figures is drawn this way.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    x, mean : array_like
        Abscissae and the sample mean at them.
    sem : array_like or None
        Standard error of the mean; no band when None or nowhere finite (one sample).
    colour : str, optional
        Line and band colour; None: the next colour of the axes' cycle.
    label : str, optional
        Legend label of the line.
    alpha : float, optional
        Opacity of the band (default 0.3).
    **line_kwargs
        Passed to :meth:`matplotlib.axes.Axes.plot` (e.g. ``lw``).

    Returns
    -------
    matplotlib.lines.Line2D
        The mean curve.
    """
    line, = ax.plot(x, mean, color=colour, label=label, **line_kwargs)
    if sem is not None and np.any(np.isfinite(sem)):
        ax.fill_between(x, mean - sem, mean + sem, color=line.get_color(), alpha=alpha, lw=0)
    return line


def empty_panels(fig) -> list[int]:
    """Indices (in ``fig.axes`` order) of the visible panels that show no data: no line of more
    than two points (reference lines drawn with ``axhline``/``axvline`` have two), no
    collection with an element (scatter, error bars, bands), no image and no patch. A panel
    left empty by missing inputs is what this finds; text-only panels count as empty too."""
    empty = []
    for index, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        lines = any(np.isfinite(np.asarray(line.get_xydata(), dtype=float)).all(axis=1).sum() > 2
                    for line in ax.get_lines())
        collections = any(len(c.get_paths()) > 0 or len(getattr(c, "get_offsets", lambda: [])()) > 0
                          for c in ax.collections)
        if not (lines or collections or ax.images or ax.patches):
            empty.append(index)
    return empty


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
