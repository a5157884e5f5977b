"""What the cell's questions answer: clearances, contacts, reach, maps, placements, runs.

Plain results with a sentence each (``str``) and, where it helps, a pandas ``table``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from ..programs import Program, ProgramMotion, ProgramReport

if TYPE_CHECKING:
    import pandas as pd

__all__ = [
    "format_length",
    "Clearance",
    "Contact",
    "CellCheck",
    "Reach",
    "ReachMap",
    "Placement",
    "CellRun",
]


def format_length(value: float, unit: str | None) -> str:
    """``4.2 mm`` (3 significant digits, at least one decimal for small values)."""
    text = f"{value:.3g}"
    return f"{text} {unit}" if unit else text


@dataclass(frozen=True)
class Clearance:
    """The smallest signed distance of a robot, per configuration, and the pair.

    Attributes
    ----------
    distance : float or ndarray, shape (T,)
        Signed distance (length units): > 0 apart, < 0 the penetration depth. ``inf``
        when there is nothing to meet.
    link : str or tuple of str
        The robot's capsule of the closest pair (``"link 3"``, the tool's name).
    other : str or tuple of str
        What it meets: an object's name, ``"link 1"`` of the same robot, or
        ``"robot2/link 4"``.
    kind : str or tuple of str
        ``"object"``, ``"self"`` or ``"robot"``.
    robot : str
    unit : str or None
    """

    distance: Any
    link: Any
    other: Any
    kind: Any
    robot: str
    unit: str | None = None

    @property
    def collides(self) -> Any:
        """``distance < 0``."""
        return np.asarray(self.distance) < 0.0

    def __str__(self) -> str:
        if np.ndim(self.distance) == 0:
            if not np.isfinite(self.distance):
                return f"clearance: {self.robot} meets nothing"
            gap = format_length(float(self.distance), self.unit)
            return f"clearance {gap}: {self.robot} {self.link} – {self.other}"
        k = int(np.argmin(self.distance))
        head = f"clearance over {len(self.distance)} configurations, least at #{k}: "
        return (
            head
            + format_length(float(self.distance[k]), self.unit)
            + f": {self.robot} {self.link[k]} – {self.other[k]}"
        )


@dataclass(frozen=True)
class Contact:
    """One contact interval of one pair.

    Attributes
    ----------
    robot, link : str
        The robot and its capsule.
    other : str
        An object, the same robot's link, or ``"robot/link k"``.
    kind : str
        ``"object"``, ``"self"`` or ``"robot"``.
    start, end : float
        Times of the first and last sample in contact (s).
    depth : float
        The deepest penetration over the interval (length units, > 0 when penetrating;
        with a margin, ``−`` the least distance).
    deepest : float
        When it is deepest (s).
    move : int or None
        The program move running at ``start`` (from 1), when the motion is a program's.
    move_kind : str or None
        ``"PTP"``, ``"LIN"``, ``"CIRC"`` or ``"Wait"``.
    message : str
        The sentence, e.g. ``move 3 (LIN): link 4 enters 'fixture' at t = 2.31 s, 4.2 mm deep``.
    """

    robot: str
    link: str
    other: str
    kind: str
    start: float
    end: float
    depth: float
    deepest: float
    move: int | None
    move_kind: str | None
    message: str


@dataclass(frozen=True)
class CellCheck:
    """What ``cell.check`` found.

    Attributes
    ----------
    contacts : tuple of Contact
        In order of start time.
    t : ndarray, shape (T,)
        Sample times (s).
    min_clearance : float
        The least signed distance over the motion (exact); ``min_time`` when,
        ``min_pair`` (robot, link, other). Each sample's least distance is
        ``cell.clearance(robot, motion.q)`` (it measures more pairs exactly).
    more : int
        Contact intervals beyond :data:`MAX_CONTACTS` (not listed).
    unit : str or None
    """

    contacts: tuple[Contact, ...]
    t: np.ndarray
    min_clearance: float
    min_time: float
    min_pair: tuple[str, str, str]
    more: int = 0
    unit: str | None = None

    @property
    def ok(self) -> bool:
        """No contact."""
        return not self.contacts

    def __len__(self) -> int:
        return len(self.contacts)

    def __iter__(self):  # type: ignore[no-untyped-def]
        return iter(self.contacts)

    @property
    def sentences(self) -> list[str]:
        """One sentence per contact, then the least clearance."""
        lines = [c.message for c in self.contacts]
        if self.more:
            lines.append(f"… and {self.more} more contact intervals")
        if np.isfinite(self.min_clearance):
            robot, link, other = self.min_pair
            lines.append(
                f"least clearance {format_length(self.min_clearance, self.unit)} at "
                f"t = {self.min_time:.3f} s: {robot} {link} – {other}"
            )
        return lines

    def __str__(self) -> str:
        head = "no contact" if self.ok else f"{len(self.contacts) + self.more} contact(s)"
        return "\n".join([head, *self.sentences])

    @property
    def table(self) -> pd.DataFrame:
        """The contacts as a pandas table, one row per interval."""
        import pandas as pd

        columns = [
            "robot",
            "link",
            "other",
            "kind",
            "start",
            "end",
            "depth",
            "deepest",
            "move",
            "move_kind",
        ]
        rows = [[getattr(c, k) for k in columns] for c in self.contacts]
        return pd.DataFrame(rows, columns=columns)


@dataclass(frozen=True)
class Reach:
    """Per target: reachable or not, how many branches, the best one, and why not.

    Attributes
    ----------
    targets : tuple of str
        Labels (a frame's name, or the point).
    reachable : ndarray of bool, shape (K,)
        Some branch is within the limits and collision-free.
    branches : ndarray of int, shape (K,)
        Closed-form solutions (``len(rc.ik_all(...))``).
    within_limits : ndarray of int, shape (K,)
        Of those, within the joint limits.
    collision_free : ndarray of int, shape (K,)
        Of those, with clearance ≥ ``margin``.
    manipulability : ndarray, shape (K,)
        The best collision-free branch's; NaN when unreachable.
    q : ndarray, shape (K, n)
        That branch (NaN when unreachable).
    clearance : ndarray, shape (K,)
        The largest clearance of a collision-free branch (``inf`` with nothing near;
        NaN when unreachable).
    labels : tuple of tuple of str
        The collision-free branches' names (``"elbow up"``).
    reasons : tuple of str
        Why not, ``""`` when reachable.
    """

    targets: tuple[str, ...]
    reachable: np.ndarray
    branches: np.ndarray
    within_limits: np.ndarray
    collision_free: np.ndarray
    manipulability: np.ndarray
    q: np.ndarray
    clearance: np.ndarray
    labels: tuple[tuple[str, ...], ...]
    reasons: tuple[str, ...]

    def __len__(self) -> int:
        return len(self.targets)

    @property
    def all_reachable(self) -> bool:
        """Every target is reachable."""
        return bool(np.all(self.reachable))

    def __str__(self) -> str:
        lines = []
        for k, name in enumerate(self.targets):
            if self.reachable[k]:
                lines.append(
                    f"{name}: reachable, {self.collision_free[k]} of {self.branches[k]} branches "
                    f"({', '.join(self.labels[k])}), manipulability {self.manipulability[k]:.3g}"
                )
            else:
                lines.append(f"{name}: not reachable: {self.reasons[k]}")
        return "\n".join(lines)

    @property
    def table(self) -> pd.DataFrame:
        """One row per target."""
        import pandas as pd

        return pd.DataFrame(
            {
                "target": self.targets,
                "reachable": self.reachable,
                "branches": self.branches,
                "within_limits": self.within_limits,
                "collision_free": self.collision_free,
                "manipulability": self.manipulability,
                "reason": self.reasons,
            }
        )


@dataclass(frozen=True)
class ReachMap:
    """Reach on a voxel grid.

    Attributes
    ----------
    points : ndarray, shape (V, 3)
        Voxel centres (cell frame), x slowest, z fastest.
    shape : (nx, ny, nz)
    branches : ndarray of int, shape (V,)
        Collision-free branches within the limits at each voxel.
    manipulability : ndarray, shape (V,)
        The best such branch's (NaN where unreachable).
    reach : Reach
        Everything per voxel (all branches, within limits, reasons).
    """

    points: np.ndarray
    shape: tuple[int, int, int]
    branches: np.ndarray
    manipulability: np.ndarray
    reach: Reach

    @property
    def reachable(self) -> np.ndarray:
        """Voxels with at least one usable branch, shape (V,)."""
        return self.branches > 0

    def grid(self, what: str = "branches") -> np.ndarray:
        """``"branches"`` or ``"manipulability"`` as an (nx, ny, nz) array."""
        if what not in ("branches", "manipulability"):
            raise InvalidInputError("what", what, "'branches' or 'manipulability'")
        return getattr(self, what).reshape(self.shape)

    def __str__(self) -> str:
        count = int(self.reachable.sum())
        most = int(self.branches.max())
        return f"reach map: {count} of {len(self.points)} voxels reachable, up to {most} branches"


@dataclass(frozen=True)
class Placement:
    """Candidate base positions and the best one.

    Attributes
    ----------
    positions : ndarray, shape (B, 3)
        Base origins tried (cell frame).
    shape : (nx, ny, nz)
    feasible : ndarray of bool, shape (B,)
        Every target reachable from there.
    reached : ndarray of int, shape (B,)
        How many targets are reachable.
    margin : ndarray, shape (B,)
        Least over the targets of the best branch's clearance (NaN where not feasible).
    manipulability : ndarray, shape (B,)
        Least over the targets of the best branch's manipulability.
    best : int or None
        Index of the best feasible base; ``best_pose`` its base pose (cell frame).
    unit : str or None
    """

    positions: np.ndarray
    shape: tuple[int, int, int]
    feasible: np.ndarray
    reached: np.ndarray
    margin: np.ndarray
    manipulability: np.ndarray
    best: int | None
    best_pose: np.ndarray | None
    unit: str | None = None

    def __str__(self) -> str:
        count = int(self.feasible.sum())
        head = f"{count} of {len(self.positions)} base positions reach every target"
        if self.best is None:
            return head + f"; the best reaches {int(self.reached.max())} of them"
        where = ", ".join(f"{v:.4g}" for v in self.positions[self.best])
        return (
            head
            + f"; best at ({where}), clearance {format_length(self.margin[self.best], self.unit)}"
        )


@dataclass(frozen=True)
class CellRun:
    """Every robot's program run at once, checked against the cell and each other.

    Attributes
    ----------
    programs : dict of Program
    motions : dict of ProgramMotion
    reports : dict of ProgramReport
        Each program's own check (joint limits, speeds, singularities).
    check : CellCheck
        Contacts of all robots side by side in time.
    cycle_time : float
        The longest program's duration (s).
    """

    programs: dict[str, Program]
    motions: dict[str, ProgramMotion]
    reports: dict[str, ProgramReport]
    check: CellCheck
    cycle_time: float

    @property
    def ok(self) -> bool:
        """No contact and no program violation."""
        return self.check.ok and all(r.ok for r in self.reports.values())

    def __str__(self) -> str:
        each = ", ".join(f"{name}: {p.duration:.3g} s" for name, p in self.programs.items())
        lines = [f"cycle time {self.cycle_time:.3g} s ({each})"]
        for name, report in self.reports.items():
            if not report.ok:
                lines.append(
                    f"{name}: {len(report)} program violation(s), "
                    f"first: {report.violations[0].message}"
                )
        lines.append(str(self.check))
        return "\n".join(lines)
