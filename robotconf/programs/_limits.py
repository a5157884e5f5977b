"""The speed and acceleration limits of a program, with their defaults.

Defaults (``L`` = ``rc.characteristic_length(robot)``, the robot's size):

========================  ==================================================
``joint_speed``           1 rad/s for revolute joints, ``0.25·L`` per s for prismatic
``joint_accel``           2 rad/s² for revolute joints, ``0.5·L`` per s² for prismatic
``cartesian_speed``       ``0.25·L`` per s (the end-effector point along a LIN/CIRC)
``cartesian_accel``       ``0.25·L`` per s² (a second to reach the default speed)
``angular_speed``         1 rad/s (the tool's turn along a LIN/CIRC)
``angular_accel``         2 rad/s²
========================  ==================================================

They are gentle teaching values, not a real controller's: set them for a real arm.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..kinematics import characteristic_length
from ._inputs import positive, rates

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = ["Limits", "LIMIT_NAMES", "resolve_limits"]

#: The program's keyword arguments that set limits, in order.
LIMIT_NAMES = (
    "joint_speed",
    "joint_accel",
    "cartesian_speed",
    "cartesian_accel",
    "angular_speed",
    "angular_accel",
)

_WHAT = {
    "joint_speed": "a joint speed (rad/s or length/s)",
    "joint_accel": "a joint acceleration (rad/s² or length/s²)",
    "cartesian_speed": "a path speed (length/s)",
    "cartesian_accel": "a path acceleration (length/s²)",
    "angular_speed": "a turning speed (rad/s)",
    "angular_accel": "a turning acceleration (rad/s²)",
}


@dataclass(frozen=True, eq=False)
class Limits:
    """The limits in force (defaults filled in).

    Attributes
    ----------
    joint_speed, joint_accel : ndarray, shape (n,)
        Per joint (rad/s, rad/s² or length/s, length/s²).
    cartesian_speed, cartesian_accel : float
        Path speed and acceleration of LIN/CIRC moves without their own.
    angular_speed, angular_accel : float
        Turning speed and acceleration of the tool along LIN/CIRC moves.

    Examples
    --------
    >>> import robotconf as rc
    >>> resolve_limits(rc.preset("scara"), {}).joint_speed.round(3)  # q3 slides: 0.25·L/s
    array([ 1.   ,  1.   , 24.142,  1.   ])
    """

    joint_speed: np.ndarray
    joint_accel: np.ndarray
    cartesian_speed: float
    cartesian_accel: float
    angular_speed: float
    angular_accel: float


def check_given(robot: Robot, given: dict[str, Any]) -> dict[str, Any]:
    """The limits given (``None`` for a default) as plain floats or tuples, checked.

    >>> import robotconf as rc
    >>> check_given(rc.preset("paper"), {"joint_speed": 2, "cartesian_speed": None})
    {'joint_speed': 2.0, 'cartesian_speed': None}
    """
    out: dict[str, Any] = {}
    for name, value in given.items():
        if value is None:
            out[name] = None
        elif name.startswith("joint"):
            out[name] = rates(value, robot.n, name, _WHAT[name])
        else:
            out[name] = positive(value, name, _WHAT[name])
    return out


def resolve_limits(robot: Robot, given: dict[str, Any]) -> Limits:
    """The limits with defaults for those not given (see the module notes).

    >>> import robotconf as rc
    >>> limits = resolve_limits(rc.preset("paper"), {})
    >>> limits.joint_speed, limits.cartesian_speed
    (array([1., 1., 1.]), 22.5)
    """
    length = characteristic_length(robot)
    prismatic = np.array([t == "prismatic" for t in robot.joint_types])

    def joint(name: str, revolute: float, per_length: float) -> np.ndarray:
        value = given.get(name)
        if value is None:
            return np.where(prismatic, per_length * length, revolute)
        return np.broadcast_to(np.asarray(value, dtype=float), (robot.n,)).copy()

    def scalar(name: str, default: float) -> float:
        value = given.get(name)
        return default if value is None else float(value)

    return Limits(
        joint_speed=joint("joint_speed", 1.0, 0.25),
        joint_accel=joint("joint_accel", 2.0, 0.5),
        cartesian_speed=scalar("cartesian_speed", 0.25 * length),
        cartesian_accel=scalar("cartesian_accel", 0.25 * length),
        angular_speed=scalar("angular_speed", 1.0),
        angular_accel=scalar("angular_accel", 2.0),
    )
