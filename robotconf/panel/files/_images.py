"""Figures as PNG bytes and downloads as ``data:`` links: no server, no network."""

from __future__ import annotations

import base64
import html
import io
from typing import TYPE_CHECKING

import ipywidgets as widgets

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["figure_png", "data_uri", "download_link", "responsive_image"]


def figure_png(figure: Figure, dpi: int = 80) -> bytes:
    """PNG bytes of a matplotlib figure (drawn off-screen, never registered with pyplot)."""
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=dpi)
    return buffer.getvalue()


def responsive_image() -> widgets.Image:
    """A PNG image widget that fits its column: shown at its own size when there is room,
    scaled down (height following) when the column is narrower, never cut off.

    >>> responsive_image().layout.max_width
    '100%'
    """
    # The <img> is the widget's own element: max-width resolves against the box it is in,
    # and height auto keeps the aspect ratio; a fixed width would overflow a narrow column.
    return widgets.Image(
        format="png",
        layout=widgets.Layout(max_width="100%", height="auto", width="auto", object_fit="contain"),
    )


def data_uri(content: bytes | str, mime: str) -> str:
    """``data:<mime>;base64,…`` for ``content`` (text is UTF-8 encoded).

    >>> data_uri("a,b\\n", "text/csv")
    'data:text/csv;base64,YSxiCg=='
    """
    raw = content.encode("utf-8") if isinstance(content, str) else content
    return f"data:{mime};base64,{base64.b64encode(raw).decode('ascii')}"


def download_link(content: bytes | str, filename: str, mime: str, label: str) -> str:
    """An HTML ``<a download>`` link that saves ``content`` from the page itself.

    >>> download_link("{}", "robot.json", "application/json", "save").startswith("<a download=")
    True
    """
    return (
        f'<a download="{html.escape(filename)}" href="{data_uri(content, mime)}" '
        f'target="_blank" style="color:#0b57d0;text-decoration:underline">{html.escape(label)}</a>'
    )
