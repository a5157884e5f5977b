"""The subproblems of :mod:`robotconf.inverse_kinematics.geometry._subproblems`, over T targets.

Each function takes arrays whose last axis holds a 3-vector, shape (T, 3) (or one (3,)
vector shared by all), and angles of shape (T,), and does per target what its one-target
twin does, in the same order of operations, so the two agree to round-off (numpy's
``arccos`` and ``arctan2`` may differ from :mod:`math`'s in the last bit).

A scalar equation's roots come back as :class:`RootsMany`: both candidate angles and a
kind code per target (:data:`TWO`, :data:`TANGENT`, :data:`NONE`, :data:`FREE`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..geometry._subproblems import RATIO_TOL
from ..geometry._subproblems import angle_about as angle_about_one
from ..geometry._subproblems import cross as cross_one

__all__ = [
    "TWO",
    "TANGENT",
    "NONE",
    "FREE",
    "RootsMany",
    "dot",
    "cross",
    "norm",
    "perp",
    "rotate",
    "rotations",
    "turn_vectors",
    "angle_about",
    "solve_cos_sin",
    "bend_angles",
    "remainder",
]

#: Root kinds, as :class:`robotconf.inverse_kinematics.geometry._subproblems.Roots` names them.
TWO, TANGENT, NONE, FREE = range(4)


class RootsMany(NamedTuple):
    """Roots of one scalar equation per target.

    ``angles`` (T, 2): for kind :data:`TWO` both roots in the one-target order, for
    :data:`TANGENT` the double root twice; ``kind`` (T,) int; ``ratio`` (T,) as
    :class:`~robotconf.inverse_kinematics.geometry._subproblems.Roots` has it.
    """

    angles: np.ndarray
    kind: np.ndarray
    ratio: np.ndarray


def dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Row-wise ``u · v``, shape (T,).

    >>> dot(np.array([[1.0, 2, 3]]), np.array([1.0, 1, 1]))
    array([6.])
    """
    return np.sum(u * v, axis=-1)


def cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Row-wise ``u × v``, shape (T, 3).

    >>> cross(np.array([[1.0, 0, 0]]), np.array([0.0, 1, 0]))
    array([[0., 0., 1.]])
    """
    u, v = np.broadcast_arrays(u, v)
    out = np.empty(u.shape)
    out[..., 0] = u[..., 1] * v[..., 2] - u[..., 2] * v[..., 1]
    out[..., 1] = u[..., 2] * v[..., 0] - u[..., 0] * v[..., 2]
    out[..., 2] = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    return out


def norm(v: np.ndarray) -> np.ndarray:
    """Row-wise length, shape (T,)."""
    return np.sqrt(dot(v, v))


def perp(w: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The part of ``v`` perpendicular to the unit ``w`` (either may be per target)."""
    return v - w * dot(w, v)[..., np.newaxis]


