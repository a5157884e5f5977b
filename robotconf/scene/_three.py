"""three.js JSON for the objects the scene draws, as meshcat's viewer loads them.

The viewer builds each object with three.js's ``ObjectLoader`` from the JSON "Object"
format 4.5: ``geometries`` and ``materials`` lists and one ``object`` that names them by
uuid. These builders write the same JSON as meshcat's Python ``meshcat.geometry``, field
for field and in the same order (``tests/test_scene_encoding.py`` compares the two), but
without importing meshcat: its package loads server libraries (pyzmq, tornado, Pillow)
that a browser kernel does not have.

Typed arrays (vertex positions and colours) are msgpack extension values, which the
viewer's msgpack decoder turns into JavaScript typed arrays; an object holding one must
travel msgpack-packed, not as JSON (:func:`~robotconf.scene._commands.set_object_op`).
"""

from __future__ import annotations

import uuid
from typing import Any

import msgpack
import numpy as np

__all__ = [
    "FLOAT32_ARRAY",
    "float32_array",
    "float32_attribute",
    "sphere",
    "cylinder",
    "box",
    "lambert_material",
    "mesh",
    "triad",
    "point_cloud",
    "polyline",
    "label_anchor",
]

#: msgpack extension code of a Float32Array in meshcat's viewer.
FLOAT32_ARRAY = 0x17

#: Defaults meshcat writes for every mesh and line material.
_MATERIAL_DEFAULTS = {
    "reflectivity": 0.5,
    "side": 2,  # THREE.DoubleSide
    "transparent": False,
    "opacity": 1.0,
    "linewidth": 1.0,
    "wireframe": False,
    "wireframeLinewidth": 1.0,
}

#: A triad's three lines (x, y, z) and their colours, from the origin out.
_TRIAD_POINTS = np.array([[0, 0, 0], [1, 0, 0], [0, 0, 0], [0, 1, 0], [0, 0, 0], [0, 0, 1]])
_TRIAD_COLORS = np.array(
    [[1, 0, 0], [1, 0.6, 0], [0, 1, 0], [0.6, 1, 0], [0, 0, 1], [0, 0.6, 1]], dtype=np.float32
)


def _uuid() -> str:
    return str(uuid.uuid4())


def float32_array(values: np.ndarray) -> msgpack.ExtType:
    """``values`` flattened to float32, as the msgpack extension the viewer decodes into a
    JavaScript ``Float32Array``.

    >>> len(float32_array(np.zeros((2, 3))).data)
    24
    """
    return msgpack.ExtType(FLOAT32_ARRAY, np.ascontiguousarray(values, dtype=np.float32).tobytes())


def float32_attribute(values: np.ndarray) -> dict[str, Any]:
    """A buffer attribute: one row of ``values`` (N, k) per vertex, packed as float32.

    >>> attribute = float32_attribute(np.zeros((2, 3)))
    >>> attribute["itemSize"], attribute["type"], len(attribute["array"].data)
    (3, 'Float32Array', 24)
    """
    rows = np.ascontiguousarray(values, dtype=np.float32)
    return {
        "itemSize": int(rows.shape[1]),
        "type": "Float32Array",
        "array": float32_array(rows),
        "normalized": False,
    }


def sphere(radius: float) -> dict[str, Any]:
    """A sphere geometry (20 × 20 segments, as meshcat draws it)."""
    return {
        "uuid": _uuid(),
        "type": "SphereGeometry",
        "radius": float(radius),
        "widthSegments": 20,
        "heightSegments": 20,
    }


def cylinder(height: float, radius: float) -> dict[str, Any]:
    """A cylinder geometry along y (three.js's convention), 50 segments round."""
    return {
        "uuid": _uuid(),
        "type": "CylinderGeometry",
        "radiusTop": float(radius),
        "radiusBottom": float(radius),
        "height": float(height),
        "radialSegments": 50,
    }


def box(width: float, height: float, depth: float) -> dict[str, Any]:
    """A box geometry: ``width`` along x, ``height`` along y, ``depth`` along z."""
    return {
        "uuid": _uuid(),
        "type": "BoxGeometry",
        "width": float(width),
        "height": float(height),
        "depth": float(depth),
    }


