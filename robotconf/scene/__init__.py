"""The 3D scene: the robot in meshcat's three.js viewer, inside any notebook front end.

Presentation: every position drawn comes from :mod:`robotconf.kinematics`; the scene draws
a :class:`~robotconf.kinematics.RobotSnapshot` (``robot.at(q)``, one kernel pass) and
computes no kinematics of its own on a ``q`` step.

The scene
    :class:`Scene` — ``show(snapshot)`` (or ``set_robot(robot, q)``, ``update(q)``), view
    options (``set_label_mode``, ``show_frames``, ``show_trace``, ``fit_view``), playback
    (``animate``, ``play``, ``pause``, ``seek``, ``set_speed``, ``playback_state``, a
    :class:`PlaybackState`), ghosts, the target marker, taught points, point clouds,
    ``export_html``; ``on_request`` / ``on_playback`` hand the page's bar and player to a
    panel, and ``receive_from_page(message)`` takes what a view sends (tests play the page
    with it; formats in ``robotconf/scene/_page.py``).
    :func:`view` shows one in the notebook; :class:`RecordingChannel` records instead of
    sending (tests and the offline HTML export use it).
The page
    The widget's code (``js/``) draws the bar above the pane — classes
    ``robotconf-scene-controls`` (the bar), ``-play``, ``-speed``, ``-time``, ``-clock``,
    ``-fit``, ``-label-mode`` (buttons ``data-mode="off|names|positions"``), ``-frames``,
    ``-trace`` — plays animations with its own clock, and writes labels as text boxes
    (``robotconf-scene-label``) with leader lines (``robotconf-scene-leader``).
Building blocks
    :class:`RobotDrawing`, :func:`robot_size`, :class:`SceneLog`, :func:`pack_ops`,
    :func:`transforms_op`, :func:`align_y`, :func:`compose`, :func:`quaternions`;
    :class:`WidgetChannel` and :func:`coalesce_ops` (these import ipywidgets on use)

>>> from robotconf.kinematics import Module, Robot
>>> scene = Scene(Robot([Module("Tz")], end_effector=(0, 0, 1)), channel=RecordingChannel())
>>> scene.labels()  # three significant digits of the robot's size (1)
['M1 (0.00, 0.00, 0.00)', 'EE (0.00, 0.00, 1.00)']
>>> scene.update([0.5]); scene.snapshot.end_effector.tolist()
[0.0, 0.0, 1.5]
"""

from typing import Any

from ._commands import ROOT, RecordingChannel, SceneLog, pack_ops, transforms_op
from ._drawing import RobotDrawing, robot_size
from ._placement import align_y, compose, quaternions
from ._playback import PlaybackState
from ._scene import Scene
from ._view import view

__all__ = [
    # the scene
    "Scene",
    "view",
    "PlaybackState",
    "RecordingChannel",
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
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
