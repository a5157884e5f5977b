"""The end-effector paths of LIN and CIRC moves: a segment or a circular arc, with slerp.

A path is parametrized by ``u`` from 0 to 1 (the move's profile drives ``u(t)``):

Line
    ``p(u) = p0 + u·(p1 − p0)``, length ``L = |p1 − p0|``.
Arc through ``p0``, ``via`` and ``p1``
    centre ``c`` (the circumcentre), radius ``r``, unit vectors ``e1 = (p0 − c)/r`` and
    ``e2 = n̂ × e1`` with ``n̂ ∥ (via − p0) × (p1 − p0)``; the arc runs counterclockwise
    about ``n̂`` from ``p0`` through ``via`` to ``p1``:
    ``p(u) = c + r·(cos φ e1 + sin φ e2)`` with ``φ = u·Φ``, length ``L = r·Φ``.
Orientation
    ``R(u) = exp(u·w) · R0`` with ``w = log(R1 R0ᵀ)`` (slerp, the shortest turn, about an
    axis fixed in the base frame), so ``ω = w·u̇`` and ``ω̇ = w·ü``.

Velocities follow by the chain rule: ``ṗ = p'(u)·u̇`` and ``p̈ = p'(u)·ü + p''(u)·u̇²``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..kinematics import rotation_matrix, rotation_vector

__all__ = ["CartesianPath", "line_path", "arc_path", "COLLINEAR_TOL"]

#: Three points whose angle at the start has a sine below this are collinear.
COLLINEAR_TOL = 1e-9


@dataclass(frozen=True, eq=False)
class CartesianPath:
    """A line or arc of the end-effector point with a slerp of its orientation.

    Attributes
    ----------
    kind : str
        ``"line"`` or ``"arc"``.
    start, end : ndarray, shape (3,)
        End points (length).
    length : float
        Path length ``L`` (length).
    turn : ndarray, shape (3,)
        ``w = log(R1 R0ᵀ)``: the orientation's total turn in the base frame (rad).
    rotation : ndarray, shape (3, 3)
        ``R0``, the start orientation.
    centre, e1, e2 : ndarray, shape (3,)
        Arc only (zeros for a line): centre and in-plane unit vectors.
    radius, sweep : float
        Arc only: ``r`` (length) and ``Φ`` (rad).

    Examples
    --------
    >>> path = line_path(np.zeros(3), np.array([2.0, 0, 0]), np.eye(3), np.eye(3))
    >>> pose, twist, rate = path.evaluate(np.array([0.5]), np.array([1.0]), np.array([0.0]))
    >>> pose[0, :3, 3], twist[0]  # halfway, at u̇ = 1/s: 2 length/s along x
    (array([1., 0., 0.]), array([2., 0., 0., 0., 0., 0.]))
    """

    kind: str
    start: np.ndarray
    end: np.ndarray
    length: float
    turn: np.ndarray
    rotation: np.ndarray
    centre: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    radius: float = 0.0
    sweep: float = 0.0

    @property
    def angle(self) -> float:
        """``θ = |w|``, the total turn of the orientation (rad)."""
        return float(np.linalg.norm(self.turn))

    def positions(self, u: np.ndarray) -> np.ndarray:
        """Points ``p(u)``, shape (T, 3)."""
        return self._point(np.asarray(u, dtype=float))[0]

    def _point(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``p(u)``, ``p'(u)``, ``p''(u)``, each (T, 3)."""
        if self.kind == "line":
            chord = self.end - self.start
            p = self.start + u[:, np.newaxis] * chord
            return p, np.broadcast_to(chord, p.shape), np.zeros_like(p)
        phi = (u * self.sweep)[:, np.newaxis]
        radial = np.cos(phi) * self.e1 + np.sin(phi) * self.e2
        tangent = -np.sin(phi) * self.e1 + np.cos(phi) * self.e2
        scale = self.radius * self.sweep
        return self.centre + self.radius * radial, scale * tangent, -scale * self.sweep * radial

    def rotations(self, u: np.ndarray) -> np.ndarray:
        """Orientations ``R(u)``, shape (T, 3, 3)."""
        u = np.asarray(u, dtype=float)
        return rotation_matrix(u[:, np.newaxis] * self.turn) @ self.rotation

    def evaluate(
        self, u: np.ndarray, ud: np.ndarray, udd: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Poses, twists and twist rates along the path for ``u(t)``, ``u̇``, ``ü``.

        Returns
        -------
        pose : ndarray, shape (T, 4, 4)
        twist : ndarray, shape (T, 6)
            ``[ṗ, ω]`` (length/s, rad/s), base frame.
        rate : ndarray, shape (T, 6)
            ``[p̈, ω̇]`` (length/s², rad/s²).
        """
        p, dp, ddp = self._point(u)
        pose = np.zeros((u.size, 4, 4))
        pose[:, :3, :3] = self.rotations(u)
        pose[:, :3, 3] = p
        pose[:, 3, 3] = 1.0
        twist = np.empty((u.size, 6))
        rate = np.empty((u.size, 6))
        twist[:, :3] = dp * ud[:, np.newaxis]
        rate[:, :3] = dp * udd[:, np.newaxis] + ddp * (ud**2)[:, np.newaxis]
        twist[:, 3:] = ud[:, np.newaxis] * self.turn
        rate[:, 3:] = udd[:, np.newaxis] * self.turn
        return pose, twist, rate


def _turn(r0: np.ndarray, r1: np.ndarray) -> np.ndarray:
    return rotation_vector(r1 @ r0.T)


def line_path(p0: np.ndarray, p1: np.ndarray, r0: np.ndarray, r1: np.ndarray) -> CartesianPath:
    """The segment from ``p0`` to ``p1`` with a slerp from ``r0`` to ``r1``.

    >>> path = line_path(np.zeros(3), np.array([3.0, 4.0, 0.0]), np.eye(3), np.eye(3))
    >>> path.length, path.positions(np.array([0.5]))
    (5.0, array([[1.5, 2. , 0. ]]))
    """
    zero = np.zeros(3)
    length = float(np.linalg.norm(p1 - p0))
    return CartesianPath("line", p0, p1, length, _turn(r0, r1), r0, zero, zero, zero)


def arc_path(
    p0: np.ndarray, via: np.ndarray, p1: np.ndarray, r0: np.ndarray, r1: np.ndarray
) -> CartesianPath | None:
    """The circular arc from ``p0`` through ``via`` to ``p1``; ``None`` when the three
    points are collinear or two of them coincide (no circle passes through them).

    >>> arc = arc_path(np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), np.array([-1.0, 0, 0]),
    ...                np.eye(3), np.eye(3))
    >>> arc.radius, float(arc.length / np.pi)  # half of the unit circle
    (1.0, 1.0)
    """
    a, b = via - p0, p1 - p0
    normal = np.cross(a, b)
    size = float(np.linalg.norm(normal))
    spans = (np.linalg.norm(a), np.linalg.norm(b), np.linalg.norm(p1 - via))
    if min(spans) == 0.0 or size <= COLLINEAR_TOL * float(spans[0] * spans[1]):
        return None
    offset = (a @ a * np.cross(b, normal) + b @ b * np.cross(normal, a)) / (2.0 * size**2)
    centre = p0 + offset
    radius = float(np.linalg.norm(offset))
    e1 = -offset / radius
    e2 = np.cross(normal / size, e1)
    end = p1 - centre
    sweep = float(np.mod(np.arctan2(end @ e2, end @ e1), 2.0 * np.pi))
    return CartesianPath(
        "arc", p0, p1, radius * sweep, _turn(r0, r1), r0, centre, e1, e2, radius, sweep
    )
