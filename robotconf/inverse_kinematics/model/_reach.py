"""A reach shell that provably holds the robot: a sphere about a point, minus a hole.

The chain is cut at its revolute joints into **segments**: the vector from one revolute
pivot to the next (the last one ends at the end-effector point). A segment is made of
constant offsets and of prismatic strokes along fixed directions, so its length is
bounded from above and below whatever its joints do; the revolute joints only turn the
segments. With ``c`` the reach centre, ``p − c`` is a sum of turned segments, so by the
triangle inequality

- ``|p − c| ≤ R = Σ maxᵢ``: the **reach sphere**;
- ``|p − c| ≥ r = max(0, maxⱼ (minⱼ − Σ_{i≠j} maxᵢ))``: the **hole** (the polygon
  inequality: one segment longer than all others together cannot be folded back to c).

When the first moving joint is revolute its pivot is fixed, and ``c`` may be any point of
its axis: everything after it turns about that axis, which keeps distances to points on
the axis. The centre is slid along the axis to remove the first segment's axial part
(the paper robot's shoulder height 20), which tightens R. Otherwise ``c`` is the base
origin and the first segment starts there.

Joint ranges of revolute joints are ignored (they only shrink the true reachable set), so
both bounds are safe: a target farther than R from c, or closer than r, is out of reach.

**Arms whose revolute axes are all parallel** (planar arms, SCARAs, a cylindrical robot)
are held tighter. A turn about the common direction ``w`` keeps every point's height
``w·p``, so only the prismatic strokes move it: the end effector stays in a **slab**
``h_lo ≤ w·p ≤ h_hi`` (a plane for a planar arm), whatever the turns. And seen along
``w``, each segment turns in the plane across it, so the triangle and polygon inequalities
hold for the segments' parts across ``w``: the distance ``ρ`` from joint 1's axis lies in
``[r⊥, R⊥]`` (an annulus). The reachable set lies in the product of the two, and the
distance to it, ``√(d_h² + d_ρ²)``, is a lower bound of the distance to reach — exact for
a planar arm without joint ranges (the set is then the annulus itself). The larger of
this and the sphere's bound is used.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product

import numpy as np

from ...kinematics import Robot

__all__ = ["Reach", "Cylinder", "reach_shell"]

# Up to 2**12 corners of a segment's stroke box are tried exactly; beyond, a sum bound.
_MAX_CORNER_JOINTS = 12
# Revolute axes count as parallel when |w × w_j| is at most this (float64 rounding).
_PARALLEL = 1e-12


@dataclass(frozen=True)
class Cylinder:
    """Where an arm with parallel revolute axes keeps its end effector: heights
    ``low ≤ w·p ≤ high`` along the unit ``direction`` w and, when ``radii`` is given, a
    distance from the line through ``point`` along w between ``radii[0]`` and
    ``radii[1]`` (length units)."""

    direction: np.ndarray
    low: float
    high: float
    point: np.ndarray
    radii: tuple[float, float] | None

    def parts(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """How far each point (T, 3) lies outside the slab, and outside the annulus."""
        height = points @ self.direction
        off = np.maximum(0.0, np.maximum(height - self.high, self.low - height))
        if self.radii is None:
            return off, np.zeros(len(points))
        across = (
            points - self.point - np.outer((points - self.point) @ self.direction, self.direction)
        )
        rho = np.linalg.norm(across, axis=-1)
        inner, outer = self.radii
        return off, np.maximum(0.0, np.maximum(rho - outer, inner - rho))


@dataclass(frozen=True)
class Reach:
    """The reach shell: centre ``center`` (3,), outer radius ``outer``, hole radius ``inner``
    (length units), the joint (0-based) whose axis holds the centre (None: the base
    origin), and, for arms whose revolute axes are all parallel, the :class:`Cylinder`
    that holds them tighter (None otherwise)."""

    center: np.ndarray
    outer: float
    inner: float
    axis_joint: int | None
    cylinder: Cylinder | None = None

    def sphere_distance(self, points: np.ndarray) -> np.ndarray:
        """How far each point (T, 3) lies outside the sphere shell: beyond R or in the hole.

        >>> Reach(np.zeros(3), 3.0, 1.0, 0).sphere_distance(np.array([[0.5, 0, 0], [5, 0, 0]]))
        array([0.5, 2. ])
        """
        radius = np.linalg.norm(points - self.center, axis=-1)
        return np.maximum(0.0, np.maximum(radius - self.outer, self.inner - radius))

    def distance(self, points: np.ndarray) -> np.ndarray:
        """A lower bound (T,) of how far each point (T, 3) lies from anything the robot
        reaches: the larger of the sphere's and the cylinder's bounds.

        >>> from robotconf.presets import preset
        >>> shell = reach_shell(preset("planar_2r", l1=2, l2=1), np.ones(2, bool), np.zeros(2))
        >>> shell.distance(np.array([[0.5, 0.0, 2.0]])).round(6)  # √(0.5² + 2²)
        array([2.061553])
        """
        out = self.sphere_distance(points)
        if self.cylinder is not None:
            off, across = self.cylinder.parts(points)
            out = np.maximum(out, np.hypot(off, across))
        return out


@dataclass
class _Segment:
    constant: np.ndarray
    strokes: list[tuple[np.ndarray, float, float]]

    def corners(self) -> np.ndarray:
        if not self.strokes:
            return self.constant[np.newaxis]
        if len(self.strokes) > _MAX_CORNER_JOINTS:
            return np.empty((0, 3))
        ends = [(u * lo, u * hi) for u, lo, hi in self.strokes]
        return np.array([self.constant + sum(choice) for choice in product(*ends)])

    def longest(self) -> float:
        corners = self.corners()
        if len(corners):
            # The norm is convex, so its maximum over the stroke box sits at a corner.
            return float(np.max(np.linalg.norm(corners, axis=-1)))
        reach = sum(np.linalg.norm(u) * max(abs(lo), abs(hi)) for u, lo, hi in self.strokes)
        return float(np.linalg.norm(self.constant) + reach)

    def shortest(self) -> float:
        if not self.strokes:
            return float(np.linalg.norm(self.constant))
        if len(self.strokes) == 1:
            u, lo, hi = self.strokes[0]
            s = np.clip(-(self.constant @ u) / (u @ u), lo, hi)
            return float(np.linalg.norm(self.constant + s * u))
        middle = self.constant + sum(u * 0.5 * (lo + hi) for u, lo, hi in self.strokes)
        spread = sum(np.linalg.norm(u) * 0.5 * (hi - lo) for u, lo, hi in self.strokes)
        return float(max(0.0, np.linalg.norm(middle) - spread))

    def middle(self) -> np.ndarray:
        return self.constant + sum((u * 0.5 * (lo + hi) for u, lo, hi in self.strokes), np.zeros(3))


def reach_shell(robot: Robot, moving: np.ndarray, held_q: np.ndarray) -> Reach:
    """The reach sphere and hole of a robot whose joints ``moving`` move.

    Parameters
    ----------
    robot : Robot
    moving : ndarray of bool, shape (n,)
        Joints the solver moves; the others are constant at ``held_q``.
    held_q : ndarray, shape (n,)
        Coordinates of the joints that do not move (radians or length).

    Returns
    -------
    Reach

    Examples
    --------
    The paper robot: the centre slides up joint 1's axis to the shoulder (0, 0, 20); the
    arm reaches 30 + 40 = 70 from there, and not closer than 40 − 30 = 10.

    >>> from robotconf.presets import preset
    >>> shell = reach_shell(preset("paper"), np.ones(3, bool), np.zeros(3))
    >>> shell.center, shell.outer, shell.inner
    (array([ 0.,  0., 20.]), 70.0, 10.0)
    """
    constants = robot.transfer_matrices(held_q)
    limits = robot.joint_limits()
    segments: list[_Segment] = []
    axes: list[int] = []  # per segment, the local axis of the joint that turns it
    rotation, position = np.eye(3), np.zeros(3)
    strokes: list[tuple[np.ndarray, float, float]] = []
    pivot: tuple[int, np.ndarray, np.ndarray, int] | None = None  # joint, point, axis, k
    for j, geometry in enumerate(robot.geometry()):
        if geometry is None or not moving[j]:
            position = position + rotation @ constants[j, :3, 3]
            rotation = rotation @ constants[j, :3, :3]
            continue
        pre = geometry.pre_matrix()
        position = position + rotation @ pre[:3, 3]
        rotation = rotation @ pre[:3, :3]
        k = int(geometry.axis) if geometry.axis is not None else 2
        turn = _axis_rotation(k, geometry.angle)
        if geometry.joint == "P":
            lo, hi = limits[j] + geometry.offset
            strokes.append((rotation[:, k].copy(), float(lo), float(hi)))
            rotation = rotation @ turn
        else:
            if pivot is None and not segments and not strokes:
                # The first revolute pivot with nothing sliding before it is fixed in
                # space: the centre goes on its axis, and the base-to-pivot part drops out.
                pivot = (j, position.copy(), rotation[:, k].copy(), k)
            else:
                segments.append(_Segment(position.copy(), strokes))
            axes.append(k)
            # The next segment is written in the frame Rot_k(θ₀ + q) turned to; any
            # q leaves its axis k where it was.
            rotation, position, strokes = np.eye(3), np.zeros(3), []
            position[k] = geometry.offset
        post = geometry.post_matrix()
        position = position + rotation @ post[:3, 3]
        rotation = rotation @ post[:3, :3]
    position = position + rotation @ robot.end_effector_point
    segments.append(_Segment(position, strokes))

    center = np.zeros(3)
    axis_joint = None
    if pivot is not None:
        axis_joint, point, axis, k = pivot
        first = segments[0]
        # The first segment is written in the frame turned by this joint, whose axis k
        # is the joint axis: sliding c along it removes the segment's axial part.
        slide = float(first.middle()[k])
        unit = np.zeros(3)
        unit[k] = 1.0
        segments[0] = _Segment(first.constant - slide * unit, first.strokes)
        center = point + slide * axis
    outer, inner = _radii(segments)
    cylinder = _cylinder(robot, moving, held_q, segments, axes, pivot)
    return Reach(center + 0.0, outer, inner, axis_joint, cylinder)


def _radii(segments: list[_Segment]) -> tuple[float, float]:
    """``(R, r)``: the sum of the longest lengths, and the polygon inequality's hole."""
    longest = [segment.longest() for segment in segments]
    shortest = [segment.shortest() for segment in segments]
    outer = float(sum(longest))
    inner = max([0.0] + [s - (outer - m) for s, m in zip(shortest, longest, strict=True)])
    return outer, float(inner)


