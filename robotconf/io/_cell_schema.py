"""The cell file schema (version 1): plain JSON data ⇄ a work cell, strictly validated.

A cell file lists robots (each a robot object of the robot file format), objects and
frames; every entry names its parent (``null``: the cell). Meshes are stored by their
path relative to the cell file. Reading builds a new cell only after every entry, name
and parent has been checked, so a bad file never leaves a half-loaded cell. Every
error names the JSON path (``objects[2].size[1]``). docs/file-format.md, "Cells",
describes the schema. A robot entry may carry its ``"program"`` (:mod:`._cell_programs`:
the program schema's object, whose moves may name cell frames).
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Literal, overload

import numpy as np

from .._errors import InvalidInputError
from .._json_fields import check_json_number, check_json_object
from .._validation import one_line
from ..cell import (
    MAX_ENTRIES,
    NAME_SEPARATOR,
    SHAPE_KINDS,
    Box,
    Cell,
    Cylinder,
    Mesh,
    Shape,
    Sphere,
    Tool,
)
from ._cell_programs import CellProgram, program_in, program_out
from ._schema import numbers, robot_from_dict, robot_to_dict, text

__all__ = ["CELL_FORMAT", "CELL_VERSION", "cell_to_dict", "cell_from_dict"]

#: The value of a cell file's ``"format"`` key.
CELL_FORMAT = "robotconf-cell"
#: The cell schema version this robotconf writes and the newest it reads.
CELL_VERSION = 1

_TOP = {
    "format": True,
    "version": True,
    "name": False,
    "unit": False,
    "robots": False,
    "objects": False,
    "frames": False,
}
_ROBOT = {
    "name": True,
    "robot": True,
    "base": False,
    "parent": False,
    "tool": False,
    "radius": False,
    "mount": False,
    "program": False,
}
_TOOL = {"name": False, "tcp": False, "capsules": False}
_FRAME = {"name": True, "pose": False, "parent": False}
_SHAPE_FIELDS = {
    "box": {"size": True},
    "cylinder": {"radius": True, "length": True},
    "sphere": {"radius": True},
    "mesh": {"path": False, "scale": False, "vertices": False, "faces": False},
}


def _pose_out(pose: np.ndarray) -> list[list[float]]:
    return [[float(x) for x in row] for row in pose]


def _pose_in(value: Any, path: str) -> np.ndarray:
    if value is None:
        return np.eye(4)
    if not isinstance(value, list) or len(value) != 4:
        raise InvalidInputError(
            path, one_line(value), "4 rows of 4 numbers (a pose)", problem="not a pose:"
        )
    return np.array([numbers(row, f"{path}[{i}]", 4) for i, row in enumerate(value)])


def _mesh_path(mesh: Mesh, folder: Path | None) -> str:
    source = Path(mesh.source)
    if folder is None:
        return source.as_posix()
    try:
        return Path(os.path.relpath(source.resolve(), folder.resolve())).as_posix()
    except ValueError:  # another drive on Windows
        return source.resolve().as_posix()


def _shape_out(shape: Shape, folder: Path | None) -> dict[str, Any]:
    data: dict[str, Any] = {"name": shape.name, "type": shape.kind}
    if isinstance(shape, Box):
        data["size"] = list(shape.size)
    elif isinstance(shape, Cylinder):
        data.update(radius=shape.radius, length=shape.length)
    elif isinstance(shape, Sphere):
        data["radius"] = shape.radius
    elif isinstance(shape, Mesh):
        if shape.source is not None:
            data.update(path=_mesh_path(shape, folder), scale=shape.scale)
        else:
            data.update(vertices=shape.vertices.tolist(), faces=shape.faces.tolist())
    data["pose"] = _pose_out(shape.pose)
    return data


def cell_to_dict(
    cell: Cell, folder: Path | None = None, *, programs: Mapping[str, Any] | None = None
) -> dict[str, Any]:
    """A cell as JSON data; mesh paths relative to ``folder`` (the cell file's).

    ``programs`` maps robot names to a :class:`~robotconf.programs.Program`, a list of
    moves or ``(moves, options)``: written as the robots' ``"program"`` (moves that name
    a cell frame keep its name; a robot without moves gets none).

    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add(rc.Sphere(2, name="ball"))
    'ball'
    >>> cell_to_dict(cell)["objects"][0]["radius"]
    2.0
    """
    programs = dict(programs or {})
    for robot in programs:
        if robot not in cell.robots:
            raise InvalidInputError(
                "programs", one_line(robot), f"robots of the cell: {list(cell.robots)}"
            )
    robots, objects, frames = [], [], []
    for name, entry in cell.entries.items():
        if entry.kind == "robot":
            tool = entry.tool  # type: ignore[attr-defined]
            radius = entry.radius  # type: ignore[attr-defined]
            if isinstance(radius, np.ndarray):
                radius = radius.tolist()
            elif isinstance(radius, Mapping):
                radius = {str(k): float(v) for k, v in radius.items()}
            robots.append(
                {
                    "name": name,
                    "robot": robot_to_dict(entry.robot),  # type: ignore[attr-defined]
                    "base": _pose_out(entry.pose),
                    "parent": entry.parent,
                    "tool": None
                    if tool is None
                    else {
                        "name": tool.name,
                        "tcp": _pose_out(tool.tcp),
                        "capsules": None
                        if tool.capsules is None
                        else [[list(p0), list(p1), r] for p0, p1, r in tool.capsules],
                    },
                    "radius": radius,
                    "mount": list(entry.mount),  # type: ignore[attr-defined]
                }
            )
            program = program_out(programs.get(name), f"programs[{name!r}]")
            if program is not None:
                robots[-1]["program"] = program
        elif entry.kind == "object":
            assert entry.shape is not None
            objects.append({**_shape_out(entry.shape, folder), "parent": entry.parent})
        else:
            own = name if entry.parent is None else name[len(entry.parent) + 1 :]
            frames.append({"name": own, "parent": entry.parent, "pose": _pose_out(entry.pose)})
    return {
        "format": CELL_FORMAT,
        "version": CELL_VERSION,
        "name": cell.name,
        "unit": cell.unit,
        "robots": robots,
        "objects": objects,
        "frames": frames,
    }


def _list(data: Mapping[str, Any], key: str) -> list[Any]:
    value = data.get(key, [])
    if not isinstance(value, list):
        raise InvalidInputError(key, one_line(value), "a list", problem="not a list:")
    return value


def _optional_text(value: Any, path: str) -> str | None:
    return None if value is None else text(value, path)


def _radius(value: Any, path: str) -> Any:
    if value is None:
        return None
    if isinstance(value, list):
        return [check_json_number(v, f"{path}[{i}]") for i, v in enumerate(value[:1000])]
    if isinstance(value, Mapping):
        check_json_object(value, path, {key: False for key in value})
        return {
            text(k, path): check_json_number(v, f"{path}.{k}")
            for k, v in list(value.items())[:1000]
        }
    return check_json_number(value, path)


def _tool(value: Any, path: str) -> Tool | None:
    if value is None:
        return None
    check_json_object(value, path, _TOOL)
    capsules = value.get("capsules")
    if capsules is not None:
        if not isinstance(capsules, list):
            raise InvalidInputError(
                f"{path}.capsules", one_line(capsules), "a list of [p0, p1, radius]"
            )
        capsules = [
            (
                numbers(c[0], f"{path}.capsules[{i}][0]", 3),
                numbers(c[1], f"{path}.capsules[{i}][1]", 3),
                check_json_number(c[2], f"{path}.capsules[{i}][2]"),
            )
            if isinstance(c, list) and len(c) == 3
            else _bad(f"{path}.capsules[{i}]", c, "[p0, p1, radius]")
            for i, c in enumerate(capsules[:100])
        ]
    try:
        return Tool(_pose_in(value.get("tcp"), f"{path}.tcp"), capsules, value.get("name", "tool"))
    except InvalidInputError as error:
        raise (
            error.within(path)
            if not error.field.startswith("tool")
            else InvalidInputError(
                f"{path}{error.field[4:]}", error.value, error.allowed, error.problem
            )
        ) from None


def _bad(path: str, value: Any, allowed: str) -> Any:
    raise InvalidInputError(path, one_line(value), allowed, problem="not:")


def _shape(value: Any, path: str, folder: Path | None) -> Shape:
    kind = value.get("type") if isinstance(value, Mapping) else None
    if kind not in SHAPE_KINDS:
        raise InvalidInputError(
            f"{path}.type",
            one_line(kind),
            " or ".join(repr(k) for k in SHAPE_KINDS),
            problem="unknown object type",
        )
    keys = {"name": True, "type": True, "pose": False, "parent": False, **_SHAPE_FIELDS[kind]}
    check_json_object(value, path, keys)
    name = text(value["name"], f"{path}.name")
    pose = _pose_in(value.get("pose"), f"{path}.pose")
    try:
        if kind == "box":
            return Box(numbers(value["size"], f"{path}.size", 3), pose, name)
        if kind == "cylinder":
            radius = check_json_number(value["radius"], f"{path}.radius")
            return Cylinder(
                radius, check_json_number(value["length"], f"{path}.length"), pose, name
            )
        if kind == "sphere":
            return Sphere(check_json_number(value["radius"], f"{path}.radius"), pose, name)
        return _mesh(value, path, folder, pose, name)
    except InvalidInputError as error:
        if error.field.startswith(path) or error.field == "mesh file":
            raise
        raise error.within(path) from None


def _mesh(
    value: Mapping[str, Any], path: str, folder: Path | None, pose: np.ndarray, name: str
) -> Mesh:
    scale = check_json_number(value.get("scale", 1.0), f"{path}.scale")
    if "path" in value:
        where = Path(text(value["path"], f"{path}.path"))
        full = where if where.is_absolute() or folder is None else folder / where
        try:
            return Mesh.load(full, pose=pose, scale=scale, name=name)
        except InvalidInputError as error:
            raise InvalidInputError(
                f"{path}.path", error.value, error.allowed, error.problem
            ) from None
    if "vertices" not in value or "faces" not in value:
        raise InvalidInputError(
            path, None, "a mesh with a path, or with vertices and faces", problem="missing:"
        )
    vertices, faces = value["vertices"], value["faces"]
    if not isinstance(vertices, list) or not isinstance(faces, list):
        raise InvalidInputError(
            f"{path}.vertices", "<not lists>", "lists of [x, y, z] and [i, j, k]"
        )
    rows = [numbers(v, f"{path}.vertices[{i}]", 3) for i, v in enumerate(vertices)]
    corners = []
    for i, face in enumerate(faces):
        if (
            not isinstance(face, list)
            or len(face) != 3
            or not all(isinstance(k, int) and not isinstance(k, bool) for k in face)
        ):
            raise InvalidInputError(f"{path}.faces[{i}]", one_line(face), "three vertex indices")
        corners.append(face)
    return Mesh(rows, np.array(corners, dtype=np.int64).reshape(-1, 3), pose, name, scale=scale)


def _entries(data: Mapping[str, Any]) -> list[tuple[str, str, str, Any, str | None]]:
    """(full name, kind, path, item, parent) of every entry, names and parents checked."""
    found: list[tuple[str, str, str, Any, str | None]] = []
    for key, kind in (("robots", "robot"), ("objects", "object"), ("frames", "frame")):
        for i, item in enumerate(_list(data, key)):
            path = f"{key}[{i}]"
            if not isinstance(item, Mapping):
                raise InvalidInputError(path, one_line(item), "an object", problem="not an object:")
            own = text(item.get("name"), f"{path}.name")
            if not own.strip() or NAME_SEPARATOR in own:
                raise InvalidInputError(
                    f"{path}.name", own, f"non-empty text without '{NAME_SEPARATOR}'"
                )
            parent = _optional_text(item.get("parent"), f"{path}.parent")
            full = f"{parent}{NAME_SEPARATOR}{own}" if kind == "frame" and parent else own
            found.append((full, kind, path, item, parent))
    if len(found) > MAX_ENTRIES:
        raise InvalidInputError("file", f"<{len(found)} entries>", f"at most {MAX_ENTRIES} entries")
    seen: dict[str, str] = {}
    for full, _, path, _, _ in found:
        if full in seen:
            raise InvalidInputError(
                f"{path}.name",
                full,
                "names used once in the cell",
                problem=f"also the name of {seen[full]}:",
            )
        seen[full] = path
    for _, _, path, _, parent in found:
        if parent is not None and parent not in seen:
            raise InvalidInputError(
                f"{path}.parent",
                parent,
                "the name of a robot, object or frame in the file",
                problem="no such parent:",
            )
    return found


def _order(found: list[tuple[str, str, str, Any, str | None]]) -> list[int]:
    """Parents before children; a cycle of parents is refused."""
    index = {full: k for k, (full, *_rest) in enumerate(found)}
    state = [0] * len(found)  # 0 new, 1 on the path, 2 done
    order: list[int] = []
    for start in range(len(found)):
        path: list[int] = []
        k: int | None = start
        while k is not None and state[k] == 0:
            state[k] = 1
            path.append(k)
            parent = found[k][4]
            k = None if parent is None else index[parent]
            if k is not None and state[k] == 1:
                loop = " → ".join(found[j][0] for j in path[path.index(k) :]) + f" → {found[k][0]}"
                raise InvalidInputError(
                    f"{found[path[-1]][2]}.parent",
                    loop,
                    "parents that lead back to the cell",
                    problem="a cycle of parents:",
                )
        for j in reversed(path):
            state[j] = 2
            order.append(j)
    return order


@overload
def cell_from_dict(
    data: Any, folder: Path | None = None, *, with_programs: Literal[False] = False
) -> Cell: ...
@overload
def cell_from_dict(
    data: Any, folder: Path | None = None, *, with_programs: Literal[True]
) -> tuple[Cell, dict[str, CellProgram]]: ...
def cell_from_dict(
    data: Any, folder: Path | None = None, *, with_programs: bool = False
) -> Cell | tuple[Cell, dict[str, CellProgram]]:
    """A new cell from parsed file data; mesh paths relative to ``folder``.

    With ``with_programs``: ``(cell, {robot name: (moves, options)})`` for the robots
    whose entry has a ``"program"`` (it is checked either way).

    >>> cell = cell_from_dict({"format": "robotconf-cell", "version": 1,
    ...     "objects": [{"name": "ball", "type": "sphere", "radius": 2}]})
    >>> cell.objects["ball"].radius
    2.0
    """
    if not isinstance(data, Mapping):
        raise InvalidInputError(
            "file", one_line(data), "a JSON object", problem="expected an object, got"
        )
    if data.get("format") != CELL_FORMAT:
        raise InvalidInputError(
            "format",
            one_line(data.get("format")),
            f"'{CELL_FORMAT}'",
            problem="not a robotconf cell file:",
        )
    version = data.get("version")
    if isinstance(version, bool) or not isinstance(version, int) or not version >= 1:
        raise InvalidInputError("version", one_line(version), f"an integer 1…{CELL_VERSION}")
    if version > CELL_VERSION:
        raise InvalidInputError(
            "version",
            version,
            f"versions up to {CELL_VERSION}: update robotconf to read it",
            problem="written by a newer robotconf: cell format version",
        )
    check_json_object(data, "file", _TOP)
    found = _entries(data)
    order = _order(found)
    names = {entry[0] for entry in found}
    programs: dict[str, CellProgram] = {}
    built = []  # everything checked before the cell is touched
    for k in order:
        full, kind, path, item, parent = found[k]
        if kind == "robot":
            check_json_object(item, path, _ROBOT)
            mount = item.get("mount", [])
            if not isinstance(mount, list):
                raise InvalidInputError(f"{path}.mount", one_line(mount), "a list of object names")
            robot = robot_from_dict(item["robot"], f"{path}.robot")
            if item.get("program") is not None:
                programs[full] = program_in(item["program"], f"{path}.program", robot, names)
            built.append(
                (
                    kind,
                    path,
                    dict(
                        name=full,
                        robot=robot,
                        base=_pose_in(item.get("base"), f"{path}.base"),
                        parent=parent,
                        tool=_tool(item.get("tool"), f"{path}.tool"),
                        radius=_radius(item.get("radius"), f"{path}.radius"),
                        mount=[
                            text(m, f"{path}.mount[{i}]") for i, m in enumerate(mount[:MAX_ENTRIES])
                        ],
                    ),
                )
            )
        elif kind == "object":
            built.append((kind, path, dict(shape=_shape(item, path, folder), parent=parent)))
        else:
            check_json_object(item, path, _FRAME)
            own = full if parent is None else full[len(parent) + 1 :]
            built.append(
                (
                    kind,
                    path,
                    dict(name=own, pose=_pose_in(item.get("pose"), f"{path}.pose"), parent=parent),
                )
            )
    name = data.get("name")
    cell = Cell(unit=_optional_text(data.get("unit"), "unit"), name=_optional_text(name, "name"))
    for kind, path, values in built:
        try:
            if kind == "robot":
                cell.add_robot(
                    values.pop("name"), values.pop("robot"), values.pop("base"), **values
                )
            elif kind == "object":
                cell.add(values["shape"], parent=values["parent"])
            else:
                cell.add_frame(values["name"], values["pose"], parent=values["parent"])
        except InvalidInputError as error:
            raise error.within(path) from None
    return (cell, programs) if with_programs else cell
