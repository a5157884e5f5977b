"""The cell's solid objects: boxes, cylinders, spheres and triangle meshes.

Shapes follow URDF: each is centred at its pose, a box's ``size`` is its full edge
lengths along the pose's x, y and z axes, and a cylinder's axis is the pose's z axis
(``length`` along it). A mesh is its triangles (a surface) given in its own frame.
Lengths are in the robot's length unit; every size is finite, > 0 and ≤ 1e150.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any, ClassVar

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_finite_number, check_vector3, one_line
from ..kinematics import MAX_PARAMETER
from ._pose import check_cell_name, check_pose

__all__ = ["Shape", "Box", "Cylinder", "Sphere", "Mesh", "SHAPE_KINDS", "MAX_TRIANGLES"]

#: The most triangles one mesh may have (a teaching cell's fixture needs a few thousand).
MAX_TRIANGLES = 200_000


def _size(value: Any, field: str) -> float:
    number = check_finite_number(value, field)
    if not 0.0 < number <= MAX_PARAMETER:
        raise InvalidInputError(
            field, number, f"a length > 0 and ≤ {MAX_PARAMETER:g}", problem="out of range:"
        )
    return number


class Shape:
    """Base of the cell's objects: a ``pose`` (4×4, in its parent's frame) and a ``name``.

    Two shapes are equal when they are of one kind with equal numbers.
    """

    kind: ClassVar[str] = ""
    pose: Any
    name: Any

    def _check_common(self) -> None:
        object.__setattr__(self, "pose", check_pose(self.pose, "pose"))
        if self.name is not None:
            object.__setattr__(self, "name", check_cell_name(self.name, "name"))

    def _numbers(self) -> tuple[Any, ...]:
        raise NotImplementedError

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        assert isinstance(other, Shape)
        mine, theirs = (
            (self._numbers(), self.pose.tobytes()),
            (other._numbers(), other.pose.tobytes()),
        )
        return self.name == other.name and mine == theirs

    __hash__ = None  # type: ignore[assignment]

    @property
    def bounding_radius(self) -> float:
        """Radius of a ball about the pose's origin that holds the whole shape."""
        raise NotImplementedError

    @property
    def inner_radius(self) -> float:
        """Radius of a ball about the pose's origin that lies inside the shape (≤ 0: none)."""
        raise NotImplementedError

    def with_pose(self, pose: Any) -> Shape:
        """A copy at another pose.

        >>> Sphere(1.0).with_pose(np.eye(4)).radius
        1.0
        """
        return replace(self, pose=pose)  # type: ignore[type-var]

    def with_name(self, name: str) -> Shape:
        """A copy with another name."""
        return replace(self, name=name)  # type: ignore[type-var]


@dataclass(frozen=True, eq=False)
class Box(Shape):
    """A box centred at its pose, with full edge lengths ``size`` along its x, y, z.

    Parameters
    ----------
    size : array-like, shape (3,)
        Edge lengths (length units, > 0).
    pose : array-like, shape (4, 4), optional
        Its centre and axes in its parent's frame (default: the cell's frame).
    name : str, optional
        Default ``"box1"``, ``"box2"``, … when added to a cell.

    Examples
    --------
    >>> import robotconf as rc
    >>> table = rc.Box([100, 60, 2], pose=rc.pose([0, 0, -1]), name="table")
    >>> table.size, round(table.bounding_radius, 3)
    ((100.0, 60.0, 2.0), 58.318)
    """

    kind: ClassVar[str] = "box"
    size: Any = (1.0, 1.0, 1.0)
    pose: Any = None
    name: Any = None

    def __post_init__(self) -> None:
        size = check_vector3(self.size, "size")
        object.__setattr__(self, "size", tuple(_size(s, f"size[{i}]") for i, s in enumerate(size)))
        self._check_common()

    def _numbers(self) -> tuple[Any, ...]:
        return self.size

    @property
    def bounding_radius(self) -> float:
        return 0.5 * float(np.linalg.norm(self.size))

    @property
    def inner_radius(self) -> float:
        return 0.5 * min(self.size)


