"""A grid of equal axes laid out once, when it is built, with constrained layout's spacing.

Constrained layout measures every axes' tick labels on two iterations at every draw, and
``savefig`` draws a figure with a layout engine twice (once to lay it out, once for real):
a 3 × 3 DVA figure spent most of its time there. A grid of equal axes needs only the
widest decoration of each column and the tallest of each row, measured once (again only
if the new sizes moved the ticks), so the figures that use this module are built without
a layout engine and placed here.

Spacing follows constrained layout's defaults: ``PAD`` (3 points) between the figure's
edge and the nearest text, twice that between the text of neighbouring axes.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ._drawing import renderer_of, ticks_once

__all__ = ["PAD", "place_grid", "grid_of"]

#: Space around every axes' decorations, in inches (constrained layout's w_pad, h_pad).
PAD = 3 / 72


def _overhangs(axes: np.ndarray, renderer: Any) -> np.ndarray:
    """Decorations beyond each axes' box, in pixels: (rows, cols, 4) as left, right,
    bottom, top."""
    out = np.zeros((*axes.shape, 4))
    with ticks_once(axes.flat):
        for (r, c), ax in np.ndenumerate(axes):
            box = ax.get_position().transformed(ax.figure.transFigure)
            tight = ax.get_tightbbox(renderer, for_layout_only=True)
            out[r, c] = (
                box.x0 - tight.x0,
                tight.x1 - box.x1,
                box.y0 - tight.y0,
                tight.y1 - box.y1,
            )
    return np.maximum(out, 0.0)


def _ticks(axes: np.ndarray) -> list[list[float]]:
    """Where each axis' ticks are for the axes' current sizes."""
    return [list(axis.get_majorticklocs()) for ax in axes.flat for axis in (ax.xaxis, ax.yaxis)]


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
    # New sizes can move the ticks (and so change the labels): measure again until
    # they stay where they were measured, which they nearly always do at once.
    for _ in range(3):
        measured = _ticks(axes)
        hang = _overhangs(axes, renderer)
        left_of, right_of = hang[..., 0].max(axis=0), hang[..., 1].max(axis=0)
        below, above = hang[..., 2].max(axis=1), hang[..., 3].max(axis=1)
        # Outer pads are already in left/right/top/bottom; 2 pads between neighbours.
        cell_w = (right - pad - left_of.sum() - right_of.sum() - 2 * pad * (cols - 1)) / cols
        cell_h = (top - bottom - below.sum() - above.sum() - 2 * pad * (rows - 1)) / rows
        x = pad + np.concatenate([[0.0], np.cumsum(left_of + cell_w + right_of + 2 * pad)])
        y = top - np.concatenate([[0.0], np.cumsum(above + cell_h + below + 2 * pad)])
        for (r, c), ax in np.ndenumerate(axes):
            ax.set_position(
                (
                    (x[c] + left_of[c]) / width,
                    (y[r] - above[r] - cell_h) / height,
                    max(cell_w, 1.0) / width,
                    max(cell_h, 1.0) / height,
                )
            )
        if _ticks(axes) == measured:
            break


def grid_of(axes: Sequence[Any] | np.ndarray) -> np.ndarray:
    """``axes`` as a 2-D object array (one column for a flat list)."""
    grid = np.asarray(axes, dtype=object)
    return grid if grid.ndim == 2 else grid.reshape(-1, 1)
