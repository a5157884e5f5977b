"""The robot in a 3D pane: Figure 14 of the paper, live in the notebook.

:class:`Scene` turns a robot into meshcat objects once and, when ``q`` changes, sends only
the transforms and label texts that changed. Every position it shows comes from the core,
so ``robot.end_effector(q)`` in a cell gives the number on the red sphere's label.
"""

from __future__ import annotations

from pathlib import Path
from time import monotonic
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_configuration, check_flag, check_integer
from ..kinematics import Robot, characteristic_length
from ._animation import AnimationState
from ._commands import (
    ROOT,
    Op,
    SceneLog,
    animation_op,
    command_op,
    fit_op,
    labels_op,
    set_object_op,
    shape_object,
    transforms_op,
)
from ._drawing import RobotDrawing, robot_size, structure_key
from ._fit import view_sphere
from ._ghosts import Ghosts
from ._labels import check_label_mode, label_digits, label_rows, merge_coincident
from ._playback import _ANIMATION_KEYS, ROBOT, Playback
from ._shown import Shown
from ._taught_points import TaughtPoints

__all__ = ["Scene", "view"]

#: Centring moves everything meshcat draws for us, and its grid and world axes with it.
CENTRED = ("/meshcat", "/Grid", "/Axes")

#: Rebuild the objects when the robot's size changes by more than this factor.
RESIZE_FACTOR = 2.0
#: Labels of points closer than this (times the view radius) are stacked in rows.
LABEL_SPACING = 0.25


