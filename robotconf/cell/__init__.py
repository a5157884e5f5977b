"""The work cell: robots, a table, fixtures and targets in one frame (docs/cell.md).

Build a cell, then ask what a cell designer asks: how close does the arm come to the
fixture, does this program hit anything, can the robot reach every pick point, where
should its base go.

The cell
    :class:`Cell` (``add_robot``, ``add``, ``add_frame``, ``set_pose``, ``pose_of``,
    ``link_capsules``, ``save``), :func:`pose`, :class:`Tool`
Objects (URDF conventions: centred at their pose, a box's size is its full edges, a
cylinder's axis is its z)
    :class:`Box`, :class:`Cylinder`, :class:`Sphere`, :class:`Mesh` (``Mesh.load``)
Questions and their answers
    ``cell.clearance`` → :class:`Clearance`; ``cell.check`` → :class:`CellCheck`,
    :class:`Contact`; ``cell.reach`` → :class:`Reach`; ``cell.reach_map`` →
    :class:`ReachMap`; ``cell.place`` → :class:`Placement`; ``cell.run`` → :class:`CellRun`
Limits
    :data:`MAX_SAMPLES`, :data:`MAX_TARGETS`, :data:`MAX_VOXELS`, :data:`MAX_TRIANGLES`,
    :data:`MAX_MESH_BYTES`, :data:`DEFAULT_RADIUS_FRACTION`
Distances between capsules and shapes: :mod:`robotconf.cell.distance`.

>>> import robotconf as rc
>>> cell = rc.Cell(unit="mm")
>>> cell.add_robot("arm", rc.preset("paper"))
>>> cell.add(rc.Box([20, 20, 20], pose=rc.pose([50, 0, 10]), name="fixture"))
'fixture'
>>> print(cell.clearance("arm", [0, 0, 0]))
clearance -3.6 mm: arm link 3 – fixture
"""

from ._answers import CellCheck, CellRun, Clearance, Contact, Placement, Reach, ReachMap
from ._cell import Cell
from ._entries import MAX_ENTRIES
from ._limits import MAX_BASES, MAX_SAMPLES, MAX_TARGETS, MAX_VOXELS
from ._links import DEFAULT_RADIUS_FRACTION, LinkModel
from ._mesh_file import MAX_MESH_BYTES
from ._pose import NAME_SEPARATOR, check_pose, pose
from ._shapes import MAX_TRIANGLES, SHAPE_KINDS, Box, Cylinder, Mesh, Shape, Sphere
from ._tool import Tool

__all__ = [
    # the cell
    "Cell",
    "pose",
    "check_pose",
    "Tool",
    "NAME_SEPARATOR",
    # objects
    "Shape",
    "Box",
    "Cylinder",
    "Sphere",
    "Mesh",
    "SHAPE_KINDS",
    # answers
    "Clearance",
    "CellCheck",
    "Contact",
    "Reach",
    "ReachMap",
    "Placement",
    "CellRun",
    "LinkModel",
    # limits
    "MAX_ENTRIES",
    "MAX_SAMPLES",
    "MAX_TARGETS",
    "MAX_VOXELS",
    "MAX_BASES",
    "MAX_TRIANGLES",
    "MAX_MESH_BYTES",
    "DEFAULT_RADIUS_FRACTION",
]
