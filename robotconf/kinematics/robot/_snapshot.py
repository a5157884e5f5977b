"""The robot at one configuration, computed once: every frame, the end effector, the joint
axes and the labelled points, from a single pass of the kernel.

A picture of the robot needs all of these together (the 3D scene draws frames, joint
markers and labels; the panel's header prints ``p_EE``; the Matrices tab prints ``M_i``).
Asking the robot for each separately composes the chain once per question. A
:class:`RobotSnapshot` composes it once: the frame poses and the end-effector pose come
out of the same kernel pass, and the origins, the joint axes and the labelled points are
read off those poses. The numbers are the very numbers the robot's own methods give
(the same kernel, the same operations): ``robot.at(q).end_effector`` equals
``robot.end_effector(q)`` bit for bit.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..kernel._block import _translate as translate_state
from ..kernel._geometry import LinkGeometry
from ..kernel._kernel import _LAST_ROW as LAST_ROW
from ..kernel._kernel import _run as run_chain
from ._named_results import END_EFFECTOR_LABEL, JointAxes, RobotPoint

__all__ = ["RobotSnapshot", "chain_snapshot"]


def chain_snapshot(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    point: np.ndarray,
    fields: Sequence[str] | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Every frame pose and the pose at ``point`` in the last frame, in one kernel pass.

    Parameters
    ----------
    links : sequence of LinkGeometry or None, length n
        ``None`` acts as identity (inactive or null module).
    q : ndarray, shape (1, n)
        One validated configuration.
    point : ndarray, shape (3,)
        A point fixed in the last frame (the end effector).
    fields : sequence of str, optional
        The name of each coordinate in errors (default ``q[i]``).

    Returns
    -------
    poses : ndarray, shape (n, 4, 4)
        ``M_i = A_1 ⋯ A_i``, as :func:`~robotconf.kinematics.chain_poses` gives them.
    tip : ndarray, shape (4, 4)
        ``M_n · Trans(point)``, as :func:`~robotconf.kinematics.chain_point_pose` gives it.

    Examples
    --------
    >>> from robotconf.kinematics import Module
    >>> links = [Module("Rz").geometry(), Module("Ry", a=(0, 0, 20)).geometry()]
    >>> poses, tip = chain_snapshot(links, np.zeros((1, 2)), np.array([40.0, 0, 0]))
    >>> poses.shape, tip[:3, 3]
    ((2, 4, 4), array([40.,  0., 20.]))
    """
    n = q.shape[1]
    poses = np.empty((n, 4, 4))
    tip = np.empty((4, 4))
    # (3, 4, 1) views of each pose's top rows: the kernel's state layout for one sample.
    rows = poses[:, :3, :, np.newaxis]

    def emit(i: int, start: int, stop: int, state: np.ndarray) -> None:
        if i >= 0:
            np.copyto(rows[i], state)
            return
        poses[:, 3] = LAST_ROW
        translate_state(state, np.empty_like(state[:, 3]), point)
        np.copyto(tip[:3, :, np.newaxis], state)
        tip[3] = LAST_ROW

    run_chain(links, q, emit, fields=fields)
    return poses, tip


class RobotSnapshot:
    """A robot at one configuration: frames, end effector, joint axes, labelled points.

    Made by :meth:`Robot.at <robotconf.Robot.at>`; immutable (its arrays are read-only).

    Attributes
    ----------
    robot : Robot
        The robot, with its own ``q`` as given.
    q : ndarray, shape (n,)
        The configuration (radians for rotations, length for translations).
    frame_poses : ndarray, shape (n, 4, 4)
        ``M_i = A_1 ⋯ A_i``, each module frame in the base frame.
    frame_origins : ndarray, shape (n, 3)
        The frames' origins (length units).
    end_effector : ndarray, shape (3,)
        ``p_EE = M_n · [P, 1]`` (length units).
    end_effector_pose : ndarray, shape (4, 4)
        ``M_n`` moved to the end-effector point.
    joint_axes : JointAxes
        A point on and the direction of every joint's axis (``NaN`` where no joint).
    points : tuple of RobotPoint, length n + 1
        ``M1 … Mn`` at the frame origins, then ``EE``: what the scene labels.

    Examples
    --------
    The paper's robot, at q = (0, −90°, 0): the arm points straight up.

    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> at = robot.at([0, -np.pi / 2, 0])
    >>> at.end_effector.round(12) + 0.0
    array([ 0.,  0., 90.])
    >>> [str(point) for point in at.points][-2:]
    ['M3 (0.0, 0.0, 50.0)', 'EE (0.0, 0.0, 90.0)']
    >>> bool((at.end_effector == robot.end_effector([0, -np.pi / 2, 0])).all())
    True
    """

    __slots__ = ("robot", "q", "frame_poses", "end_effector_pose", "_axes", "_points")

    def __init__(self, robot: Any, q: np.ndarray, poses: np.ndarray, tip: np.ndarray):
        for array in (q, poses, tip):
            array.flags.writeable = False
        self.robot = robot
        self.q = q
        self.frame_poses = poses
        self.end_effector_pose = tip
        self._axes: JointAxes | None = None
        self._points: tuple[RobotPoint, ...] | None = None

    @property
    def frame_origins(self) -> np.ndarray:
        """Origins of the module frames, shape (n, 3) (length units)."""
        return self.frame_poses[:, :3, 3]

    @property
    def end_effector(self) -> np.ndarray:
        """The end-effector position ``p_EE``, shape (3,) (length units)."""
        return self.end_effector_pose[:3, 3]

    @property
    def joint_axes(self) -> JointAxes:
        """Every joint's axis, read off the frame poses (no kernel pass)."""
        if self._axes is None:
            from ..quantities._jacobian import joint_screws
            from ..quantities._joint_axes import axes_from_screws

            components = self.frame_poses[:, :3, :, np.newaxis]  # (n, 3, 4, T=1)
            screws = joint_screws(self.robot, components)
            self._axes = axes_from_screws(screws, 1, self.robot.n, batched=False)
        return self._axes

    @property
    def points(self) -> tuple[RobotPoint, ...]:
        """``M1 … Mn`` and ``EE`` with their positions, as the scene labels them."""
        if self._points is None:
            origins = self.frame_origins
            named = [RobotPoint(name, origins[i]) for i, name in enumerate(self.robot.module_names)]
            named.append(RobotPoint(END_EFFECTOR_LABEL, self.end_effector))
            self._points = tuple(named)
        return self._points

    def __repr__(self) -> str:
        q = np.round(self.q, 6).tolist()
        return f"<RobotSnapshot of {self.robot.n} modules at q={q}>"
