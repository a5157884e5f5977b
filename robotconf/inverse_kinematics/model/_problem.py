"""One inverse-kinematics problem in the solver's own units, for a batch of targets.

The solver works in scaled, dimension-free units so that a robot in millimetres and the
same robot in metres take the same steps: position errors and prismatic joints are
divided by the robot's size ``L`` (:func:`~robotconf.characteristic_length`), angles stay
in radians. Each row of the error also carries the square root of its mask weight.

Orientation rows mean turns about the target's own x, y, z axes (about the tool's axes
once the solver has converged): the error is the rotation vector of ``R_target · Rᵀ``
turned by ``R_targetᵀ``, and the Jacobian's angular rows likewise. When all three turn
rows count with the same weight, turning both by ``R_targetᵀ`` changes no length and no
least-squares step (the rows are only rotated), so the solver then leaves both in the
base frame and saves the products; :attr:`Problem.base_frame` says which frame holds.

What depends only on the robot (its size, ranges, the folded chain of
:mod:`._chain`, its reach shell) is computed once per robot and kept
(:func:`robot_model`), since an interactive caller solves for the same robot many times.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...kinematics import Robot, characteristic_length
from ._chain import Chain, Pass, Workspace, compile_chain
from ._reach import Reach, reach_shell
from ._rotation import rotation_vector_last
from ._targets import Targets

__all__ = ["Problem", "RobotModel", "make_problem", "robot_model", "FULL_TURN"]

FULL_TURN = 2.0 * np.pi


def _frozen(array: np.ndarray) -> np.ndarray:
    array.setflags(write=False)
    return array


@dataclass(frozen=True, eq=False)
class RobotModel:
    """What the solver needs to know about a robot, whatever the targets.

    Arrays are read-only (they are shared between calls); ``(n,)`` arrays are indexed by
    coordinate, ``(m,)`` ones by the chain's moving joints.
    """

    robot: Robot
    length: float  # L
    moving: np.ndarray  # (n,) bool: the joints the solver moves
    prismatic: np.ndarray  # (n,) bool
    revolute: np.ndarray  # (n,) bool
    lower: np.ndarray  # (n,) joint ranges
    upper: np.ndarray
    wraps: np.ndarray  # (n,) bool: revolute with a range of a full turn or more
    chain: Chain
    reach: Reach


@lru_cache(maxsize=16)
def robot_model(robot: Robot) -> RobotModel:
    """The :class:`RobotModel` of a robot, computed once (robots are immutable).

    >>> from robotconf.presets import preset
    >>> model = robot_model(preset("paper"))
    >>> model.length, model.chain.size, model.reach.outer
    (90.0, 3, 70.0)
    """
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
    prismatic = np.array([t == "prismatic" for t in types], dtype=bool)
    revolute = np.array([t == "revolute" for t in types], dtype=bool)
    limits = robot.joint_limits()
    wraps = revolute & (limits[:, 1] - limits[:, 0] >= FULL_TURN * (1.0 - 1e-12))
    chain = compile_chain(robot, moving, robot.q)
    moving[:] = False
    moving[chain.joints] = True  # a joint module with no axis (none) does not move
    return RobotModel(
        robot=robot,
        length=characteristic_length(robot),
        moving=_frozen(moving),
        prismatic=_frozen(prismatic),
        revolute=_frozen(revolute),
        lower=_frozen(limits[:, 0].copy()),
        upper=_frozen(limits[:, 1].copy()),
        wraps=_frozen(wraps),
        chain=chain,
        reach=reach_shell(robot, moving, robot.q),
    )


@dataclass(frozen=True, eq=False)
class Problem:
    """Everything the iteration needs; arrays indexed by target (T), joint (n), moving
    joint (m) or constrained row (r)."""

    robot: Robot
    positions: np.ndarray  # (T, 3) target points
    rotations: np.ndarray | None  # (T, 3, 3) target rotations, None in mode "position"
    rows: np.ndarray  # (r,) indices of the constrained rows among x y z rx ry rz
    row_scale: np.ndarray  # (r,) √weight / L for positions, √weight for turns
    column_scale: np.ndarray  # (n,) L for prismatic, 1 for revolute, 0 for held joints
    moving: np.ndarray  # (n,) bool: the joints the solver moves
    held_q: np.ndarray  # (n,) coordinates of the joints it does not move
    lower: np.ndarray  # (n,) joint ranges
    upper: np.ndarray
    wraps: np.ndarray  # (n,) bool: revolute with a range of a full turn or more
    length: float  # L
    position_tol: float  # absolute, length units
    orientation_tol: float  # rad
    chain: Chain
    base_frame: bool  # turn rows (if any) in the base frame rather than the target's
    scale: np.ndarray  # (r, m) the Jacobian's row and column scales
    split: int  # the number of position rows (they come first)
    leading: bool  # the rows are 0, 1, …, r − 1 (a slice selects them)

    @property
    def position_rows(self) -> np.ndarray:
        """Which constrained rows are position rows, (r,) bool."""
        return self.rows < 3

    @property
    def joints(self) -> np.ndarray:
        """The moving joints' coordinates, (m,) int."""
        return self.chain.joints

    # -- the error and the Jacobian ---------------------------------------------------------

    def evaluate(
        self,
        positions: np.ndarray,
        rotations: np.ndarray | None,
        x: np.ndarray,
        jacobian: bool = True,
        workspace: Workspace | None = None,
    ) -> tuple[np.ndarray, np.ndarray | None]:
        """Error and Jacobian at moving coordinates ``x`` (B, m), from one pass of the chain.

        Parameters
        ----------
        positions : ndarray, shape (B, 3)
            The targets' points.
        rotations : ndarray, shape (3, 3, B), or None
            The targets' rotations, batch last (:meth:`rotations_of`); None in mode
            "position".
        x : ndarray, shape (B, m)
        jacobian : bool
            Whether to compute the Jacobian too.
        workspace : Workspace, optional
            Where the pass keeps its large arrays: the Jacobian returned then lives in it
            and is valid until the next call with the same workspace.

        Returns
        -------
        error : ndarray, shape (B, r)
            The constrained rows of the error, unscaled (length units and rad), turn rows
            in the solver's frame (:attr:`base_frame`).
        jacobian : ndarray, shape (B, r, m), or None
            Their derivatives by the moving coordinates, in the solver's units.
        """
        chain = self.chain.run(x, workspace)
        error = self._errors(positions, rotations, chain.columns)
        if not jacobian:
            return error, None
        return error, self._jacobian(chain, rotations, workspace)

    def rotations_of(self, index: np.ndarray) -> np.ndarray | None:
        """The rotations of targets ``index`` batch last, (3, 3, B), as :meth:`evaluate`
        takes them."""
        if self.rotations is None:
            return None
        return np.ascontiguousarray(self.rotations[index].transpose(1, 2, 0))

    def _errors(
        self, positions: np.ndarray, rotations: np.ndarray | None, columns: Sequence[np.ndarray]
    ) -> np.ndarray:
        full = np.empty((len(positions), 6))
        np.subtract(positions, columns[3].T, out=full[:, :3])
        if self._turns:
            assert rotations is not None
            # R_target·Rᵀ = Σ_j (column j of R_target) ⊗ (column j of R), batch last.
            product = rotations[:, 0, np.newaxis] * columns[0]
            product += rotations[:, 1, np.newaxis] * columns[1]
            product += rotations[:, 2, np.newaxis] * columns[2]
            turn = rotation_vector_last(product)
            if not self.base_frame:
                turn = _turned_back(rotations, turn)
            full[:, 3:] = turn.T
        return full[:, : len(self.rows)] if self.leading else full[:, self.rows]

    @property
    def _turns(self) -> bool:
        """Whether some turn row counts (then the targets have rotations)."""
        return self.rotations is not None and bool(self.rows[-1] >= 3)

    def _jacobian(
        self, chain: Pass, rotations: np.ndarray | None, workspace: Workspace | None = None
    ) -> np.ndarray:
        turns = self._turns
        axes = chain.axes
        lever = chain.columns[3] - chain.pivots
        shape = (6 if turns else 3, *axes.shape[::2])  # (rows, m, B)
        full = np.empty(shape) if workspace is None else workspace.get("full", shape)
        # z × lever, one component at a time (a turn's linear velocity per unit q̇).
        for i in range(3):
            j, k = (i + 1) % 3, (i + 2) % 3
            np.subtract(axes[:, j] * lever[:, k], axes[:, k] * lever[:, j], out=full[i])
        if turns:
            full[3:] = axes.transpose(1, 0, 2)
        slides = np.flatnonzero(~self.chain.revolute)
        if slides.size:
            full[:3, slides] = axes[slides].transpose(1, 0, 2)
            if turns:
                full[3:, slides] = 0.0
        if turns and not self.base_frame:
            assert rotations is not None
            full[3:] = _turned_back(rotations[:, :, np.newaxis], full[3:])
        rows = full[: len(self.rows)] if self.leading else full[self.rows]
        shape = (rows.shape[-1], *rows.shape[:2])
        out = np.empty(shape) if workspace is None else workspace.get("jacobian", shape)
        np.multiply(rows.transpose(2, 0, 1), self.scale, out=out)
        return out

    def expand(self, jacobian: np.ndarray) -> np.ndarray:
        """A (B, r, m) Jacobian with zero columns for the joints that do not move: (B, r, n)."""
        out = np.zeros((*jacobian.shape[:2], self.robot.n))
        out[:, :, self.joints] = jacobian
        return out

    def _targets(self, index: np.ndarray) -> tuple[np.ndarray, np.ndarray | None]:
        return self.positions[index], self.rotations_of(index)

    def errors_at(self, index: np.ndarray, q: np.ndarray) -> np.ndarray:
        """The errors (B, r) of targets ``index`` at coordinates ``q`` (B, n)."""
        return self.evaluate(*self._targets(index), q[:, self.joints], False)[0]

    def errors_from_pose(self, index: np.ndarray, pose: np.ndarray) -> np.ndarray:
        """The errors (B, r) of targets ``index`` for end-effector poses (B, 4, 4)."""
        columns = [pose[:, :3, k].T for k in range(4)]
        return self._errors(*self._targets(index), columns)

    def jacobian_at(self, index: np.ndarray, q: np.ndarray) -> np.ndarray:
        """The Jacobians (B, r, m) of targets ``index`` at coordinates ``q`` (B, n)."""
        jacobian = self.evaluate(*self._targets(index), q[:, self.joints])[1]
        assert jacobian is not None
        return jacobian

    # -- sizes of errors --------------------------------------------------------------------

    def scaled(self, error: np.ndarray) -> np.ndarray:
        """Errors (B, r) in the solver's units."""
        return error * self.row_scale

    def energy(self, error: np.ndarray) -> np.ndarray:
        """``E = ½‖e‖²`` of (B, r) unscaled errors, in the solver's units, (B,)."""
        scaled = error * self.row_scale
        return 0.5 * (scaled[:, np.newaxis, :] @ scaled[:, :, np.newaxis])[:, 0, 0]

    def error_norms(self, error: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position error (length) and orientation error (rad) of (B, r) errors."""
        position = np.sqrt(np.sum(error[:, : self.split] ** 2, axis=-1))
        orientation = np.sqrt(np.sum(error[:, self.split :] ** 2, axis=-1))
        return position, orientation

    def converged(self, error: np.ndarray) -> np.ndarray:
        """Whether each of (B, r) errors meets both tolerances, (B,) bool."""
        squares = error * error
        position = np.sum(squares[:, : self.split], axis=-1)
        orientation = np.sum(squares[:, self.split :], axis=-1)
        # Compared squared: the square roots of error_norms cost time in the solver's loop.
        return (position <= self.position_tol**2) & (orientation <= self.orientation_tol**2)

    # -- joint ranges -------------------------------------------------------------------------

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

    def full_q(self, x: np.ndarray) -> np.ndarray:
        """Coordinates (B, n) from the moving ones (B, m), the others held."""
        out = np.tile(self.held_q, (len(x), 1))
        out[:, self.joints] = x
        return out


def _turned_back(rotations: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """``R_targetᵀ · v`` with rotations (3, 3, …, B) and vectors (3, …, B), batch last."""
    out = np.empty_like(vectors)
    for j in range(3):
        out[j] = rotations[0, j] * vectors[0]
        out[j] += rotations[1, j] * vectors[1]
        out[j] += rotations[2, j] * vectors[2]
    return out


def make_problem(
    robot: Robot, targets: Targets, weights: np.ndarray, tol: float, orientation_tol: float
) -> Problem:
    """The problem for validated targets and mask weights (see :class:`Problem`)."""
    model = robot_model(robot)
    length = model.length
    column_scale = np.where(model.prismatic, length, 1.0) * model.moving
    rows = np.flatnonzero(weights > 0)
    row_scale = np.sqrt(weights[rows]) * np.where(rows < 3, 1.0 / length, 1.0)
    turn_weights = weights[3:][weights[3:] > 0]
    base_frame = len(turn_weights) in (0, 3) and bool(np.all(turn_weights == turn_weights[:1]))
    return Problem(
        robot=robot,
        positions=targets.positions,
        rotations=targets.rotations,
        rows=rows,
        row_scale=row_scale,
        column_scale=column_scale,
        moving=model.moving,
        held_q=robot.q,
        lower=model.lower,
        upper=model.upper,
        wraps=model.wraps,
        length=length,
        position_tol=tol * length,
        orientation_tol=orientation_tol,
        chain=model.chain,
        base_frame=base_frame,
        scale=row_scale[:, np.newaxis] * column_scale[model.chain.joints],
        split=int(np.sum(rows < 3)),
        leading=bool(np.array_equal(rows, np.arange(len(rows)))),
    )
