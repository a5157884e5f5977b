"""Which closed form fits a robot, read from its joint axes (never from its name).

The test is geometric, on the joint lines at q = 0 (:mod:`..geometry._chain_axes`), so a DH table
in either convention and a chain of modules describing the same arm are recognized alike:

======================  ==================================================================
family                  joint lines
======================  ==================================================================
planar 2R, planar 3R    2 or 3 revolute axes, all parallel, no two the same line
SCARA                   the same plus one prismatic joint along them, anywhere in the chain
3R elbow                3 revolute: axes 2 ∥ 3 (distinct), axis 1 not parallel to them
spherical-wrist 6R      6 revolute: axes 2 ∥ 3 and axis 1 as above; axes 4, 5, 6 meet in
                        one point (4 ∦ 5, 5 ∦ 6)
UR                      6 revolute: axes 2 ∥ 3 ∥ 4 (distinct) and axis 1 not parallel to
                        them; axes 5 and 6 meet (5 ∦ 4, 6 ∦ 5)
======================  ==================================================================

Lines are parallel within 1e-9 rad and meet within 1e-9 of the robot's size.
"""

from __future__ import annotations

import dataclasses
import math
from collections import OrderedDict
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..geometry._chain_axes import (
    ChainAxes,
    axes_at,
    common_point,
    line_gap,
    misalignment,
    reference_configuration,
)
from ..geometry._subproblems import perp

__all__ = [
    "FAMILIES",
    "CLOSED_FORMS",
    "NotClosedForm",
    "classify",
    "closed_form_structure",
    "recognize",
    "refuse",
]

#: Every family :func:`recognize` can answer, in the order it tries them.
FAMILIES = ("planar 2R", "planar 3R", "SCARA", "3R elbow", "spherical-wrist 6R", "UR")

#: What the closed forms cover, for error messages.
CLOSED_FORMS = (
    "closed forms cover planar 2R/3R arms and SCARAs (parallel revolute axes), 3R elbow "
    "arms (axis 1 across axes 2 ∥ 3), spherical-wrist 6R arms (axes 4, 5, 6 meet at one "
    "point) and UR-type 6R arms (axes 2 ∥ 3 ∥ 4, axes 5 and 6 meet); for any robot use "
    "rc.ik(robot, target) (numeric)"
)

ANGLE_TOL = 1e-9
GAP_TOL = 1e-9


class NotClosedForm(Exception):
    """Why a robot fits no closed-form family (internal; :func:`refuse` words it)."""


def _deg(angle: float) -> str:
    return f"{math.degrees(angle):.4g}°"


def _axis(chain: ChainAxes, k: int) -> str:
    """``axis 3``, with the coordinate's name when the numbering differs (``axis 3 (q5)``)."""
    column = chain.joints[k].column
    return f"axis {k + 1}" + ("" if column == k else f" (q{column + 1})")


def _pair(chain: ChainAxes, a: int, b: int) -> str:
    """``axes 4 and 5`` (with coordinate names when the numbering differs)."""
    return f"{_axis(chain, a)} and {_axis(chain, b)}".replace("axis", "axes", 1).replace(
        " and axis ", " and ", 1
    )


def _require_parallel(chain: ChainAxes, first: int, others: range, conclusion: str) -> None:
    for k in others:
        off = misalignment(chain.joints[first].direction, chain.joints[k].direction)
        if off > ANGLE_TOL:
            raise NotClosedForm(
                f"{_axis(chain, k)} is {_deg(off)} off parallel to {_axis(chain, first)}, "
                f"so {conclusion}"
            )


def _require_apart(chain: ChainAxes, a: int, b: int) -> None:
    if line_gap(chain.joints[a], chain.joints[b]) <= GAP_TOL * chain.scale:
        raise NotClosedForm(f"{_pair(chain, a, b)} are the same line")


def _require_crossing(chain: ChainAxes, a: int, b: int) -> None:
    off = misalignment(chain.joints[a].direction, chain.joints[b].direction)
    if off <= ANGLE_TOL:
        raise NotClosedForm(f"{_pair(chain, a, b)} are parallel")


