"""The geometric Jacobian of a module frame or of the end-effector, and the joint screws.

For joint ``j`` with unit axis ``z_j`` through the point ``o_j`` (both in the base frame),
the Jacobian column for a point ``p`` is

.. math::

    J_j = \\begin{bmatrix} z_j \\times (p - o_j) \\\\ z_j \\end{bmatrix} \\text{ (revolute)},
    \\qquad
    J_j = \\begin{bmatrix} z_j \\\\ 0 \\end{bmatrix} \\text{ (prismatic)},

so that ``[v; ω] = J · q̇``. Linear rows come first, then angular rows. Joints after the
frame, inactive modules and ``none``/``fixed`` modules give zero columns.

The arrays here are component-major, ``(…, 3, T)``, so each x/y/z row is contiguous
over the ``T`` samples.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from ..._budget import check_finite_result, check_memory
from ..._validation import check_joint_values, one_line
from ..conventions._conventions import JOINT_OF_LETTER
from ..kernel._kernel import kernel_bytes

if TYPE_CHECKING:
    from ..robot._robot import Robot

__all__ = [
    "jacobian",
    "JointScrew",
    "joint_screws",
    "pose_components",
    "point_names",
    "ee_position",
    "cross_components",
    "rotate_components",
]


_SMALLER = "fewer samples per call (split q into chunks), or a larger memory budget"


class JointScrew(NamedTuple):
    """The motion axis of one link, in the base frame, over ``T`` samples.

    ``joint`` is the kernel's joint letter (:data:`~robotconf.kinematics.JOINT_LETTERS`:
    ``"R"``, ``"P"``) or ``None`` (inactive, ``none`` or ``fixed`` module: then ``axis`` and
    ``point`` are ``None``). ``axis`` has shape (3, T) or (3, 1) (unit
    vector) and ``point`` (3, T) or (3, 1) (length): a point on the joint axis.
    """

    joint: str | None
    axis: np.ndarray | None
    point: np.ndarray | None


def pose_components(robot: Robot, q: np.ndarray) -> np.ndarray:
    """Frame poses ``[R | p]`` in component-major layout.

    Parameters
    ----------
    robot : Robot
    q : ndarray, shape (T, n)
        Validated coordinates.

    Returns
    -------
    ndarray, shape (n, 3, 4, T)
        ``out[i, :, :3]`` is frame i's rotation, ``out[i, :, 3]`` its origin.

    Raises
    ------
    InvalidInputError
        ``q`` when the poses and their copy would not fit the memory budget, or when a
        frame position overflows.
    """
    check_memory("q", one_line(q), kernel_bytes(q.shape[0], robot.n, 28 * robot.n), _SMALLER)
    poses = robot.frame_poses(q)
    return np.ascontiguousarray(poses[:, :, :3, :].transpose(1, 2, 3, 0))


def rotate_components(rotation: np.ndarray | None, vector: np.ndarray) -> np.ndarray:
    """``R · v`` for R of shape (3, 3, T) (or identity) and a constant 3-vector → (3, T)."""
    if rotation is None:
        return vector[:, np.newaxis].copy()
    out = rotation[:, 0] * vector[0]
    for c in (1, 2):
        if vector[c] != 0.0:
            out += rotation[:, c] * vector[c]
    return out


def joint_screws(robot: Robot, poses: np.ndarray) -> list[JointScrew]:
    """Axis and a point on the axis of every joint, in the base frame.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (n, 3, 4, T)
        From :func:`pose_components`.

    Returns
    -------
    list of JointScrew, length n
    """
    screws = []
    for i, g in enumerate(robot.geometry()):
        if g is None or g.axis is None or g.joint is None or g.is_identity:
            screws.append(JointScrew(None, None, None))
            continue
        rotation = poses[i - 1, :, :3] if i else None
        origin = poses[i - 1, :, 3] if i else np.zeros((3, 1))
        unit = np.zeros(3)
        unit[g.axis] = 1.0
        direction = unit if g.pre_rotation is None else g.pre_rotation[:, g.axis]
        axis = rotate_components(rotation, direction)
        point = origin
        if g.pre_translation is not None:
            point = origin + rotate_components(rotation, g.pre_translation)
        screws.append(JointScrew(g.joint, axis, point))
    return screws


def point_names(robot: Robot) -> tuple[str, ...]:
    """The names of the points a motion reports: module names, then ``"EE"``."""
    return (*robot.module_names, "EE")


def cross_components(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product of component-major arrays of shape (3, …)."""
    shape = np.broadcast_shapes(a.shape, b.shape)
    out = np.empty(shape)
    np.subtract(a[1] * b[2], a[2] * b[1], out=out[0])
    np.subtract(a[2] * b[0], a[0] * b[2], out=out[1])
    np.subtract(a[0] * b[1], a[1] * b[0], out=out[2])
    return out


