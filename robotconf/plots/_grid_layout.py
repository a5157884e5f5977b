"""A grid of equal axes laid out in one measuring pass, with constrained layout's spacing.

Constrained layout measures every axes' tick labels on two iterations at every draw, and
``savefig`` draws a figure with a layout engine twice (once to lay it out, once for real):
a 3 × 3 DVA figure spent two thirds of its time there. A grid of equal axes needs only
the widest decoration of each column and the tallest of each row, measured once, so the
figures that use this module are built without a layout engine and placed here.

Spacing follows constrained layout's defaults: ``PAD`` (3 points) between the figure's
edge and the nearest text, twice that between the text of neighbouring axes.
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = ["PAD", "place_grid", "wrap_to_width", "renderer_of"]

#: Space around every axes' decorations, in inches (constrained layout's w_pad, h_pad).
PAD = 3 / 72


def renderer_of(fig: Any) -> Any:
    """The renderer ``fig.savefig`` and a notebook's display will draw with.

    The figure gets an Agg canvas of its own (a bare Figure's base canvas makes a new
    one, with a new renderer and empty text caches, at every save).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    if not isinstance(fig.canvas, FigureCanvasAgg):
        FigureCanvasAgg(fig)
    return fig.canvas.get_renderer()


def text_width(renderer: Any, text: Any, string: str) -> float:
    """Width in pixels of ``string`` drawn with the font of the Text artist ``text``."""
    width, _, _ = renderer.get_text_width_height_descent(
        string, text.get_fontproperties(), ismath=False
    )
    return float(width)


def wrap_to_width(text: Any, width: float) -> None:
    """Break ``text`` (a Text artist of a figure) into lines no wider than ``width``
    pixels.

    matplotlib's own ``wrap=True`` measures the text word by word at every draw; this
    measures it a few times, once.
    """
    renderer = renderer_of(text.figure)
    string = " ".join(text.get_text().split())
    average = text_width(renderer, text, string) / max(len(string), 1)
    columns = max(int(width / max(average, 1e-9)), 10)
    while True:
        lines = textwrap.wrap(string, columns, break_on_hyphens=False)
        if columns <= 10 or max(text_width(renderer, text, line) for line in lines) <= width:
            break
        columns = int(columns * 0.95)
    text.set_text("\n".join(lines))


def _overhangs(axes: np.ndarray, renderer: Any) -> np.ndarray:
    """Decorations beyond each axes' box, in pixels: (rows, cols, 4) as left, right,
    bottom, top."""
    out = np.zeros((*axes.shape, 4))
    for (r, c), ax in np.ndenumerate(axes):
        box = ax.get_position().transformed(ax.figure.transFigure)
        tight = ax.get_tightbbox(renderer, for_layout_only=True)
        out[r, c] = (box.x0 - tight.x0, tight.x1 - box.x1, box.y0 - tight.y0, tight.y1 - box.y1)
    return np.maximum(out, 0.0)


def place_grid(
    fig: Any,
    axes: np.ndarray,
    *,
    title: Any = None,
    note: Any = None,
    legend: Any = None,
) -> None:
    """Place a grid of equal axes so that no text overlaps and nothing is cut.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        A figure without a layout engine.
    axes : ndarray of Axes, shape (rows, cols)
    title : Text, optional
        The figure's title (``fig.suptitle``), put at the top.
    note : Text, optional
        A note at the bottom left, already broken into lines (:func:`wrap_to_width`).
    legend : Legend, optional
        A figure legend at the top right (``loc="upper right"``); the axes keep clear
        of it.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> fig = Figure(figsize=(6, 4), dpi=100, layout="none")
    >>> axes = fig.subplots(2, 2, squeeze=False)
    >>> label = axes[1, 0].set_ylabel("a label")
    >>> place_grid(fig, axes, title=fig.suptitle("four"))
    >>> round(float(axes[1, 0].get_tightbbox().x0), 1)  # 3 points from the edge at 100 dpi
    4.2
    """
    renderer = renderer_of(fig)
    width, height = fig.bbox.width, fig.bbox.height
    pad = PAD * fig.dpi
    top = height - pad
    if title is not None:
        title.set_verticalalignment("top")
        title.set_y(1 - pad / height)
        top -= title.get_window_extent(renderer).height + 2 * pad
    bottom = pad
    if note is not None:
        note.set_position((pad / width, pad / height))
        bottom += note.get_window_extent(renderer).height + 2 * pad
    right = width - pad
    if legend is not None:
        right -= legend.get_window_extent(renderer).width + pad
    rows, cols = axes.shape
    # Twice: new sizes can change the ticks (and so the labels) a little.
    for _ in range(2):
        hang = _overhangs(axes, renderer)
        left_of, right_of = hang[..., 0].max(axis=0), hang[..., 1].max(axis=0)
        below, above = hang[..., 2].max(axis=1), hang[..., 3].max(axis=1)
        # Outer pads are already in left/right/top/bottom; 2 pads between neighbours.
        cell_w = (right - pad - left_of.sum() - right_of.sum() - 2 * pad * (cols - 1)) / cols
        cell_h = (top - bottom - below.sum() - above.sum() - 2 * pad * (rows - 1)) / rows
        x = pad + np.concatenate([[0.0], np.cumsum(left_of + cell_w + right_of + 2 * pad)])
        y = top - np.concatenate([[0.0], np.cumsum(above + cell_h + below + 2 * pad)])
        moved = 0.0
        for (r, c), ax in np.ndenumerate(axes):
            box = (
                (x[c] + left_of[c]) / width,
                (y[r] - above[r] - cell_h) / height,
                max(cell_w, 1.0) / width,
                max(cell_h, 1.0) / height,
            )
            moved = max(moved, float(np.max(np.abs(np.subtract(ax.get_position().bounds, box)))))
            ax.set_position(box)
        if moved * max(width, height) < 0.5:
            break


def grid_of(axes: Sequence[Any] | np.ndarray) -> np.ndarray:
    """``axes`` as a 2-D object array (one column for a flat list)."""
    grid = np.asarray(axes, dtype=object)
    return grid if grid.ndim == 2 else grid.reshape(-1, 1)
