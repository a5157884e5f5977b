"""The 3D scene: the robot in meshcat's three.js viewer, inside any notebook front end.

Presentation: every position drawn comes from :mod:`robotconf.kinematics`.

The scene
    :class:`Scene`, :func:`view`, :class:`RecordingChannel` (a channel that records
    instead of sending: tests and the offline HTML export use it), :class:`SceneControls`
    (the bar above the pane: play, pause, speed, time, fit view, labels, frames, trace)
Building blocks
    :class:`RobotDrawing`, :func:`robot_size`, :class:`SceneLog`, :func:`pack_ops`,
    :func:`transforms_op`, :func:`align_y`, :func:`compose`, :func:`quaternions`;
    :class:`WidgetChannel`, :func:`coalesce_ops` and :class:`SceneControls` (these import
    ipywidgets on use)

>>> from robotconf.kinematics import Module, Robot
>>> scene = Scene(Robot([Module("Tz")], end_effector=(0, 0, 1)), channel=RecordingChannel())
>>> scene.labels()  # three significant digits of the robot's size (1)
['M1 (0.00, 0.00, 0.00)', 'EE (0.00, 0.00, 1.00)']
"""

from typing import Any

from ._commands import ROOT, RecordingChannel, SceneLog, pack_ops, transforms_op
from ._drawing import RobotDrawing, robot_size
from ._placement import align_y, compose, quaternions
from ._scene import Scene, view

__all__ = [
    # the scene
    "Scene",
    "view",
    "RecordingChannel",
    "SceneControls",
    # building blocks
    "RobotDrawing",
    "robot_size",
    "SceneLog",
    "ROOT",
    "pack_ops",
    "transforms_op",
    "align_y",
    "compose",
    "quaternions",
    "WidgetChannel",
    "coalesce_ops",
]

# The widget transport imports anywidget and ipywidgets: only when asked for.
_LAZY = ("WidgetChannel", "coalesce_ops")


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        from . import _widget

        return getattr(_widget, name)
    if name == "SceneControls":
        from ._controls import SceneControls

        return SceneControls
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