def ee_position(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """End-effector position ``p_n + R_n · P`` from component-major poses → (3, T)."""
    last = poses[-1]
    return last[:, 3] + rotate_components(last[:, :3], robot.end_effector_point)


def jacobian(robot: Robot, q: Any = None, frame: Any = None) -> np.ndarray:
    """Geometric Jacobian of a module frame's origin or of the end-effector.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,) or (T, n), optional
        Coordinates (radians for rotations, length for translations); default: the
        modules' own ``q``.
    frame : int, str or None
        ``None`` or ``"EE"``: the end-effector point; a module as :meth:`Robot.index` reads
        it (``0 … n−1``, ``"M2"``, the module's own name or ``"q2"``): the origin of that
        module's frame.

    Returns
    -------
    ndarray, shape (6, n) or (T, 6, n)
        Rows 0–2 map ``q̇`` to the point's linear velocity (length/s), rows 3–5 to the
        frame's angular velocity (rad/s), both in the base frame.

    Raises
    ------
    InvalidInputError
        For bad coordinates or an unknown frame; ``q`` when the result would not fit the
        memory budget, or when frame positions or their differences overflow (only
        prismatic coordinates near ``1e308`` can do that).

    Examples
    --------
    The paper robot at the parking position: turning q1 moves the EE along y with lever
    arm 70, turning q2 or q3 moves it down along z with lever arms 70 and 40.

    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> jacobian(robot, [0, 0, 0]) + 0.0
    array([[  0.,   0.,   0.],
           [ 70.,   0.,   0.],
           [  0., -70., -40.],
           [  0.,   0.,   0.],
           [  0.,   1.,   1.],
           [  1.,   0.,   0.]])
    >>> jacobian(robot, [0, 0, 0], frame="M3")[:3, 2] + 0.0
    array([0., 0., 0.])
    """
    values, batched = (
        (robot.q[np.newaxis, :], False)
        if q is None
        else check_joint_values(q, robot.n, robot.coordinate_names)
    )
    index = robot.n if frame is None else robot.index(frame, "frame", end_effector=True)
    # Poses, their copy, the (6, n, T) result and its transpose, per-joint temporaries.
    nbytes = kernel_bytes(values.shape[0], robot.n, 40 * robot.n + 30)
    check_memory("q", one_line(q), nbytes, _SMALLER)
    poses = pose_components(robot, values)
    out = np.zeros((6, robot.n, values.shape[0]))
    # Frame positions are finite (the kernel checks), but p - o_j of two near 1e308 is not:
    # that becomes the error below rather than numpy's warnings.
    with np.errstate(over="ignore", invalid="ignore"):
        point = ee_position(robot, poses) if index == robot.n else poses[index, :, 3]
        for j, screw in enumerate(joint_screws(robot, poses)[: index + 1]):
            if screw.joint is None:
                continue
            if JOINT_OF_LETTER[screw.joint] == "revolute":
                lever = point - screw.point  # type: ignore[operator]
                out[:3, j] = cross_components(screw.axis, lever)  # type: ignore[arg-type]
                out[3:, j] = screw.axis
            else:
                out[:3, j] = screw.axis
    result = np.ascontiguousarray(out.transpose(2, 0, 1))
    check_finite_result(result, "q", one_line(q), "the Jacobian entries")
    return result if batched else result[0]
