"""A robot's tool: its TCP (tool centre point) and its own capsules."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, check_vector3, one_line
from ._pose import check_cell_name, check_pose

__all__ = ["Tool", "MAX_TOOL_CAPSULES"]

#: The most capsules one tool may have.
MAX_TOOL_CAPSULES = 16


@dataclass(frozen=True, eq=False)
class Tool:
    """A tool on a robot's flange (its end-effector frame): a TCP and its geometry.

    Parameters
    ----------
    tcp : array-like, shape (4, 4), optional
        The TCP in the flange frame (the end-effector point with the last module's
        axes). Programs and reach targets in the cell are for the TCP. Default: the
        flange itself.
    capsules : sequence of (p0, p1, radius), optional
        The tool's body as capsules in the flange frame (points in length units). Default:
        one capsule from the flange to the TCP with the robot's link radius (none when
        the TCP is the flange).
    name : str
        Shown in contacts (``"gripper"``); default ``"tool"``.

    Examples
    --------
    >>> import robotconf as rc
    >>> gripper = rc.Tool(tcp=rc.pose([15, 0, 0]), name="gripper")
    >>> gripper.tcp[:3, 3], gripper.capsules
    (array([15.,  0.,  0.]), None)
    """

    tcp: Any = None
    capsules: Any = None
    name: Any = "tool"

    def __post_init__(self) -> None:
        object.__setattr__(self, "tcp", check_pose(self.tcp, "tool.tcp"))
        object.__setattr__(self, "name", check_cell_name(self.name, "tool.name"))
        if self.capsules is None:
            return
        allowed = f"a list of 1 to {MAX_TOOL_CAPSULES} (p0, p1, radius) in the flange frame"
        if (
            not isinstance(self.capsules, (list, tuple))
            or not 1 <= len(self.capsules) <= MAX_TOOL_CAPSULES
        ):
            raise InvalidInputError(
                "tool.capsules", one_line(self.capsules), allowed, problem="not:"
            )
        checked = []
        for i, item in enumerate(self.capsules):
            field = f"tool.capsules[{i}]"
            if not isinstance(item, (list, tuple)) or len(item) != 3:
                raise InvalidInputError(field, one_line(item), "(p0, p1, radius)", problem="not:")
            p0, p1 = check_vector3(item[0], f"{field}[0]"), check_vector3(item[1], f"{field}[1]")
            radius = check_finite_number(item[2], f"{field}[2]")
            if not radius > 0.0:
                raise InvalidInputError(
                    f"{field}[2]", radius, "a radius > 0", problem="must be > 0:"
                )
            checked.append((p0, p1, radius))
        object.__setattr__(self, "capsules", tuple(checked))

    def segments(self, link_radius: float) -> tuple[np.ndarray, np.ndarray]:
        """The tool's capsules in the flange frame: ends (k, 2, 3) and radii (k,).

        >>> import robotconf as rc
        >>> ends, radii = rc.Tool(tcp=rc.pose([15, 0, 0])).segments(2.0)
        >>> ends.tolist(), radii.tolist()
        ([[[0.0, 0.0, 0.0], [15.0, 0.0, 0.0]]], [2.0])
        """
        if self.capsules is not None:
            ends = np.array([[c[0], c[1]] for c in self.capsules], dtype=float)
            return ends, np.array([c[2] for c in self.capsules], dtype=float)
        tip = self.tcp[:3, 3]
        if not np.any(tip):
            return np.zeros((0, 2, 3)), np.zeros(0)
        return np.array([[np.zeros(3), tip]]), np.array([link_radius])

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Tool):
            return NotImplemented
        return (
            self.name == other.name
            and np.array_equal(self.tcp, other.tcp)
            and self.capsules == other.capsules
        )

    __hash__ = None  # type: ignore[assignment]
