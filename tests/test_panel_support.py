"""Shared helpers for the configurator panel tests (no tests here).

A recording fake stands in for the 3D scene: the panel talks to it through the same four
members as to ``robotconf.scene.Scene`` (``widget``, ``set_robot``, ``update``,
``animate``), so the tests see exactly what the panel asked the scene to do.
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np

import robotconf as rc
from robotconf.panel import Configurator


class FakeScene:
    """Records every call the panel makes; ``created`` counts factory calls."""

    created = 0

    def __init__(self, robot: rc.Robot):
        FakeScene.created += 1
        self.robot = robot
        self.q = robot.q
        self.widget = widgets.HTML("fake scene")
        self.calls: list[tuple[str, Any]] = []

    def set_robot(self, robot: rc.Robot, q: Any = None) -> None:
        self.calls.append(("set_robot", robot))
        self.robot, self.q = robot, np.asarray(q if q is not None else robot.q)

    def update(self, q: Any) -> None:
        self.calls.append(("update", np.array(q)))
        self.q = np.asarray(q)

    def animate(self, motion: Any, speed: float = 1.0) -> None:
        self.calls.append(("animate", motion))

    def names(self) -> list[str]:
        return [name for name, _ in self.calls]


def paper_robot() -> rc.Robot:
    """The paper's R_zR_yR_y robot (§3), built explicitly: l1 = 20, l2 = 30, l3 = 40."""
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def make_panel(robot: rc.Robot | None = None, **options: Any) -> Configurator:
    """A panel on the paper's robot (default) with a recording fake scene."""
    return Configurator(
        paper_robot() if robot is None else robot, scene_factory=FakeScene, **options
    )
