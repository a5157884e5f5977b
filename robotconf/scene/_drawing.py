"""What the 3D scene draws for a robot, and where: the paper's Figure 14 as scene items.

A :class:`RobotDrawing` is built from a robot's *structure* (how many modules, of which
joint types). :meth:`RobotDrawing.place` turns a
:class:`~robotconf.kinematics.RobotSnapshot` (the robot at one ``q``, from one kernel
pass) into one transform per item without computing any kinematics itself;
:meth:`RobotDrawing.placements` does the same for a whole motion. Positions come only
from the core (frame poses, joint axes and the end effector).
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
    RobotSnapshot,
    characteristic_length,
    format_point,
    joint_axes,
)
from ._labels import label_digits
from ._placement import Placement, align_y, compose

__all__ = [
    "DrawnItem",
    "RobotDrawing",
    "robot_size",
    "snapshot_size",
    "structure_of",
    "COLORS",
]

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


@dataclass(frozen=True)
class DrawnItem:
    """One object of the scene.

    Attributes
    ----------
    path : str
        Scene path under the robot's root, e.g. ``"M2/sphere"``.
    shape : {"sphere", "cylinder", "box", "triad", "label"}
        Unit shape (cylinder and box: length 1 along y); a label is an invisible anchor
        that the page writes its text beside.
    size : float
        Radius (sphere, cylinder), half-width (box), length (triad) or how far from its
        point the page writes a label's text (the radius of the sphere there), in the
        robot's length units.
    color : int
        0xRRGGBB.
    layer : {"body", "frames", "labels"}
        What :meth:`Scene.show_frames` / :meth:`Scene.set_label_mode` switch.
    """

    path: str
    shape: str
    size: float
    color: int
    layer: str = "body"


def _polyline_length(origins: np.ndarray, end_effector: np.ndarray) -> float:
    points = np.vstack([np.zeros(3), origins, end_effector])
    length = float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())
    return length if length > 0 else 1.0


def snapshot_size(snapshot: RobotSnapshot) -> float:
    """The size :func:`robot_size` gives, read off a snapshot (no kinematics)."""
    return _polyline_length(snapshot.frame_origins, snapshot.end_effector)


def robot_size(robot: Robot, q: Any = None) -> float:
    """The robot's size for drawing: the length of its polyline base → frames → EE.

    Used to scale spheres, links and markers (the paper's robot is 70 units long, a UR5
    under 1 m). Falls back to 1 for a robot with every point at the origin.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot_size(rc.Robot([rc.Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0)))
    60.0
    """
    return snapshot_size(robot.at(q))


def structure_of(snapshot: RobotSnapshot) -> tuple[Any, ...]:
    """What decides the scene's objects: the number of links and each link's joint.

    >>> import robotconf as rc
    >>> structure_of(rc.preset("paper").at())
    (3, ('R', 'R', 'R'))
    """
    return (snapshot.robot.n, snapshot.joint_axes.joints)


class RobotDrawing:
    """The scene items of a robot and their transforms at any ``q``.

    Parameters
    ----------
    robot : Robot
    size : float
        Drawing size in length units (see :func:`robot_size`).
    joints : tuple, optional
        Each link's joint letter or ``None`` (``snapshot.joint_axes.joints``); default:
        the robot's own.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> drawing = RobotDrawing(robot, 70.0)
    >>> drawing.labels(robot.at())
    ['M1 (0.0, 0.0, 0.0)', 'M2 (0.0, 0.0, 20.0)', 'M3 (30.0, 0.0, 20.0)', 'EE (70.0, 0.0, 20.0)']
    >>> drawing.place(robot.at()).shape
    (19, 4, 4)
    """

    def __init__(self, robot: Robot, size: float, joints: tuple[Any, ...] | None = None) -> None:
        self.robot = robot
        self.size = float(size)
        if joints is None:
            joints = robot.at().joint_axes.joints
        self.joints = tuple(joints)
        self.structure = (robot.n, self.joints)
        #: Each link's joint type, or None where nothing moves (inactive, none, fixed).
        self.joint_types = tuple(None if j is None else JOINT_OF_LETTER[j] for j in self.joints)
        self.point_names = [*robot.module_names, END_EFFECTOR_LABEL]
        items = [DrawnItem("base/frame", "triad", 2 * TRIAD_LENGTH * size, 0)]
        # A label keeps clear of the biggest sphere (the end effector's) drawn at its point.
        clearance = 1.2 * SPHERE_RADIUS * size
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
            items.append(DrawnItem(f"modules/{i}/label", "label", clearance, 0, "labels"))
        items.append(DrawnItem("ee/link", "cylinder", LINK_RADIUS * size, COLORS["link"]))
        items.append(
            DrawnItem("ee/sphere", "sphere", 1.2 * SPHERE_RADIUS * size, COLORS["end_effector"])
        )
        items.append(DrawnItem("ee/label", "label", clearance, 0, "labels"))
        self.items = tuple(items)
        self.paths = tuple(item.path for item in items)
        self.label_paths = tuple(item.path for item in items if item.shape == "label")
        index = {path: k for k, path in enumerate(self.paths)}
        n = robot.n
        # Where each kind of item sits in `items`, so one configuration is placed with a
        # handful of array operations instead of a loop over the links.
        self._links = np.array([index[f"links/{i}"] for i in range(n)] + [index["ee/link"]])
        self._spheres = np.array(
            [index[f"modules/{i}/sphere"] for i in range(n)] + [index["ee/sphere"]]
        )
        self._frames = np.array([index[f"modules/{i}/frame"] for i in range(n)], dtype=int)
        self._labels = np.array(
            [index[f"modules/{i}/label"] for i in range(n)] + [index["ee/label"]]
        )
        kinds = self.joint_types
        self._revolute = np.array([i for i in range(n) if kinds[i] == "revolute"], dtype=int)
        self._prismatic = np.array([i for i in range(n) if kinds[i] == "prismatic"], dtype=int)
        self._revolute_items = np.array(
            [index[f"modules/{i}/joint"] for i in self._revolute], dtype=int
        )
        self._prismatic_items = np.array(
            [index[f"modules/{i}/joint"] for i in self._prismatic], dtype=int
        )
        #: The items along a direction, in _arrange's order: links, drums, bars.
        self._along = np.concatenate([self._links, self._revolute_items, self._prismatic_items])
        self._identity = np.broadcast_to(np.eye(3), (1, len(items), 3, 3))

    def place(self, snapshot: RobotSnapshot) -> np.ndarray:
        """The 4×4 transform of every item for one snapshot, shape (m, 4, 4).

        Reads the snapshot's frame poses, joint axes and end effector: no kinematics here.
        """
        axes = snapshot.joint_axes
        placement = self._arrange(
            snapshot.frame_poses[None],
            snapshot.end_effector[None],
            axes.point[None],
            axes.direction[None],
        )
        return compose(placement.position[0], placement.rotation[0], placement.scale[0])

    def placements(self, q: Any) -> Placement:
        """Position, rotation and scale of every item, shape (m, …) or (T, m, …).

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n)
            Coordinates (radians / length units): a motion, or the ghosts of a Reach
            target (one batch of the core's calls for all samples).
        """
        robot = self.robot
        values, batched = check_joint_values(q, robot.n, robot.coordinate_names)
        axes = joint_axes(robot, values)
        placement = self._arrange(
            robot.frame_poses(values), robot.end_effector(values), axes.point, axes.direction
        )
        if batched:
            return placement
        return Placement(placement.position[0], placement.rotation[0], placement.scale[0])

    def _arrange(
        self, poses: np.ndarray, ee: np.ndarray, point: np.ndarray, direction: np.ndarray
    ) -> Placement:
        """Items placed from frame poses (T, n, 4, 4), the EE (T, 3) and the joint axes'
        points and directions (T, n, 3): a handful of array operations, whatever n."""
        samples, m = poses.shape[0], len(self.items)
        origins = poses[:, :, :3, 3]
        ends = np.concatenate([origins, ee[:, None]], axis=1)  # the labelled points
        starts = np.concatenate([np.zeros((samples, 1, 3)), origins], axis=1)
        position = np.zeros((samples, m, 3))
        rotation = np.repeat(self._identity, samples, axis=0)
        scale = np.ones((samples, m, 3))
        position[:, self._spheres] = ends
        position[:, self._labels] = ends  # the page lifts each text above its point
        position[:, self._frames] = origins
        rotation[:, self._frames] = poses[:, :, :3, :3]
        # Items along a direction, all turned by one align_y: the links (from the previous
        # point to the next); the revolute joints' drums, on the joint's own axis as the
        # core defines it (rc.joint_axes: a standard DH joint i turns about z_{i-1}
        # through frame i-1's origin, |a_i| away from frame i's; a module or modified DH
        # joint about its own frame's axis), centred where the joint sits; the prismatic
        # joints' bars, along the slide from where it starts to where the slid frame's
        # origin projects on it (a standard DH row adds a_i across, off the axis).
        rev, pri = self._revolute, self._prismatic
        links = ends - starts
        start, along = point[:, pri], direction[:, pri]
        travel = np.einsum("...k,...k->...", origins[:, pri] - start, along)
        turned = align_y(np.concatenate([links, direction[:, rev], along], axis=1))
        link_length = np.sqrt(np.einsum("...k,...k->...", links, links))
        tiny = 1e-9 * self.size
        # A zero-length link or bar is drawn as nothing: scaled to `tiny` across.
        width = np.concatenate(
            [
                np.where(link_length > tiny, 1.0, tiny),
                np.ones((samples, len(rev))),
                np.where(np.abs(travel) > tiny, 1.0, tiny),
            ],
            axis=1,
        )
        length = np.concatenate(
            [
                np.where(link_length > tiny, link_length, tiny),
                np.full((samples, len(rev)), 3.0 * SPHERE_RADIUS * self.size),
                np.maximum(np.abs(travel), 2.0 * SPHERE_RADIUS * self.size),
            ],
            axis=1,
        )
        k = self._along
        position[:, k] = np.concatenate(
            [(starts + ends) / 2.0, point[:, rev], start + 0.5 * travel[..., None] * along],
            axis=1,
        )
        rotation[:, k] = turned
        scale[:, k] = np.stack([width, length, width], axis=-1)
        return Placement(position, rotation, scale)

    def labels(self, snapshot: RobotSnapshot, digits: int | None = None) -> list[str]:
        """Label texts ``"M2 (0.0, 0.0, 20.0)"`` of a snapshot's points.

        ``digits``: decimals; default three significant digits of the robot's
        characteristic length (:func:`~robotconf.scene._labels.label_digits`).
        """
        if digits is None:
            digits = label_digits(characteristic_length(self.robot))
        return [format_point(name, xyz, digits) for name, xyz in snapshot.points]