def _point_off_axis(chain: ChainAxes, point: np.ndarray, k: int, what: str) -> None:
    joint = chain.joints[k]
    if np.linalg.norm(perp(joint.direction, point - joint.point)) <= GAP_TOL * chain.scale:
        raise NotClosedForm(f"{what} lies on {_axis(chain, k)}, so that joint cannot move it")


def _parallel_family(chain: ChainAxes) -> str:
    revolute = [k for k, joint in enumerate(chain.joints) if joint.kind == "R"]
    slides = len(chain.joints) - len(revolute)
    if not 2 <= len(revolute) <= 3 or slides > 1:
        raise NotClosedForm(
            f"it has {len(revolute)} revolute and {slides} prismatic joints (a planar arm or "
            "SCARA has 2-3 revolute joints and at most one prismatic)"
        )
    _require_parallel(
        chain, revolute[0], range(len(chain.joints)), "this is not a planar arm or SCARA"
    )
    for a, b in zip(revolute, revolute[1:], strict=False):
        _require_apart(chain, a, b)
    if len(revolute) == 2:
        _point_off_axis(chain, chain.home[:3, 3], revolute[1], "the end-effector point")
    return "SCARA" if slides else f"planar {len(revolute)}R"


def _elbow_arm(chain: ChainAxes) -> None:
    """Axes 2 ∥ 3 (distinct) and axis 1 crossing them: the first three of an elbow arm."""
    _require_parallel(chain, 1, range(2, 3), "this is not an elbow arm")
    _require_crossing(chain, 0, 1)
    _require_apart(chain, 1, 2)


def _spherical_wrist(chain: ChainAxes) -> None:
    gaps = {(a, b): line_gap(chain.joints[a], chain.joints[b]) for a, b in ((3, 4), (4, 5), (3, 5))}
    (a, b), worst = max(gaps.items(), key=lambda item: item[1])
    if worst > GAP_TOL * chain.scale:
        raise NotClosedForm(
            f"the last three axes do not intersect ({_pair(chain, a, b)}: closest approach "
            f"{worst:.6g}), so this is not a spherical-wrist arm"
        )
    centre, miss = common_point(chain.joints[3:])
    if miss > GAP_TOL * chain.scale:
        raise NotClosedForm(
            f"the last three axes meet pairwise but not at one point (they miss by "
            f"{miss:.6g}), so this is not a spherical-wrist arm"
        )
    _require_crossing(chain, 3, 4)
    _require_crossing(chain, 4, 5)
    _elbow_arm(chain)
    _point_off_axis(chain, centre, 2, "the wrist centre")


def _ur_arm(chain: ChainAxes) -> None:
    _require_parallel(chain, 1, range(2, 4), "this is not a UR arm either")
    _require_crossing(chain, 0, 1)
    _require_apart(chain, 1, 2)
    _require_apart(chain, 2, 3)
    gap = line_gap(chain.joints[4], chain.joints[5])
    if gap > GAP_TOL * chain.scale:
        raise NotClosedForm(
            f"{_pair(chain, 4, 5)} do not intersect (closest approach {gap:.6g}), so this is "
            "not a UR arm either"
        )
    _require_crossing(chain, 3, 4)
    _require_crossing(chain, 4, 5)


def classify(chain: ChainAxes) -> str:
    """The family of a robot's joint lines; raises :class:`NotClosedForm` saying why not.

    >>> import robotconf as rc
    >>> from robotconf.inverse_kinematics.geometry._chain_axes import chain_axes
    >>> classify(chain_axes(rc.preset("scara")))
    'SCARA'
    """
    letters = chain.letters
    if not letters:
        raise NotClosedForm("it has no joint to move")
    try:
        return _parallel_family(chain)
    except NotClosedForm as error:
        planar_why = str(error)
    if letters == "RRR":
        try:
            _elbow_arm(chain)
            _point_off_axis(chain, chain.home[:3, 3], 2, "the end-effector point")
        except NotClosedForm as error:
            raise NotClosedForm(f"{planar_why}; {error}") from None
        return "3R elbow"
    if letters == "RRRRRR":
        whys = []
        for family, check in (("spherical-wrist 6R", _spherical_wrist), ("UR", _ur_arm)):
            try:
                check(chain)
            except NotClosedForm as error:
                whys.append(str(error))
                continue
            return family
        raise NotClosedForm(f"{whys[0]}; {whys[1]}")
    raise NotClosedForm(
        f"its joints are {letters}: closed forms here need 2-4 joints with parallel axes "
        "(planar, SCARA), 3 revolute (elbow arm) or 6 revolute (spherical wrist, UR)"
    )


