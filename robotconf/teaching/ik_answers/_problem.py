"""What an inverse-kinematics answer is judged against: the robot, the target, and the
forward kinematics that decides whether a configuration reaches it.

An IK exercise has many right answers (two elbow solutions, whole turns added to any
angle), so an answer is never compared with one stored solution: its end effector is
computed and compared with the target. The closed-form solutions of
:func:`robotconf.ik_all` are read only to explain a wrong answer or to list every
solution of a set.
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import as_float_array, check_finite_number, one_line
from ...inverse_kinematics import IKSolutions, ik_all
from ...kinematics import Robot, characteristic_length
from ..reading._shown import number_text

__all__ = ["MAX_ANGLE", "IKProblem", "turn_angle"]

#: Largest joint angle (rad) an answer may hold: beyond it a float cannot tell angles
#: 0.001 rad apart, so the answer could not be judged modulo a full turn.
MAX_ANGLE = 1e9

_TARGET = "a point (x, y, z), shape (3,), or a pose, a (4, 4) homogeneous matrix"
_MODES = ("position", "pose")


def turn_angle(rotation: np.ndarray, goal: np.ndarray) -> np.ndarray:
    """The angle (rad) still to turn from ``rotation`` to ``goal``, shapes (..., 3, 3).

    Read from both the sine and the cosine of ``goal · rotationᵀ``, so it stays accurate
    near 0 and near π.

    >>> turn_angle(np.eye(3), np.diag([1.0, -1.0, -1.0])).round(6)
    np.float64(3.141593)
    """
    rest = goal @ np.swapaxes(rotation, -1, -2)
    skew = rest - np.swapaxes(rest, -1, -2)
    sine = 0.5 * np.sqrt(skew[..., 2, 1] ** 2 + skew[..., 0, 2] ** 2 + skew[..., 1, 0] ** 2)
    cosine = 0.5 * (np.trace(rest, axis1=-2, axis2=-1) - 1.0)
    return np.arctan2(sine, cosine)


def _check_target(target: Any, mode: Any) -> tuple[np.ndarray, np.ndarray | None, str]:
    """The target point (3,), its rotation (pose mode) and the mode, checked."""
    if mode not in _MODES:
        raise InvalidInputError("mode", mode, '"position" or "pose"')
    array = as_float_array(target, "target", _TARGET)
    if array.shape not in ((3,), (4, 4)) or not np.all(np.isfinite(array)):
        raise InvalidInputError("target", one_line(target), _TARGET + ", finite")
    if array.shape == (3,):
        if mode == "pose":
            raise InvalidInputError(
                "target", one_line(target), "a (4, 4) pose in mode 'pose'", problem="a point:"
            )
        return array.copy(), None, mode
    turn = array[:3, :3]
    rotation_like = np.abs(turn.T @ turn - np.eye(3)).max() <= 1e-6 and np.linalg.det(turn) > 0
    if not np.allclose(array[3], (0, 0, 0, 1), atol=1e-9) or not rotation_like:
        raise InvalidInputError(
            "target",
            one_line(target),
            _TARGET + " with a rotation block (orthonormal within 1e-6) and last row 0 0 0 1",
        )
    return array[:3, 3].copy(), (turn.copy() if mode == "pose" else None), mode


class IKProblem:
    """One inverse-kinematics exercise: reach ``target`` with ``robot``.

    Parameters
    ----------
    robot : Robot
    target : array-like, shape (3,) or (4, 4)
        A point, or a pose (its point alone counts in mode ``"position"``).
    mode : {"position", "pose"}
    tol : float
        Relative to the robot's size ``L = rc.characteristic_length(robot)``: a
        configuration reaches the target when its end effector is within ``tol·L`` of the
        point (and, in mode ``"pose"``, its orientation within ``tol`` rad).

    Examples
    --------
    >>> import robotconf as rc
    >>> problem = IKProblem(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0], "position", 1e-3)
    >>> problem.reaches(np.array([[0, np.pi / 2], [0, 0]])).tolist()
    [True, False]
    """

    def __init__(self, robot: Any, target: Any, mode: Any, tol: Any) -> None:
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", one_line(robot), "a robotconf Robot")
        tol = check_finite_number(tol, "tol")
        if not 0 < tol < 1:
            raise InvalidInputError("tol", tol, "a number between 0 and 1 (relative to the size)")
        self.robot = robot
        self.point, self.rotation, self.mode = _check_target(target, mode)
        self.target = np.asarray(as_float_array(target, "target", _TARGET)).copy()
        self.tol = tol
        self.size = characteristic_length(robot)
        self.reach_tol = tol * self.size
        types = robot.joint_types
        moving = np.arange(robot.n) < robot.active
        self.revolute = np.array([t == "revolute" for t in types]) & moving
        self.moving = np.array([t in ("revolute", "prismatic") for t in types]) & moving
        self.names = robot.coordinate_names

    @property
    def n(self) -> int:
        """Number of coordinates an answer holds."""
        return self.robot.n

    def check_sizes(self, q: np.ndarray, entries: list[str]) -> None:
        """Refuse angles a float cannot judge modulo a full turn (``|q| > MAX_ANGLE``)."""
        huge = np.abs(q) > MAX_ANGLE
        rows, cols = np.nonzero(np.atleast_2d(huge & self.revolute))
        if rows.size:
            index = int(rows[0]) * self.n + int(cols[0])
            raise InvalidInputError(
                "student",
                entries[index] if index < len(entries) else float(np.ravel(q)[index]),
                f"joint angles within ±{MAX_ANGLE:g} rad",
                problem="too large to check modulo a full turn:",
            )

    def reached(self, q: np.ndarray) -> np.ndarray:
        """End-effector points of configurations ``q`` (..., n) → (..., 3)."""
        try:
            return np.asarray(self.robot.end_effector(q))
        except InvalidInputError as error:  # a slide so long that the chain overflows
            raise InvalidInputError("student", error.value, error.allowed, error.problem) from None

    def misses(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position error (length) and orientation error (rad; 0 in mode "position")."""
        distance = np.linalg.norm(self.reached(q) - self.point, axis=-1)
        if self.rotation is None:
            return distance, np.zeros_like(distance)
        turns = np.asarray(self.robot.end_effector_pose(q))[..., :3, :3]
        return distance, turn_angle(turns, self.rotation)

    def reaches(self, q: np.ndarray) -> np.ndarray:
        """Whether each configuration of ``q`` (..., n) reaches the target."""
        distance, turn = self.misses(q)
        return np.asarray((distance <= self.reach_tol) & (turn <= self.tol))

    def turned_to(self, solution: np.ndarray, q: np.ndarray) -> np.ndarray:
        """``solution`` with each revolute joint turned by whole turns to lie nearest ``q``."""
        turns = np.round((q - solution) / (2 * math.pi))
        return solution + np.where(self.revolute, 2 * math.pi * turns, 0.0)

    def gap(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Per-joint differences, revolute joints modulo a full turn, ignored coordinates 0."""
        difference = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
        turns = difference - 2 * math.pi * np.round(difference / (2 * math.pi))
        difference = np.where(self.revolute, turns, difference)
        return np.abs(np.where(self.moving, difference, 0.0))

    def closest(self, q: np.ndarray, rows: np.ndarray) -> tuple[int, float]:
        """The row of ``rows`` (k, n) nearest to ``q`` and its largest joint difference."""
        spread = self.gap(q[None, :], rows).max(axis=1)
        best = int(np.argmin(spread))
        return best, float(spread[best])

    @cached_property
    def solutions(self) -> IKSolutions | None:
        """Every closed-form solution, or ``None`` for a robot :func:`ik_all` cannot solve."""
        goal = self.target if self.mode == "pose" else self.point
        try:
            return ik_all(self.robot, goal)
        except InvalidInputError:
            return None

    def outside_limits(self, q: np.ndarray) -> list[str]:
        """Which joints of ``q`` lie outside the robot's ranges, in words (a revolute angle
        counts as inside when it or a whole turn away from it is)."""
        words = []
        for i, (lo, hi) in enumerate(self.robot.joint_limits()):
            if not self.moving[i]:
                continue
            value = float(q[i])
            if self.revolute[i]:
                shifted = value - 2 * math.pi * math.floor((value - lo) / (2 * math.pi))
                if shifted <= hi + 1e-12:
                    continue
            elif lo - 1e-12 <= value <= hi + 1e-12:
                continue
            side = (
                f"above its upper limit {number_text(hi)}"
                if value > hi
                else (f"below its lower limit {number_text(lo)}")
            )
            words.append(f"{self.names[i]} = {number_text(value)} is {side}")
        return words

    def point_text(self, point: np.ndarray) -> str:
        """A point as hints quote it: ``(1, 0.5, 0)``."""
        return "(" + ", ".join(number_text(x + 0.0) for x in np.round(point, 12)) + ")"
