"""The robot as the solver sees it: constant transforms between the joints it moves.

Every link is ``P · Rot_k(θ₀ + q) · Trans_k(d₀) · Q`` or ``P · Rot_k(θ₀) · Trans_k(d₀ + q) · Q``
(:class:`~robotconf.kinematics.LinkGeometry`). A turn or slide along axis ``k`` is one
along z seen through the cyclic permutation ``Π_k = [e_{k+1}, e_{k+2}, e_k]``
(``Rot_k = Π_k Rot_z Π_kᵀ``), and links the solver does not move (held, inactive, ``none``
and ``fixed`` modules) are constant. So the whole chain folds, once per robot, into

.. math::

    T(q) = C_0 · Z_1(q_1) · C_1 · Z_2(q_2) ⋯ Z_m(q_m) · C_m

with constant ``C_i`` (the last one carrying the end-effector point) and ``Z_j`` a turn
about or a slide along z. One pass over the ``m`` moving joints then gives the end-effector
pose and every joint's axis and pivot, hence the Jacobian: per joint, a turn changes two
columns of the pose and a constant only the columns its nonzero entries reach (a DH
twist of ±90° two, an offset the point).

The frames agree with :meth:`Robot.frame_poses` to float64 rounding (the constants are
multiplied in another order); :func:`~robotconf.ik` checks its final answers with the
robot's own kinematics.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...kinematics import Robot, cos_sin

__all__ = ["Chain", "Workspace", "compile_chain"]


def _permutation(axis: int) -> np.ndarray:
    """``Π_k`` as a 4×4 transform: x → e_{k+1}, y → e_{k+2}, z → e_k."""
    out = np.zeros((4, 4))
    out[(axis + 1) % 3, 0] = 1.0
    out[(axis + 2) % 3, 1] = 1.0
    out[axis, 2] = 1.0
    out[3, 3] = 1.0
    return out


def _turn(axis: int, angle: float) -> np.ndarray:
    """``Rot_k(angle)``, exactly the identity for angle 0."""
    out = np.eye(4)
    if angle != 0.0:
        c, s = np.cos(angle), np.sin(angle)
        i, j = (axis + 1) % 3, (axis + 2) % 3
        out[i, i], out[i, j], out[j, i], out[j, j] = c, -s, s, c
    return out


def _slide(axis: int, distance: float) -> np.ndarray:
    """``Trans_k(distance)``."""
    out = np.eye(4)
    out[axis, 3] = distance
    return out


#: One column of a constant product, as (source column, factor) pairs (zeros left out).
Terms = tuple[tuple[int, float], ...]


class Workspace:
    """Arrays kept from one step of the solver to the next, by name.

    Arrays above glibc's mmap threshold (128 kB: a Jacobian of 1000 runs is 288 kB) are
    fresh pages each time numpy allocates them, and every page is faulted in at first
    touch — a large part of a step's time at large batches. The solver's loop writes its
    biggest temporaries into these instead: :meth:`get` returns an array of the shape
    asked, carved from one kept buffer per name (reallocated only when it must grow), valid
    until the next :meth:`get` of that name.
    """

    def __init__(self) -> None:
        self._buffers: dict[str, np.ndarray] = {}

    def get(self, name: str, shape: tuple[int, ...]) -> np.ndarray:
        size = int(np.prod(shape))
        buffer = self._buffers.get(name)
        if buffer is None or buffer.size < size:
            buffer = self._buffers[name] = np.empty(size)
        return buffer[:size].reshape(shape)


@dataclass(frozen=True, eq=False)
class Pass:
    """One pass of the chain over a batch of B configurations, components first.

    Attributes
    ----------
    axes, pivots : ndarray, shape (m, 3, B)
        Each moving joint's unit axis and a point on it (its frame's origin), base frame.
    columns : tuple of four ndarray, shape (3, B)
        The end-effector pose: its rotation's columns x, y, z, then its point.
    """

    axes: np.ndarray
    pivots: np.ndarray
    columns: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]

    def pose(self) -> np.ndarray:
        """The end-effector poses as (B, 4, 4) matrices."""
        out = np.zeros((self.columns[0].shape[-1], 4, 4))
        out[:, 3, 3] = 1.0
        for k, column in enumerate(self.columns):
            out[:, :3, k] = column.T
        return out


@dataclass(frozen=True, eq=False)
class Chain:
    """A robot folded into ``C_0 · Z_1 · C_1 ⋯ Z_m · C_m`` (see the module notes).

    Attributes
    ----------
    joints : ndarray of int, shape (m,)
        The robot coordinates the solver moves, in chain order.
    revolute : ndarray of bool, shape (m,)
        Turn (True) or slide (False) of each.
    constants : ndarray, shape (m + 1, 4, 4)
        ``C_0 … C_m``; ``C_m`` ends at the end-effector point.
    """

    joints: np.ndarray
    revolute: np.ndarray
    constants: np.ndarray
    programs: tuple[tuple[Terms, ...], ...] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        # Per constant, the nonzero terms of its rotation's columns and of its translation.
        programs = tuple(
            tuple(_terms(c[:3, k]) for k in range(3)) + (_terms(c[:3, 3]),) for c in self.constants
        )
        object.__setattr__(self, "programs", programs)

    @property
    def size(self) -> int:
        """The number ``m`` of moving joints."""
        return len(self.joints)

    def run(self, x: np.ndarray, workspace: Workspace | None = None) -> Pass:
        """The end-effector pose and every joint's axis at moving coordinates ``x`` (B, m).

        The state is the pose's four columns, each (3, B) with the batch innermost, so
        every operation runs over the whole batch at once; a constant's zero entries
        (most of them, for DH arms) cost nothing. Each configuration is computed by the
        same sequence of elementwise operations whatever the batch holds.

        Examples
        --------
        >>> from robotconf.presets import preset
        >>> robot = preset("paper")
        >>> chain = compile_chain(robot, np.ones(3, bool), robot.q)
        >>> q = np.array([[0.3, -0.2, 0.5]])
        >>> bool(np.allclose(chain.run(q).pose(), robot.end_effector_pose(q), atol=1e-12))
        True
        """
        count, m = x.shape
        # cos and sin from the tangent half-angle, as the kinematics kernel does: numpy
        # vectorizes tan but not float64 cos and sin. Contiguous rows, so that every
        # batch size takes the same path.
        angle = np.ascontiguousarray(x.T)
        cos, sin = cos_sin(angle)
        first = self.constants[0]
        start = np.empty((4, 3, count))
        start[...] = first[:3].T[:, :, np.newaxis]
        columns = list(start)
        if workspace is None:
            axes, pivots = np.empty((m, 3, count)), np.empty((m, 3, count))
        else:
            axes = workspace.get("axes", (m, 3, count))
            pivots = workspace.get("pivots", (m, 3, count))
        for j in range(m):
            x_axis, y_axis, z_axis, point = columns
            axes[j] = z_axis
            pivots[j] = point
            if self.revolute[j]:
                # Rot_z: x ← c x + s y, y ← c y − s x.
                c, s = cos[j], sin[j]
                turned = x_axis * s
                x_axis *= c
                x_axis += y_axis * s
                y_axis *= c
                y_axis -= turned
            else:
                point += z_axis * angle[j]
            columns = _apply(self.programs[j + 1], columns)
        return Pass(axes, pivots, (columns[0], columns[1], columns[2], columns[3]))


def _terms(column: np.ndarray) -> Terms:
    """The nonzero entries of a constant's column. Entries at float64 rounding of the
    column's largest (the 6e-17 that cos(90°) leaves in a DH twist) count as zero: they
    move no result beyond rounding, and each would cost an operation per step."""
    floor = 4.0 * np.finfo(float).eps * float(np.max(np.abs(column), initial=0.0))
    return tuple((i, float(column[i])) for i in range(len(column)) if abs(column[i]) > floor)


def _combine(columns: list[np.ndarray], terms: Terms) -> np.ndarray:
    """``Σ factor · columns[i]`` as a new array."""
    i, factor = terms[0]
    out = columns[i] * factor
    for i, factor in terms[1:]:
        if factor == 1.0:
            out += columns[i]
        elif factor == -1.0:
            out -= columns[i]
        else:
            out += columns[i] * factor
    return out


def _apply(program: tuple[Terms, ...], columns: list[np.ndarray]) -> list[np.ndarray]:
    """The pose times a constant ``[R | t]``: columns ``Σ_i R[i, k]·col_i``, point
    ``p + Σ_i t_i·col_i``; a column the constant leaves alone is kept as it is."""
    out = []
    for k in range(3):
        terms = program[k]
        out.append(columns[k] if terms == ((k, 1.0),) else _combine(columns, terms))
    point = columns[3]
    if program[3]:
        point = point + _combine(columns, program[3])
    out.append(point)
    return out


def compile_chain(robot: Robot, moving: np.ndarray, held_q: np.ndarray) -> Chain:
    """Fold a robot into a :class:`Chain` over the joints ``moving`` moves.

    Parameters
    ----------
    robot : Robot
    moving : ndarray of bool, shape (n,)
        The coordinates the solver moves (revolute or prismatic joints of active modules).
    held_q : ndarray, shape (n,)
        The values the other coordinates keep (radians or length).

    Returns
    -------
    Chain

    Examples
    --------
    The paper robot turns about z, then twice about y: three joints, four constants, the
    last one ending at the end-effector point (40, 0, 0) of the third frame.

    >>> from robotconf.presets import preset
    >>> chain = compile_chain(preset("paper"), np.ones(3, bool), np.zeros(3))
    >>> chain.joints, chain.constants.shape
    (array([0, 1, 2]), (4, 4, 4))
    """
    held = robot.transfer_matrices(held_q)
    constants: list[np.ndarray] = []
    joints: list[int] = []
    revolute: list[bool] = []
    current = np.eye(4)
    for j, geometry in enumerate(robot.geometry()):
        if geometry is None or not moving[j] or geometry.axis is None or geometry.joint is None:
            current = current @ held[j]
            continue
        k = geometry.axis
        permutation = _permutation(k)
        # P·Rot_k(θ₀)·Trans_k(d₀) with the joint's own q between Rot_k(θ₀) and Trans_k(d₀)
        # for a turn, after Trans_k(d₀) for a slide (turn and slide about one axis commute).
        before = geometry.pre_matrix() @ _turn(k, geometry.angle)
        after = geometry.post_matrix()
        if geometry.joint == "R":
            after = _slide(k, geometry.offset) @ after
        else:
            before = before @ _slide(k, geometry.offset)
        constants.append(current @ before @ permutation)
        current = permutation.T @ after
        joints.append(j)
        revolute.append(geometry.joint == "R")
    point = np.eye(4)
    point[:3, 3] = robot.end_effector_point
    constants.append(current @ point)
    return Chain(
        joints=np.array(joints, dtype=int),
        revolute=np.array(revolute, dtype=bool),
        constants=np.array(constants),
    )
