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


def _finite_points(line) -> np.ndarray:
    """Which points of a line are finite; a line with more than two is data (``axhline`` and
    ``axvline`` draw reference lines of two)."""
    return np.isfinite(np.asarray(line.get_xydata(), dtype=float)).all(axis=1)


def empty_panels(fig) -> list[int]:
    """Indices (in ``fig.axes`` order) of the visible panels that show no data: no line of more
    than two points (reference lines drawn with ``axhline``/``axvline`` have two), no
    collection with an element (scatter, error bars, bands), no image and no patch. A panel
    left empty by missing inputs is what this finds; text-only panels count as empty too."""
    empty = []
    for index, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        lines = any(_finite_points(line).sum() > 2 for line in ax.get_lines())
        collections = any(len(c.get_paths()) > 0 or len(getattr(c, "get_offsets", lambda: [])()) > 0
                          for c in ax.collections)
        if not (lines or collections or ax.images or ax.patches):
            empty.append(index)
    return empty


def _data_points_on_screen(ax, pixel: float = 1.0) -> np.ndarray:
    """Display coordinates (n, 2) of what ``ax`` draws as data, inside the axes window: the
    vertices of every line of more than two points with its segments sampled every ``pixel``
    (reference lines of ``axhline``/``axvline`` have two points and are left out), the offsets
    of scatter markers and the segments of error bars. Bands (``fill_between``) are left out:
    their curve is a line."""
    from matplotlib.collections import LineCollection, PathCollection

    pieces = []
    for line in ax.get_lines():
        finite = _finite_points(line)
        if not line.get_visible() or finite.sum() <= 2:
            continue
        screen = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float)[finite])
        pieces.append(screen)
        if line.get_linestyle() not in ("None", "none", "", " "):
            pieces.append(_sampled_segments(screen, pixel))
    for collection in ax.collections:
        if not collection.get_visible():
            continue
        if isinstance(collection, PathCollection) and len(collection.get_offsets()):
            pieces.append(collection.get_offset_transform().transform(np.asarray(collection.get_offsets(), dtype=float)))
        elif isinstance(collection, LineCollection):
            for path in collection.get_paths():
                pieces.append(_sampled_segments(collection.get_transform().transform(path.vertices), pixel))
    if not pieces:
        return np.empty((0, 2))
    points = np.concatenate(pieces)
    points = points[np.isfinite(points).all(axis=1)]
    window = ax.get_window_extent()
    inside = ((points[:, 0] >= window.x0) & (points[:, 0] <= window.x1)
              & (points[:, 1] >= window.y0) & (points[:, 1] <= window.y1))
    return points[inside]


def _sampled_segments(screen: np.ndarray, pixel: float) -> np.ndarray:
    """Points every ``pixel`` along the polyline ``screen`` (display coordinates)."""
    if len(screen) < 2:
        return screen
    start, end = screen[:-1], screen[1:]
    steps = np.clip(np.ceil(np.hypot(*(end - start).T) / pixel).astype(int), 1, 10_000)
    fractions = np.concatenate([np.arange(m) / m for m in steps])
    index = np.repeat(np.arange(len(start)), steps)
    return start[index] + fractions[:, None] * (end - start)[index]


def labels_over_data(fig, margin: float = 1.0) -> list[tuple[int, str, int]]:
    """Legends and text notes of ``fig`` that lie on its data.

    For each visible panel (``fig.axes`` order) the legend's box (title included), the box
    of every non-empty text drawn in data or axes coordinates (``ax.text``, ``ax.annotate``)
    and the box of every inset (``ax.inset_axes``, tick labels included), shrunk by ``margin``
    pixels, are tested against the panel's data as drawn
    (:func:`_data_points_on_screen`: curves sampled every pixel, markers, error bars).

    Returns
    -------
    list of (panel index, what, points)
        ``what`` is ``"legend"``, ``"text '...'"`` or ``"inset"``; ``points`` how many data points lie
        inside its box. Empty when no legend or note covers data.
    """
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    found = []
    for index, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        boxes = []
        legend = ax.get_legend()
        if legend is not None and legend.get_visible():
            boxes.append(("legend", legend.get_window_extent(renderer)))
        for text in ax.texts:
            if text.get_visible() and text.get_text().strip():
                boxes.append((f"text {text.get_text().strip()!r}", text.get_window_extent(renderer)))
        for child in ax.child_axes:  # insets, their tick labels included
            if child.get_visible():
                boxes.append(("inset", child.get_tightbbox(renderer)))
        if not boxes:
            continue
        points = _data_points_on_screen(ax)
        for what, box in boxes:
            inside = ((points[:, 0] > box.x0 + margin) & (points[:, 0] < box.x1 - margin)
                      & (points[:, 1] > box.y0 + margin) & (points[:, 1] < box.y1 - margin))
            if inside.any():
                found.append((index, what, int(inside.sum())))
    return found


def legend_below(ax, *, ncol: int = 2, fontsize: float = 6, **kwargs):
    """The legend of ``ax`` in ``ncol`` columns under its x label, off the data: for panels
    whose curves leave no corner free. Extra keyword arguments go to ``ax.legend``."""
    from matplotlib.transforms import offset_copy

    below = offset_copy(ax.transAxes, fig=ax.figure, y=-30, units="points")  # tick labels + x label
    return ax.legend(loc="upper center", bbox_to_anchor=(0.5, 0.0), bbox_transform=below, ncol=ncol,
                     fontsize=fontsize, **kwargs)


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