class Scene(Ghosts, Playback, TaughtPoints):
    """A robot drawn in meshcat's three.js viewer inside the notebook.

    Inverse kinematics draws beside it: :meth:`show_ghosts` (faint copies at other
    coordinates) and :meth:`show_target` (a target marker), see ``_ghosts.py``; a robot
    program's taught points with :meth:`show_taught_points` (``_taught_points.py``).

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Initial coordinates; default: the modules' own ``q``.
    height : int
        Pane height in pixels.
    labels : {"positions", "names", "off"} or bool
        What the labels show: ``EE (70.0, 0.0, 20.0)``, ``EE``, or nothing (``True`` is
        ``"positions"``, ``False`` is ``"off"``).
    frames : bool
        Show an RGB triad (x red, y green, z blue) at every module frame.
    controls : bool
        Put the control bar above the pane (animation, fit view, labels, frames, trace).
    channel : object, optional
        Where ops go: default a notebook widget; tests pass a
        :class:`~robotconf.scene.RecordingChannel`.
    max_rate : float or None
        Messages per second to the notebook at most (default 60).

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, Scene
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> scene = Scene(robot, channel=RecordingChannel())
    >>> scene.labels()[-1]
    'EE (70.0, 0.0, 20.0)'
    >>> scene.update([0, 0.5, 0])
    >>> scene.channel.kinds()[-2:]
    ['transforms', 'labels']
    """

    def __init__(
        self,
        robot: Robot,
        q: Any = None,
        *,
        height: int = 420,
        labels: bool | str = True,
        frames: bool = False,
        controls: bool = True,
        channel: Any = None,
        max_rate: float | None = 60.0,
    ) -> None:
        _check_robot(robot)
        height = check_integer(height, "height", 100, 4000, "an integer from 100 to 4000 (pixels)")
        self._label_mode = check_label_mode(labels)
        self._frames_on = check_flag(frames, "frames")
        self._controls_on = check_flag(controls, "controls")
        self._trace_on = False
        self.height = height
        self._log = SceneLog()
        self._shown = Shown()
        self._pane = None
        self._widget: Any = None
        self._controls: Any = None
        self._animation: AnimationState | None = None
        self._view_radius = 1.0
        self._digits = 1
        if channel is None:
            from ._widget import SceneWidget, WidgetChannel, shared_code

            self._pane = SceneWidget(height=height, code=shared_code())
            channel = WidgetChannel(self._pane, self._replay, max_rate=max_rate)
            channel.on_event = self._view_event
        self.channel = channel
        self._drawing: RobotDrawing | None = None
        self._shown_in_cell: int | None = None
        self.robot = robot
        self.q = robot.q
        self._send(self._setup_ops())
        self.set_robot(robot, q)

    # -- what users call -------------------------------------------------------------------

    @property
    def widget(self) -> Any:
        """The widget to place in a layout: the control bar above the pane (``None`` with a
        custom channel)."""
        if self._widget is None and self._pane is not None:
            if self._controls_on:
                import ipywidgets

                self._widget = ipywidgets.VBox([self.controls.widget, self._pane])
            else:
                self._widget = self._pane
        return self._widget

    @property
    def pane(self) -> Any:
        """The 3D pane alone (an anywidget), or ``None`` with a custom channel."""
        return self._pane

    @property
    def controls(self) -> Any:
        """The scene's control bar (:class:`~robotconf.scene.SceneControls`), made on use."""
        if self._controls is None:
            from ._controls import SceneControls

            self._controls = SceneControls(self)
        return self._controls

    @property
    def label_mode(self) -> str:
        """What the labels show: ``"off"``, ``"names"`` or ``"positions"``."""
        return self._label_mode

    @property
    def frames_shown(self) -> bool:
        """Whether the module frames' triads are shown."""
        return self._frames_on

    def set_robot(self, robot: Robot, q: Any = None) -> None:
        """Show another robot; objects are rebuilt only if its structure changed.

        Parameters
        ----------
        robot : Robot
        q : array-like, shape (n,), optional
            Default: the robot's own ``q``.
        """
        _check_robot(robot)
        values = self._values(robot, q)
        size = robot_size(robot, values)
        drawing = self._drawing
        self.robot = robot
        self._digits = label_digits(characteristic_length(robot))
        if (
            drawing is None
            or drawing.structure != structure_key(robot)
            or not 1 / RESIZE_FACTOR <= size / drawing.size <= RESIZE_FACTOR
        ):
            self._build(RobotDrawing(robot, size), values)
        else:
            drawing.robot = robot
        self.update(values)

    def update(self, q: Any) -> None:
        """Move the robot to ``q`` (n,): one message with what changed.

        An animation loaded before is dropped: the pane shows ``q``, now and after a
        page reload.

        Parameters
        ----------
        q : array-like, shape (n,)
            Radians for rotations, length units for translations.

        Raises
        ------
        InvalidInputError
            For a bad ``q``, or a trajectory of shape (T, n): :meth:`animate` plays a motion.
        """
        drawing = self._require_drawing()
        values = self._values(self.robot, q)
        ops: list[Op] = []
        if self._animation is not None:
            ops += self._drop_animation()
        self.q = values
        paths = [self._path(p) for p in drawing.paths]
        matrices = drawing.placements(values).matrices()
        changed, moved = self._shown.transforms(paths, matrices)
        live = [transforms_op(changed, moved)] if changed else []
        logged = [transforms_op(paths, matrices)]
        label_live, label_logged = self._label_ops()
        self._send(ops + live + label_live, logged=logged + label_logged)

    def labels(self) -> list[str]:
        """The position labels at the current ``q``: ``["M1 (…)", …, "EE (…)"]``."""
        return self._require_drawing().labels(self.q, self._digits)

    def show_frames(self, visible: bool = True) -> None:
        """Show or hide the RGB triads at the module frames (x red, y green, z blue)."""
        self._frames_on = check_flag(visible, "visible")
        self._send([self._visibility_op("frames", self._frames_on)])
        self._sync_controls()

    def show_labels(self, visible: bool = True) -> None:
        """Show the position labels, or hide every label (see :meth:`set_label_mode`)."""
        self.set_label_mode("positions" if check_flag(visible, "visible") else "off")

    def set_label_mode(self, mode: str) -> None:
        """What the labels show: ``"off"``, ``"names"`` or ``"positions"``."""
        self._label_mode = check_label_mode(mode)
        live, logged = self._label_ops()
        visibility = self._visibility_op("labels", self._label_mode != "off")
        self._send([visibility, *live], logged=[visibility, *logged])
        self._sync_controls()

    def fit_view(self) -> None:
        """Centre the robot at its current ``q`` and zoom until it fills the pane.

        The camera keeps its direction; the scene's centre moves to the middle of the
        sphere around everything drawn (:func:`~robotconf.scene._fit.view_sphere`).
        """
        drawing = self._require_drawing()
        centre, radius = view_sphere(drawing, self.q)
        self._view_radius = radius
        shift = np.eye(4)
        shift[:3, 3] = -centre / drawing.size
        ops = [_transform_command(path, shift) for path in CENTRED]
        ops.append(fit_op(radius / drawing.size))
        self._send(ops)

    def add_point_cloud(
        self, name: str, points: Any, color: Any = (0.2, 0.4, 0.9), size: float | None = None
    ) -> None:
        """Draw points (e.g. a workspace) in the robot's frame.

        Parameters
        ----------
        name : str
            Replaces an earlier cloud of the same name.
        points : array-like, shape (N, 3)
            Base-frame positions (length units).
        color : array-like, shape (3,) or (N, 3)
            RGB in 0…1.
        size : float, optional
            Point size in length units; default 1 % of the robot's size.
        """
        from ._points import point_cloud_op

        drawing = self._require_drawing()
        path = f"{ROOT}/clouds/{_clean_name(name)}"
        op = point_cloud_op(path, points, color, size or 0.01 * drawing.size)
        self._send([op])

    def export_html(self, path: str | Path) -> Path:
        """Write the scene as one self-contained HTML file that opens offline.

        The viewer code is inlined (no CDN, no network); an animation keeps its controls.

        Returns
        -------
        pathlib.Path
        """
        from ._html import scene_html

        target = Path(path)
        target.write_text(scene_html(self._replay(), title=self.robot.name or "robot"), "utf-8")
        return target

    def close(self) -> None:
        """Close the widget (its views release their WebGL contexts)."""
        self.channel.close()
        if self._controls is not None:
            self._controls.close()
        if self._widget is not None and self._widget is not self._pane:
            self._widget.close()

    def _ipython_display_(self) -> None:
        from IPython.display import display

        # `rc.view(robot)` as a cell's last line displays the pane, then IPython displays
        # the returned scene again: skip that second one (same cell), allow any later one.
        if self._shown_in_cell is not None and self._shown_in_cell == _execution_count():
            self._shown_in_cell = None
            return
        widget = self.widget
        display(widget if widget is not None else repr(self))

    def __repr__(self) -> str:
        return f"<Scene of {self.robot.n} modules at q={np.round(self.q, 4).tolist()}>"

    # -- building blocks -------------------------------------------------------------------

    def _build(self, drawing: RobotDrawing, values: np.ndarray) -> None:
        # A fresh view has nothing to delete, so the delete itself is not logged.
        self._log.forget(ROBOT)
        ops = [command_op({"type": "delete", "path": ROBOT})]
        if self._animation is not None:
            ops.insert(0, animation_op("clear"))
            for key in _ANIMATION_KEYS:
                self._log.drop(key)
            self._animation = None
        self._send(ops, log=False)
        self._drawing = drawing
        self._shown.forget()
        scale = 1.0 / drawing.size
        ops = [_transform_command(ROOT, np.diag([scale, scale, scale, 1.0]))]
        for item in drawing.items:
            obj = shape_object(item.shape, item.size, item.color)
            ops.append(set_object_op(self._path(item.path), obj))
        ops.append(self._visibility_op("frames", self._frames_on))
        ops.append(self._visibility_op("labels", self._label_mode != "off"))
        self._send(ops)
        self.q = values
        self.fit_view()
        self._sync_controls()

    def _label_ops(self) -> tuple[list[Op], list[Op]]:
        """The labels that changed (for live views) and all labels (for the log)."""
        drawing = self._require_drawing()
        if self._label_mode == "off":
            return [], []
        points = drawing.label_points(self.q)
        names = list(drawing.point_names)
        if self._animation is not None:
            # The names themselves, one per moving point: the viewer replays transforms, so
            # a number, or a merge of points that part during the motion, would be wrong.
            texts = names
        else:
            texts = merge_coincident(names, points, self._digits, self._label_mode == "positions")
        rows = label_rows(points, LABEL_SPACING * self._view_radius, [not t for t in texts])
        paths = [self._path(p) for p in drawing.label_paths]
        changed = self._shown.labels(paths, texts, rows)
        live = [labels_op(*changed)] if changed[0] else []
        return live, [labels_op(paths, texts, rows)]

    def _sync_controls(self) -> None:
        if self._controls is not None:
            self._controls.sync()

    def _replay(self) -> list[Op]:
        """The log in replay order: the animation (paused) before the current transforms,
        so a new view or a reloaded page shows the current ``q``."""
        ops = self._log.ops()
        animation = [op for op in ops if _log_key(op) in _ANIMATION_KEYS]
        rest = [op for op in ops if _log_key(op) not in _ANIMATION_KEYS]
        first_state = next(
            (k for k, op in enumerate(rest) if op.content["op"] in ("transforms", "labels")),
            len(rest),
        )
        ops = rest[:first_state] + animation + rest[first_state:]
        state = self._animation
        if state is not None and state.still_playing(monotonic()):
            # A view that opens while the motion plays (the cell that made the scene and
            # animated it) plays it too; once it has ended, views show the current q.
            ops.append(animation_op("play"))
        return ops

    def _setup_ops(self) -> list[Op]:
        return [
            # Look at the robot from the front right, slightly above; fit_view sets the
            # distance, keeping this direction.
            command_op(
                {
                    "type": "set_property",
                    "path": "/Cameras/default/rotated/<object>",
                    "property": "position",
                    "value": [0.9, 0.6, 0.9],
                }
            ),
        ]

    def _visibility_op(self, layer: str, visible: bool) -> Op:
        drawing = self._require_drawing()
        paths = [self._path(item.path) for item in drawing.items if item.layer == layer]
        return Op({"op": "visible", "paths": paths, "value": bool(visible)})

    def _path(self, item_path: str) -> str:
        return f"{ROBOT}/{item_path}"

    def _send(self, ops: list[Op], *, log: bool = True, logged: list[Op] | None = None) -> None:
        """Send ``ops`` to the live views; record ``logged`` (default: the same ops) as the
        state a new view replays."""
        if log:
            for op in ops if logged is None else logged:
                self._log.record(_log_key(op), op)
        if ops:
            self.channel.send(ops)

    def _values(self, robot: Robot, q: Any) -> np.ndarray:
        # A motion (T, n) is refused here: animate() plays it.
        return check_configuration(robot.q if q is None else q, robot.n, robot.coordinate_names)

    def _require_drawing(self) -> RobotDrawing:
        assert self._drawing is not None, "the scene has no robot yet"
        return self._drawing


