"""URDF export: a robot as the XML that ROS, MoveIt, PyBullet and friends read.

Every link robotconf knows is ``A(q) = P · Screw_k(θ0 + q_R, d0 + q_P) · Q`` (see
:class:`~robotconf.LinkGeometry`). URDF moves a child frame by ``origin · Motion(q)``
about or along a fixed axis, so module ``i`` becomes

* a joint ``q<i>`` whose ``origin`` is the constant part ``P · Screw_k(θ0, d0)`` and whose
  ``axis`` is the principal axis ``k`` (revolute or prismatic, limits from
  :meth:`Robot.joint_limits`), ending in link ``M<i>`` (the module's own name);
* when ``Q`` is not the identity (a standard DH row: ``Tx(a)·Rx(α)``), the joint ends in an
  intermediate link ``M<i>_joint`` and a fixed joint ``q<i>_post`` with origin ``Q`` leads
  on to ``M<i>``;
* ``none`` modules and inactive modules (after ``active``) become fixed identity joints,
  ``fixed`` modules fixed joints with their offset, so that every module still has its
  link and link ``M<i>`` is exactly robotconf's frame ``M_i``;
* the end-effector point ``P`` is link ``end_effector`` on a fixed joint from the last
  module's link.

The file holds kinematics only: links have no inertia, visuals or collisions.
Only the standard library's XML writer is used, which escapes every attribute. Every
number written is finite: a ``scale`` that would push a length past the float range is
refused, and a last check refuses any inf or NaN before it reaches the text.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from typing import TYPE_CHECKING, Any

import numpy as np

from .._budget import check_finite_result
from .._errors import InvalidInputError
from .._validation import check_finite_number
from ..kinematics import JOINT_OF_LETTER, LinkGeometry, link_matrices, rpy_from_matrix

if TYPE_CHECKING:  # pragma: no cover
    from ..kinematics import Robot

__all__ = ["to_urdf", "rpy_from_matrix", "PLACEHOLDER_EFFORT", "PLACEHOLDER_VELOCITY"]

#: URDF requires ``effort`` (N or N·m) and ``velocity`` (m/s or rad/s) on every moving
#: joint's ``<limit>``. robotconf models kinematics only and knows neither, so these are
#: placeholders — not properties of the robot. Override them before using the file for
#: control or planning. They are non-zero because some tools divide by them.
PLACEHOLDER_EFFORT = 1.0
PLACEHOLDER_VELOCITY = 1.0

BASE_LINK = "base_link"
END_EFFECTOR_LINK = "end_effector"

#: Numbers smaller than this print as 0, so that the rounding noise of cos(π/2) does not
#: clutter the file (1e-15 of a length or angle unit is far below any tolerance).
ZERO_BELOW = 1e-15


def _parts(g: LinkGeometry | None) -> tuple[np.ndarray, np.ndarray]:
    """(origin, post): the constant transforms before and after the joint's motion."""
    if g is None:  # inactive module: identity
        return np.eye(4), np.eye(4)
    origin = g.pre_matrix()
    if g.axis is not None:
        # The screw at q = 0 carries the row's constant θ and d.
        origin = origin @ link_matrices([g.screw()], np.zeros((1, 1)))[0, 0]
    return origin, g.post_matrix()


def _number(value: float) -> str:
    """Shortest text that reads back as the same float; whole numbers without ``.0``."""
    value = float(value)
    if not math.isfinite(value):  # the checks before should make this impossible
        raise InvalidInputError(
            "robot", value, "finite numbers only", problem="URDF would get a non-finite number:"
        )
    if abs(value) < ZERO_BELOW:
        return "0"
    return str(int(value)) if value.is_integer() and abs(value) < 1e15 else repr(value)


def _scaled(values: np.ndarray, scale: float) -> np.ndarray:
    """Lengths times ``scale``, refused when the product leaves the float range."""
    with np.errstate(over="ignore"):
        out = values * scale
    check_finite_result(out, "scale", scale, "the scaled lengths")
    return out


def _triple(values: Any) -> str:
    return " ".join(_number(v) for v in values)


class _Names:
    """Unique, tool-friendly names: characters outside ``[A-Za-z0-9_.-]`` become ``_``."""

    def __init__(self, *reserved: str):
        self.taken = set(reserved)

    def take(self, wanted: str) -> str:
        base = re.sub(r"[^A-Za-z0-9_.-]", "_", wanted) or "frame"
        name, k = base, 2
        while name in self.taken:
            name, k = f"{base}_{k}", k + 1
        self.taken.add(name)
        return name


def _joint(
    root: ET.Element, name: str, kind: str, parent: str, child: str, pose: np.ndarray
) -> ET.Element:
    joint = ET.SubElement(root, "joint", name=name, type=kind)
    ET.SubElement(joint, "parent", link=parent)
    ET.SubElement(joint, "child", link=child)
    ET.SubElement(
        joint, "origin", xyz=_triple(pose[:3, 3]), rpy=_triple(rpy_from_matrix(pose[:3, :3]))
    )
    return joint


