"""Faint copies of a robot and a target marker: what inverse kinematics shows in the pane.

:class:`Ghosts` is the part of :class:`~robotconf.scene.Scene` that draws

- **ghost robots**: semi-transparent copies of a robot at other coordinates (every
  closed-form solution of a target), under ``/meshcat/robotconf/ghosts``;
- a **target marker**: a sphere at a point, plus an RGB triad for a pose, under
  ``/meshcat/robotconf/target``; orange-red when the target cannot be reached.

Both use the scene's own ops (meshcat ``set_object`` with transparent materials,
transforms, visibility), so they need nothing new on the page, work offline, and sit in
the scene log: a reloaded page, a second view and an HTML export show them too. Both live
beside the robot, not under it, so a rebuilt robot keeps them; their sizes follow the
robot drawing's size, like the robot's own spheres and links.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_flag, check_joint_values, one_line
from ..kinematics import Robot
from ._commands import ROOT, Op, command_op, set_object_op, shape_object, transforms_op
from ._drawing import SPHERE_RADIUS, TRIAD_LENGTH, RobotDrawing, structure_key
from ._three import triad

if TYPE_CHECKING:
    from ._commands import SceneLog

__all__ = [
    "Ghosts",
    "GHOSTS",
    "TARGET",
    "GHOST_OPACITY",
    "TARGET_COLORS",
    "MAX_GHOSTS",
    "ghost_object",
]

#: Ghost robots live under this path, one group per solution: ``…/ghosts/0``, ``…/1``.
GHOSTS = f"{ROOT}/ghosts"
#: The target marker's group: ``…/target/sphere`` and, for a pose, ``…/target/frame``.
TARGET = f"{ROOT}/target"
#: Opacity of a ghost's materials: visible, yet clearly not the robot.
GHOST_OPACITY = 0.3
#: The marker's colour (0xRRGGBB): violet for a target reached or reachable, orange-red
#: for one that is not.
TARGET_COLORS = {True: 0x9467BD, False: 0xFF4500}
#: Opacity of the marker's sphere: the end-effector's red sphere shows through it.
TARGET_OPACITY = 0.5
#: The marker's radius, relative to the robot drawing's size (the EE sphere's is 0.042).
TARGET_RADIUS = 1.6 * SPHERE_RADIUS
#: More ghosts than any closed form gives (a 6R arm has at most 16 solutions).
MAX_GHOSTS = 64

_TARGET = "a point (3,) or a pose (4, 4) with last row [0, 0, 0, 1], in length units"


def _faint(obj: dict[str, Any], opacity: float) -> dict[str, Any]:
    """The same three.js object with see-through materials that hide nothing behind them."""
    for material in obj["materials"]:
        # No depth writes: a ghost never hides the robot or another ghost behind it.
        material.update(transparent=True, opacity=float(opacity), depthWrite=False)
    return obj


def ghost_object(shape: str, size: float, color: int) -> dict[str, Any]:
    """The three.js JSON of one ghost item: the robot's shape, see-through.

    Parameters
    ----------
    shape : {"sphere", "cylinder", "box"}
    size : float
        Radius or half-width (length units).
    color : int
        0xRRGGBB, the robot's own colour for that item.

    Examples
    --------
    >>> material = ghost_object("sphere", 1.0, 0xD62728)["materials"][0]
    >>> material["transparent"], material["opacity"], material["depthWrite"]
    (True, 0.3, False)
    """
    return _faint(shape_object(shape, size, color), GHOST_OPACITY)


def _check_target(value: Any) -> np.ndarray:
    """A target as a 4×4 pose (a point gets the identity rotation); ``is_pose`` aside."""
    array = as_float_array(value, "target", _TARGET)
    if array.shape not in ((3,), (4, 4)):
        raise InvalidInputError(
            "target", one_line(value), _TARGET, problem=f"wrong shape {array.shape}:"
        )
    if not np.isfinite(array).all():
        raise InvalidInputError("target", one_line(value), _TARGET, problem="NaN or infinity in")
    if array.shape == (3,):
        pose = np.eye(4)
        pose[:3, 3] = array
        return pose
    if np.max(np.abs(array[3] - (0.0, 0.0, 0.0, 1.0))) > 1e-9:
        raise InvalidInputError(
            "target", one_line(value), _TARGET, problem="the last row is not [0, 0, 0, 1]:"
        )
    return array.copy()


class Ghosts:
    """The ghost and target methods of :class:`~robotconf.scene.Scene` (a mixin: the
    scene provides ``_send``, ``_log`` and ``_require_drawing``).

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, Scene
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> scene = Scene(arm, channel=RecordingChannel())
    >>> scene.show_ghosts(arm, [[0.0, np.pi / 2], [np.pi / 2, -np.pi / 2]])
    >>> scene.ghost_count
    2
    >>> scene.show_target([1.0, 1.0, 0.0], reachable=True)
    >>> scene.target_shown
    True
    >>> scene.clear_ghosts(); scene.clear_target()
    >>> scene.ghost_count, scene.target_shown
    (0, False)
    """

    _log: SceneLog

    if TYPE_CHECKING:  # provided by the scene

        def _send(
            self, ops: list[Op], *, log: bool = True, logged: list[Op] | None = None
        ) -> None: ...

        def _require_drawing(self) -> RobotDrawing: ...

    # Ghost state: the drawing the ghost objects were built from, how many slots exist,
    # how many show. Target state: what its objects look like (colour, pose, size).
    _ghost_drawing: RobotDrawing | None = None
    _ghost_slots: int = 0
    _ghost_count: int = 0
    _target_look: tuple[bool, bool, float] | None = None

    @property
    def ghost_count(self) -> int:
        """How many ghost robots the pane shows."""
        return self._ghost_count

    @property
    def target_shown(self) -> bool:
        """Whether the target marker is drawn."""
        return self._target_look is not None

    def show_ghosts(self, robot: Robot, qs: Any) -> None:
        """Draw faint copies of ``robot`` at each row of ``qs`` (replacing earlier ones).

        Parameters
        ----------
        robot : Robot
            The robot to copy (usually the scene's own); only its geometry is used.
        qs : array-like, shape (k, n)
            One configuration per ghost (radians / length units); ``k = 0`` clears them.

        Raises
        ------
        InvalidInputError
            ``robot`` that is not a Robot, ``qs`` of the wrong shape or not finite, or
            more than :data:`MAX_GHOSTS` rows.
        """
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", one_line(robot), "a robotconf Robot")
        if np.size(qs) == 0:
            self.clear_ghosts()
            return
        rows, batched = check_joint_values(qs, robot.n, robot.coordinate_names, "qs")
        if not batched:
            raise InvalidInputError(
                "qs",
                one_line(qs),
                f"shape (k, {robot.n}): one configuration per ghost",
                problem="one configuration without a ghost axis:",
            )
        if len(rows) > MAX_GHOSTS:
            raise InvalidInputError(
                "qs", f"<{len(rows)} rows>", f"at most {MAX_GHOSTS} ghosts", problem="too many:"
            )
        size = self._require_drawing().size
        drawing = self._ghost_drawing
        ops: list[Op] = []
        if (
            drawing is None
            or drawing.structure != structure_key(robot)
            or drawing.size != size
            or len(rows) > self._ghost_slots
        ):
            self.clear_ghosts()
            drawing = RobotDrawing(robot, size)
            self._ghost_drawing, self._ghost_slots = drawing, len(rows)
            ops += self._ghost_objects(drawing, len(rows))
        else:
            drawing.robot = robot  # the same shapes; lengths may differ
        ops += self._ghost_poses(drawing, rows)
        for slot in range(self._ghost_slots):
            ops.append(
                Op({"op": "visible", "paths": [f"{GHOSTS}/{slot}"], "value": slot < len(rows)})
            )
        self._ghost_count = len(rows)
        self._send(ops)

    def clear_ghosts(self) -> None:
        """Remove every ghost robot (from live views and from what a reload shows)."""
        if self._ghost_drawing is None:
            return
        self._log.forget(GHOSTS)
        self._send([command_op({"type": "delete", "path": GHOSTS})], log=False)
        self._ghost_drawing, self._ghost_slots, self._ghost_count = None, 0, 0

    def show_target(self, target: Any, reachable: bool = True) -> None:
        """Mark a target: a sphere at its point, and an RGB triad (x red, y green, z blue)
        for a pose; violet when ``reachable``, orange-red otherwise.

        Parameters
        ----------
        target : array-like, shape (3,) or (4, 4)
            A point or a homogeneous pose in the base frame (length units).
        reachable : bool
            Whether the robot can reach it (only the colour changes).

        Raises
        ------
        InvalidInputError
            ``target`` of the wrong shape, not finite, or a pose whose last row is not
            [0, 0, 0, 1]; ``reachable`` that is not a boolean.
        """
        is_pose = np.shape(target) == (4, 4)
        pose = _check_target(target)
        reachable = check_flag(reachable, "reachable")
        size = self._require_drawing().size
        look = (reachable, is_pose, size)
        old, ops = self._target_look, []
        if old is None or old[0] != reachable or old[2] != size:
            sphere = shape_object("sphere", TARGET_RADIUS * size, TARGET_COLORS[reachable])
            ops.append(set_object_op(f"{TARGET}/sphere", _faint(sphere, TARGET_OPACITY)))
        if is_pose and (old is None or not old[1] or old[2] != size):
            ops.append(set_object_op(f"{TARGET}/frame", triad(2 * TRIAD_LENGTH * size)))
        if not is_pose and old is not None and old[1]:
            self._log.forget(f"{TARGET}/frame")
            self._send([command_op({"type": "delete", "path": f"{TARGET}/frame"})], log=False)
        matrix = pose.T.ravel().tolist()  # meshcat reads column-major
        ops.append(command_op({"type": "set_transform", "path": TARGET, "matrix": matrix}))
        self._target_look = look
        self._send(ops)

    def clear_target(self) -> None:
        """Remove the target marker."""
        if self._target_look is None:
            return
        self._log.forget(TARGET)
        self._send([command_op({"type": "delete", "path": TARGET})], log=False)
        self._target_look = None

    # -- building blocks -------------------------------------------------------------------

    def _ghost_objects(self, drawing: RobotDrawing, slots: int) -> list[Op]:
        # The body only: no frames' triads, no labels (their numbers would be the ghost's).
        items = [i for i in drawing.items if i.layer == "body" and i.shape != "triad"]
        return [
            set_object_op(
                f"{GHOSTS}/{slot}/{item.path}", ghost_object(item.shape, item.size, item.color)
            )
            for slot in range(slots)
            for item in items
        ]

    def _ghost_poses(self, drawing: RobotDrawing, rows: np.ndarray) -> list[Op]:
        keep = [k for k, i in enumerate(drawing.items) if i.layer == "body" and i.shape != "triad"]
        matrices = drawing.placements(rows).matrices()[:, keep]  # (k, items, 4, 4)
        names = [drawing.items[k].path for k in keep]
        # One op per ghost: its log entry stays the same whatever the number shown.
        return [
            transforms_op([f"{GHOSTS}/{slot}/{name}" for name in names], matrices[slot])
            for slot in range(len(rows))
        ]
