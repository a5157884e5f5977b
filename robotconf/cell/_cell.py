"""The work cell: robots, objects, frames and tools in one frame (docs/cell.md)."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_configuration, one_line
from ..kinematics import Robot
from ._entries import MAX_ENTRIES, Entry, RobotEntry, check_parent, resolve_world_poses
from ._links import LinkModel
from ._pose import NAME_SEPARATOR, check_cell_name, check_pose
from ._shapes import Shape
from ._tool import Tool
from .distance import Obstacle, Obstacles

if TYPE_CHECKING:
    from ._answers import CellCheck, CellRun, Clearance, Placement, Reach, ReachMap

__all__ = ["Cell"]


class Cell:
    """A work cell: robots on their bases, objects (a table, fixtures), frames and tools.

    Everything is placed in the cell's frame or on a parent (a robot, an object or a
    frame) and moves with it. Lengths are the robots' length unit (``unit`` names it in
    messages), angles radians.

    Parameters
    ----------
    unit : str, optional
        The length unit, shown in sentences (``"4.2 mm deep"``).
    name : str, optional

    Examples
    --------
    The paper's arm (mm) beside a table with a fixture and a pick point:

    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> cell.add(rc.Box([60, 80, 4], pose=rc.pose([55, 0, -2]), name="table"))
    'table'
    >>> cell.add(rc.Box([10, 10, 20], pose=rc.pose([0, 25, 10])), parent="table")
    'box1'
    >>> cell.add_frame("pick", rc.pose([0, 0, 32]), parent="table")
    'table/pick'
    >>> cell.pose_of("table/pick")[:3, 3]
    array([55.,  0., 30.])
    >>> print(cell.clearance("arm", [0, 0, 0]))
    clearance 16.4 mm: arm link 2 – table
    """

    def __init__(self, *, unit: str | None = None, name: str | None = None):
        if unit is not None and not isinstance(unit, str):
            raise InvalidInputError("unit", one_line(unit), "text such as 'mm', or None")
        self.unit = unit
        self.name = name
        self._entries: dict[str, Entry] = {}
        self._cache: dict[str, Any] = {}

    # -- building --------------------------------------------------------------------

    def _add_entry(self, entry: Entry) -> str:
        if entry.name in self._entries:
            raise InvalidInputError(
                "name", entry.name, "a name not yet in the cell", problem="already in the cell:"
            )
        if len(self._entries) >= MAX_ENTRIES:
            raise InvalidInputError(
                "name", entry.name, f"at most {MAX_ENTRIES} entries", "the cell is full:"
            )
        self._entries[entry.name] = entry
        self._cache.clear()
        return entry.name

    def add_robot(
        self,
        name: str,
        robot: Robot,
        base: Any = None,
        *,
        tool: Tool | None = None,
        radius: Any = None,
        mount: Any = (),
        parent: str | None = None,
    ) -> None:
        """Place a robot.

        Parameters
        ----------
        name : str
        robot : Robot
        base : array-like, shape (4, 4), optional
            Its base frame in the parent's frame (``rc.pose(xyz, rpy)``).
        tool : Tool, optional
            TCP and tool geometry on the flange.
        radius : float, sequence or dict, optional
            Link radii (see :class:`~robotconf.cell._links.LinkModel`); default 4 % of
            the robot's size.
        mount : str or sequence of str
            Objects the robot stands on: its base links (those no joint moves) may touch
            them.
        parent : str, optional
            An object or frame the robot stands on (it moves with it).
        """
        name = check_cell_name(name, "name")
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", one_line(robot), "a Robot", problem="not a robot:")
        if tool is not None and not isinstance(tool, Tool):
            raise InvalidInputError(
                "tool", one_line(tool), "rc.Tool(…) or None", problem="not a tool:"
            )
        mounts = (mount,) if isinstance(mount, str) else tuple(mount)
        for m in mounts:
            check_cell_name(m, "mount")
        entry = RobotEntry(
            name,
            "robot",
            check_pose(base, "base"),
            check_parent(self._entries, parent, "parent"),
            robot=robot,
            tool=tool,
            radius=radius,
            mount=mounts,
            links=LinkModel(robot, tool, radius),
        )
        self._add_entry(entry)

    def add(self, shape: Shape, *, parent: str | None = None) -> str:
        """Add an object (``rc.Box``, ``rc.Cylinder``, ``rc.Sphere``, ``rc.Mesh``); returns its
        name.

        Its pose is in the parent's frame (default: the cell's). An unnamed object is
        called ``"box1"``, ``"box2"``, … by kind.
        """
        if not isinstance(shape, Shape):
            raise InvalidInputError(
                "shape", one_line(shape), "rc.Box, rc.Cylinder, rc.Sphere or rc.Mesh"
            )
        name = shape.name
        if name is None:
            count = 1
            while f"{shape.kind}{count}" in self._entries:
                count += 1
            name = f"{shape.kind}{count}"
            shape = shape.with_name(name)
        entry = Entry(
            name, "object", shape.pose, check_parent(self._entries, parent, "parent"), shape
        )
        return self._add_entry(entry)

    def add_frame(self, name: str, pose: Any = None, *, parent: str | None = None) -> str:
        """Add a named frame (a pick point, an approach pose); returns its full name.

        With a parent the full name is ``"parent/name"`` and the frame moves with it.
        """
        own = check_cell_name(name, "name")
        up = check_parent(self._entries, parent, "parent")
        full = own if up is None else f"{up}{NAME_SEPARATOR}{own}"
        return self._add_entry(Entry(full, "frame", check_pose(pose, "pose"), up))

    def set_pose(self, name: str, pose: Any) -> None:
        """Move a robot's base, an object or a frame (in its parent's frame)."""
        entry = self._entry(name)
        entry.pose = check_pose(pose, "pose")
        if entry.shape is not None:
            entry.shape = entry.shape.with_pose(entry.pose)
        self._cache.clear()

    def remove(self, name: str) -> None:
        """Remove an entry; refused while other entries are placed on it."""
        self._entry(name)
        children = [e.name for e in self._entries.values() if e.parent == name]
        if children:
            raise InvalidInputError(
                "name",
                name,
                f"an entry without children (on it: {children[:5]})",
                problem="other entries are placed on",
            )
        del self._entries[name]
        self._cache.clear()

    # -- reading ---------------------------------------------------------------------

    def _entry(self, name: Any, field: str = "name") -> Entry:
        if not isinstance(name, str) or name not in self._entries:
            raise InvalidInputError(
                field,
                one_line(name),
                f"one of {sorted(self._entries)[:20]}",
                problem="not in the cell:",
            )
        return self._entries[name]

    def robot_entry(self, name: Any = None) -> RobotEntry:
        """The entry of a robot (the only one when ``name`` is None)."""
        robots = self.robots
        if name is None:
            if len(robots) != 1:
                raise InvalidInputError(
                    "robot",
                    None,
                    f"one of {list(robots)}",
                    problem="the cell has several robots (or none): name one;",
                )
            name = robots[0]
        entry = self._entry(name, "robot")
        if not isinstance(entry, RobotEntry):
            raise InvalidInputError("robot", name, f"one of {list(robots)}", problem="not a robot:")
        return entry

    def robot(self, name: Any = None) -> Robot:
        """The :class:`Robot` placed as ``name``."""
        robot = self.robot_entry(name).robot
        assert robot is not None
        return robot

    @property
    def robots(self) -> tuple[str, ...]:
        """Names of the robots."""
        return tuple(n for n, e in self._entries.items() if e.kind == "robot")

    @property
    def objects(self) -> dict[str, Shape]:
        """The objects by name (their poses in their parents' frames)."""
        return {n: e.shape for n, e in self._entries.items() if e.shape is not None}

    @property
    def frames(self) -> tuple[str, ...]:
        """Full names of the frames."""
        return tuple(n for n, e in self._entries.items() if e.kind == "frame")

    @property
    def entries(self) -> dict[str, Entry]:
        """Every entry by name (a copy of the mapping)."""
        return dict(self._entries)

    def parent_of(self, name: str) -> str | None:
        """The entry ``name`` is placed on (None: the cell)."""
        return self._entry(name).parent

    def _world(self) -> dict[str, np.ndarray]:
        if "world" not in self._cache:
            self._cache["world"] = resolve_world_poses(self._entries)
        world: dict[str, np.ndarray] = self._cache["world"]
        return world

    def pose_of(self, name: str) -> np.ndarray:
        """The pose of a robot's base, an object or a frame in the cell's frame, (4, 4)."""
        self._entry(name)
        return self._world()[name].copy()

    def obstacles(self) -> tuple[Obstacles, tuple[str, ...]]:
        """The objects in the cell's frame, arranged for the distance queries, and their names."""
        if "obstacles" not in self._cache:
            world = self._world()
            items, names = [], []
            for name, shape in self.objects.items():
                pose = world[name]
                if shape.kind == "box":
                    params = np.array(shape.size)  # type: ignore[attr-defined]
                elif shape.kind == "cylinder":
                    params = np.array([shape.radius, shape.length])  # type: ignore[attr-defined]
                elif shape.kind == "sphere":
                    params = np.array([shape.radius])  # type: ignore[attr-defined]
                else:
                    tri = shape.triangles  # type: ignore[attr-defined]
                    params = np.einsum("ij,fkj->fki", pose[:3, :3], tri) + pose[:3, 3]
                items.append(
                    Obstacle(shape.kind, pose, params, shape.bounding_radius, shape.inner_radius)
                )
                names.append(name)
            self._cache["obstacles"] = (Obstacles(items), tuple(names))
        cached: tuple[Obstacles, tuple[str, ...]] = self._cache["obstacles"]
        return cached

    def _robot_entries(self) -> dict[str, RobotEntry]:
        return {n: e for n, e in self._entries.items() if isinstance(e, RobotEntry)}

    def coordinates(self, robot: str | None, q: Any) -> np.ndarray:
        """``q`` for a robot as (T, n) (one configuration gives T = 1)."""
        model = self.robot(robot)
        allowed = f"{model.n} coordinates, or (T, {model.n}) of them"
        if np.ndim(q) == 2:
            array = as_float_array(q, "q", allowed)
            if array.shape[1] != model.n:
                raise InvalidInputError("q", f"<array of shape {array.shape}>", allowed)
            check_memory_rows(array)
            if not np.all(np.isfinite(array)):
                raise InvalidInputError("q", "<array with NaN or inf>", "finite coordinates")
            return array
        return check_configuration(q, model.n, model.coordinate_names, "q")[np.newaxis]

    # -- geometry ----------------------------------------------------------------------

    def link_names(self, robot: str | None = None) -> tuple[str, ...]:
        """The names of a robot's capsules: ``"link 1"``, …, then its tool's."""
        links = self.robot_entry(robot).links
        assert links is not None
        return links.names

    def link_capsules(
        self, robot: str | None = None, q: Any = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """A robot's capsules in the cell's frame.

        Parameters
        ----------
        robot : str, optional
            Its name (may be left out when the cell has one robot).
        q : array-like, shape (n,) or (T, n), optional
            Coordinates; default the robot's own ``q``.

        Returns
        -------
        segments : ndarray, shape (L, 2, 3) or (T, L, 2, 3)
            Each link's segment ends (length units, cell frame).
        radii : ndarray, shape (L,)

        Examples
        --------
        >>> import robotconf as rc
        >>> cell = rc.Cell()
        >>> cell.add_robot("arm", rc.preset("paper"), base=rc.pose([0, 0, 10]))
        >>> segments, radii = cell.link_capsules("arm", [0, 0, 0])
        >>> segments[:, 1]  # where each link ends
        array([[ 0.,  0., 30.],
               [30.,  0., 30.],
               [70.,  0., 30.]])
        """
        from ._pairs import cell_capsules

        entry = self.robot_entry(robot)
        assert entry.robot is not None and entry.links is not None
        given = entry.robot.q if q is None else q
        array = self.coordinates(entry.name, given)
        segments = cell_capsules(entry, self._world()[entry.name], array)
        single = np.ndim(given) == 1
        return (segments[0] if single else segments), entry.links.radii.copy()

    # -- questions ---------------------------------------------------------------------

    def clearance(
        self, robot: str | None = None, q: Any = None, *, others: Any = None
    ) -> Clearance:
        """The smallest signed distance of a robot to everything else, and the pair.

        See :func:`robotconf.cell._clearance.clearance`.
        """
        from ._clearance import clearance

        return clearance(self, robot, q, others)

    def check(
        self, motion: Any, robot: str | None = None, *, margin: float = 0.0, dt: float = 0.01
    ) -> CellCheck:
        """Every contact along a motion or program (see :func:`robotconf.cell._check.check`)."""
        from ._check import check

        return check(self, motion, robot, margin=margin, dt=dt)

    def reach(self, robot: str | None = None, targets: Any = None, **options: Any) -> Reach:
        """Which targets a robot reaches, by how many branches (see :mod:`._reach`)."""
        from ._reach import reach

        return reach(self, robot, targets, **options)

    def reach_map(
        self, robot: str | None = None, region: Any = None, step: Any = None, **options: Any
    ) -> ReachMap:
        """Branches and manipulability on a voxel grid (see :mod:`._reach_map`)."""
        from ._reach_map import reach_map

        return reach_map(self, robot, region, step, **options)

    def place(
        self, robot: str | None = None, targets: Any = None, region: Any = None, **options: Any
    ) -> Placement:
        """Base positions from which every target is reachable, and the best one."""
        from ._reach_map import place

        return place(self, robot, targets, region, **options)

    def program(self, robot: str | None, moves: Any, **options: Any) -> Any:
        """A :class:`~robotconf.programs.Program` for a robot, with cell frames resolved."""
        from ._run import cell_program

        return cell_program(self, robot, moves, **options)

    def run(self, programs: Any, *, dt: float = 0.01, margin: float = 0.0) -> CellRun:
        """Plan every robot's program, check contacts, report the cycle time."""
        from ._run import run

        return run(self, programs, dt=dt, margin=margin)

    # -- files -------------------------------------------------------------------------

    def to_json(self, path: str | os.PathLike[str] | None = None, indent: int | None = 2) -> str:
        """The cell file's text (docs/file-format.md, "Cells"); ``path`` anchors mesh paths."""
        from ..io import cell_to_json

        return cell_to_json(self, path, indent)

    def save(self, path: str | os.PathLike[str]) -> Any:
        """Write the cell file (meshes by their path relative to it); returns the path."""
        from ..io import save_cell

        return save_cell(self, path)

    def __repr__(self) -> str:
        kinds = {
            k: sum(e.kind == k for e in self._entries.values())
            for k in ("robot", "object", "frame")
        }
        unit = f", unit={self.unit!r}" if self.unit else ""
        robots, objects, frames = kinds["robot"], kinds["object"], kinds["frame"]
        return f"Cell({robots} robots, {objects} objects, {frames} frames{unit})"


def check_memory_rows(array: np.ndarray) -> None:
    """Refuse more coordinate rows than the cell's queries are sized for."""
    from ._limits import MAX_SAMPLES

    if array.shape[0] > MAX_SAMPLES:
        raise InvalidInputError(
            "q", f"<{array.shape[0]} rows>", f"at most {MAX_SAMPLES} configurations"
        )