def _check_robot(robot: Any) -> None:
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")


def _clean_name(name: Any) -> str:
    if not isinstance(name, str) or not name or not all(c.isalnum() or c in "_-" for c in name):
        raise InvalidInputError("name", name, "letters, digits, '_' or '-'")
    return name


def _transform_command(path: str, matrix: np.ndarray) -> Op:
    return command_op({"type": "set_transform", "path": path, "matrix": matrix.T.ravel().tolist()})


def _log_key(op: Op) -> tuple[str, str]:
    content = op.content
    if content["op"] == "command":
        command = content["command"]
        return (command["type"], command.get("path", ""))
    if content["op"] == "packed":
        # Keyed like its JSON form: one packed set_object per path, not one for the scene.
        return (content["type"], content["path"])
    if content["op"] in ("transforms", "labels", "visible"):
        return (content["op"], "|".join(content["paths"]))
    if content["op"] == "animation":
        return ("animation", content["action"])
    return (content["op"], "")


def view(robot: Robot, q: Any = None, *, display: bool = True, **options: Any) -> Scene:
    """Show a robot in a 3D pane in the notebook (see :class:`Scene` for ``options``).

    Examples
    --------
    >>> import robotconf as rc
    >>> scene = rc.view(rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0)), display=False)
    >>> scene.labels()
    ['M1 (0.00, 0.00, 0.00)', 'EE (1.00, 0.00, 0.00)']
    """
    scene = Scene(robot, q, **options)
    if display:
        from IPython.display import display as show

        show(scene)
        scene._shown_in_cell = _execution_count()
    return scene


def _execution_count() -> int | None:
    """The running cell's number in IPython, or None outside it."""
    import sys

    if "IPython" not in sys.modules:
        return None
    from IPython import get_ipython

    shell = get_ipython()
    return None if shell is None else int(shell.execution_count)
