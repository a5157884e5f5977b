"""Where the cell's 3D view plugs in: :class:`robotconf.scene.CellScene` by default, any
look-alike in tests.

The designer talks to the view only through these members of ``CellScene``:
``show(cell, qs=None)``, ``animate(cell_run, speed=1.0, play=True)``,
``show_reach_map(reach_map)``, ``clear_reach_map()``, ``show_capsules(flag)``,
``select(name_or_None)``, ``fit_view()``, ``export_html(path, title=...)`` and
``widget``. The view highlights contacts itself when it animates a run.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from typing import Any, Protocol

import ipywidgets as widgets

__all__ = ["CellSceneLike", "PlaceholderCellScene", "default_scene_factory"]


class CellSceneLike(Protocol):
    """What the designer needs from a cell's 3D view."""

    widget: Any

    def show(self, cell: Any, qs: Any = None) -> None: ...

    def animate(self, cell_run: Any, *, speed: float = 1.0, play: bool = True) -> None: ...

    def show_reach_map(self, reach_map: Any) -> None: ...

    def clear_reach_map(self) -> None: ...

    def show_capsules(self, shown: bool) -> None: ...

    def select(self, name: str | None) -> None: ...

    def fit_view(self) -> None: ...

    def export_html(self, path: Any, title: str = ...) -> Any: ...


class PlaceholderCellScene:
    """Stands in when the 3D view cannot be built here; says why (every other part of
    the designer works).

    >>> import robotconf as rc
    >>> scene = PlaceholderCellScene(rc.Cell(), "no view")
    >>> "no view" in scene.widget.value
    True
    """

    def __init__(self, cell: Any, reason: str) -> None:
        self.cell = cell
        self.widget = widgets.HTML(
            f"<i>The 3D view is not available here ({html.escape(reason)}); every other "
            "part of the designer works.</i>"
        )

    def show(self, cell: Any, qs: Any = None) -> None:
        """Remember the cell."""
        self.cell = cell

    def animate(self, cell_run: Any, *, speed: float = 1.0, play: bool = True) -> None:
        """Nothing to animate without a view."""

    def show_reach_map(self, reach_map: Any) -> None:
        """Nothing to draw it in."""

    def clear_reach_map(self) -> None:
        """Nothing drawn."""

    def show_capsules(self, shown: bool) -> None:
        """Nothing drawn."""

    def select(self, name: str | None) -> None:
        """Nothing drawn."""

    def fit_view(self) -> None:
        """Nothing drawn."""

    def export_html(self, path: Any, title: str = "robotconf cell") -> Any:
        """A page that says why there is no view."""
        from pathlib import Path

        Path(path).write_text(
            f"<!doctype html><title>{html.escape(title)}</title>{self.widget.value}", "utf-8"
        )
        return path


def default_scene_factory(height: int = 480) -> Callable[[Any], Any]:
    """``cell -> robotconf.scene.CellScene(cell, height=height)``, or a placeholder."""

    def factory(cell: Any) -> Any:
        try:
            from .. import scene
        except ImportError as error:  # the view is optional for every other feature
            return PlaceholderCellScene(cell, str(error))
        if not hasattr(scene, "CellScene"):
            return PlaceholderCellScene(cell, "this robotconf has no robotconf.scene.CellScene")
        return scene.CellScene(cell, height=height, labels=True)

    return factory
