"""Drawing a figure without matplotlib's repeated work: one renderer, ticks once.

A bare Figure gets a new Agg canvas, renderer and empty text caches at every save; a
figure given its own Agg canvas keeps them. And while one figure is drawn (or measured
for its layout), matplotlib asks each 2D axis for its ticks up to eight times (the
spines, the tick labels, the axis label, the title each ask again), running the tick
locator and formatter each time; nothing changes in between, so :func:`ticks_once`
lets each axis compute them once.
"""

from __future__ import annotations

import contextlib
import textwrap
from collections.abc import Iterable, Iterator
from typing import Any

__all__ = ["renderer_of", "text_width", "wrap_to_width", "ticks_once", "save_figure"]


def renderer_of(fig: Any) -> Any:
    """The renderer that ``fig.savefig`` (at the figure's dpi) and a notebook's display
    draw with: the figure gets an Agg canvas of its own, which keeps it."""
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


@contextlib.contextmanager
def ticks_once(axes: Iterable[Any]) -> Iterator[None]:
    """Within the block, each axis of the 2D ``axes`` computes its ticks once.

    Only for blocks that change no limits, sizes or tick settings: a draw, or a layout's
    measuring pass. matplotlib versions without the private method are left alone.
    """
    patched = []
    for ax in axes:
        if getattr(ax, "name", None) == "3d":
            continue  # a 3D axis projects its ticks as it draws
        for axis in (ax.xaxis, ax.yaxis):
            compute = getattr(axis, "_update_ticks", None)
            if compute is None:
                continue
            axis._update_ticks = _remembered(compute)
            patched.append(axis)
    try:
        yield
    finally:
        for axis in patched:
            del axis._update_ticks  # the class's method again


def _remembered(compute: Any) -> Any:
    found: list[Any] = []

    def once() -> Any:
        if not found:
            found.append(compute())
        return found[0]

    return once


def save_figure(fig: Any, path: Any, *, dpi: float | None = None) -> None:
    """``fig.savefig(path, dpi=dpi)`` (a path or a binary file), each 2D axis computing
    its ticks once.

    >>> import io
    >>> from matplotlib.figure import Figure
    >>> fig = Figure(figsize=(2, 1))
    >>> lines = fig.add_subplot().plot([0, 1], [0, 1])
    >>> buffer = io.BytesIO()
    >>> save_figure(fig, buffer, dpi=50)
    >>> buffer.getvalue()[:4]
    b'\\x89PNG'
    """
    renderer_of(fig)
    with ticks_once(fig.axes):
        fig.savefig(path, dpi=dpi)
