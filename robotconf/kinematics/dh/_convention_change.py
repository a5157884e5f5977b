"""A DH table in the other convention: the same robot (:func:`convert_dh`) or the same
numbers (:func:`reinterpret_dh`, a different robot).

Why converting is a regrouping: a row is built from two factors, the joint's
``Z = Rz(θ)·Tz(d)`` (q adds to θ or d) and the link's ``X = Tx(a)·Rx(α)``, which equals
``Rx(α)·Tx(a)`` because a turn about x leaves the x axis alone. A standard row is ``Z·X``
and a modified row ``X·Z``, so a standard chain ``Z1 X1 · Z2 X2 ⋯ Zn Xn`` is the modified
chain ``(I Z1) · (X1 Z2) ⋯ (X(n−1) Zn)`` followed by ``Xn``: θ, d and the joint stay in
their row, a and α move one row down, and the ends need a home (docs/conventions.md, "DH
in the other convention").
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..links._dh import DHLink, check_convention
from ..robot._robot import Robot

__all__ = ["convert_dh", "reinterpret_dh"]

#: A link factor X = Tx(a)·Rx(α) as (a, α).
_Factor = tuple[float, float]
_NO_LINK: _Factor = (0.0, 0.0)


def convert_dh(robot: Robot, convention: str, *, constant: Any = ()) -> Robot:
    """The same robot as a DH table in ``convention``: other numbers, same motion.

    Both conventions attach frame i to link i (the link that joint i moves), with its x
    axis along the common normal from joint i's axis to joint i+1's, but at opposite ends
    of that normal: the **standard** frame i sits on joint i+1's axis (its z), the
    **modified** (Craig) frame i on joint i's axis (its z). So θ, d, the joint, ``q``, the
    name and the range stay in row i, while a and α move one row: standard row i's
    ``(a_i, α_i)`` is modified row i+1's (Craig's table lists ``a_{i−1}, α_{i−1}`` in row i).

    Kept exactly, for every q:

    - the base frame and the **end-effector pose** (its point and its axes);
    - **every joint's axis**, the same line with the same direction (standard z_{i−1},
      modified z_i), so each coordinate moves the robot the same way: the same joint
      axes and the same end-effector Jacobian;
    - **link i's frame up to the row's own length and twist**: standard frame i =
      modified frame i · Tx(a_i) · Rx(α_i), where (a_i, α_i) is standard row i's —
      the same x axis, the origins a_i apart along it, the same angular velocity.

    Frame i itself moves (unless a_i = α_i = 0): no conversion can keep it, because the
    two conventions put it at opposite ends of link i.

    The ends need a home. Standard → modified: modified row 1 gets a = α = 0 (frame 0 is
    the base); the last row's a_n and α_n lie beyond the last joint, so with α_n = 0 the
    end-effector point takes a_n (``P + (a_n, 0, 0)``), and otherwise a row
    ``"tool (constant)" = (θ 0, d 0, a_n, α_n)`` is appended, whose frame is the
    standard frame n (P stays). Modified → standard: the last row gets a = α = 0 and P
    stays; modified row 1's a and α place joint 1 relative to the base (usually 0: Craig
    puts frame 0 on frame 1 at q1 = 0), which standard DH cannot, so when they are not 0
    a row ``"base (constant)" = (θ 0, d 0, a, α)`` comes first. An added row's coordinate
    must stay at 0 (its Jacobian column belongs to a joint you hold); the original joints
    keep their coordinates in order, after the base row if there is one.

    Parameters
    ----------
    robot : Robot
        DH rows only (either convention, even mixed), all active.
    convention : {"standard", "modified"}
        The convention of the result.
    constant : int, str or iterable of them
        Rows whose coordinate is held, as :meth:`Robot.index` reads them (e.g. the
        ``"tool (constant)"`` row an earlier conversion added): a held row that is the
        identity (θ + q = 0 and d = 0 revolute, θ = 0 and d + q = 0 prismatic) is dropped,
        its a and α joining its neighbours', so converting back gives the original rows.
        Any other held row stays a row.

    Returns
    -------
    Robot
        DH rows in ``convention`` (lengths in the robot's units, angles in radians), the
        end-effector point (3,) and the robot's name. A robot already in ``convention``
        comes back equal.

    Raises
    ------
    InvalidInputError
        For a robot with modules (``modules[i]``; :func:`modules_to_dh` writes those as DH
        rows), with inactive rows, an unknown convention or ``constant`` entry, or
        ``constant`` rows that leave no joint.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0.5, 1, np.pi / 2, "R"), (0, 0, 2, 0, "R")])
    >>> craig = convert_dh(arm, "modified")
    >>> [link.row() for link in craig.modules]
    [(0.0, 0.5, 0.0, 0.0, 'R'), (0.0, 0.0, 1.0, 1.5707963267948966, 'R')]
    >>> craig.end_effector_point  # a_2 = 2 lies beyond the last joint: the point takes it
    array([2., 0., 0.])
    >>> np.allclose(craig.end_effector_pose([0.3, -0.4]), arm.end_effector_pose([0.3, -0.4]))
    True
    >>> [link.row() for link in convert_dh(craig, "standard").modules]  # a_2 stays in P
    [(0.0, 0.5, 1.0, 1.5707963267948966, 'R'), (0.0, 0.0, 0.0, 0.0, 'R')]
    """
    convention = check_convention(convention)
    links = _dh_links(robot)
    if robot.active != robot.n:
        raise InvalidInputError(
            "robot",
            f"{robot.active} of {robot.n} rows active",
            "all rows active (robot.with_active(None)); the rows after the active ones would "
            "take the last active row's a and α",
            problem="has inactive rows:",
        )
    held = _held(robot, constant)
    joints, after_last = _regroup(links, held)
    if not joints:
        raise InvalidInputError(
            "constant", constant, "held rows that leave at least one joint", "leaves no joint:"
        )
    taken = {link.name for link, _ in joints}
    point = robot.end_effector_point
    if convention == "standard":
        afters = [before for _, before in joints[1:]] + [after_last]
        rows = [_row(link, x, convention) for (link, _), x in zip(joints, afters, strict=True)]
        base = joints[0][1]
        if base != _NO_LINK:
            rows.insert(0, _held_row("base", base, convention, taken))
    else:
        rows = [_row(link, before, convention) for link, before in joints]
        a, alpha = after_last
        if alpha != 0.0:  # a turn of the tool's axes: only a row can hold it
            rows.append(_held_row("tool", after_last, convention, taken))
        elif a != 0.0:
            point = point + np.array([a, 0.0, 0.0])
    return Robot(rows, end_effector=point, name=robot.name)


def reinterpret_dh(robot: Robot, convention: str) -> Robot:
    """The same numbers read in ``convention``: in general a **different** robot.

    What a standard/modified switch does when it keeps the table: every row keeps θ, d,
    a, α, the joint, ``q``, name and range, and only its convention changes. A standard
    row is ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)`` and a modified one ``Rx(α)·Tx(a)·Rz(θ)·Tz(d)``, so
    the robot changes unless every a and α is 0. To keep the robot, use
    :func:`convert_dh`.

    Parameters
    ----------
    robot : Robot
        DH rows only.
    convention : {"standard", "modified"}

    Returns
    -------
    Robot
        The same rows, end-effector point, active count and name, all in ``convention``.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 1, np.pi / 2, "R"), (0, 0, 2, 0, "R")])
    >>> reinterpret_dh(arm, "modified").modules[0]
    DHLink(theta=0.0, d=0.0, a=1.0, alpha=1.5707963267948966, joint='R', convention='modified')
    >>> arm.end_effector([0.5, 0.0]).round(3), reinterpret_dh(arm, "modified").end_effector(
    ...     [0.5, 0.0]
    ... ).round(3)
    (array([2.633, 1.438, 0.   ]), array([2.755, 0.   , 0.959]))
    """
    convention = check_convention(convention)
    rows = [_row(link, (link.a, link.alpha), convention) for link in _dh_links(robot)]
    active = None if robot.active == robot.n else robot.active
    return Robot(rows, end_effector=robot.end_effector_point, active=active, name=robot.name)


def _dh_links(robot: Robot) -> list[DHLink]:
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a Robot made of DH rows")
    for i, link in enumerate(robot.modules):
        if not isinstance(link, DHLink):
            raise InvalidInputError(
                f"modules[{i}]",
                link,
                "DH rows (DHLink) only; modules_to_dh(robot, convention) writes modules as DH rows",
                problem="is not a DH row:",
            )
    return [link for link in robot.modules if isinstance(link, DHLink)]


def _held(robot: Robot, constant: Any) -> set[int]:
    items = (
        constant if isinstance(constant, Iterable) and not isinstance(constant, str) else [constant]
    )
    return {robot.index(item, "constant") for item in items}


def _regroup(links: list[DHLink], held: set[int]) -> tuple[list[tuple[DHLink, _Factor]], _Factor]:
    """Each joint with the link factor X before it, and the X after the last joint.

    A standard row's X follows its joint and a modified row's precedes it; two X in a row
    (mixed conventions, or a dropped held row between them) multiply into one, exactly:
    ``Tx(a)·Rx(α)·Tx(b)·Rx(β) = Tx(a + b)·Rx(α + β)``.
    """
    joints: list[tuple[DHLink, _Factor]] = []
    pending = _NO_LINK
    for i, link in enumerate(links):
        factor = (link.a, link.alpha)
        if link.convention == "modified":
            pending = _then(pending, factor)
        if not (i in held and _is_identity(link)):
            joints.append((link, pending))
            pending = _NO_LINK
        if link.convention == "standard":
            pending = _then(pending, factor)
    return joints, pending


def _then(first: _Factor, second: _Factor) -> _Factor:
    if first == _NO_LINK:
        return second  # keeps the numbers exactly as given
    if second == _NO_LINK:
        return first
    return (first[0] + second[0], first[1] + second[1])


def _is_identity(link: DHLink) -> bool:
    """Whether the row's joint factor Rz(θ)·Tz(d), with q held, does nothing."""
    if link.joint == "R":
        return link.theta + link.q == 0.0 and link.d == 0.0
    return link.theta == 0.0 and link.d + link.q == 0.0


def _row(link: DHLink, factor: _Factor, convention: str) -> DHLink:
    return DHLink(
        link.theta,
        link.d,
        factor[0],
        factor[1],
        link.joint,
        convention,
        q=link.q,
        name=link.name,
        limits=link.limits,
    )


def _held_row(end: str, factor: _Factor, convention: str, taken: set[str | None]) -> DHLink:
    """A row that only carries a link factor: its joint is held at 0, like a module's
    ``"(constant)"`` coordinate (docs/conventions.md, "DH ⇄ modules")."""
    name, k = f"{end} (constant)", 2
    while name in taken:
        name, k = f"{end} {k} (constant)", k + 1
    return DHLink(0.0, 0.0, factor[0], factor[1], "R", convention, name=name)
