"""Faint copies of a robot: what inverse kinematics shows in the pane beside the robot.

:class:`GhostsLayer` is the part of :class:`~robotconf.scene.Scene` that draws **ghost
robots**: semi-transparent copies of a robot at other coordinates (every closed-form
solution of a target), under ``/meshcat/robotconf/ghosts``. A ghost has a body only, no
frames and no labels: a number beside it would read as the robot's.

Ghosts use the scene's own ops (meshcat ``set_object`` with transparent materials,
transforms, visibility), so they need nothing new on the page, work offline, and sit in
the scene log: a reloaded page, a second view and an HTML export show them too. They live
beside the robot, not under it, so a rebuilt robot keeps them; their sizes follow the
robot drawing's size, like the robot's own spheres and links. The target marker
(:mod:`robotconf.scene._target`) shares their see-through look.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_joint_values, one_line
from ..kinematics import Robot
from ._commands import ROOT, Op, Outbox, set_object_op, shape_object, transforms_op
from ._drawing import RobotDrawing, structure_of

__all__ = ["GhostsLayer", "GHOSTS", "GHOST_OPACITY", "MAX_GHOSTS", "ghost_object", "faint"]

#: Ghost robots live under this path, one group per solution: ``…/ghosts/0``, ``…/1``.
GHOSTS = f"{ROOT}/ghosts"
#: Opacity of a ghost's materials: visible, yet clearly not the robot.
GHOST_OPACITY = 0.3
#: More ghosts than any closed form gives (a 6R arm has at most 16 solutions).
MAX_GHOSTS = 64


def faint(obj: dict[str, Any], opacity: float) -> dict[str, Any]:
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
    return faint(shape_object(shape, size, color), GHOST_OPACITY)


class GhostsLayer:
    """Ghost robots beside the scene's robot.

    Parameters
    ----------
    outbox : Outbox
    size : callable
        Returns the robot drawing's size (length units): ghosts are drawn at its scale.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> ghosts = GhostsLayer(Outbox(RecordingChannel()), lambda: 2.0)
    >>> ghosts.show(arm, [[0.0, np.pi / 2], [np.pi / 2, -np.pi / 2]])
    >>> ghosts.count, ghosts.extent().shape
    (2, (6, 3))
    >>> ghosts.clear(); ghosts.count
    0
    """

    def __init__(self, outbox: Outbox, size: Callable[[], float]) -> None:
        self._outbox = outbox
        self._size = size
        # The drawing the ghost objects were built from, how many slots exist, how many
        # show, and where their joints and end effectors stand (for the fit).
        self._drawing: RobotDrawing | None = None
        self._slots = 0
        self.count = 0
        self._points = np.zeros((0, 3))

    def show(self, robot: Robot, qs: Any) -> None:
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
            self.clear()
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
        size = self._size()
        drawing = self._drawing
        ops: list[Op] = []
        if (
            drawing is None
            or drawing.structure != structure_of(robot.at())
            or drawing.size != size
            or len(rows) > self._slots
        ):
            self.clear()
            drawing = RobotDrawing(robot, size)
            self._drawing, self._slots = drawing, len(rows)
            ops += _ghost_objects(drawing, len(rows))
        else:
            drawing.robot = robot  # the same shapes; lengths may differ
        ops += self._poses(drawing, rows)
        for slot in range(self._slots):
            ops.append(
                Op({"op": "visible", "paths": [f"{GHOSTS}/{slot}"], "value": slot < len(rows)})
            )
        self.count = len(rows)
        self._outbox.send(ops)

    def clear(self) -> None:
        """Remove every ghost robot (from live views and from what a reload shows)."""
        if self._drawing is None:
            return
        self._outbox.delete(GHOSTS)
        self._drawing, self._slots, self.count = None, 0, 0
        self._points = np.zeros((0, 3))

    def extent(self) -> np.ndarray:
        """Where the shown ghosts' joints and end effectors stand, shape (k, 3)."""
        return self._points

    def _poses(self, drawing: RobotDrawing, rows: np.ndarray) -> list[Op]:
        keep = [k for k, i in enumerate(drawing.items) if i.layer == "body" and i.shape != "triad"]
        placement = drawing.placements(rows)
        matrices = placement.matrices()[:, keep]  # (k, items, 4, 4)
        spheres = [k for k, i in enumerate(drawing.items) if i.shape == "sphere"]
        self._points = placement.position[:, spheres].reshape(-1, 3)
        names = [drawing.items[k].path for k in keep]
        # One op per ghost: its log entry stays the same whatever the number shown.
        return [
            transforms_op([f"{GHOSTS}/{slot}/{name}" for name in names], matrices[slot])
            for slot in range(len(rows))
        ]


def _ghost_objects(drawing: RobotDrawing, slots: int) -> list[Op]:
    # The body only: no frames' triads, no labels (their numbers would be the ghost's).
    items = [i for i in drawing.items if i.layer == "body" and i.shape != "triad"]
    return [
        set_object_op(
            f"{GHOSTS}/{slot}/{item.path}", ghost_object(item.shape, item.size, item.color)
        )
        for slot in range(slots)
        for item in items
    ]
