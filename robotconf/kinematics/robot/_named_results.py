"""Small named results of the kinematics: labelled points and joint axes.

They live apart from the functions that make them so that :class:`RobotSnapshot`
(which the robot itself builds) can carry them without importing the robot.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_integer, check_vector3, one_line

__all__ = ["RobotPoint", "JointAxes", "format_point", "END_EFFECTOR_LABEL"]

#: Name of the end-effector point (as in :class:`~robotconf.Motion`'s points).
END_EFFECTOR_LABEL = "EE"


class RobotPoint(NamedTuple):
    """A named point: unpacks as ``name, position``.

    Attributes
    ----------
    name : str
        A module name (``"M1"`` or the module's own) or ``"EE"``.
    position : ndarray, shape (3,)
        Base-frame position (length units).
    """

    name: str
    position: np.ndarray

    def __str__(self) -> str:
        return format_point(self.name, self.position)


class JointAxes(NamedTuple):
    """Joint axes of a robot at one configuration or along a trajectory.

    Attributes
    ----------
    joints : tuple of str or None, length n
        The kernel's joint letters (:data:`~robotconf.kinematics.JOINT_LETTERS`): ``"R"``
        (revolute), ``"P"`` (prismatic); ``None`` for no joint (a ``none`` or ``fixed``
        module, or a module after the active count). :data:`JOINT_OF_LETTER` turns a letter
        back into a joint type.
    point : ndarray, shape (n, 3) or (T, n, 3)
        A point on each axis (length units): where the joint sits before it moves. NaN
        for links without a joint.
    direction : ndarray, shape (n, 3) or (T, n, 3)
        Unit vector along each axis. NaN for links without a joint.
    """

    joints: tuple[str | None, ...]
    point: np.ndarray
    direction: np.ndarray


def format_point(name: str, xyz: Any, digits: int = 1) -> str:
    """A point's label as the paper prints it: ``"EE (70.0, 0.0, 20.0)"``.

    Parameters
    ----------
    name : str
    xyz : array-like, shape (3,)
        Position (length units).
    digits : int
        Decimals, 0 to 15. Values that round to zero print as ``0.0``, never ``-0.0``.

    Returns
    -------
    str

    Examples
    --------
    >>> format_point("EE", [70, -1e-17, 20])
    'EE (70.0, 0.0, 20.0)'
    >>> format_point("M3", [29.99996, 0, 20], digits=3)
    'M3 (30.000, 0.000, 20.000)'
    """
    if not isinstance(name, str):
        raise InvalidInputError("name", one_line(name), "text", problem="not text:")
    digits = check_integer(digits, "digits", 0, 15)
    values = check_vector3(xyz, "xyz")
    # round() first, then + 0.0: a tiny negative would otherwise print as "-0.0".
    shown = ", ".join(f"{round(v, digits) + 0.0:.{digits}f}" for v in values)
    return f"{name} ({shown})"
