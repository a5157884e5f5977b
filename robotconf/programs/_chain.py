"""What a program needs of its robot: which joints move, which rows count, and the
least-squares solves of ``J q̇ = ẋ`` and ``J q̈ = ẍ − J̇ q̇``.

Rows and columns are scaled as ``rc.ik`` scales them (position rows divided by the
robot's size ``L = rc.characteristic_length``, prismatic columns multiplied by it), so the
singular values compare across robots and units: ``σ = 1`` is a unit turn moving the end
effector by a robot's size.

``J̇ q̇`` (the bias acceleration) is computed exactly, without differencing:

* linear rows: the end effector's acceleration when ``q̈ = 0``, from the outward
  recursion of :func:`robotconf.motion.analytic_dva` (its ``ω × (ω × r)``, ``ω̇ × r``
  and Coriolis terms are exactly ``J̇_v q̇``);
* angular rows: ``Σ_j ω_{j−1} × z_j q̇_j``, the turning of each revolute axis ``z_j`` by
  the angular velocity ``ω_{j−1} = Σ_{k<j} z_k q̇_k`` of the body carrying it, read from
  the angular columns of ``J`` (which are ``z_j``, and 0 for prismatic joints).

The tests check it against the central difference ``(J(q + h q̇) − J(q − h q̇)) q̇ / 2h``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..kinematics import (
    JOINT_OF_LETTER,
    characteristic_length,
    cross_components,
    ee_position,
    joint_screws,
    pose_components,
)
from ..motion import analytic_dva
from ._rotation import rotation_error

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = ["Chain", "make_chain", "moving_joints", "kinematics", "solve", "bias", "pose_error"]

#: Relative size below which a singular value counts as zero when finding the rank.
RANK_TOL = 1e-9


@dataclass(frozen=True, eq=False)
class Chain:
    """The robot as a program drives it.

    Attributes
    ----------
    robot : Robot
    moving : ndarray of bool, shape (n,)
        Joints a program moves: revolute or prismatic, active, and not a held
        ``(constant)`` module (as ``rc.ik`` decides).
    mode : str
        ``"pose"`` when the moving joints can set position and orientation (generic rank
        6), else ``"position"``: the end-effector point only.
    rows : ndarray of int
        ``0 … 5`` or ``0 … 2``: the rows of ``[v; ω]`` that count.
    rank : int
        Generic rank of those rows over the moving joints.
    length : float
        ``L``, the robot's size (length).
    row_scale, column_scale : ndarray
        ``1/L`` for position rows, 1 for turns; ``L`` for prismatic, 1 for revolute
        columns, 0 for joints that do not move.
    """

    robot: Robot
    moving: np.ndarray
    mode: str
    rows: np.ndarray
    rank: int
    length: float
    row_scale: np.ndarray
    column_scale: np.ndarray


def _rank(matrices: np.ndarray) -> int:
    sigma = np.linalg.svd(matrices, compute_uv=False)
    return int(np.max(np.sum(sigma > RANK_TOL * np.maximum(sigma[:, :1], 1e-300), axis=1)))


def moving_joints(robot: Robot) -> np.ndarray:
    """Which coordinates a program moves, shape (n,) bool: revolute or prismatic joints
    among the active modules, not a held ``(constant)`` module. The others keep the
    robot's own values in every move.

    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz"), rc.Module("none", (1, 0, 0)), rc.Module("Tx")])
    >>> moving_joints(arm).tolist()
    [True, False, True]
    """
    types, names = robot.joint_types, robot.module_names
    return np.array(
        [
            j < robot.active
            and types[j] in ("revolute", "prismatic")
            and not names[j].endswith("(constant)")
            for j in range(robot.n)
        ],
        dtype=bool,
    )


def make_chain(robot: Robot, start: np.ndarray) -> Chain:
    """The chain of ``robot``; ranks are taken at ``start`` and 4 fixed random samples.

    >>> import robotconf as rc
    >>> make_chain(rc.preset("paper"), np.zeros(3)).mode
    'position'
    >>> make_chain(rc.preset("puma560"), np.zeros(6)).rank
    6
    """
    n = robot.n
    moving = moving_joints(robot)
    length = characteristic_length(robot)
    prismatic = np.array([t == "prismatic" for t in robot.joint_types])
    column_scale = np.where(prismatic, length, 1.0) * moving
    limits = robot.joint_limits()
    rng = np.random.default_rng(0)
    samples = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.random((4, n))
    samples = np.where(moving, samples, robot.q)
    jac = robot.jacobian(np.vstack([start, samples]))[:, :, moving] * column_scale[moving]
    row_scale = np.array([1.0 / length] * 3 + [1.0] * 3)
    scaled = jac * row_scale[:, np.newaxis]
    if moving.any() and _rank(scaled) == 6:
        mode, rows, rank = "pose", np.arange(6), 6
    else:
        rows = np.arange(3)
        rank = _rank(scaled[:, :3]) if moving.any() else 0
        mode = "position"
    return Chain(robot, moving, mode, rows, rank, length, row_scale[rows], column_scale)


def kinematics(chain: Chain, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """End-effector poses and geometric Jacobians from one pass of the kernel.

    Parameters
    ----------
    chain : Chain
    q : ndarray, shape (T, n)

    Returns
    -------
    pose : ndarray, shape (T, 4, 4)
    jac : ndarray, shape (T, 6, n)
        The columns of :func:`robotconf.kinematics.jacobian` (linear rows first).
    """
    robot = chain.robot
    poses = pose_components(robot, q)
    point = ee_position(robot, poses)
    jac = np.zeros((6, robot.n, q.shape[0]))
    for j, screw in enumerate(joint_screws(robot, poses)):
        if screw.joint is None or screw.axis is None:
            continue
        if JOINT_OF_LETTER[screw.joint] == "revolute":
            jac[:3, j] = cross_components(screw.axis, point - screw.point)
            jac[3:, j] = screw.axis
        else:
            jac[:3, j] = screw.axis
    pose = np.zeros((q.shape[0], 4, 4))
    pose[:, :3, :3] = poses[-1, :, :3].transpose(2, 0, 1)
    pose[:, :3, 3] = point.T
    pose[:, 3, 3] = 1.0
    return pose, np.ascontiguousarray(jac.transpose(2, 0, 1))


def solve(
    chain: Chain, jac: np.ndarray, rhs: np.ndarray, damping: float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """Minimum-norm least squares ``J x = rhs`` over the moving joints, batched.

    Parameters
    ----------
    chain : Chain
    jac : ndarray, shape (T, 6, n)
    rhs : ndarray, shape (T, 6)
        Twists or their rates; only ``chain.rows`` are used.
    damping : float
        0: the pseudo-inverse over the generic rank (exact; huge near a singularity).
        λ > 0: damped least squares ``σ/(σ² + λ²)`` on the scaled system.

    Returns
    -------
    x : ndarray, shape (T, n)
        Zero for joints that do not move.
    sigma : ndarray, shape (T,)
        The smallest of the generic-rank singular values of the scaled ``J``: 0 at a
        singularity, about 1 far from one.
    """
    count, n = jac.shape[0], chain.robot.n
    x = np.zeros((count, n))
    if chain.rank == 0:
        return x, np.zeros(count)
    cols = chain.column_scale[chain.moving]
    scaled = jac[:, chain.rows][:, :, chain.moving] * cols * chain.row_scale[:, np.newaxis]
    u, sigma, vt = np.linalg.svd(scaled, full_matrices=False)
    r = chain.rank
    u, sigma, vt = u[:, :, :r], sigma[:, :r], vt[:, :r]
    if damping > 0.0:
        inverse = sigma / (sigma**2 + damping**2)
    else:
        with np.errstate(divide="ignore"):
            inverse = np.where(sigma > 0.0, 1.0 / sigma, 0.0)
    rows = rhs[:, chain.rows] * chain.row_scale
    coefficients = np.einsum("tmr,tm->tr", u, rows) * inverse
    x[:, chain.moving] = np.einsum("trk,tr->tk", vt, coefficients) * cols
    return x, sigma[:, -1]


def bias(chain: Chain, q: np.ndarray, qd: np.ndarray, jac: np.ndarray) -> np.ndarray:
    """``J̇ q̇`` of the end effector (see the module notes), shape (T, 6).

    Parameters
    ----------
    q, qd : ndarray, shape (T, n)
    jac : ndarray, shape (T, 6, n)
        The Jacobians at ``q``.
    """
    out = np.empty((q.shape[0], 6))
    dva = analytic_dva(chain.robot, q, qd, np.zeros_like(qd))
    out[:, :3] = dva[-1, 3].T
    spin = jac[:, 3:, :] * qd[:, np.newaxis, :]  # (T, 3, n): z_j q̇_j
    before = np.cumsum(spin, axis=2) - spin  # ω_{j−1}
    out[:, 3:] = np.cross(before, spin, axis=1).sum(axis=2)
    return out


def pose_error(chain: Chain, target: np.ndarray, pose: np.ndarray) -> np.ndarray:
    """``[p_target − p, log(R_target Rᵀ)]``, shape (T, 6) (only ``chain.rows`` matter)."""
    error = np.zeros((pose.shape[0], 6))
    error[:, :3] = target[:, :3, 3] - pose[:, :3, 3]
    if chain.mode == "pose":
        error[:, 3:] = rotation_error(target[:, :3, :3], pose[:, :3, :3])
    return error
