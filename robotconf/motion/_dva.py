"""Displacement, velocity and acceleration (DVA) of every frame origin and the end-effector.

Three named ways (docs/conventions.md, "Motion and DVA"), all numpy only and vectorized
over the ``T`` samples:

``analytic``
    The classical outward recursion of rigid-body kinematics with the signals' exact
    ``q̇`` and ``q̈``. For link ``i`` with joint axis ``z`` through the point ``o`` (a point
    of the previous body) and ``d = p_i − o``:

    * the point ``o``: ``v_o = v_{i−1} + ω_{i−1} × r``,
      ``a_o = a_{i−1} + ω̇_{i−1} × r + ω_{i−1} × (ω_{i−1} × r)`` with ``r = o − p_{i−1}``;
    * revolute: ``ω_i = ω_{i−1} + z q̇``, ``ω̇_i = ω̇_{i−1} + z q̈ + ω_{i−1} × z q̇``,
      ``v_i = v_o + ω_i × d``, ``a_i = a_o + ω̇_i × d + ω_i × (ω_i × d)``;
    * prismatic: ``ω_i = ω_{i−1}``, ``v_i = v_o + ω_i × d + z q̇``,
      ``a_i = a_o + ω̇_i × d + ω_i × (ω_i × d) + 2 ω_{i−1} × z q̇ + z q̈`` (Coriolis).

    The end-effector is a point of the last body. The result equals ``J · q̇`` with the
    geometric Jacobian (:func:`robotconf.kinematics.jacobian`), which the tests check.

``numeric``
    Central finite differences of the sampled positions (more accurate than Simulink's
    Derivative block, which is ``backward`` below).
    Velocity: second-order central differences ``(x[k+1] − x[k−1]) / 2dt`` inside and
    second-order one-sided differences at both ends (``numpy.gradient`` with
    ``edge_order=2``). Acceleration: the compact second difference
    ``(x[k+1] − 2x[k] + x[k−1]) / dt²`` inside and the second-order one-sided
    ``(2x[0] − 5x[1] + 4x[2] − x[3]) / dt²`` at the ends. Both have error ``O(dt²)`` for
    smooth motion. At a kink of the input (a repeating sequence's corner or jump) the exact
    acceleration is an impulse and these differences show a spike of height ≈ Δv/dt:
    the spike is real, not noise. A jump that falls on the last sample of a run (or the
    first) meets the one-sided ``(3x[−1] − 4x[−2] + x[−3]) / 2dt`` instead, about
    ``3Δx/2dt``: three times an inner velocity spike, an effect of where the data end,
    not a bigger kink. Angular velocity comes from ``Ṙ Rᵀ`` with ``Ṙ`` differenced the
    same way as velocity.

``backward``
    What Simulink's Derivative block outputs: ``Δu/Δt = (u(t) − u(t − dt)) / dt``, the
    first-order backward difference, and ``0`` at the first sample (the block's initial
    output). Acceleration is the same block applied to that velocity, as two chained
    Derivative blocks give it: ``(x[k] − 2x[k−1] + x[k−2]) / dt²`` from the third sample
    on, ``0`` at the first, and ``v[1]/dt`` at the second (the velocity's step up from the
    initial 0: a start-up spike that Simulink shows too). Error ``O(dt)`` for smooth
    motion. Across a jump ``Δx`` of the input the velocity spike is ``Δx/dt`` on one
    sample, about twice the central difference's ``Δx/2dt`` spread over two, and the
    last sample of a run is differenced like every other. Angular velocity: ``Ṙ Rᵀ``
    with ``Ṙ`` by the same backward difference (0 at the first sample).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from .._errors import InvalidInputError
from ..kinematics import (
    cross_components,
    ee_position,
    joint_screws,
    pose_components,
    rotate_components,
)

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = [
    "QUANTITIES",
    "analytic_dva",
    "numeric_dva",
    "backward_dva",
    "first_derivative",
    "second_derivative",
    "backward_derivative",
    "backward_second_derivative",
]

#: Quantities per point, in table order. ``displacement`` is position minus the position
#: at the first sample; ``angular_velocity`` is the frame's (for the EE: the last frame's).
QUANTITIES = ("position", "displacement", "velocity", "acceleration", "angular_velocity")

_POS, _DISP, _VEL, _ACC, _OMEGA = range(5)

Vec = np.ndarray | None  # component-major (3, T) or (3, 1); None means identically zero


def _add(*terms: Vec) -> Vec:
    present = [t for t in terms if t is not None]
    if not present:
        return None
    total = present[0] + present[1] if len(present) > 1 else present[0].copy()
    for t in present[2:]:
        total += t
    return total


def _cross_or_none(a: Vec, b: Vec) -> Vec:
    return None if a is None or b is None else cross_components(a, b)


def _rigid(v: Vec, a: Vec, w: Vec, wd: Vec, r: np.ndarray) -> tuple[Vec, Vec]:
    """Velocity and acceleration of a point at offset ``r`` in a rigid body."""
    wr = _cross_or_none(w, r)
    return _add(v, wr), _add(a, _cross_or_none(wd, r), _cross_or_none(w, wr))


def _fill(slot: np.ndarray, value: Vec) -> None:
    if value is None:
        slot.fill(0.0)
    else:
        np.copyto(slot, value)


def _empty(robot: Robot, samples: int) -> np.ndarray:
    return np.empty((robot.n + 1, len(QUANTITIES), 3, samples))


def _positions(robot: Robot, poses: np.ndarray, out: np.ndarray) -> None:
    """Position and displacement of every frame origin and of the EE."""
    out[:-1, _POS] = poses[:, :, 3]
    out[-1, _POS] = ee_position(robot, poses)
    np.subtract(out[:, _POS], out[:, _POS, :, :1], out=out[:, _DISP])


def analytic_dva(robot: Robot, q: np.ndarray, qd: np.ndarray, qdd: np.ndarray) -> np.ndarray:
    """Exact DVA from the coordinates and their exact time derivatives.

    Parameters
    ----------
    robot : Robot
    q, qd, qdd : ndarray, shape (T, n)
        Coordinates and their first and second time derivatives (rad, rad/s, rad/s² for
        rotations; length, length/s, length/s² for translations).

    Returns
    -------
    ndarray, shape (n + 1, 5, 3, T)
        Points (frames M1…Mn, then EE) × :data:`QUANTITIES` × (x, y, z) × samples, in
        the base frame.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(2, 0, 0))
    >>> out = analytic_dva(robot, np.zeros((1, 1)), np.ones((1, 1)), np.zeros((1, 1)))
    >>> out[-1, 2, :, 0], out[-1, 3, :, 0]  # EE on a unit-speed circle of radius 2
    (array([0., 2., 0.]), array([-2.,  0.,  0.]))
    """
    poses = pose_components(robot, q)
    out = _empty(robot, q.shape[0])
    _positions(robot, poses, out)
    v: Vec = None
    a: Vec = None
    w: Vec = None
    wd: Vec = None
    previous: np.ndarray | None = None  # origin of the previous frame (None: base origin)
    for i, screw in enumerate(joint_screws(robot, poses)):
        origin = poses[i, :, 3]
        rate = qd[:, i] if screw.joint and np.any(qd[:, i]) else None
        accel = qdd[:, i] if screw.joint and np.any(qdd[:, i]) else None
        if rate is None and accel is None:
            if previous is not None:
                v, a = _rigid(v, a, w, wd, origin - previous)
        else:
            joint_point = screw.point
            assert joint_point is not None and screw.axis is not None  # a moving joint
            r = joint_point - previous if previous is not None else joint_point
            v, a = _rigid(v, a, w, wd, r)
            d = origin - joint_point
            z_rate = None if rate is None else screw.axis * rate
            z_accel = None if accel is None else screw.axis * accel
            if screw.joint == "R":
                wd = _add(wd, z_accel, _cross_or_none(w, z_rate))
                w = _add(w, z_rate)
                v, a = _rigid(v, a, w, wd, d)
            else:
                v, a = _rigid(v, a, w, wd, d)
                coriolis = _cross_or_none(w, z_rate)
                v = _add(v, z_rate)
                a = _add(a, z_accel, None if coriolis is None else 2.0 * coriolis)
        previous = origin
        _fill(out[i, _VEL], v)
        _fill(out[i, _ACC], a)
        _fill(out[i, _OMEGA], w)
    tip = rotate_components(poses[-1, :, :3], robot.end_effector_point)
    v, a = _rigid(v, a, w, wd, tip)
    _fill(out[-1, _VEL], v)
    _fill(out[-1, _ACC], a)
    _fill(out[-1, _OMEGA], w)
    return out


def first_derivative(x: np.ndarray, dt: float) -> np.ndarray:
    """Second-order finite-difference derivative along the last axis (uniform ``dt``).

    Central ``(x[k+1] − x[k−1]) / 2dt`` inside, second-order one-sided at the ends.

    >>> first_derivative(np.array([0.0, 1.0, 4.0, 9.0]), 1.0)  # x = t²: exact
    array([0., 2., 4., 6.])
    """
    return np.gradient(x, dt, axis=-1, edge_order=2)


def second_derivative(x: np.ndarray, dt: float) -> np.ndarray:
    """Second-order finite-difference second derivative along the last axis (≥ 4 samples).

    ``(x[k+1] − 2x[k] + x[k−1]) / dt²`` inside, ``(2x[0] − 5x[1] + 4x[2] − x[3]) / dt²``
    and its mirror at the ends.

    >>> second_derivative(np.array([0.0, 1.0, 8.0, 27.0, 64.0]), 1.0)  # x = t³: 6t
    array([ 0.,  6., 12., 18., 24.])
    """
    out = np.empty_like(x)
    inner = out[..., 1:-1]
    np.subtract(x[..., 2:], x[..., 1:-1], out=inner)
    inner -= x[..., 1:-1]
    inner += x[..., :-2]
    out[..., 0] = 2.0 * x[..., 0] - 5.0 * x[..., 1] + 4.0 * x[..., 2] - x[..., 3]
    out[..., -1] = 2.0 * x[..., -1] - 5.0 * x[..., -2] + 4.0 * x[..., -3] - x[..., -4]
    out /= dt * dt
    return out


def backward_derivative(x: np.ndarray, dt: float) -> np.ndarray:
    """First-order backward difference along the last axis, as Simulink's Derivative block.

    ``(x[k] − x[k−1]) / dt`` for ``k ≥ 1`` and ``0`` at ``k = 0``: the block's initial
    output is zero, as it has no earlier input to difference with.

    >>> backward_derivative(np.array([0.0, 1.0, 4.0, 9.0]), 1.0)  # x = t²: 2t − 1 (lags dt/2)
    array([0., 1., 3., 5.])
    """
    out = np.empty_like(x)
    out[..., 0] = 0.0
    np.subtract(x[..., 1:], x[..., :-1], out=out[..., 1:])
    out[..., 1:] /= dt
    return out


def backward_second_derivative(x: np.ndarray, dt: float) -> np.ndarray:
    """Two chained Derivative blocks: :func:`backward_derivative` of the backward velocity.

    ``0`` at ``k = 0``, ``(x[1] − x[0]) / dt²`` at ``k = 1`` (the velocity's step from its
    initial 0) and ``(x[k] − 2x[k−1] + x[k−2]) / dt²`` from ``k = 2`` on.

    >>> backward_second_derivative(np.array([0.0, 1.0, 4.0, 9.0, 16.0]), 1.0)  # x = t²: 2
    array([0., 1., 2., 2., 2.])
    """
    return backward_derivative(backward_derivative(x, dt), dt)


#: Fewest samples the numeric method accepts (the one-sided second difference uses 4).
MIN_NUMERIC_SAMPLES = 4

_Differentiator = Callable[[np.ndarray, float], np.ndarray]


def _differenced_dva(
    robot: Robot, q: np.ndarray, dt: float, first: _Differentiator, second: _Differentiator
) -> np.ndarray:
    """DVA with the given finite differences of the sampled positions and rotations."""
    poses = pose_components(robot, q)
    out = _empty(robot, q.shape[0])
    _positions(robot, poses, out)
    out[:, _VEL] = first(out[:, _POS], dt)
    out[:, _ACC] = second(out[:, _POS], dt)
    rotation = poses[:, :, :3]
    rate = first(rotation, dt)
    # ω̂ = Ṙ Rᵀ: only its antisymmetric part is kept (the symmetric part is round-off).
    spin = np.einsum("iakt,ibkt->iabt", rate, rotation)
    omega = out[:-1, _OMEGA]
    omega[:, 0] = 0.5 * (spin[:, 2, 1] - spin[:, 1, 2])
    omega[:, 1] = 0.5 * (spin[:, 0, 2] - spin[:, 2, 0])
    omega[:, 2] = 0.5 * (spin[:, 1, 0] - spin[:, 0, 1])
    out[-1, _OMEGA] = omega[-1]
    return out


def numeric_dva(robot: Robot, q: np.ndarray, dt: float) -> np.ndarray:
    """DVA by central finite differences of the sampled positions (see module notes).

    Parameters
    ----------
    robot : Robot
    q : ndarray, shape (T, n)
        Coordinates sampled every ``dt`` seconds, ``T ≥ 4``.
    dt : float
        Time step (s).

    Returns
    -------
    ndarray, shape (n + 1, 5, 3, T)
        Same layout as :func:`analytic_dva`.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Tx")])
    >>> t = np.arange(5) * 0.5
    >>> numeric_dva(robot, (t**2)[:, None], 0.5)[0, 3, 0]  # x = t²: acceleration 2
    array([2., 2., 2., 2., 2.])
    """
    if q.shape[0] < MIN_NUMERIC_SAMPLES:
        raise InvalidInputError(
            "t_end",
            q.shape[0],
            f"at least {MIN_NUMERIC_SAMPLES} samples: a later t_end or a smaller dt",
            problem="too few samples for finite differences:",
        )
    return _differenced_dva(robot, q, dt, first_derivative, second_derivative)


def backward_dva(robot: Robot, q: np.ndarray, dt: float) -> np.ndarray:
    """DVA by backward differences, as Simulink's Derivative block shows them.

    Velocity ``(x[k] − x[k−1]) / dt``, acceleration the same difference of that
    velocity (two chained blocks); both are 0 at the first sample, the block's initial
    output (see module notes).

    Parameters
    ----------
    robot : Robot
    q : ndarray, shape (T, n)
        Coordinates sampled every ``dt`` seconds, ``T ≥ 1``.
    dt : float
        Time step (s).

    Returns
    -------
    ndarray, shape (n + 1, 5, 3, T)
        Same layout as :func:`analytic_dva`.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Tx")])
    >>> t = np.arange(5) * 0.5
    >>> backward_dva(robot, (2 * t)[:, None], 0.5)[0, 2, 0]  # x = 2t: 0 first, then 2
    array([0., 2., 2., 2., 2.])
    """
    return _differenced_dva(robot, q, dt, backward_derivative, backward_second_derivative)