@dataclass(frozen=True, eq=False)
class Cylinder(Shape):
    """A solid cylinder centred at its pose, its axis along the pose's z.

    Parameters
    ----------
    radius : float
        Radius (> 0).
    length : float
        Full length along the axis (> 0).
    pose, name
        As for :class:`Box` (default name ``"cylinder1"``, …).

    Examples
    --------
    >>> import robotconf as rc
    >>> rc.Cylinder(5, 20, pose=rc.pose([40, 0, 10])).inner_radius
    5.0
    """

    kind: ClassVar[str] = "cylinder"
    radius: Any = 1.0
    length: Any = 1.0
    pose: Any = None
    name: Any = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", _size(self.radius, "radius"))
        object.__setattr__(self, "length", _size(self.length, "length"))
        self._check_common()

    def _numbers(self) -> tuple[Any, ...]:
        return (self.radius, self.length)

    @property
    def bounding_radius(self) -> float:
        return float(np.hypot(self.radius, 0.5 * self.length))

    @property
    def inner_radius(self) -> float:
        return min(self.radius, 0.5 * self.length)


@dataclass(frozen=True, eq=False)
class Sphere(Shape):
    """A ball of ``radius`` centred at its pose (default name ``"sphere1"``, …).

    >>> import robotconf as rc
    >>> rc.Sphere(3, pose=rc.pose([50, 0, 30])).bounding_radius
    3.0
    """

    kind: ClassVar[str] = "sphere"
    radius: Any = 1.0
    pose: Any = None
    name: Any = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", _size(self.radius, "radius"))
        self._check_common()

    def _numbers(self) -> tuple[Any, ...]:
        return (self.radius,)

    @property
    def bounding_radius(self) -> float:
        return self.radius

    @property
    def inner_radius(self) -> float:
        return self.radius


