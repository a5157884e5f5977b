"""A robot as its joint axes at q = 0: the one description every closed form reads.

Whether a robot is given by DH rows or by the paper's modules, each joint turns about (or
slides along) a line in space. At the reference configuration (every joint at 0, held
modules at their own ``q``) joint ``i`` has the unit direction ``w_i`` through the point
``p_i`` (:func:`robotconf.kinematics.joint_axes`), and the end-effector has the pose
``M₀``. Then for every ``q`` (the product-of-exponentials form of the kinematics)

.. math::

    T(q) = e^{[\\xi_1] q_1} \\cdots e^{[\\xi_m] q_m} M_0,

where ``e^{[ξ] q}`` turns by ``q`` about the line ``(p, w)`` (revolute) or shifts by
``q·w`` (prismatic). Joint offsets (DH θ and d), axis directions and frame placements all
live in ``(p_i, w_i)`` and ``M₀``, so one solver serves DH tables of either convention
and module chains alike, and its angles are the robot's own coordinates.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...kinematics import Robot, characteristic_length, joint_axes
from ._subproblems import cross, perp, rotate, rotation

_MOVING = ("revolute", "prismatic")

__all__ = [
    "AxisJoint",
    "ChainAxes",
    "chain_axes",
    "reference_configuration",
    "axes_at",
    "line_gap",
    "common_point",
    "misalignment",
]


@dataclass(frozen=True, eq=False)
class AxisJoint:
    """One joint as a line in space at the reference configuration.

    Attributes
    ----------
    column : int
        Its coordinate's position in the robot's ``q``.
    kind : {"R", "P"}
        Revolute (turns about the line) or prismatic (slides along it).
    point : ndarray, shape (3,)
        A point on the line (length units).
    direction : ndarray, shape (3,)
        Unit vector: a positive ``q`` turns right-handedly about it, or slides along it.
    """

    column: int
    kind: str
    point: np.ndarray
    direction: np.ndarray

    def move(self, value: float, x: np.ndarray) -> np.ndarray:
        """Where the joint at ``value`` takes the point ``x``, shape (3,)."""
        if self.kind == "P":
            return x + value * self.direction
        return self.point + rotate(self.direction, value, x - self.point)

    def turn(self, value: float) -> np.ndarray:
        """The rotation part of the joint's motion, shape (3, 3)."""
        return np.eye(3) if self.kind == "P" else rotation(self.direction, value)


@dataclass(frozen=True, eq=False)
class ChainAxes:
    """The joints of a robot at its reference configuration, and the home pose.

    Attributes
    ----------
    robot : Robot
    joints : tuple of AxisJoint
        The moving joints, base first (held modules, ``none`` and ``fixed`` left out).
    home : ndarray, shape (4, 4)
        End-effector pose ``M₀`` at the reference configuration.
    reference : ndarray, shape (n,)
        The full coordinate vector at the reference: joints 0, others their own ``q``.
    scale : float
        The robot's size (:func:`robotconf.kinematics.characteristic_length`).
    """

    robot: Robot
    joints: tuple[AxisJoint, ...]
    home: np.ndarray
    reference: np.ndarray
    scale: float

    @property
    def letters(self) -> str:
        """The joint types in order, e.g. ``"RRPR"``."""
        return "".join(joint.kind for joint in self.joints)

    def current(self, k: int) -> float:
        """The robot's own coordinate of joint ``k``: the value a free joint keeps."""
        return float(self.robot.q[self.joints[k].column])

    def move(self, values: Iterable[float], x: np.ndarray, first: int = 0) -> np.ndarray:
        """Joints ``first, first + 1, …`` at ``values`` applied to the point ``x``."""
        values = list(values)
        for k in reversed(range(len(values))):
            x = self.joints[first + k].move(values[k], x)
        return x

    def turn(self, values: Iterable[float], first: int = 0) -> np.ndarray:
        """The rotation of joints ``first, first + 1, …`` at ``values``, shape (3, 3)."""
        out = np.eye(3)
        for k, value in enumerate(values):
            out = out @ self.joints[first + k].turn(value)
        return out


