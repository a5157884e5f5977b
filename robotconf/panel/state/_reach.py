"""The Reach tab's part of the state: the target, how it is given, and the last outcome."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...kinematics import Robot, matrix_from_rpy, rpy_from_matrix

__all__ = ["ReachState", "ReachOutcome", "REACH_MODES", "target_of", "target_numbers"]

#: How a target is given: a point for the end effector, or a full pose.
REACH_MODES = ("position", "pose")


@dataclass(frozen=True)
class ReachOutcome:
    """What the last solve or click said, in the core's words.

    Attributes
    ----------
    success : bool
    reason : str
        The solver's ``reason`` (``converged``, ``unreachable`` …) or ``"closed form"``
        for a clicked branch.
    message : str
        The solver's sentence, or the clicked branch's label.
    warning : str
        What the solver warned about (a planar arm asked for a pose), or ``""``.
    reached : Robot or None
        The robot the solve or click produced (to tell later whether it moved since).
    """

    success: bool
    reason: str
    message: str
    warning: str = ""
    reached: Robot | None = None


@dataclass(frozen=True)
class ReachState:
    """The target and what happened to it.

    Attributes
    ----------
    mode : str
        One of :data:`REACH_MODES`.
    target : tuple of 6 floats or None
        ``(x, y, z, roll, pitch, yaw)`` in core units (length, radians); ``None`` until
        the student sets one: the target then follows the end effector.
    outcome : ReachOutcome or None
        The last solve or click (``None`` before any, or after "from current pose").
    show_all : bool
        Draw every closed-form solution as a ghost robot.

    Examples
    --------
    >>> import robotconf as rc
    >>> state = ReachState()
    >>> target_numbers(state, rc.preset("paper"))[:3]
    (70.0, 0.0, 20.0)
    """

    mode: str = "position"
    target: tuple[float, float, float, float, float, float] | None = None
    outcome: ReachOutcome | None = None
    show_all: bool = True


def target_numbers(
    state: ReachState, robot: Robot
) -> tuple[float, float, float, float, float, float]:
    """The six numbers the target controls show: the state's target, or the end
    effector's pose while the target follows the robot."""
    if state.target is not None:
        return state.target
    pose = robot.at().end_effector_pose
    x, y, z = (float(v) for v in pose[:3, 3])
    roll, pitch, yaw = (float(v) for v in rpy_from_matrix(pose[:3, :3]))
    return (x, y, z, roll, pitch, yaw)


def target_of(numbers: tuple[float, ...], mode: str) -> np.ndarray:
    """What :func:`robotconf.ik` takes: a point (3,), or a pose (4, 4) in ``"pose"`` mode.

    >>> target_of((1.0, 2.0, 3.0, 0.0, 0.0, 0.0), "position")
    array([1., 2., 3.])
    >>> target_of((1.0, 2.0, 3.0, 0.0, 0.0, 0.0), "pose")[:3, 3]
    array([1., 2., 3.])
    """
    point = np.array(numbers[:3], dtype=float)
    if mode != "pose":
        return point
    pose = np.eye(4)
    pose[:3, :3] = matrix_from_rpy(*numbers[3:6])
    pose[:3, 3] = point
    return pose
