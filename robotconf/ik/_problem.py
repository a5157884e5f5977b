"""One inverse-kinematics problem in the solver's own units, for a batch of targets.

The solver works in scaled, dimension-free units so that a robot in millimetres and the
same robot in metres take the same steps: position errors and prismatic joints are
divided by the robot's size ``L`` (:func:`~robotconf.characteristic_length`), angles stay
in radians. Each row of the error also carries the square root of its mask weight.

Orientation rows are written in the target frame: the error is the rotation vector of
``R_target · Rᵀ`` turned by ``R_targetᵀ``, and the Jacobian's angular rows likewise, so
that mask entries 4–6 mean turns about the target's own x, y, z axes (about the tool's
axes once the solver has converged).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..kinematics import Robot, characteristic_length
from ._rotation import rotation_vector
from ._targets import Targets

__all__ = ["Problem", "make_problem", "FULL_TURN"]

FULL_TURN = 2.0 * np.pi


@dataclass(frozen=True)
class Problem:
    """Everything the iteration needs; arrays indexed by target (T) or joint (n)."""

    robot: Robot
    positions: np.ndarray  # (T, 3) target points
    rotations: np.ndarray | None  # (T, 3, 3) target rotations, None in mode "position"
    rows: np.ndarray  # (m,) indices of the constrained rows among x y z rx ry rz
    row_scale: np.ndarray  # (m,) √weight / L for positions, √weight for turns
    column_scale: np.ndarray  # (n,) L for prismatic, 1 for revolute, 0 for held joints
    moving: np.ndarray  # (n,) bool: the joints the solver moves
    held_q: np.ndarray  # (n,) coordinates of the joints it does not move
    lower: np.ndarray  # (n,) joint ranges
    upper: np.ndarray
    wraps: np.ndarray  # (n,) bool: revolute with a range of a full turn or more
    length: float  # L
    position_tol: float  # absolute, length units
    orientation_tol: float  # rad

    @property
    def position_rows(self) -> np.ndarray:
        """Which constrained rows are position rows, (m,) bool."""
        return self.rows < 3

    def pose_errors(self, index: np.ndarray, pose: np.ndarray) -> np.ndarray:
        """The constrained rows of the error, unscaled: (B, m), length units and rad.

        Parameters
        ----------
        index : ndarray of int, shape (B,)
            Which targets.
        pose : ndarray, shape (B, 4, 4)
            The end-effector poses reached.
        """
        error = np.empty((len(index), 6))
        error[:, :3] = self.positions[index] - pose[:, :3, 3]
        if self.rotations is None:
            error[:, 3:] = 0.0
        else:
            target = self.rotations[index]
            turn = rotation_vector(target @ pose[:, :3, :3].transpose(0, 2, 1))
            error[:, 3:] = np.einsum("bji,bj->bi", target, turn)
        return error[:, self.rows]

    def scaled(self, error: np.ndarray) -> np.ndarray:
        """Errors (B, m) in the solver's units."""
        return error * self.row_scale

    def energy(self, error: np.ndarray) -> np.ndarray:
        """``E = ½‖e‖²`` of (B, m) unscaled errors, in the solver's units, (B,)."""
        scaled = error * self.row_scale
        return 0.5 * np.einsum("bm,bm->b", scaled, scaled)

    def jacobian(self, index: np.ndarray, q: np.ndarray) -> np.ndarray:
        """The constrained rows of the Jacobian in the solver's units, (B, m, n)."""
        full = self.robot.jacobian(q)
        if self.rotations is not None:
            full[:, 3:] = np.einsum("bji,bjk->bik", self.rotations[index], full[:, 3:])
        return full[:, self.rows] * self.row_scale[:, np.newaxis] * self.column_scale

    def pose(self, q: np.ndarray) -> np.ndarray:
        """End-effector poses (B, 4, 4) at coordinates (B, n)."""
        return self.robot.end_effector_pose(q)

    def error_norms(self, error: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position error (length) and orientation error (rad) of (B, m) errors."""
        position = np.linalg.norm(error[:, self.position_rows], axis=-1)
        orientation = np.linalg.norm(error[:, ~self.position_rows], axis=-1)
        return position, orientation

    def converged(self, error: np.ndarray) -> np.ndarray:
        """Whether each of (B, m) errors meets both tolerances, (B,) bool."""
        position, orientation = self.error_norms(error)
        return (position <= self.position_tol) & (orientation <= self.orientation_tol)

    def project(self, q: np.ndarray, limits: bool) -> np.ndarray:
        """Coordinates (B, n) moved into the joint ranges; held joints reset.

        A revolute joint whose range spans a full turn wraps (any angle has a twin
        inside); other joints are clipped to their range.
        """
        out = np.where(self.moving, q, self.held_q)
        if not limits:
            return out
        outside = self.wraps & ((out < self.lower) | (out > self.upper))
        wrapped = self.lower + np.mod(out - self.lower, FULL_TURN)
        out = np.where(outside, wrapped, out)
        return np.where(self.moving, np.clip(out, self.lower, self.upper), out)


def make_problem(
    robot: Robot, targets: Targets, weights: np.ndarray, tol: float, orientation_tol: float
) -> Problem:
    """The problem for validated targets and mask weights (see :class:`Problem`)."""
    length = characteristic_length(robot)
    types = robot.joint_types
    names = robot.module_names
    moving = np.array(
        [
            j < robot.active
            and types[j] in ("revolute", "prismatic")
            and not names[j].endswith("(constant)")
            for j in range(robot.n)
        ],
        dtype=bool,
    )
    prismatic = np.array([t == "prismatic" for t in types])
    column_scale = np.where(prismatic, length, 1.0) * moving
    rows = np.flatnonzero(weights > 0)
    row_scale = np.sqrt(weights[rows]) * np.where(rows < 3, 1.0 / length, 1.0)
    limits = robot.joint_limits()
    revolute = np.array([t == "revolute" for t in types])
    wraps = revolute & (limits[:, 1] - limits[:, 0] >= FULL_TURN * (1.0 - 1e-12))
    return Problem(
        robot=robot,
        positions=targets.positions,
        rotations=targets.rotations,
        rows=rows,
        row_scale=row_scale,
        column_scale=column_scale,
        moving=moving,
        held_q=robot.q,
        lower=limits[:, 0].copy(),
        upper=limits[:, 1].copy(),
        wraps=wraps,
        length=length,
        position_tol=tol * length,
        orientation_tol=orientation_tol,
    )
