"""A robot's body as capsules: one per link between consecutive distinct points.

The chain's points are the base origin, every module frame's origin and the end
effector. Points that coincide at every configuration (two joints at one place) are
merged; each remaining neighbour pair is a link, a capsule around its segment, named
``"link 1"``, ``"link 2"``, … from the base. A tool adds its own capsules, which move
with the flange. A link whose ends never move with the joints is part of the base.

Self-collision is checked between links that are not neighbours (their capsules meet
at the joint by construction) and that do not already touch at the robot's reference
configuration (its own ``q``), as a robot's design places them, the way MoveIt's setup
assistant disables "default" collisions; :attr:`LinkModel.self_pairs` lists them.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, one_line
from ..kinematics import Robot, characteristic_length
from ._tool import Tool
from .distance import segment_segment_distance

__all__ = ["LinkModel", "DEFAULT_RADIUS_FRACTION"]

#: A link's default radius: this fraction of the robot's size
#: (:func:`robotconf.characteristic_length`), e.g. 3.6 for the paper arm's 90.
DEFAULT_RADIUS_FRACTION = 0.04

_PROBES = 4


def _chain_points(robot: Robot, q: np.ndarray) -> np.ndarray:
    """Base origin, module origins, end effector: shape (T, n + 2, 3)."""
    t = q.shape[0]
    out = np.zeros((t, robot.n + 2, 3))
    out[:, 1:-1] = robot.frame_origins(q)
    out[:, -1] = robot.end_effector(q)
    return out


class LinkModel:
    """The capsules of one robot in its base frame, and which pairs may collide.

    Parameters
    ----------
    robot : Robot
    tool : Tool, optional
    radius : float, sequence or mapping, optional
        Every arm link's radius (one number), one per link, or ``{link: radius}`` for
        some (links by number from 1 or by name ``"link 2"``); default
        :data:`DEFAULT_RADIUS_FRACTION` of the robot's size.

    Examples
    --------
    >>> import robotconf as rc
    >>> model = LinkModel(rc.preset("paper"))
    >>> model.names, model.radii.tolist()
    (('link 1', 'link 2', 'link 3'), [3.6, 3.6, 3.6])
    >>> model.self_pairs
    ((0, 2),)
    """

    def __init__(self, robot: Robot, tool: Tool | None = None, radius: Any = None):
        self.robot = robot
        self.tool = tool
        size = characteristic_length(robot)
        self.default_radius = DEFAULT_RADIUS_FRACTION * size
        limits = robot.joint_limits()
        rng = np.random.default_rng(0)
        probes = np.vstack(
            [
                robot.q,
                np.zeros(robot.n),
                rng.uniform(limits[:, 0], limits[:, 1], (_PROBES, robot.n)),
            ]
        )
        points = _chain_points(robot, probes)
        pairs: list[tuple[int, int]] = []
        last = 0
        for i in range(1, robot.n + 2):
            gap = np.linalg.norm(points[:, i] - points[:, last], axis=1)
            if gap.max() > 1e-9 * size:
                pairs.append((last, i))
                last = i
        self._pairs = np.array(pairs, dtype=np.int64).reshape(-1, 2)
        arm = len(pairs)
        self._tool_ends: np.ndarray
        tool_radii: np.ndarray
        self._tool_ends, tool_radii = (
            tool.segments(self.default_radius)
            if tool is not None
            else (np.zeros((0, 2, 3)), np.zeros(0))
        )
        self.arm_links = arm
        count = arm + len(tool_radii)
        if count == 0:
            raise InvalidInputError(
                "robot", one_line(robot), "a robot with some length (its points all coincide)"
            )
        tool_names = (
            (
                [tool.name]
                if len(tool_radii) == 1
                else [f"{tool.name} {k + 1}" for k in range(len(tool_radii))]
            )
            if tool is not None
            else []
        )
        self.names: tuple[str, ...] = tuple([f"link {k + 1}" for k in range(arm)] + tool_names)
        self.radii = np.concatenate([self._arm_radii(radius, arm), tool_radii])
        self.radii.setflags(write=False)
        moving = np.ptp(points, axis=0).max(axis=1) > 1e-9 * size  # (n + 2,)
        self.static = np.array(
            [not (moving[i] or moving[j]) for i, j in pairs] + [False] * len(tool_radii), dtype=bool
        )
        self.self_pairs = self._find_self_pairs()

    def _arm_radii(self, radius: Any, arm: int) -> np.ndarray:
        out = np.full(arm, self.default_radius)
        if radius is None:
            return out
        if isinstance(radius, Mapping):
            for key, value in radius.items():
                index = self._link_index(key, arm)
                out[index] = self._radius(value, f"radius[{key!r}]")
            return out
        if isinstance(radius, (list, tuple, np.ndarray)):
            if len(radius) != arm:
                raise InvalidInputError(
                    "radius",
                    one_line(radius),
                    f"one number, {arm} numbers (one per link) or a dict",
                )
            return np.array([self._radius(v, f"radius[{k}]") for k, v in enumerate(radius)])
        return np.full(arm, self._radius(radius, "radius"))

    @staticmethod
    def _radius(value: Any, field: str) -> float:
        number = check_finite_number(value, field)
        if not number > 0.0:
            raise InvalidInputError(field, number, "a radius > 0", problem="must be > 0, got")
        return number

    def _link_index(self, key: Any, arm: int) -> int:
        names = [f"link {k + 1}" for k in range(arm)]
        if isinstance(key, str) and key in names:
            return names.index(key)
        if isinstance(key, (int, np.integer)) and not isinstance(key, bool) and 1 <= key <= arm:
            return int(key) - 1
        raise InvalidInputError("radius", one_line(key), f"a link number 1…{arm} or a name {names}")

    def index(self, key: Any, field: str = "link") -> int:
        """A link's position from its number (1…L) or name (``"link 2"``, the tool's)."""
        if isinstance(key, str) and key in self.names:
            return self.names.index(key)
        if (
            isinstance(key, (int, np.integer))
            and not isinstance(key, bool)
            and 1 <= key <= len(self.names)
        ):
            return int(key) - 1
        raise InvalidInputError(
            field, one_line(key), f"a link number 1…{len(self.names)} or one of {self.names}"
        )

    def capsules(self, q: np.ndarray) -> np.ndarray:
        """Segment ends in the robot's base frame, shape (T, L, 2, 3), for q (T, n)."""
        t = q.shape[0]
        points = np.zeros((t, self.robot.n + 2, 3))
        points[:, 1:-1] = self.robot.frame_origins(q)
        if not len(self._tool_ends):
            points[:, -1] = self.robot.end_effector(q)
            return points[:, self._pairs]  # (T, arm, 2, 3)
        flange = self.robot.end_effector_pose(q)  # (T, 4, 4)
        points[:, -1] = flange[:, :3, 3]
        ends = flange[:, :3, :3] @ self._tool_ends.reshape(-1, 3).T + flange[:, :3, 3:]
        tool = np.swapaxes(ends, 1, 2).reshape(t, -1, 2, 3)
        return np.concatenate([points[:, self._pairs], tool], axis=1)

    def _find_self_pairs(self) -> tuple[tuple[int, int], ...]:
        count = len(self.names)
        arm = self.arm_links
        candidates = [
            (i, j)
            for i in range(count)
            for j in range(i + 2, count)
            if not (self.static[i] and self.static[j])
            and not (i >= arm and j >= arm)  # a tool's capsules are one body
            and not (i == arm - 1 and j >= arm)  # the tool sits on the last link
        ]
        if not candidates:
            return ()
        reference = self.capsules(self.robot.q[np.newaxis])[0]
        pairs = np.array(candidates)
        gap = (
            segment_segment_distance(
                reference[pairs[:, 0], 0],
                reference[pairs[:, 0], 1],
                reference[pairs[:, 1], 0],
                reference[pairs[:, 1], 1],
            )
            - self.radii[pairs[:, 0]]
            - self.radii[pairs[:, 1]]
        )
        return tuple((int(i), int(j)) for (i, j), g in zip(candidates, gap, strict=True) if g > 0.0)
