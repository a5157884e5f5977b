"""Exact signed distances between capsules and the cell's shapes, vectorized.

Every function takes arrays of pairs and returns one signed distance per pair: the
distance when apart, ``−`` the penetration depth (the shortest translation that
separates them) when they overlap. docs/cell.md gives the formulas and how they were
checked against an independent library.

Pairs
    :func:`point_segment_distance`, :func:`segment_segment_distance` (capsule–capsule,
    capsule–sphere), :func:`segment_box_distance`, :func:`segment_cylinder_distance`,
    :func:`segment_triangle_distance`, :func:`point_triangle_distance`
Many capsules against many objects (with a broad phase)
    :class:`Obstacle`, :class:`Obstacles`, :func:`capsule_obstacle_distances`,
    :func:`capsule_pair_distances`

>>> import numpy as np
>>> segment_box_distance(np.array([[2.0, 0, 0]]), np.array([[3.0, 0, 0]]), np.ones((1, 3)))
array([1.])
"""

from ._box import segment_box_distance
from ._cylinder import segment_cylinder_distance
from ._obstacles import Obstacle, Obstacles, capsule_obstacle_distances, capsule_pair_distances
from ._segments import point_segment_distance, segment_segment_distance
from ._triangle import point_triangle_distance, segment_triangle_distance

__all__ = [
    "point_segment_distance",
    "segment_segment_distance",
    "segment_box_distance",
    "segment_cylinder_distance",
    "segment_triangle_distance",
    "point_triangle_distance",
    "Obstacle",
    "Obstacles",
    "capsule_obstacle_distances",
    "capsule_pair_distances",
]