def recognize(robot: Any, *, constant: Any = ()) -> str | None:
    """The closed-form family of a robot, from its geometry alone.

    Parameters
    ----------
    robot : Robot
        Given by DH rows (either convention), modules, or both.
    constant : int, str or iterable of them
        More modules held at their own ``q`` rather than driven, as :meth:`Robot.index`
        reads them. Modules named ``"… (constant)"`` (the held twists of
        :func:`robotconf.dh_to_modules`) are always held, as in :func:`robotconf.ik`.

    Returns
    -------
    str or None
        One of ``"planar 2R"``, ``"planar 3R"``, ``"SCARA"``, ``"3R elbow"``,
        ``"spherical-wrist 6R"``, ``"UR"``; ``None`` for any other geometry (then
        :func:`ik_all` says what differs).

    Examples
    --------
    >>> import robotconf as rc
    >>> recognize(rc.preset("puma560")), recognize(rc.preset("ur5"))
    ('spherical-wrist 6R', 'UR')
    >>> recognize(rc.preset("paper")), recognize(rc.preset("cartesian"))
    ('3R elbow', None)
    """
    return closed_form_structure(robot, constant)[1]


#: Structures kept (robots are immutable, and an interactive caller asks about a few).
_KEPT = 32
_STRUCTURES: OrderedDict[tuple[Any, ...], tuple[Any, ChainAxes, str | None, str]] = OrderedDict()


def _frozen(chain: ChainAxes) -> ChainAxes:
    """Make the kept arrays read-only: every later call shares them."""
    for array in (
        chain.home,
        chain.reference,
        *(x for j in chain.joints for x in (j.point, j.direction)),
    ):
        array.setflags(write=False)
    return chain


def closed_form_structure(robot: Any, constant: Any = ()) -> tuple[ChainAxes, str | None, str]:
    """A robot's joint lines, its family and why it has none, read once per geometry.

    The joint lines depend on the robot's links, its end-effector point and the values
    of the held modules only: copies made by :meth:`Robot.with_q` share the links'
    kernel description (``robot.geometry()``), so they share one entry here, and the
    answer carries the robot asked about (whose own ``q`` a free joint keeps).

    Returns
    -------
    chain : ChainAxes
    family : str or None
        As :func:`recognize`.
    why : str
        Why there is no closed form (``""`` when there is one), for :func:`refuse`.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.preset("paper")
    >>> chain, family, why = closed_form_structure(arm)
    >>> family, closed_form_structure(arm.with_q([0.1, 0.2, 0.3]))[0].joints is chain.joints
    ('3R elbow', True)
    """
    moving, reference = reference_configuration(robot, constant)
    geometry = robot.geometry()
    key = (
        id(geometry),
        robot.active,
        robot.end_effector_point.tobytes(),
        tuple(moving),
        reference.tobytes(),
    )
    kept = _STRUCTURES.get(key)
    if kept is not None and kept[0] is geometry:
        _STRUCTURES.move_to_end(key)
        chain = kept[1] if kept[1].robot is robot else dataclasses.replace(kept[1], robot=robot)
        return chain, kept[2], kept[3]
    chain = _frozen(axes_at(robot, moving, reference))
    try:
        family, why = classify(chain), ""
    except NotClosedForm as error:
        family, why = None, str(error)
    # The geometry is kept with the entry, so its id cannot be reused while it is here.
    _STRUCTURES[key] = (geometry, chain, family, why)
    while len(_STRUCTURES) > _KEPT:
        _STRUCTURES.popitem(last=False)
    return chain, family, why


def refuse(chain: ChainAxes, why: NotClosedForm) -> InvalidInputError:
    """The error for a robot without a closed form: what differs, and what to use instead."""
    name = chain.robot.name or f"the robot with joints {chain.letters or '(none)'}"
    return InvalidInputError(
        "robot", name, CLOSED_FORMS, problem=f"{why}: there is no closed form for"
    )
