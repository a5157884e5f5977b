"""Where the 3D scene plugs in: the real meshcat scene by default, any look-alike in tests.

The panel talks to a scene through :class:`SceneLike` only — ``show(snapshot)``, the view
options, the Reach and Program drawings, the playback, and the ``widget`` attribute — so
headless tests can inject a recording fake and the panel never depends on how the scene
draws. Every method but ``show`` and ``widget`` is optional: a scene without it simply
does not draw that part.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from typing import Any, Protocol

import ipywidgets as widgets

__all__ = ["SceneLike", "default_scene_factory", "PlaceholderScene"]


class SceneLike(Protocol):
    """What the panel needs from a 3D scene (see :class:`robotconf.scene.Scene`)."""

    widget: Any

    def show(self, snapshot: Any) -> None: ...


class PlaceholderScene:
    """Stands in when the 3D scene package is not available; says why.

    >>> import robotconf as rc
    >>> scene = PlaceholderScene(rc.Robot([rc.Module("Rz")]), "no meshcat")
    >>> scene.update([0.1]); "no meshcat" in scene.widget.value
    True
    """

    def __init__(self, robot: Any, reason: str):
        self.robot = robot
        self.q = robot.q
        self.snapshot: Any = None
        self.widget = widgets.HTML(
            f"<i>The 3D scene is not available here ({html.escape(reason)}); every other "
            "part of the panel works.</i>"
        )

    def show(self, snapshot: Any) -> None:
        """Remember what would be drawn."""
        self.snapshot, self.robot, self.q = snapshot, snapshot.robot, snapshot.q

    def set_robot(self, robot: Any, q: Any = None) -> None:
        self.robot, self.q = robot, robot.q if q is None else q

    def update(self, q: Any) -> None:
        self.q = q

    def animate(self, motion: Any, speed: float = 1.0) -> None:
        """Nothing to animate without a scene."""


def default_scene_factory(height: int = 420) -> Callable[[Any], Any]:
    """``robot -> robotconf.scene.Scene`` (imported on first use), or a placeholder.

    The scene's ``widget`` is its control bar (play, speed, time, fit, labels, frames,
    trace) above the 3D pane, so the panel's tab shows both.
    """

    def factory(robot: Any) -> Any:
        try:
            from ...scene import Scene
        except ImportError as error:  # the scene is optional for every other feature
            return PlaceholderScene(robot, str(error))
        return Scene(robot, robot.q, height=height)

    return factory