def _material(kind: str, color: int, vertex_colors: bool) -> dict[str, Any]:
    return {
        "uuid": _uuid(),
        "type": kind,
        "color": int(color),
        **_MATERIAL_DEFAULTS,
        "vertexColors": 2 if vertex_colors else 0,  # three.js's enum of the time
    }


def lambert_material(color: int) -> dict[str, Any]:
    """A matte material of one colour (0xRRGGBB), lit by the scene's lights."""
    return _material("MeshLambertMaterial", color, vertex_colors=False)


def _object(kind: str, geometry: dict[str, Any], material: dict[str, Any]) -> dict[str, Any]:
    return {
        "metadata": {"version": 4.5, "type": "Object"},
        "geometries": [geometry],
        "materials": [material],
        "object": {
            "uuid": _uuid(),
            "type": kind,
            "geometry": geometry["uuid"],
            "material": material["uuid"],
            "matrix": np.eye(4).ravel().tolist(),
        },
    }


def mesh(geometry: dict[str, Any], material: dict[str, Any]) -> dict[str, Any]:
    """A mesh object: one geometry, one material, no transform of its own.

    >>> obj = mesh(sphere(1.0), lambert_material(0xD62728))
    >>> obj["object"]["type"], obj["geometries"][0]["type"], obj["materials"][0]["color"]
    ('Mesh', 'SphereGeometry', 14034728)
    """
    return _object("Mesh", geometry, material)


def _vertices(position: np.ndarray, color: np.ndarray) -> dict[str, Any]:
    return {
        "uuid": _uuid(),
        "type": "BufferGeometry",
        "data": {
            "attributes": {
                "position": float32_attribute(position),
                "color": float32_attribute(color),
            }
        },
    }


def triad(length: float) -> dict[str, Any]:
    """Three line segments from the origin: x red, y green, z blue, each ``length`` long."""
    geometry = _vertices(_TRIAD_POINTS * float(length), _TRIAD_COLORS)
    material = _material("LineBasicMaterial", 0xFFFFFF, vertex_colors=True)
    return _object("LineSegments", geometry, material)


def point_cloud(position: np.ndarray, color: np.ndarray, size: float) -> dict[str, Any]:
    """Points at ``position`` (N, 3), each coloured by its row of ``color`` (N, 3) in 0…1.

    >>> cloud = point_cloud(np.zeros((5, 3)), np.ones((5, 3)), size=0.1)
    >>> cloud["object"]["type"], cloud["materials"][0]["size"]
    ('Points', 0.1)
    """
    material = {
        "uuid": _uuid(),
        "type": "PointsMaterial",
        "color": 0xFFFFFF,
        "size": float(size),
        "vertexColors": 2,
    }
    return _object("Points", _vertices(position, color), material)


def polyline(points: np.ndarray, color: int) -> dict[str, Any]:
    """A line through ``points`` (N, 3) in one colour (0xRRGGBB): a path, e.g. the EE's.

    >>> line = polyline(np.zeros((4, 3)), 0xD62728)
    >>> line["object"]["type"], line["materials"][0]["type"]
    ('Line', 'LineBasicMaterial')
    """
    geometry = {
        "uuid": _uuid(),
        "type": "BufferGeometry",
        "data": {"attributes": {"position": float32_attribute(points)}},
    }
    material = _material("LineBasicMaterial", color, vertex_colors=False)
    return _object("Line", geometry, material)


def label_anchor(clearance: float) -> dict[str, Any]:
    """An empty object that marks where a label stands (its text is drawn by the page).

    The page draws each label as text beside the anchor's point on screen, at one size at
    any zoom, at least ``clearance`` (length units: the radius of the sphere drawn there)
    away from the point, wrapped inside the pane and with a leader line when it had to
    move farther; in the scene itself the anchor is invisible. An animation moves the
    anchors like any other item, so the labels follow the robot.

    >>> anchor = label_anchor(2.5)["object"]
    >>> anchor["type"], anchor["userData"]
    ('Object3D', {'clearance': 2.5})
    """
    return {
        "metadata": {"version": 4.5, "type": "Object"},
        "geometries": [],
        "materials": [],
        "object": {
            "uuid": _uuid(),
            "type": "Object3D",
            "matrix": np.eye(4).ravel().tolist(),
            "userData": {"clearance": float(clearance)},
        },
    }