def rotate(w: np.ndarray, angle: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``R(w, angle) · v`` by Rodrigues' formula, shape (T, 3).

    >>> rotate(np.array([0.0, 0, 1]), np.array([np.pi / 2]), np.array([1.0, 0, 0])).round(12)
    array([[0., 1., 0.]])
    """
    c, s = np.cos(angle)[:, np.newaxis], np.sin(angle)[:, np.newaxis]
    return v * c + cross(w, v) * s + w * (dot(w, v)[..., np.newaxis] * (1.0 - c))


def rotations(w: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """The rotation matrices ``R(w, angle)`` about one unit axis ``w`` (3,), (T, 3, 3)."""
    k = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    s = np.sin(angle)[:, np.newaxis, np.newaxis]
    c = np.cos(angle)[:, np.newaxis, np.newaxis]
    return np.eye(3) + s * k + (1.0 - c) * (k @ k)


def turn_vectors(matrices: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``matrices[t] @ v[t]`` (or one shared ``v`` (3,)), shape (T, 3)."""
    if v.ndim == 1:
        return matrices @ v
    return (matrices @ v[:, :, np.newaxis])[:, :, 0]


def angle_about(
    w: np.ndarray, u: np.ndarray, v: np.ndarray, tiny: np.ndarray | float
) -> tuple[np.ndarray, np.ndarray]:
    """The angle that turns ``u`` onto ``v`` about the unit ``w``, and whether it is fixed.

    Returns ``(angle (T,), fixed (T,) bool)``; ``fixed`` is False where the one-target
    twin returns None (either vector within ``tiny`` of the axis).
    """
    a, b = perp(w, u), perp(w, v)
    fixed = (norm(a) > tiny) & (norm(b) > tiny)
    return np.arctan2(dot(w, cross(a, b)), dot(a, b)), fixed


def remainder(x: np.ndarray) -> np.ndarray:
    """``math.remainder(x, 2π)`` for angles within a few turns: ``x − 2π·round(x / 2π)``,
    exact there (Sterbenz), ties to even."""
    turn = 2 * math.pi
    return x - turn * np.rint(x / turn)


def solve_cos_sin(
    a: np.ndarray | float, b: np.ndarray | float, c: np.ndarray, scale: float
) -> RootsMany:
    """All ``x`` with ``a cos x + b sin x = c``, per target (see the one-target twin).

    >>> roots = solve_cos_sin(1.0, 0.0, np.array([0.5, 2.0]), 1.0)
    >>> roots.kind.tolist(), roots.angles[0].round(12).tolist()
    ([0, 2], [1.047197551197, -1.047197551197])
    """
    count = len(c)
    a = np.broadcast_to(np.asarray(a, dtype=float), (count,))
    b = np.broadcast_to(np.asarray(b, dtype=float), (count,))
    rho = np.hypot(a, b)
    flat = rho <= 1e-12 * scale
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(flat, np.nan, c / np.where(flat, 1.0, rho))
    free = flat & (np.abs(c) <= 1e-10 * scale)
    ratio = np.where(flat & ~free, np.inf, ratio)
    centre = np.arctan2(b, a)
    size = np.abs(ratio)
    kind = np.full(count, TWO)
    kind[size >= 1.0 - RATIO_TOL] = TANGENT
    kind[size > 1.0 + RATIO_TOL] = NONE
    kind[flat] = np.where(free[flat], FREE, NONE)
    spread = np.arccos(np.clip(np.where(kind == TWO, ratio, 0.0), -1.0, 1.0))
    double = remainder(np.where(ratio > 0, centre, centre + math.pi))
    angles = np.stack([remainder(centre + spread), remainder(centre - spread)], axis=1)
    tangent = kind == TANGENT
    angles[tangent] = double[tangent, np.newaxis]
    return RootsMany(angles, kind, ratio)


def _angle(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    return np.arctan2(norm(cross(u, v)), dot(u, v))


def bend_angles(axis: np.ndarray, w: np.ndarray, x: np.ndarray, v: np.ndarray) -> RootsMany:
    """The wrist's middle joint per target: ``axis``, ``w``, ``x`` fixed (3,), ``v`` (T, 3)
    (see :func:`robotconf.inverse_kinematics.geometry._subproblems.bend_angles`)."""
    closest = angle_about_one(w, x, axis, 1e-12)
    start = 0.0 if closest is None else closest
    theta_a = math.atan2(float(np.linalg.norm(cross_one(w, axis))), float(w @ axis))
    theta_b = math.atan2(float(np.linalg.norm(cross_one(w, x))), float(w @ x))
    g = _angle(axis, v)
    scale = math.sin(theta_a) * math.sin(theta_b)
    half_sin = (np.sin(g / 2) ** 2 - math.sin((theta_a - theta_b) / 2) ** 2) / scale
    half_cos = (np.cos(g / 2) ** 2 - math.cos((theta_a + theta_b) / 2) ** 2) / scale
    ratio = half_cos - half_sin
    none = (half_sin < -RATIO_TOL) | (half_cos < -RATIO_TOL)
    phi = 2.0 * np.arctan2(np.sqrt(np.maximum(half_sin, 0.0)), np.sqrt(np.maximum(half_cos, 0.0)))
    kind = np.where(none, NONE, np.where(np.sin(phi) <= 1e-10, TANGENT, TWO))
    angles = np.stack([start + phi, start - phi], axis=1)
    tangent = kind == TANGENT
    angles[tangent] = (start + np.where(phi[tangent] < 1.0, 0.0, math.pi))[:, np.newaxis]
    return RootsMany(angles, kind, ratio)
