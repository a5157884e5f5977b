"""The Robot methods that live outside ``_robot.py``: joint ranges and files.

``Robot`` inherits them from :class:`RobotMethods`, which keeps ``_robot.py`` about
kinematics and editing; each method delegates to its own module.
"""

from __future__ import annotations

from ._files import FileMethods
from ._limits import LimitsMethods

__all__ = ["RobotMethods"]


class RobotMethods(LimitsMethods, FileMethods):
    """``joint_limits``, ``with_limits`` (:mod:`._limits`); ``to_json``, ``from_json``,
    ``save`` (:mod:`._files`)."""

    __slots__ = ()
