"""Geometric building blocks of the closed-form solutions (Paden–Kahan subproblems).

Every closed form in this folder is a sequence of three questions about a rotation
``R(w, q)`` about a unit axis ``w``:

- :func:`angle_about`: which ``q`` turns the vector ``u`` onto ``v`` (subproblem 1);
- :func:`turn_to_level`: which ``q`` gives ``n · R(w, q) x`` a prescribed value (the
  equation ``a cos q + b sin q = c``; subproblem 3, "rotate to a distance", is one);
- :func:`bend_angles`: which ``q`` sets the angle between ``R(w, q) x`` and a fixed axis,
  written with half-angles so that it stays accurate next to a wrist singularity.

All vectors are numpy arrays of shape (3,); angles are radians.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

__all__ = [
    "RATIO_TOL",
    "Roots",
    "angle_about",
    "bend_angles",
    "cross",
    "perp",
    "rotate",
    "rotation",
    "solve_cos_sin",
    "turn_to_level",
    "unit",
]

#: How far ``c / √(a² + b²)`` may pass ±1 and still count as the tangent (double) root:
#: the round-off of a target computed by forward kinematics is a few 1e-16.
RATIO_TOL = 1e-12


class Roots(NamedTuple):
    """Solutions of one scalar equation in an angle.

    Attributes
    ----------
    angles : tuple of float
        Zero, one (a double root) or two angles, radians, in no particular order.
    kind : {"two", "tangent", "none", "free"}
        ``free``: every angle solves it (the axis does not matter); then ``angles`` is ().
    ratio : float
        ``c / √(a² + b²)``: beyond ±1 there is no solution (``inf`` when ``a = b = 0``).
    """

    angles: tuple[float, ...]
    kind: str
    ratio: float


def cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``u × v`` for two 3-vectors (``np.cross`` costs ten times more on one pair).

    >>> cross(np.array([1.0, 0, 0]), np.array([0, 1.0, 0]))
    array([0., 0., 1.])
    """
    return np.array(
        [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    )


def unit(v: np.ndarray) -> np.ndarray:
    """``v / |v|``.

    >>> unit(np.array([3.0, 0.0, 4.0]))
    array([0.6, 0. , 0.8])
    """
    return v / float(np.linalg.norm(v))


def perp(w: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The part of ``v`` perpendicular to the unit vector ``w``.

    >>> perp(np.array([0.0, 0.0, 1.0]), np.array([1.0, 2.0, 3.0]))
    array([1., 2., 0.])
    """
    return v - w * float(w @ v)


def rotate(w: np.ndarray, angle: float, v: np.ndarray) -> np.ndarray:
    """``R(w, angle) · v`` by Rodrigues' formula (right hand about the unit axis ``w``).

    >>> rotate(np.array([0.0, 0.0, 1.0]), np.pi / 2, np.array([1.0, 0.0, 0.0])).round(12)
    array([0., 1., 0.])
    """
    c, s = math.cos(angle), math.sin(angle)
    return v * c + cross(w, v) * s + w * (float(w @ v) * (1.0 - c))


def rotation(w: np.ndarray, angle: float) -> np.ndarray:
    """The rotation matrix ``R(w, angle)``, shape (3, 3).

    >>> rotation(np.array([1.0, 0.0, 0.0]), np.pi).round(12) + 0.0
    array([[ 1.,  0.,  0.],
           [ 0., -1.,  0.],
           [ 0.,  0., -1.]])
    """
    k = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * (k @ k)


def angle_about(w: np.ndarray, u: np.ndarray, v: np.ndarray, tiny: float) -> float | None:
    """The angle that turns ``u`` onto ``v`` about the unit axis ``w`` (subproblem 1).

    Only the parts perpendicular to ``w`` count; ``None`` when either is shorter than
    ``tiny`` (the vector lies on the axis, so every angle does).

    >>> z = np.array([0.0, 0.0, 1.0])
    >>> angle_about(z, np.array([1.0, 0.0, 5.0]), np.array([0.0, 2.0, 5.0]), 1e-12)
    1.5707963267948966
    """
    a, b = perp(w, u), perp(w, v)
    if np.linalg.norm(a) <= tiny or np.linalg.norm(b) <= tiny:
        return None
    return math.atan2(float(w @ cross(a, b)), float(a @ b))


def solve_cos_sin(a: float, b: float, c: float, scale: float) -> Roots:
    """All ``x`` with ``a cos x + b sin x = c``.

    Parameters
    ----------
    a, b, c : float
    scale : float
        The size of the terms, for deciding that ``a`` and ``b`` both vanish.

    Returns
    -------
    Roots
        ``atan2(b, a) ± acos(c / √(a² + b²))`` (within ±π); a ratio within
        :data:`RATIO_TOL` of ±1 is the double root.

    Examples
    --------
    >>> roots = solve_cos_sin(1.0, 0.0, 0.5, 1.0)
    >>> roots.kind, sorted(round(x, 12) for x in roots.angles)
    ('two', [-1.047197551197, 1.047197551197])
    >>> solve_cos_sin(1.0, 0.0, 2.0, 1.0).kind
    'none'
    """
    rho = math.hypot(a, b)
    if rho <= 1e-12 * scale:
        free = abs(c) <= 1e-10 * scale
        return Roots((), "free" if free else "none", math.nan if free else math.inf)
    ratio = c / rho
    centre = math.atan2(b, a)
    if abs(ratio) > 1.0 + RATIO_TOL:
        return Roots((), "none", ratio)
    if abs(ratio) >= 1.0 - RATIO_TOL:
        double = centre if ratio > 0 else centre + math.pi
        return Roots((math.remainder(double, 2 * math.pi),), "tangent", ratio)
    spread = math.acos(ratio)
    two = (centre + spread, centre - spread)
    return Roots(tuple(math.remainder(x, 2 * math.pi) for x in two), "two", ratio)


def turn_to_level(w: np.ndarray, x: np.ndarray, n: np.ndarray, level: float, scale: float) -> Roots:
    """All ``q`` with ``n · R(w, q) x = level`` (``w`` a unit vector).

    With ``R(w, q) x = x cos q + (w × x) sin q + w (w·x)(1 − cos q)`` this is
    :func:`solve_cos_sin` with ``a = n·x − (n·w)(w·x)``, ``b = n·(w × x)`` and
    ``c = level − (n·w)(w·x)``.

    >>> z = np.array([0.0, 0.0, 1.0])
    >>> roots = turn_to_level(z, np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), 1.0, 1.0)
    >>> roots.kind, round(roots.angles[0], 12)
    ('tangent', 1.570796326795)
    """
    along = float(n @ w) * float(w @ x)
    return solve_cos_sin(float(n @ x) - along, float(n @ cross(w, x)), level - along, scale)


def _angle(u: np.ndarray, v: np.ndarray) -> float:
    """The angle between two vectors, accurate near 0 and π (``atan2`` of cross and dot)."""
    return math.atan2(float(np.linalg.norm(cross(u, v))), float(u @ v))


def bend_angles(axis: np.ndarray, w: np.ndarray, x: np.ndarray, v: np.ndarray) -> Roots:
    """All ``q`` for which ``R(w, q) x`` makes the same angle with ``axis`` as ``v`` does.

    This is the wrist's middle joint: ``x`` is the last axis, ``axis`` the one the wrist
    turns about first, ``v`` where the last axis must point. With ``θa``, ``θb`` the
    (fixed) angles of ``axis`` and ``x`` to ``w``, ``g`` the angle of ``v`` to ``axis``
    and ``φ = q − q₀`` measured from ``q₀``, where ``R(w, q₀) x`` comes closest to
    ``axis``, the spherical law of cosines reads, in half-angles,
    ``sin²(g/2) = sin²((θa − θb)/2) + sin θa sin θb sin²(φ/2)`` and
    ``cos²(g/2) = cos²((θa + θb)/2) + sin θa sin θb cos²(φ/2)``. Both are accurate when
    ``φ`` is near 0 or π, where ``acos`` of a cosine would lose half the digits.

    Parameters
    ----------
    axis, w, x, v : ndarray, shape (3,)
        Unit vectors; ``w`` must be neither parallel to ``axis`` nor to ``x``.

    Returns
    -------
    Roots
        ``q₀ ± φ``; ``tangent`` when ``φ`` is 0 or π (the wrist singularity: one root).

    Examples
    --------
    An orthogonal wrist turns the last axis away from the first by exactly ``|q − q₀|``:

    >>> ex, ey, ez = np.eye(3)
    >>> roots = bend_angles(ez, ey, ez, rotate(ey, 0.3, ez))
    >>> sorted(round(q, 12) for q in roots.angles)
    [-0.3, 0.3]
    """
    closest = angle_about(w, x, axis, 1e-12)
    start = 0.0 if closest is None else closest
    theta_a, theta_b, g = _angle(w, axis), _angle(w, x), _angle(axis, v)
    scale = math.sin(theta_a) * math.sin(theta_b)
    half_sin = (math.sin(g / 2) ** 2 - math.sin((theta_a - theta_b) / 2) ** 2) / scale
    half_cos = (math.cos(g / 2) ** 2 - math.cos((theta_a + theta_b) / 2) ** 2) / scale
    ratio = half_cos - half_sin  # cos φ, for the message when there is no solution
    if half_sin < -RATIO_TOL or half_cos < -RATIO_TOL:
        return Roots((), "none", ratio)
    phi = 2.0 * math.atan2(math.sqrt(max(half_sin, 0.0)), math.sqrt(max(half_cos, 0.0)))
    if math.sin(phi) <= 1e-10:
        return Roots((start + (0.0 if phi < 1.0 else math.pi),), "tangent", ratio)
    return Roots((start + phi, start - phi), "two", ratio)
