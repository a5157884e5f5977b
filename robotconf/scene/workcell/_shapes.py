"""The cell's objects as three.js objects: boxes, cylinders, spheres and triangle meshes.

Each object is drawn in its own frame and placed by its pose (the group at its path gets
the pose; the shape itself sits at the group's ``<object>``), following the cell's URDF
conventions: centred at the pose, a box's size its full edges along x, y, z, a
cylinder's axis the pose's z. three.js draws a cylinder along its y axis, so the
cylinder carries a quarter turn about x of its own (y → z) in its object matrix.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...cell import Box, Cylinder, Mesh, Shape, Sphere
from .._three import (
    box,
    cylinder,
    lambert_material,
    line_segments,
    mesh,
    sphere,
    triangles_geometry,
)

__all__ = [
    "OBJECT_COLOR",
    "CONTACT_COLOR",
    "SELECTION_COLOR",
    "QUARTER_TURN_X",
    "shape_object",
    "same_geometry",
    "local_box",
    "wire_box",
    "drawing_bytes",
    "rgb",
]

#: The objects' neutral colour (0xRRGGBB): a warm grey, apart from the robots' colours.
OBJECT_COLOR = 0xB4AC9C
#: What a link and the object it meets turn to while they are in contact.
CONTACT_COLOR = 0xE8161B
#: The outline of the selected entry.
SELECTION_COLOR = 0xFFA000

#: A quarter turn about x: three.js's cylinder axis (y) onto the cell's (z).
QUARTER_TURN_X = np.array(
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
)

#: The 12 edges of the cube [-½, ½]³, as 24 end points.
_CUBE_EDGES = (
    np.array(
        [
            [corner, corner + np.eye(3)[axis]]
            for axis in range(3)
            for corner in (
                np.array([(b >> 0) & 1, (b >> 1) & 1, (b >> 2) & 1], dtype=float) for b in range(8)
            )
            if corner[axis] == 0
        ]
    ).reshape(-1, 3)
    - 0.5
)


def rgb(color: int) -> np.ndarray:
    """0xRRGGBB as (r, g, b) in 0…1, as the viewer's colours hold it.

    >>> rgb(0xFF8000).tolist()
    [1.0, 0.5019607843137255, 0.0]
    """
    return np.array([(color >> 16) & 255, (color >> 8) & 255, color & 255]) / 255.0


def shape_object(shape: Shape, color: int = OBJECT_COLOR) -> dict[str, Any]:
    """The three.js JSON of one object in its own frame (its pose goes to its group).

    Examples
    --------
    >>> import robotconf as rc
    >>> geometry = shape_object(rc.Box([100, 60, 4]))["geometries"][0]
    >>> geometry["width"], geometry["height"], geometry["depth"]
    (100.0, 60.0, 4.0)
    >>> turned = shape_object(rc.Cylinder(5, 20))["object"]["matrix"]  # column-major
    >>> np.reshape(turned, (4, 4)).T[:3, 1].tolist()  # its y axis drawn along z
    [0.0, 0.0, 1.0]
    """
    material = lambert_material(color)
    if isinstance(shape, Box):
        return mesh(box(*shape.size), material)
    if isinstance(shape, Cylinder):
        obj = mesh(cylinder(shape.length, shape.radius), material)
        obj["object"]["matrix"] = QUARTER_TURN_X.T.ravel().tolist()
        return obj
    if isinstance(shape, Sphere):
        return mesh(sphere(shape.radius), material)
    assert isinstance(shape, Mesh)
    return mesh(triangles_geometry(shape.triangles), material)


def same_geometry(a: Shape | None, b: Shape) -> bool:
    """Whether two objects look the same in their own frames (their poses aside).

    >>> import robotconf as rc
    >>> same_geometry(rc.Box([1, 2, 3]), rc.Box([1, 2, 3], pose=rc.pose([5, 0, 0])))
    True
    >>> same_geometry(rc.Box([1, 2, 3]), rc.Box([1, 2, 4]))
    False
    """
    if a is None or type(a) is not type(b):
        return False
    if isinstance(a, Box):
        return bool(a.size == b.size)  # type: ignore[attr-defined]
    if isinstance(a, Cylinder):
        return bool((a.radius, a.length) == (b.radius, b.length))  # type: ignore[attr-defined]
    if isinstance(a, Sphere):
        return bool(a.radius == b.radius)  # type: ignore[attr-defined]
    assert isinstance(a, Mesh) and isinstance(b, Mesh)
    # A moved mesh keeps its arrays (its copy shares them): compare by identity first.
    return (a.vertices is b.vertices or np.array_equal(a.vertices, b.vertices)) and (
        a.faces is b.faces or np.array_equal(a.faces, b.faces)
    )


def local_box(shape: Shape) -> tuple[np.ndarray, np.ndarray]:
    """The centre (3,) and full edges (3,) of a box around the object in its own frame.

    >>> import robotconf as rc
    >>> [v.tolist() for v in local_box(rc.Cylinder(5, 20))]
    [[0.0, 0.0, 0.0], [10.0, 10.0, 20.0]]
    """
    if isinstance(shape, Box):
        return np.zeros(3), np.array(shape.size)
    if isinstance(shape, Cylinder):
        return np.zeros(3), np.array([2 * shape.radius, 2 * shape.radius, shape.length])
    if isinstance(shape, Sphere):
        return np.zeros(3), np.full(3, 2 * shape.radius)
    assert isinstance(shape, Mesh)
    low, high = shape.vertices.min(axis=0), shape.vertices.max(axis=0)
    return 0.5 * (low + high), high - low


def wire_box(color: int) -> dict[str, Any]:
    """The 12 edges of the unit cube centred at the origin, drawn over everything (its
    transform gives it its size).

    >>> lines = wire_box(SELECTION_COLOR)
    >>> len(lines["geometries"][0]["data"]["attributes"]["position"]["array"].data) // 12
    24
    """
    obj = line_segments(_CUBE_EDGES, color)
    for material in obj["materials"]:
        # Seen through whatever is in front of it: an outline that hides is no outline.
        material.update(depthTest=False, transparent=True)
    return obj


def drawing_bytes(shape: Shape) -> int:
    """About how many bytes the object's drawing takes on its way to the page (a mesh's
    corners as float32, in the message and its copies); the others are a few hundred.

    >>> import robotconf as rc
    >>> drawing_bytes(rc.Sphere(1.0))
    1024
    """
    if isinstance(shape, Mesh):
        return 4 * 36 * int(shape.faces.shape[0]) + 1024
    return 1024
