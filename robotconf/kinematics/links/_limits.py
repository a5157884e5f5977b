"""Joint ranges (limits): validation and the documented defaults.

A range ``(lo, hi)`` bounds a link's coordinate ``q``: radians for revolute joints, length
units for prismatic ones. robotconf does not clamp ``q`` to it (a student may well drive a
joint past its stop to see what happens); workspace sampling, sliders and URDF export read
the ranges from :meth:`Robot.joint_limits`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_vector3, one_line
from ..conventions._bounds import MAX_PARAMETER, check_parameter

if TYPE_CHECKING:
    from ._link import Link

__all__ = ["check_limits", "check_link_limits", "chain_length", "chain_limits", "default_limits"]

_ALLOWED = f"None, or (lo, hi): two finite numbers with lo < hi, |lo|, |hi| ≤ {MAX_PARAMETER:.0e}"


def check_limits(value: Any, field: str = "limits") -> tuple[float, float] | None:
    """Validate a joint range: ``None`` or two finite numbers ``lo < hi``.

    Parameters
    ----------
    value : None or array-like, shape (2,)
        ``(lo, hi)``: radians for a revolute joint, length units for a prismatic one;
        each at most :data:`~robotconf.kinematics.MAX_PARAMETER` in magnitude.
    field : str
        Name used in error messages.

    Returns
    -------
    tuple of 2 floats, or None

    Raises
    ------
    InvalidInputError
        For text, booleans, complex numbers, a length other than 2, NaN or infinity,
        a magnitude above ``1e150``, or ``lo ≥ hi``.

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
        raise InvalidInputError(
            field, one_line(value), _ALLOWED, problem="expected two numbers (lo, hi):"
        )
    lo = check_parameter(value[0], f"{field}[0]")
    hi = check_parameter(value[1], f"{field}[1]")
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


def chain_length(links: Sequence[Link], end_effector: Any) -> float:
    """The size ``L`` of a chain: its constant lengths plus ``|P|``; ``1.0`` when all are zero.

    ``L`` is the sum of :meth:`Link.constant_length` over the links — ``|a|`` of each
    module, ``√(a² + d²)`` of each DH row (its ``d`` only when revolute, as a prismatic
    ``d`` is the coordinate's zero point) — plus the length of the end-effector point
    ``P``. A chain of bare joints has no length of its own, so it gets 1.

    Parameters
    ----------
    links : sequence of Link
    end_effector : array-like, shape (3,)
        The end-effector point in the last frame (length).

    Returns
    -------
    float
        Length units.

    Examples
    --------
    >>> from robotconf.kinematics import Module
    >>> chain_length([Module("Rz"), Module("Tz", a=(0, 0, 20))], (40, 0, 0))
    60.0
    """
    total = float(np.linalg.norm(check_vector3(end_effector, "end_effector")))
    total += sum(link.constant_length() for link in links)
    return total if total > 0.0 else 1.0


def default_limits(joint_type: str, length: float) -> tuple[float, float]:
    """The documented default range of a coordinate with no range of its own.

    Revolute ``(−π, π)``; prismatic ``(−L, L)`` with the chain's size ``L``
    (:func:`chain_length`); ``none`` and ``fixed`` ``(0, 0)``.

    >>> default_limits("prismatic", 60.0)
    (-60.0, 60.0)
    """
    if joint_type == "revolute":
        return (-float(np.pi), float(np.pi))
    if joint_type == "prismatic":
        return (-length, length)
    return (0.0, 0.0)


def chain_limits(links: Sequence[Link], end_effector: Any) -> np.ndarray:
    """Ranges of all coordinates of a chain, shape (n, 2): own where given, else default.

    >>> from robotconf.kinematics import Module
    >>> chain_limits([Module("Rz", limits=(-1, 1)), Module("Tz")], (2, 0, 0))
    array([[-1.,  1.],
           [-2.,  2.]])
    """
    length = chain_length(links, end_effector)
    rows = [
        link.limits if link.limits is not None else default_limits(link.joint_type, length)
        for link in links
    ]
    return np.array(rows, dtype=float).reshape(len(rows), 2)
