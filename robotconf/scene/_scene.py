"""The robot in a 3D pane: Figure 14 of the paper, live in the notebook.

:class:`Scene` turns a robot into meshcat objects once and, when ``q`` changes, sends only
transforms and label texts. Every position it shows comes from the core, so
``robot.end_effector(q)`` in a cell gives the number on the red sphere's label.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_configuration, check_flag, check_integer
from ..kinematics import Robot
from ._animation import animation_command
from ._commands import (
    ROOT,
    Op,
    SceneLog,
    command_op,
    labels_op,
    set_object_op,
    shape_object,
    transforms_op,
)
from ._drawing import RobotDrawing, robot_size, structure_key

__all__ = ["Scene", "view"]

#: The robot's objects live under this path; clouds and the base frame beside it.
ROBOT = f"{ROOT}/robot"

#: Rebuild the objects when the robot's size changes by more than this factor.
RESIZE_FACTOR = 2.0


class Scene:
    """A robot drawn in meshcat's three.js viewer inside the notebook.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Initial coordinates; default: the modules' own ``q``.
    height : int
        Pane height in pixels.
    labels : bool
        Show position labels (``EE (70.0, 0.0, 20.0)``).
    frames : bool
        Show an RGB triad (x red, y green, z blue) at every module frame.
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
        labels: bool = True,
        frames: bool = False,
        channel: Any = None,
        max_rate: float | None = 60.0,
    ) -> None:
        _check_robot(robot)
        height = check_integer(height, "height", 100, 4000, "an integer from 100 to 4000 (pixels)")
        self._labels_on = check_flag(labels, "labels")
        self._frames_on = check_flag(frames, "frames")
        self.height = height
        self._log = SceneLog()
        self._widget = None
        if channel is None:
            from ._widget import SceneWidget, WidgetChannel, shared_code

            self._widget = SceneWidget(height=height, code=shared_code())
            channel = WidgetChannel(self._widget, self._log.ops, max_rate=max_rate)
        self.channel = channel
        self._shown_labels: list[str] = []
        self._drawing: RobotDrawing | None = None
        self._shown_in_cell: int | None = None
        self.robot = robot
        self.q = robot.q
        self._send(self._setup_ops())
        self.set_robot(robot, q)

    # -- what users call -------------------------------------------------------------------

    @property
    def widget(self) -> Any:
        """The ipywidgets widget to place in a layout (``None`` with a custom channel)."""
        return self._widget

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
        if (
            drawing is None
            or drawing.structure != structure_key(robot)
            or not 1 / RESIZE_FACTOR <= size / drawing.size <= RESIZE_FACTOR
        ):
            self._build(RobotDrawing(robot, size))
        else:
            drawing.robot = robot
        self.robot = robot
        self.update(values)

    def update(self, q: Any) -> None:
        """Move the robot to ``q`` (n,): one message with transforms and label texts.

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
        matrices = drawing.placements(values).matrices()
        ops = [transforms_op([self._path(p) for p in drawing.paths], matrices)]
        texts = drawing.labels(values)
        if self._labels_on and texts != self._shown_labels:
            ops.append(labels_op([self._path(p) for p in drawing.label_paths], texts))
            self._shown_labels = texts
        self.q = values
        self._send(ops)

    def labels(self) -> list[str]:
        """The position labels at the current ``q``: ``["M1 (…)", …, "EE (…)"]``."""
        return self._require_drawing().labels(self.q)

    def show_frames(self, visible: bool = True) -> None:
        """Show or hide the RGB triads at the module frames (x red, y green, z blue)."""
        self._frames_on = check_flag(visible, "visible")
        self._send([self._visibility_op("frames", self._frames_on)])

    def show_labels(self, visible: bool = True) -> None:
        """Show or hide the position labels."""
        self._labels_on = check_flag(visible, "visible")
        ops = [self._visibility_op("labels", self._labels_on)]
        if self._labels_on:
            self._shown_labels = self.labels()
            drawing = self._require_drawing()
            ops.append(labels_op([self._path(p) for p in drawing.label_paths], self._shown_labels))
        self._send(ops)

    def animate(self, motion: Any, *, speed: float = 1.0, play: bool = True) -> None:
        """Play a simulated motion in the pane (play / pause / time scrubber in its menu).

        Labels show names only while the animation runs: the viewer replays transforms,
        and a number that does not follow the robot would be wrong. ``update(q)``
        brings the numbers back.

        Parameters
        ----------
        motion : Motion
            From :func:`robotconf.simulate` with this scene's robot.
        speed : float
            Playback speed (1 = real time).
        play : bool
            Start playing at once.
        """
        drawing = self._require_drawing()
        command = animation_command(drawing, motion, speed=speed, play=play, root=ROBOT)
        # The names themselves: cutting "M2 (…)" at " (" would also cut a name holding it.
        names = list(drawing.point_names)
        self._shown_labels = names
        self._send(
            [labels_op([self._path(p) for p in drawing.label_paths], names), command_op(command)]
        )

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
        target.write_text(scene_html(self._log.ops(), title=self.robot.name or "robot"), "utf-8")
        return target

    def close(self) -> None:
        """Close the widget (its views release their WebGL contexts)."""
        self.channel.close()

    def _ipython_display_(self) -> None:
        from IPython.display import display

        # `rc.view(robot)` as a cell's last line displays the pane, then IPython displays
        # the returned scene again: skip that second one (same cell), allow any later one.
        if self._shown_in_cell is not None and self._shown_in_cell == _execution_count():
            self._shown_in_cell = None
            return
        display(self._widget if self._widget is not None else repr(self))

    def __repr__(self) -> str:
        return f"<Scene of {self.robot.n} modules at q={np.round(self.q, 4).tolist()}>"

    # -- building blocks -------------------------------------------------------------------

    def _build(self, drawing: RobotDrawing) -> None:
        # A fresh view has nothing to delete, so the delete itself is not logged.
        self._log.forget(ROBOT)
        self._send([command_op({"type": "delete", "path": ROBOT})], log=False)
        self._drawing = drawing
        self._shown_labels = []
        scale = 1.0 / drawing.size
        ops = [_transform_command(ROOT, np.diag([scale, scale, scale, 1.0]))]
        for item in drawing.items:
            obj = shape_object(item.shape, item.size, item.color)
            ops.append(set_object_op(self._path(item.path), obj))
        ops.append(self._visibility_op("frames", self._frames_on))
        ops.append(self._visibility_op("labels", self._labels_on))
        self._send(ops)

    def _setup_ops(self) -> list[Op]:
        return [
            # Look at a robot of unit size from the front right, slightly above.
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

    def _send(self, ops: list[Op], *, log: bool = True) -> None:
        if log:
            for op in ops:
                self._log.record(_log_key(op), op)
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
    return (content["op"], "")


def view(robot: Robot, q: Any = None, *, display: bool = True, **options: Any) -> Scene:
    """Show a robot in a 3D pane in the notebook (see :class:`Scene` for ``options``).

    Examples
    --------
    >>> import robotconf as rc
    >>> scene = rc.view(rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0)), display=False)
    >>> scene.labels()
    ['M1 (0.0, 0.0, 0.0)', 'EE (1.0, 0.0, 0.0)']
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
