"""Where each joint's axis lies in the base frame: the line a revolute joint turns about
or a prismatic joint slides along.

The 3D scene draws its joint markers on these lines; the Jacobian uses the same screws
(:func:`robotconf.kinematics.joint_screws`), so the picture and the velocities agree.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..._validation import check_joint_values
from ..robot._named_results import JointAxes
from ._jacobian import JointScrew, joint_screws, pose_components

if TYPE_CHECKING:
    from ..robot._robot import Robot

__all__ = ["JointAxes", "joint_axes", "axes_from_screws"]


def joint_axes(robot: Robot, q: Any = None) -> JointAxes:
    """The axis of every joint in the base frame.

    For a module, the joint sits at its frame origin before it moves (the offset ``a`` is
    applied first, paper §2.3); for a standard DH row it is the previous frame's z axis;
    for a modified DH row, its own z axis.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,) or (T, n), optional
        Coordinates (radians for rotations, length for translations); default: the
        modules' own ``q``.

    Returns
    -------
    JointAxes

    Examples
    --------
    The paper's robot: module 2 turns about y through (0, 0, 20).

    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> axes = rc.joint_axes(robot)
    >>> axes.joints
    ('R', 'R', 'R')
    >>> axes.point[1], axes.direction[1]
    (array([ 0.,  0., 20.]), array([0., 1., 0.]))
    """
    values, batched = check_joint_values(
        robot.q if q is None else q, robot.n, robot.coordinate_names
    )
    screws = joint_screws(robot, pose_components(robot, values))
    return axes_from_screws(screws, values.shape[0], robot.n, batched)


def axes_from_screws(screws: list[JointScrew], samples: int, n: int, batched: bool) -> JointAxes:
    """:class:`JointAxes` from :func:`~robotconf.kinematics.joint_screws` of ``samples``
    configurations (``batched=False``: one configuration, without its time axis)."""
    point = np.full((samples, n, 3), np.nan)
    direction = np.full((samples, n, 3), np.nan)
    for i, screw in enumerate(screws):
        if screw.joint is None or screw.axis is None or screw.point is None:
            continue
        point[:, i] = np.broadcast_to(screw.point, (3, samples)).T
        direction[:, i] = np.broadcast_to(screw.axis, (3, samples)).T
    joints = tuple(screw.joint for screw in screws)
    if batched:
        return JointAxes(joints, point, direction)
    return JointAxes(joints, point[0], direction[0])