def chain_axes(robot: Robot, constant: Any = ()) -> ChainAxes:
    """The joint lines of ``robot`` at q = 0 (held modules at their own ``q``).

    Parameters
    ----------
    robot : Robot
    constant : int, str or iterable of them
        More modules held at their own ``q`` (as :meth:`Robot.index` reads them); modules
        whose name ends in ``"(constant)"`` (the held twists of
        :func:`robotconf.kinematics.dh_to_modules`) are always held.

    Returns
    -------
    ChainAxes

    Examples
    --------
    >>> import robotconf as rc
    >>> axes = chain_axes(rc.preset("planar_2r"))
    >>> axes.letters, axes.joints[1].point, axes.home[:3, 3]
    ('RR', array([40.,  0.,  0.]), array([70.,  0.,  0.]))
    """
    moving, reference = reference_configuration(robot, constant)
    return axes_at(robot, moving, reference)


def reference_configuration(robot: Robot, constant: Any = ()) -> tuple[list[int], np.ndarray]:
    """The moving joints' columns and the reference ``q`` (moving joints at 0, held ones
    at their own values), as :func:`chain_axes` reads them."""
    if not isinstance(robot, Robot):
        raise InvalidInputError(
            "robot", type(robot).__name__, "a robotconf Robot", problem="not a robot:"
        )
    items = (
        constant if isinstance(constant, Iterable) and not isinstance(constant, str) else [constant]
    )
    held = {robot.index(item, "constant") for item in items}
    # The held twists of dh_to_modules, as the numeric solver reads them.
    held |= {i for i, name in enumerate(robot.module_names) if name.endswith("(constant)")}
    reference = robot.q.astype(float)
    kinds = robot.joint_types[: robot.active]
    moving = [i for i, kind in enumerate(kinds) if kind in _MOVING and i not in held]
    reference[moving] = 0.0
    return moving, reference


def axes_at(robot: Robot, moving: list[int], reference: np.ndarray) -> ChainAxes:
    """:func:`chain_axes` once the moving joints and the reference are known."""
    lines = joint_axes(robot, reference)
    joints = tuple(
        AxisJoint(i, str(lines.joints[i]), lines.point[i].copy(), lines.direction[i].copy())
        for i in moving
    )
    home = robot.end_effector_pose(reference)
    return ChainAxes(robot, joints, home, reference, characteristic_length(robot))


def misalignment(u: np.ndarray, v: np.ndarray) -> float:
    """The angle between two lines with unit directions ``u`` and ``v``, 0 … π/2 (rad).

    >>> round(misalignment(np.array([0.0, 0, 1]), np.array([0.0, 0, -1])), 12)
    0.0
    """
    return float(np.arctan2(np.linalg.norm(cross(u, v)), abs(float(u @ v))))


def line_gap(a: AxisJoint, b: AxisJoint) -> float:
    """The closest approach of two joint lines (length units; 0 when they meet).

    >>> z = np.array([0.0, 0.0, 1.0])
    >>> line_gap(AxisJoint(0, "R", np.zeros(3), z), AxisJoint(1, "R", np.array([3.0, 4, 0]), z))
    5.0
    """
    normal = cross(a.direction, b.direction)
    size = float(np.linalg.norm(normal))
    offset = b.point - a.point
    if size < 1e-12:
        return float(np.linalg.norm(perp(a.direction, offset)))
    return abs(float(offset @ normal)) / size


def common_point(lines: Iterable[AxisJoint]) -> tuple[np.ndarray, float]:
    """The point nearest to all the lines (least squares) and its largest distance to one.

    >>> ex, ey = np.eye(3)[:2]
    >>> point, miss = common_point([AxisJoint(0, "R", np.zeros(3), ex),
    ...                             AxisJoint(1, "R", np.array([2.0, 0, 0]), ey)])
    >>> point.round(12) + 0.0, round(miss, 12)
    (array([2., 0., 0.]), 0.0)
    """
    lines = list(lines)
    matrix = np.zeros((3, 3))
    rhs = np.zeros(3)
    for line in lines:
        projector = np.eye(3) - np.outer(line.direction, line.direction)
        matrix += projector
        rhs += projector @ line.point
    point = np.linalg.lstsq(matrix, rhs, rcond=None)[0]
    miss = max(float(np.linalg.norm(perp(line.direction, point - line.point))) for line in lines)
    return point, miss
