"""New matplotlib figures that show themselves in a notebook, without pyplot's state.

robotconf's plots build a bare :class:`matplotlib.figure.Figure` (no pyplot figure
manager, so nothing is shown twice or piles up). IPython only knows how to display such a
figure once matplotlib's inline support is set up, which normally happens when pyplot
first draws in a kernel; a fresh kernel would print ``<Figure size …>`` instead of the
picture. Importing the inline backend (it configures IPython when it is the kernel's
backend, and does nothing otherwise) sets that up.
"""

from __future__ import annotations

import contextlib
import sys
from typing import Any, Literal

__all__ = ["new_figure"]


def new_figure(
    figsize: Any,
    *,
    layout: Literal["constrained", "none"] = "constrained",
    dpi: float | None = None,
) -> Any:
    """A Figure that a notebook cell displays as a picture.

    ``layout`` is matplotlib's layout engine (``"none"`` for figures placed by
    :mod:`._grid_layout`); ``dpi`` defaults to matplotlib's ``figure.dpi``.

    >>> new_figure((4, 3)).get_size_inches().tolist()
    [4.0, 3.0]
    """
    from matplotlib.figure import Figure

    if "IPython" in sys.modules:
        # matplotlib_inline comes with ipykernel; without it there is no notebook anyway.
        with contextlib.suppress(ImportError):
            import matplotlib_inline.backend_inline  # noqa: F401 - notebook figure display

    if layout == "constrained":
        return Figure(figsize=figsize, layout="constrained", dpi=dpi)
    figure = Figure(figsize=figsize, dpi=dpi)
    figure.set_layout_engine("none")  # whatever the user's rcParams ask for
    return figure