@dataclass(frozen=True, eq=False)
class Mesh(Shape):
    """A triangle mesh in its own frame, placed by its pose (default name ``"mesh1"``, …).

    A mesh is its surface: its distance to a link is the least over its triangles, and a
    link that passes through a triangle penetrates it (a link wholly inside a closed mesh,
    touching no triangle, is not seen). Load STL or OBJ files with :meth:`load`.

    Parameters
    ----------
    vertices : array-like, shape (V, 3)
        Vertex positions (length units), already scaled.
    faces : array-like of int, shape (F, 3)
        Vertex indices of each triangle, 1 ≤ F ≤ :data:`MAX_TRIANGLES`.
    pose, name
        As for :class:`Box`.
    source : str, optional
        The file it was read from (a cell file stores this path, relative to itself).
    scale : float
        The factor the file's coordinates were multiplied by (kept for the cell file).

    Examples
    --------
    >>> import robotconf as rc
    >>> tetra = rc.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                 [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> tetra.triangles.shape
    (4, 3, 3)
    """

    kind: ClassVar[str] = "mesh"
    vertices: Any = None
    faces: Any = None
    pose: Any = None
    name: Any = None
    source: Any = None
    scale: Any = 1.0

    def __post_init__(self) -> None:
        vertices = as_float_array(self.vertices, "vertices", "an (V, 3) array of numbers")
        if vertices.ndim != 2 or vertices.shape[1:] != (3,) or vertices.shape[0] < 3:
            raise InvalidInputError(
                "vertices", one_line(self.vertices), "an (V, 3) array, V ≥ 3", problem="shape:"
            )
        if not np.all(np.isfinite(vertices)) or np.abs(vertices).max() > MAX_PARAMETER:
            raise InvalidInputError(
                "vertices", "<non-finite or huge coordinates>", f"finite, |x| ≤ {MAX_PARAMETER:g}"
            )
        faces = np.asarray(self.faces) if self.faces is not None else np.zeros((0, 3))
        if faces.ndim != 2 or faces.shape[1:] != (3,) or not 1 <= faces.shape[0] <= MAX_TRIANGLES:
            raise InvalidInputError(
                "faces",
                f"<array of shape {faces.shape}>",
                f"an (F, 3) array of vertex indices, 1 ≤ F ≤ {MAX_TRIANGLES}",
                problem="shape:",
            )
        if faces.dtype.kind not in "iu" or faces.min() < 0 or faces.max() >= len(vertices):
            raise InvalidInputError(
                "faces", one_line(faces[:3]), f"integers from 0 to {len(vertices) - 1}"
            )
        vertices = np.ascontiguousarray(vertices, dtype=float)
        faces = np.ascontiguousarray(faces, dtype=np.int64)
        vertices.setflags(write=False)
        faces.setflags(write=False)
        object.__setattr__(self, "vertices", vertices)
        object.__setattr__(self, "faces", faces)
        object.__setattr__(self, "scale", _size(self.scale, "scale"))
        if self.source is not None and not isinstance(self.source, str):
            raise InvalidInputError("source", one_line(self.source), "a path as text, or None")
        self._check_common()

    def _numbers(self) -> tuple[Any, ...]:
        return (self.vertices.tobytes(), self.faces.tobytes(), self.source, self.scale)

    @property
    def triangles(self) -> np.ndarray:
        """Corner positions of every triangle in the mesh's frame, shape (F, 3, 3)."""
        return self.vertices[self.faces]

    @property
    def bounding_radius(self) -> float:
        return float(np.max(np.linalg.norm(self.vertices, axis=1)))

    @property
    def inner_radius(self) -> float:
        # A surface holds no ball; the nearest vertex is within the bounding radius.
        return -self.bounding_radius

    @classmethod
    def load(
        cls,
        path: str | os.PathLike[str],
        *,
        pose: Any = None,
        scale: Any = 1.0,
        name: Any = None,
    ) -> Mesh:
        """Read an STL (binary or text) or OBJ file with trimesh.

        Parameters
        ----------
        path : str or path-like
            The file (``.stl`` or ``.obj``), at most
            :data:`robotconf.cell.MAX_MESH_BYTES` bytes.
        pose : array-like, shape (4, 4), optional
            Where the file's frame sits in its parent's frame.
        scale : float
            Multiplies the file's coordinates (e.g. 1000 for a file in metres in a cell
            in millimetres).
        name : str, optional
            Default: the file's name without its suffix.

        Raises
        ------
        InvalidInputError
            Naming the file: missing, unreadable, too large, not STL/OBJ, malformed,
            empty, with too many triangles or with non-finite coordinates. Sizes are
            checked before the file is parsed.

        Examples
        --------
        >>> import tempfile, pathlib, robotconf as rc
        >>> text = "solid t\\nfacet normal 0 0 1\\nouter loop\\nvertex 0 0 0\\nvertex 1 0 0\\n"
        >>> text += "vertex 0 1 0\\nendloop\\nendfacet\\nendsolid t\\n"
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     path = pathlib.Path(folder, "plate.stl")
        ...     _ = path.write_text(text)
        ...     plate = rc.Mesh.load(path, scale=10)
        >>> plate.name, plate.triangles.shape, float(plate.vertices.max())
        ('plate', (1, 3, 3), 10.0)
        """
        from ._mesh_file import read_mesh

        vertices, faces, source, stem = read_mesh(path, scale)
        return cls(
            vertices,
            faces,
            pose=pose,
            name=stem if name is None else name,
            source=source,
            scale=scale,
        )


#: Kind (the JSON ``"type"``) → class.
SHAPE_KINDS: dict[str, type[Shape]] = {
    "box": Box,
    "cylinder": Cylinder,
    "sphere": Sphere,
    "mesh": Mesh,
}
