"""Joint ranges (limits): validation, the documented defaults, and the Robot methods.

A range ``(lo, hi)`` bounds a link's coordinate ``q``: radians for revolute joints, length
units for prismatic ones. robotconf does not clamp ``q`` to it (a student may well drive a
joint past its stop to see what happens); workspace sampling, sliders and URDF export read
the ranges from :meth:`Robot.joint_limits`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, cast

import numpy as np

from ._errors import InvalidInputError
from ._validation import check_finite_number

if TYPE_CHECKING:
    from ._link import Link
    from ._robot import Robot

__all__ = ["check_limits", "characteristic_length", "robot_joint_limits", "LimitsMethods"]

_ALLOWED = "None, or (lo, hi): two finite numbers with lo < hi"


def check_limits(value: Any, field: str = "limits") -> tuple[float, float] | None:
    """Validate a joint range: ``None`` or two finite numbers ``lo < hi``.

    Parameters
    ----------
    value : None or array-like, shape (2,)
        ``(lo, hi)``: radians for a revolute joint, length units for a prismatic one.
    field : str
        Name used in error messages.

    Returns
    -------
    tuple of 2 floats, or None

    Raises
    ------
    InvalidInputError
        For text, booleans, a length other than 2, NaN or infinity, or ``lo ≥ hi``.

    Examples
    --------
    >>> check_limits([-1, 2])
    (-1.0, 2.0)
    >>> check_limits((1, 1))
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: limits: lower limit must be below upper limit, got (1.0, 1.0); ...
    """
    if value is None:
        return None
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise InvalidInputError(field, value, _ALLOWED, problem="expected two numbers (lo, hi):")
    lo = check_finite_number(value[0], f"{field}[0]")
    hi = check_finite_number(value[1], f"{field}[1]")
    if not lo < hi:
        raise InvalidInputError(
            field, (lo, hi), _ALLOWED, problem="lower limit must be below upper limit, got"
        )
    return (lo, hi)


def check_link_limits(value: Any, joint_type: str) -> tuple[float, float] | None:
    """:func:`check_limits`, refusing a range on a link without joint (none, fixed)."""
    limits = check_limits(value)
    if limits is not None and joint_type not in ("revolute", "prismatic"):
        raise InvalidInputError(
            "limits",
            limits,
            f"None for a '{joint_type}' module (it has no joint)",
            problem=f"a '{joint_type}' module has no joint to limit, got",
        )
    return limits


def characteristic_length(robot: Robot) -> float:
    """The robot's size L: the default stroke of a prismatic joint is ``(−L, L)``.

    ``L`` is the sum of the constant lengths along the chain — ``|a|`` of each module,
    ``√(a² + d²)`` of each DH row (its ``d`` only when revolute, as a prismatic ``d`` is
    the coordinate's zero point) — plus ``|P|`` of the end-effector point; ``1.0`` when all
    of these are zero (a chain of bare joints).

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz"), rc.Module("Tz", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> characteristic_length(robot)
    60.0
    """
    total = float(np.linalg.norm(robot.end_effector_point))
    for link in robot.modules:
        total += _link_length(link)
    return total if total > 0.0 else 1.0


def _link_length(link: Link) -> float:
    from ._dh import DHLink  # local: _dh imports this module

    if isinstance(link, DHLink):
        return float(np.hypot(link.a, link.d if link.joint == "R" else 0.0))
    offsets = getattr(link, "a", (0.0, 0.0, 0.0))
    return 0.0 if getattr(link, "kind", "") == "none" else float(np.linalg.norm(offsets))


def robot_joint_limits(robot: Robot) -> np.ndarray:
    """Ranges of all coordinates, explicit where given, else the defaults (see docs)."""
    length = None
    rows = []
    for link in robot.modules:
        limits = getattr(link, "limits", None)
        if limits is None:
            if link.joint_type == "revolute":
                limits = (-np.pi, np.pi)
            elif link.joint_type == "prismatic":
                length = characteristic_length(robot) if length is None else length
                limits = (-length, length)
            else:
                limits = (0.0, 0.0)
        rows.append(limits)
    return np.array(rows, dtype=float).reshape(robot.n, 2)


def _link_index(robot: Robot, index_or_name: Any) -> int:
    names = robot.module_names
    if isinstance(index_or_name, str):
        if index_or_name in names:
            return names.index(index_or_name)
        allowed = f"a module name ({', '.join(names)}) or an index 0…{robot.n - 1}"
        raise InvalidInputError("index", index_or_name, allowed, problem="unknown module")
    allowed = f"an integer from 0 to {robot.n - 1}, or a module name"
    if isinstance(index_or_name, (bool, np.bool_)) or not isinstance(
        index_or_name, (int, np.integer)
    ):
        raise InvalidInputError("index", index_or_name, allowed, problem="not an index or name:")
    if not 0 <= int(index_or_name) < robot.n:
        raise InvalidInputError("index", int(index_or_name), allowed, problem="out of range:")
    return int(index_or_name)


class LimitsMethods:
    """The joint-range methods of :class:`~robotconf.Robot` (kept here to keep it short)."""

    __slots__ = ()

    def joint_limits(self) -> np.ndarray:
        """The range ``(lo, hi)`` of every coordinate, shape (n, 2).

        A link's own ``limits`` where given; otherwise the documented defaults
        (docs/conventions.md, "Joint ranges"): revolute ``(−π, π)``; prismatic ``(−L, L)``
        with ``L`` = :func:`characteristic_length`; ``none`` and ``fixed`` ``(0, 0)``.

        Returns
        -------
        ndarray, shape (n, 2)
            Radians for revolute rows, length units for prismatic rows.

        Examples
        --------
        >>> import robotconf as rc
        >>> modules = [rc.Module("Rz", limits=(-1, 1)), rc.Module("Tz", a=(0, 0, 20))]
        >>> robot = rc.Robot([*modules, rc.Module("fixed")], end_effector=(40, 0, 0))
        >>> robot.joint_limits()
        array([[ -1.,   1.],
               [-60.,  60.],
               [  0.,   0.]])
        """
        return robot_joint_limits(cast("Robot", self))

    def with_limits(self, index_or_name: Any, limits: Any) -> Robot:
        """A copy where one link has the range ``limits`` (``None``: back to the default).

        Parameters
        ----------
        index_or_name : int or str
            0-based index or display name (``"M2"``) of the link.
        limits : None or (lo, hi)
            Radians for revolute, length units for prismatic joints; ``lo < hi``.

        Examples
        --------
        >>> import robotconf as rc
        >>> robot = rc.Robot([rc.Module("Rz"), rc.Module("Ry")]).with_limits("M2", (0, 1.5))
        >>> robot.joint_limits()[1]
        array([0. , 1.5])
        """
        robot = cast("Robot", self)
        i = _link_index(robot, index_or_name)
        link = robot.modules[i]
        try:
            changed = link.with_limits(limits)  # type: ignore[attr-defined]
        except InvalidInputError as error:
            raise error.within(f"modules[{i}]") from None
        return robot.with_module(i, changed)