def _cylinder(
    robot: Robot,
    moving: np.ndarray,
    held_q: np.ndarray,
    segments: list[_Segment],
    axes: list[int],
    pivot: tuple[int, np.ndarray, np.ndarray, int] | None,
) -> Cylinder | None:
    """The slab and annulus of an arm whose moving revolute axes are all parallel."""
    types = robot.joint_types
    turns = [j for j in range(robot.n) if moving[j] and types[j] == "revolute"]
    slides = [j for j in range(robot.n) if moving[j] and types[j] == "prismatic"]
    if not turns:
        return None
    q = np.where(moving, 0.0, held_q)
    jacobian = robot.jacobian(q)
    direction = jacobian[3:, turns[0]]
    direction = direction / np.linalg.norm(direction)
    spread = np.linalg.norm(np.cross(direction, jacobian[3:, turns].T), axis=-1)
    if np.any(spread > _PARALLEL):
        return None
    # Every turn keeps the height w·p; a slide s along u adds s·(w·u) whatever the turns.
    height = float(direction @ robot.end_effector(q))
    limits = robot.joint_limits()
    low = high = height
    for j in slides:
        rate = float(direction @ jacobian[:3, j])
        ends = rate * (limits[j] - q[j])
        low, high = low + float(np.min(ends)), high + float(np.max(ends))
    radii = None
    if pivot is not None and len(axes) == len(segments):
        # Each segment is written in the frame of the joint that turns it, whose own axis
        # k is w: its part across w drops coordinate k.
        flat = [_across(segment, k) for segment, k in zip(segments, axes, strict=True)]
        outer, inner = _radii(flat)
        radii = (inner, outer)
    point = pivot[1] if pivot is not None else np.zeros(3)
    return Cylinder(direction, low, high, point.copy(), radii)


def _across(segment: _Segment, k: int) -> _Segment:
    keep = np.ones(3)
    keep[k] = 0.0
    strokes = [(u * keep, lo, hi) for u, lo, hi in segment.strokes]
    return _Segment(segment.constant * keep, strokes)


def _axis_rotation(k: int, angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    i, j = (k + 1) % 3, (k + 2) % 3
    out = np.eye(3)
    out[i, i], out[i, j], out[j, i], out[j, j] = c, -s, s, c
    return out