def to_urdf(
    robot: Robot,
    name: str | None = None,
    *,
    scale: float = 1.0,
    effort: float = PLACEHOLDER_EFFORT,
    velocity: float = PLACEHOLDER_VELOCITY,
) -> str:
    """The robot as a URDF document (kinematics only).

    Parameters
    ----------
    robot : Robot
    name : str, optional
        The ``<robot name>``; default: the robot's name, else ``"robotconf_robot"``.
    scale : float
        Factor applied to every length (offsets, DH lengths, the end-effector point,
        prismatic limits). URDF expects metres: ``scale=0.001`` for a robot in mm.
        Prismatic joint values in the URDF are then in the scaled unit too.
    effort, velocity : float
        Values written into every ``<limit>``; placeholders (see
        :data:`PLACEHOLDER_EFFORT`), since robotconf has no dynamics.

    Returns
    -------
    str
        The XML text. Links: ``base_link``, one per module (its name, sanitized and made
        unique), ``<name>_joint`` where a DH row needs it, ``end_effector``. Joints:
        ``q1 … qn`` (one per module, so a configuration maps by name), ``q<i>_post``,
        ``end_effector_joint``. Joint limits come from :meth:`Robot.joint_limits`.

    Raises
    ------
    InvalidInputError
        For a name that is not text, a non-positive or non-finite scale, effort or
        velocity, or a scale that makes a length overflow (``scale``).

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> text = to_urdf(robot, "arm", scale=0.001)
    >>> print(text.splitlines()[0])
    <?xml version="1.0"?>
    >>> '<origin xyz="0 0 0.02" rpy="0 0 0" />' in text
    True
    """
    from ..kinematics import Robot

    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")
    if name is not None and not isinstance(name, str):
        raise InvalidInputError("name", name, "text or None", problem="not text:")
    factors = {}
    for field, value in (("scale", scale), ("effort", effort), ("velocity", velocity)):
        factors[field] = check_finite_number(value, field)
        if factors[field] <= 0.0:
            raise InvalidInputError(
                field, factors[field], "a finite number > 0", problem="must be positive, got"
            )
    scale = factors["scale"]
    limits = np.asarray(robot.joint_limits(), dtype=float)  # type: ignore[attr-defined]
    root = ET.Element("robot", name=name or robot.name or "robotconf_robot")
    root.append(
        ET.Comment(
            " Generated by robotconf: kinematics only (no inertia or geometry). Lengths x "
            f"{scale!r}. effort/velocity limits are placeholders, not robot data. "
        )
    )
    links = _Names(BASE_LINK, END_EFFECTOR_LINK)
    joints = _Names(*robot.coordinate_names, "end_effector_joint")
    ET.SubElement(root, "link", name=BASE_LINK)
    parent = BASE_LINK
    for i, (label, g) in enumerate(zip(robot.module_names, robot.geometry(), strict=True)):
        origin, post = _parts(g)
        origin[:3, 3] = _scaled(origin[:3, 3], scale)
        post[:3, 3] = _scaled(post[:3, 3], scale)
        moving = g is not None and g.axis is not None and g.joint is not None
        has_post = not np.array_equal(post, np.eye(4))
        frame = links.take(label)
        child = links.take(f"{frame}_joint") if moving and has_post else frame
        ET.SubElement(root, "link", name=child)
        joint_name = robot.coordinate_names[i]
        if not moving:
            _joint(root, joint_name, "fixed", parent, frame, origin @ post)
        else:
            assert g is not None and g.axis is not None and g.joint is not None  # moving says so
            # URDF's joint types are robotconf's words: "revolute", "prismatic".
            kind = JOINT_OF_LETTER[g.joint]
            joint = _joint(root, joint_name, kind, parent, child, origin)
            ET.SubElement(joint, "axis", xyz=_triple(np.eye(3)[g.axis]))
            # A stroke is a length and scales; an angle does not.
            lo, hi = _scaled(limits[i], scale) if kind == "prismatic" else limits[i]
            ET.SubElement(
                joint,
                "limit",
                lower=_number(lo),
                upper=_number(hi),
                effort=_number(factors["effort"]),
                velocity=_number(factors["velocity"]),
            )
            if has_post:
                ET.SubElement(root, "link", name=frame)
                _joint(root, joints.take(f"{joint_name}_post"), "fixed", child, frame, post)
        parent = frame
    ET.SubElement(root, "link", name=END_EFFECTOR_LINK)
    tool = np.eye(4)
    tool[:3, 3] = _scaled(robot.end_effector_point, scale)
    _joint(root, "end_effector_joint", "fixed", parent, END_EFFECTOR_LINK, tool)
    ET.indent(root, space="  ")
    return '<?xml version="1.0"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
