"""The target marker: where inverse kinematics is asked to bring the end effector.

:class:`TargetMarker` is the part of :class:`~robotconf.scene.Scene` that draws a sphere at
a target point, plus an RGB triad for a pose, under ``/meshcat/robotconf/target``: violet
when the robot can reach it, orange-red when it cannot. The sphere is see-through, so the
end-effector's red sphere shows inside it when the robot gets there. The scene keeps the
marker in view (a target far outside the robot's reach is where a student looks first).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_flag, one_line
from ._commands import ROOT, Outbox, command_op, set_object_op, shape_object
from ._drawing import SPHERE_RADIUS, TRIAD_LENGTH
from ._ghosts import faint
from ._three import triad

__all__ = ["TargetMarker", "TARGET", "TARGET_COLORS", "TARGET_RADIUS", "check_target"]

#: The marker's group: ``…/target/sphere`` and, for a pose, ``…/target/frame``.
TARGET = f"{ROOT}/target"
#: The marker's colour (0xRRGGBB): violet for a target reached or reachable, orange-red
#: for one that is not.
TARGET_COLORS = {True: 0x9467BD, False: 0xFF4500}
#: Opacity of the marker's sphere: the end-effector's red sphere shows through it.
TARGET_OPACITY = 0.5
#: The marker's radius, relative to the robot drawing's size (the EE sphere's is 0.042).
TARGET_RADIUS = 1.6 * SPHERE_RADIUS

_TARGET = "a point (3,) or a pose (4, 4) with last row [0, 0, 0, 1], in length units"


def check_target(value: Any) -> np.ndarray:
    """A target as a 4×4 pose (a point gets the identity rotation).

    >>> check_target([1, 2, 3])[:3, 3]
    array([1., 2., 3.])
    """
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


class TargetMarker:
    """The target marker of the scene.

    Parameters
    ----------
    outbox : Outbox
    size : callable
        Returns the robot drawing's size (length units): the marker is drawn at its scale.

    Examples
    --------
    >>> from robotconf.scene import RecordingChannel
    >>> marker = TargetMarker(Outbox(RecordingChannel()), lambda: 70.0)
    >>> marker.show([10.0, 20.0, 5.0], reachable=False)
    >>> marker.shown, marker.extent().tolist()
    (True, [[10.0, 20.0, 5.0]])
    >>> marker.clear(); marker.shown
    False
    """

    def __init__(self, outbox: Outbox, size: Callable[[], float]) -> None:
        self._outbox = outbox
        self._size = size
        # What its objects look like (reachable, is a pose, size), None when not drawn.
        self._look: tuple[bool, bool, float] | None = None
        self._point = np.zeros((0, 3))

    @property
    def shown(self) -> bool:
        """Whether the marker is drawn."""
        return self._look is not None

    def show(self, target: Any, reachable: bool = True) -> None:
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
        pose = check_target(target)
        reachable = check_flag(reachable, "reachable")
        size = self._size()
        old, ops = self._look, []
        if old is None or old[0] != reachable or old[2] != size:
            sphere = shape_object("sphere", TARGET_RADIUS * size, TARGET_COLORS[reachable])
            ops.append(set_object_op(f"{TARGET}/sphere", faint(sphere, TARGET_OPACITY)))
        if is_pose and (old is None or not old[1] or old[2] != size):
            ops.append(set_object_op(f"{TARGET}/frame", triad(2 * TRIAD_LENGTH * size)))
        if not is_pose and old is not None and old[1]:
            self._outbox.delete(f"{TARGET}/frame")
        matrix = pose.T.ravel().tolist()  # meshcat reads column-major
        ops.append(command_op({"type": "set_transform", "path": TARGET, "matrix": matrix}))
        self._look = (reachable, is_pose, size)
        self._point = pose[None, :3, 3]
        self._outbox.send(ops)

    def clear(self) -> None:
        """Remove the marker."""
        if self._look is None:
            return
        self._outbox.delete(TARGET)
        self._look = None
        self._point = np.zeros((0, 3))

    def extent(self) -> np.ndarray:
        """The target's point, shape (1, 3), or (0, 3) when none is shown."""
        return self._point
