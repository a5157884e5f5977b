"""The robot: an ordered chain of links plus an end-effector point, and its snapshots.

:class:`Robot` is immutable (every ``with_…`` returns a new robot); its kinematics
(frames, origins, end effector) run through the kernel, vectorized over samples.
``robot.at(q)`` is a :class:`RobotSnapshot`: one kernel pass, every frame, the joint axes
and the labelled points a picture needs.

The robot
    :class:`Robot`, :func:`characteristic_length`
One configuration, computed once
    :class:`RobotSnapshot`; its named results :class:`RobotPoint`, :class:`JointAxes`,
    :func:`format_point`, :data:`END_EFFECTOR_LABEL`

>>> from robotconf.kinematics import Module
>>> Robot([Module("Rz"), Module("Tx", a=(0, 0, 1))]).at([0.0, 2.0]).end_effector
array([2., 0., 1.])
"""

from ._named_results import END_EFFECTOR_LABEL, JointAxes, RobotPoint, format_point
from ._robot import Robot, characteristic_length
from ._snapshot import RobotSnapshot

__all__ = [
    "Robot",
    "characteristic_length",
    "RobotSnapshot",
    "RobotPoint",
    "JointAxes",
    "format_point",
    "END_EFFECTOR_LABEL",
]
