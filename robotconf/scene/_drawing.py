"""What the 3D scene draws for a robot, and where: the paper's Figure 14 as scene items.

A :class:`RobotDrawing` is built from a robot's *structure* (how many modules, of which
joint types); :meth:`RobotDrawing.placements` then turns the core's frame poses, joint
axes and end-effector into one transform per item for any ``q``. Positions come only from
the core (:meth:`~robotconf.Robot.frame_poses`, :func:`~robotconf.joint_axes`,
:meth:`~robotconf.Robot.end_effector`, :func:`~robotconf.robot_points`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import check_joint_values
from ..kinematics import (
    END_EFFECTOR_LABEL,
    JOINT_OF_LETTER,
    Robot,
    characteristic_length,
    format_point,
    joint_axes,
)
from ._labels import label_digits
from ._placement import Placement, align_y, segment_placement

__all__ = ["DrawnItem", "RobotDrawing", "robot_size", "COLORS"]

#: Colours as 0xRRGGBB: the paper's green joints and red end-effector.
COLORS = {
    "joint": 0x2CA02C,
    "end_effector": 0xD62728,
    "link": 0x8C8C8C,
    "revolute": 0x1F77B4,
    "prismatic": 0xFF7F0E,
    "passive": 0xBBBBBB,
}

#: Sizes relative to the robot's size (:func:`robot_size`).
SPHERE_RADIUS = 0.035
#: The marker of a joint by joint type: a drum on a revolute axis, a bar along a prismatic
#: one; (shape, size relative to the sphere radius).
JOINT_MARKERS = {"revolute": ("cylinder", 0.6), "prismatic": ("box", 0.5)}
LINK_RADIUS = 0.012
TRIAD_LENGTH = 0.12
LABEL_HEIGHT = 0.05
#: Labels stand just above the spheres (the viewer sizes and stacks them on screen).
LABEL_LIFT = 1.5 * SPHERE_RADIUS


@dataclass(frozen=True)
class DrawnItem:
    """One object of the scene.

    Attributes
    ----------
    path : str
        Scene path under the robot's root, e.g. ``"M2/sphere"``.
    shape : {"sphere", "cylinder", "box", "triad", "label"}
        Unit shape (cylinder and box: length 1 along y).
    size : float
        Radius (sphere, cylinder), half-width (box) or length (triad, label height), in
        the robot's length units.
    color : int
        0xRRGGBB.
    layer : {"body", "frames", "labels"}
        What :meth:`Scene.show_frames` / :meth:`Scene.show_labels` switch.
    """

    path: str
    shape: str
    size: float
    color: int
    layer: str = "body"


def robot_size(robot: Robot, q: Any = None) -> float:
    """The robot's size for drawing: the length of its polyline base → frames → EE.

    Used to scale spheres, links and labels (the paper's robot is 70 units long, a UR5
    under 1 m). Falls back to 1 for a robot with every point at the origin.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot_size(rc.Robot([rc.Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0)))
    60.0
    """
    origins = robot.frame_origins(q)
    points = np.vstack([np.zeros(3), origins, robot.end_effector(q)])
    length = float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())
    return length if length > 0 else 1.0


class RobotDrawing:
    """The scene items of a robot and their transforms at any ``q``.

    Parameters
    ----------
    robot : Robot
    size : float
        Drawing size in length units (see :func:`robot_size`).

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> drawing = RobotDrawing(robot, 70.0)
    >>> drawing.labels(robot.q)
    ['M1 (0.0, 0.0, 0.0)', 'M2 (0.0, 0.0, 20.0)', 'M3 (30.0, 0.0, 20.0)', 'EE (70.0, 0.0, 20.0)']
    """

    def __init__(self, robot: Robot, size: float) -> None:
        self.robot = robot
        self.size = float(size)
        self.structure = structure_key(robot)
        joints = joint_axes(robot).joints
        self.joints = joints
        #: Each link's joint type, or None where nothing moves (inactive, none, fixed).
        self.joint_types = tuple(None if j is None else JOINT_OF_LETTER[j] for j in joints)
        names = [*robot.module_names, END_EFFECTOR_LABEL]
        self.point_names = names
        items = [DrawnItem("base/frame", "triad", 2 * TRIAD_LENGTH * size, 0)]
        for i in range(robot.n):
            items.append(DrawnItem(f"links/{i}", "cylinder", LINK_RADIUS * size, COLORS["link"]))
            joint_type = self.joint_types[i]
            color = COLORS["passive"] if joint_type is None else COLORS["joint"]
            items.append(DrawnItem(f"modules/{i}/sphere", "sphere", SPHERE_RADIUS * size, color))
            if joint_type is not None:
                shape, factor = JOINT_MARKERS[joint_type]
                marker = factor * SPHERE_RADIUS * size
                items.append(DrawnItem(f"modules/{i}/joint", shape, marker, COLORS[joint_type]))
            items.append(DrawnItem(f"modules/{i}/frame", "triad", TRIAD_LENGTH * size, 0, "frames"))
            items.append(DrawnItem(f"modules/{i}/label", "label", LABEL_HEIGHT * size, 0, "labels"))
        items.append(DrawnItem("ee/link", "cylinder", LINK_RADIUS * size, COLORS["link"]))
        items.append(
            DrawnItem("ee/sphere", "sphere", 1.2 * SPHERE_RADIUS * size, COLORS["end_effector"])
        )
        items.append(DrawnItem("ee/label", "label", LABEL_HEIGHT * size, 0, "labels"))
        self.items = tuple(items)
        self.paths = tuple(item.path for item in items)
        self._index = {path: k for k, path in enumerate(self.paths)}
        self.label_paths = tuple(item.path for item in items if item.shape == "label")

    def placements(self, q: Any) -> Placement:
        """Position, rotation and scale of every item, shape (m, …) or (T, m, …).

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n)
            Coordinates (radians / length units).
        """
        robot = self.robot
        values, batched = check_joint_values(q, robot.n, robot.coordinate_names)
        samples, n, m = values.shape[0], robot.n, len(self.items)
        poses = robot.frame_poses(values)
        origins = poses[:, :, :3, 3]
        ee = robot.end_effector(values)
        axes = joint_axes(robot, values)
        position = np.zeros((samples, m, 3))
        rotation = np.broadcast_to(np.eye(3), (samples, m, 3, 3)).copy()
        scale = np.ones((samples, m, 3))
        tiny = 1e-9 * self.size
        previous = np.zeros((samples, 3))
        lift = np.array([0.0, 0.0, LABEL_LIFT * self.size])

        def put(path: str, placement: Placement) -> None:
            k = self._index[path]
            position[:, k] = placement.position
            rotation[:, k] = placement.rotation
            scale[:, k] = placement.scale

        for i in range(n):
            put(f"links/{i}", segment_placement(previous, origins[:, i], tiny))
            position[:, self._index[f"modules/{i}/sphere"]] = origins[:, i]
            if self.joint_types[i] is not None:
                put(f"modules/{i}/joint", self._joint_placement(axes, origins, i, tiny))
            k = self._index[f"modules/{i}/frame"]
            position[:, k] = origins[:, i]
            rotation[:, k] = poses[:, i, :3, :3]
            position[:, self._index[f"modules/{i}/label"]] = origins[:, i] + lift
            previous = origins[:, i]
        put("ee/link", segment_placement(previous, ee, tiny))
        position[:, self._index["ee/sphere"]] = ee
        position[:, self._index["ee/label"]] = ee + lift
        if batched:
            return Placement(position, rotation, scale)
        return Placement(position[0], rotation[0], scale[0])

    def _joint_placement(self, axes: Any, origins: np.ndarray, i: int, tiny: float) -> Placement:
        # On the joint's own axis, as the core defines it (rc.joint_axes): a standard DH
        # joint i turns about z_{i-1} through frame i-1's origin, which is |a_i| away from
        # frame i's origin; a module or modified DH joint turns about its own frame's axis.
        start, direction = axes.point[:, i], axes.direction[:, i]
        if self.joint_types[i] == "revolute":
            # A short drum centred where the joint sits.
            length = 3.0 * SPHERE_RADIUS * self.size
            scale = np.broadcast_to([1.0, length, 1.0], start.shape)
            return Placement(start, align_y(direction), scale)
        # A prismatic joint: a bar along the slide, from where it starts to where the slid
        # frame's origin projects on it (a standard DH row adds a_i across, off the axis).
        travel = np.einsum("...k,...k->...", origins[:, i] - start, direction)
        placement = segment_placement(start, start + travel[..., None] * direction, tiny)
        minimum = 2.0 * SPHERE_RADIUS * self.size
        placement.scale[..., 1] = np.maximum(placement.scale[..., 1], minimum)
        placement.rotation = align_y(direction)
        return placement

    def labels(self, q: Any, digits: int | None = None) -> list[str]:
        """Label texts ``"M2 (0.0, 0.0, 20.0)"`` for one configuration ``q`` (n,).

        ``digits``: decimals; default three significant digits of the robot's
        characteristic length (:func:`~robotconf.scene._labels.label_digits`).
        """
        return self.label_texts(self.label_points(q), digits)

    def label_texts(self, points: np.ndarray, digits: int | None = None) -> list[str]:
        """Label texts for the points :meth:`label_points` gave."""
        if digits is None:
            digits = label_digits(characteristic_length(self.robot))
        return [
            format_point(name, p, digits) for name, p in zip(self.point_names, points, strict=True)
        ]

    def label_points(self, q: Any) -> np.ndarray:
        """Where the labels stand at ``q`` (n,): every frame origin, then the EE, (n + 1, 3)."""
        return np.vstack([self.robot.frame_origins(q), self.robot.end_effector(q)[None]])


def structure_key(robot: Robot) -> tuple[Any, ...]:
    """What decides the scene's objects: the number of links and each link's joint."""
    return (robot.n, joint_axes(robot).joints)
