"""Modules → DH rows: the paper's chain regrouped into a DH table of either convention.

The way back from :func:`~robotconf.kinematics.dh_to_modules`
(:mod:`robotconf.kinematics.dh._to_modules`, whose notes say how a constant θ or α is
a module held at its value).

:func:`modules_to_dh` groups whole modules into DH rows using only exact identities (Rz
and Tz commute, Tx and Rx commute, translations commute), so every DH frame is the frame
of the module that ends its row: it never moves a frame. It succeeds exactly when every
joint turns about or slides along its own z axis and the constant parts between joints
have the DH order with a module ending where each DH frame sits, and otherwise says which
module breaks the pattern and why.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..conventions._conventions import (
    AXIS_NAMES,
    DH_CONVENTIONS,
    DH_FACTORS,
    JOINT_LETTERS,
    ROTATION_KINDS,
    dh_formula,
    kind_axis,
)
from ..links._dh import DHLink, check_convention
from ..links._module import Module
from ..robot._robot import Robot
from ._to_modules import _X, _Y, _Z, _expand

__all__ = ["modules_to_dh"]

#: The rotation module about each axis index.
_ROTATION = {kind_axis(kind): kind for kind in ROTATION_KINDS}
#: Kinds of elementary ops: a turn or a slide (the joint letters), or a constant translation.
_R, _P, _T = JOINT_LETTERS["revolute"], JOINT_LETTERS["prismatic"], "T"


def _pattern(convention: str) -> str:
    """What a chain must look like to become DH rows, read from the convention's factors."""
    factors = [kind for kind, _ in DH_FACTORS[convention]]
    about_z = "/".join(kind for kind in factors if kind_axis(kind) == _Z)
    about_x = " and ".join(kind for kind in factors if kind_axis(kind) == _X)
    z_part = f"joint about/along z with constant {about_z}"
    x_part = f"constant {about_x}"
    first, then = (z_part, x_part) if kind_axis(factors[0]) == _Z else (x_part, z_part)
    return (
        f"per row: {first}, then {then} ({convention} DH: {dh_formula(convention)}), each "
        "row made of whole modules (its DH frame is the frame of its last module); no y, no "
        "joint about/along x"
    )


_PATTERN = {convention: _pattern(convention) for convention in DH_CONVENTIONS}


@dataclass(frozen=True)
class _Op:
    """One elementary transform: a translation vector, or a rotation/slide along an axis."""

    kind: str  # _T: constant translation by `vector`; _R/_P: rotate/slide along `axis`
    link: int
    axis: int = 2
    value: float = 0.0
    joint: bool = False
    vector: tuple[float, float, float] = (0.0, 0.0, 0.0)


@dataclass(frozen=True)
class _Piece:
    """One link of the chain as elementary ops. A DH frame can only sit where a piece ends:
    the frames inside a module (after its offset, before its motion) are nobody's frames."""

    link: int
    ops: tuple[_Op, ...]

    @property
    def joint(self) -> bool:
        return any(op.joint for op in self.ops)

    @property
    def turns_about_z(self) -> bool:
        return any(op.kind == _R and not op.joint and op.axis == _Z for op in self.ops)


@dataclass
class _Row:
    stage: str
    theta: float = 0.0
    d: float = 0.0
    a: float = 0.0
    alpha: float = 0.0
    joint: _Op | None = None


class _Misfit(Exception):
    """An op cannot join the current row (carries the explanation)."""

    def __init__(self, link: int, problem: str):
        self.link = link
        self.problem = problem


def _pieces(robot: Robot, constant: set[int]) -> list[_Piece]:
    pieces = []
    for i, link in enumerate(robot.modules[: robot.active]):
        if isinstance(link, DHLink):
            modules, joint = _expand(link)
            ops = [
                op
                for k, module in enumerate(modules)
                for op in _module_ops(module, i, k == joint and i not in constant)
            ]
        elif isinstance(link, Module):
            ops = _module_ops(link, i, link.is_joint and i not in constant)
        else:
            raise InvalidInputError(f"modules[{i}]", link, "Module or DHLink")
        pieces.append(_Piece(i, tuple(ops)))
    return pieces


def _module_ops(module: Module, index: int, joint: bool) -> list[_Op]:
    ops = [_Op(_T, index, vector=module.a)] if any(module.a) else []
    axis = kind_axis(module.kind)
    if axis is not None and (joint or module.q != 0.0):
        letter = JOINT_LETTERS[module.joint_type]
        # A held slide is just a constant translation; a held turn stays a rotation.
        kind = letter if joint or letter == _R else _T
        ops.append(_Op(kind, index, axis, module.q, joint, _axis_vector(axis, module.q)))
    return ops


def _axis_vector(axis: int, value: float) -> tuple[float, float, float]:
    vector = [0.0, 0.0, 0.0]
    vector[axis] = value
    return (vector[0], vector[1], vector[2])


def _describe(op: _Op) -> str:
    if op.kind == _T:
        axes = " and ".join(AXIS_NAMES[k] for k in range(3) if op.vector[k] != 0.0)
        return f"an offset along {axes}"
    if op.joint:
        return "a second joint"
    return "a twist about x" if op.axis == _X else f"a constant turn about {AXIS_NAMES[op.axis]}"


def _y_problem(op: _Op) -> str:
    what = {_R: "turns about", _P: "slides along", _T: "is offset along"}[op.kind]
    return (
        f"{what} the y axis, but a DH table has no y: every row turns/slides along z and "
        "twists about x"
    )


def _check_axes(op: _Op) -> None:
    if op.kind == _T and op.vector[_Y] != 0.0 or op.kind != _T and op.axis == _Y:
        raise _Misfit(op.link, _y_problem(op))
    if op.joint and op.axis == _X:
        what = "turns about" if op.kind == _R else "slides along"
        raise _Misfit(
            op.link, f"is a joint that {what} x, but every DH joint turns about or slides along z"
        )


def _feed_standard(row: _Row, op: _Op) -> _Op | None:
    """Absorb ``op`` into a standard row; return it when it must start the next row."""
    _check_axes(op)
    if op.kind == _T:
        x, _, z = op.vector
        if row.stage == "Z":
            if x != 0.0 and row.joint is None:
                raise _Misfit(
                    op.link,
                    "is offset along x before its row's joint, but in "
                    "standard DH the offset a (along x) follows the joint",
                )
            row.d += z
            if x != 0.0:
                row.a, row.stage = row.a + x, "X"
        elif z != 0.0 and row.alpha != 0.0:
            return op  # Tz cannot pass the twist: it belongs to the next row
        else:
            row.a += x  # Tx commutes with Rx…
            row.d += z  # …and, without a twist, Tz passes Tx back to the row's Tz(d)
        return None
    if op.axis == _X:  # a held rotation about x: the twist α
        if row.joint is None:
            raise _Misfit(
                op.link,
                "twists about x before its row's joint, but in standard "
                "DH the twist α follows the joint",
            )
        row.alpha, row.stage = row.alpha + op.value, "X"
        return None
    if row.stage == "X" or (op.joint and row.joint is not None):
        return op  # about/along z after the x part, or a second joint: the next row
    if op.joint:
        row.joint = op
    else:
        row.theta += op.value
    return None


def _feed_modified(row: _Row, op: _Op) -> _Op | None:
    """Absorb ``op`` into a modified (Craig) row; return it when it must start the next row.

    Stages: ``X`` (the twist and offset a), ``Tz`` (an offset along z came, which commutes
    with Tx but not with the twist), ``Z`` (a turn about z or the joint came).
    """
    _check_axes(op)
    if op.kind == _T:
        x, _, z = op.vector
        if x != 0.0 and row.stage == "Z":
            if row.joint is None:
                raise _Misfit(
                    op.link,
                    "is offset along x after a constant turn about z but "
                    "before any joint, which modified DH cannot express",
                )
            return op  # the next row's a
        row.a += x
        if z != 0.0:
            row.d += z
            row.stage = "Z" if row.stage == "Z" else "Tz"
        return None
    if op.axis == _X:
        if row.stage != "X":
            if row.joint is None:
                after = "a constant turn about z" if row.stage == "Z" else "an offset along z"
                raise _Misfit(
                    op.link,
                    f"twists about x after {after} but before any joint, which modified DH "
                    "cannot express",
                )
            return op  # the next row's α
        row.alpha += op.value
        return None
    if op.joint and row.joint is not None:
        return op
    row.stage = "Z"
    if op.joint:
        row.joint = op
    else:
        row.theta += op.value
    return None


_FEED = {"standard": _feed_standard, "modified": _feed_modified}
_START = {"standard": "Z", "modified": "X"}


def _absorb(row: _Row, piece: _Piece, convention: str) -> _Row:
    """A copy of ``row`` with all of ``piece`` in it; ``_Misfit`` if the row cannot end there."""
    grown = replace(row)
    for op in piece.ops:
        if _FEED[convention](grown, op) is not None:
            raise _Misfit(
                piece.link,
                f"has {_describe(op)} after its joint, which only the next DH row can hold; "
                "that row would start inside the module, where there is no frame",
            )
    return grown


def _fill(chunk: list[_Piece], convention: str) -> _Row:
    """One row made of ``chunk``: the pieces from where it starts up to its joint's piece."""
    row = _Row(_START[convention])
    for piece in chunk:
        row = _absorb(row, piece, convention)
    return row


def _fit_rows(
    pieces: list[_Piece], joints: list[int], convention: str
) -> tuple[list[_Row], list[_Piece]]:
    """The DH rows, and the pieces after the last one (for the end-effector point)."""
    row = _fill(pieces[: joints[0] + 1], convention)
    rows = []
    for joint, following in zip(joints, joints[1:], strict=False):  # pairs of neighbours
        done, row = _split(row, pieces, joint, following, convention)
        rows.append(done)
    end = joints[-1] + 1
    while end < len(pieces):  # the last row takes what it can; the rest has no row
        try:
            row = _absorb(row, pieces[end], convention)
        except _Misfit:
            break
        end += 1
    rows.append(row)
    return rows, pieces[end:]


def _split(
    row: _Row, pieces: list[_Piece], joint: int, following: int, convention: str
) -> tuple[_Row, _Row]:
    """End ``row`` (filled up to its joint's piece) at a piece before the next joint's.

    Returns the finished row and the next one, filled up to the next joint's piece.
    """
    ends = [row]  # ends[k]: the row with the k pieces after its joint's; no more fit
    for piece in pieces[joint + 1 : following]:
        try:
            ends.append(_absorb(ends[-1], piece, convention))
        except _Misfit:
            break
    starts: dict[int, _Row] = {}
    misfits: list[_Misfit] = []
    for start in range(joint + 1, joint + len(ends) + 1):
        try:
            starts[start] = _fill(pieces[start : following + 1], convention)
        except _Misfit as misfit:
            misfits.append(misfit)
    if not starts:  # explain the latest start: the row before could not end any later
        raise _with_hint(misfits[-1], ends[-1], pieces[joint + len(ends)], convention)
    start = _boundary(sorted(starts), pieces, joint, following)
    return ends[start - joint - 1], starts[start]


def _boundary(starts: list[int], pieces: list[_Piece], joint: int, following: int) -> int:
    """Where the next row starts when it could start at several pieces.

    Only constants along the common z axis (shifts and turns, which commute) can go either
    way. Shifts stay with the earlier joint and turns go with the later one: where
    :func:`dh_to_modules` puts a row's d and θ, so its chains come back with their frames.
    """
    turn = next((k for k in range(joint + 1, following) if pieces[k].turns_about_z), following)
    later = [start for start in starts if start >= turn]
    return later[0] if later else starts[-1]


def _with_hint(misfit: _Misfit, row: _Row, piece: _Piece, convention: str) -> _Misfit:
    """Say how to fix a module that the end of a row would cut in two."""
    first = piece.ops[0] if piece.ops else None
    if misfit.link != piece.link or first is None or first.kind != _T:
        return misfit
    x, _, z = first.vector
    feed = _FEED[convention]
    if len(piece.ops) > 1 and feed(replace(row), first) is None:
        hint = (
            f"its offset {first.vector} would fit the row before only as a module of its "
            "own (a fixed module in front of it)"
        )
    elif x != 0.0 and z != 0.0 and feed(replace(row), replace(first, vector=(x, 0.0, 0.0))) is None:
        hint = "its x part would fit the row before, its z part the next: split it in two"
    else:
        return misfit
    return _Misfit(misfit.link, f"{misfit.problem}; {hint}, as every DH frame is a module's frame")


def modules_to_dh(robot: Robot, convention: str = "standard", *, constant: Any = ()) -> Robot:
    """The same robot as a DH table with the same frames, when its modules allow one.

    Parameters
    ----------
    robot : Robot
        Modules (and DH links, which are expanded first); only the active ones count.
    convention : {"standard", "modified"}
        The DH convention of the result.
    constant : int, str or iterable of them
        Modules whose coordinate is held, as :meth:`Robot.index` reads them (0-based index,
        module name or coordinate name): their current ``q`` is a constant rotation or
        offset, not a joint (as :func:`dh_to_modules` produces).

    Returns
    -------
    Robot
        One DH row per joint, in chain order, with the joint module's ``q``, name and
        range. Coordinate k of the result is the k-th joint module's coordinate (``none``
        modules and held modules have none).

        **Every DH frame is a frame of the input.** Row i is made of whole modules and
        DH frame i is the frame of the module where row i ends, so the frames, their
        Jacobians and velocities agree, not only the end-effector (for a chain from
        :func:`dh_to_modules`: exactly the DH frames it came from). Where row i could end
        at several modules (constant shifts along and turns about the z axis between two
        joints commute), the shifts stay with joint i and the turns go with joint i+1,
        as :func:`dh_to_modules` places d and θ. Constants after the last joint that its
        row cannot hold are folded into the end-effector point (the point is kept; its
        axes are those of the last DH frame).

    Raises
    ------
    InvalidInputError
        Naming the first module that breaks the pattern (``modules[i]``) and why — e.g.
        a joint about y, an offset along x before its row's joint in standard DH, or a
        module that a DH frame would have to cut in two. A DH row of the other convention
        has other frames: :func:`~robotconf.convert_dh` converts those.

    Examples
    --------
    Modified DH frames sit on the joint axes, like these modules' frames:

    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))],
    ...                end_effector=(40, 0, 0))
    >>> [link.row() for link in modules_to_dh(arm, "modified").modules]
    [(0.0, 20.0, 0.0, 0.0, 'R'), (0.0, 0.0, 30.0, 0.0, 'R')]

    Standard DH frame 1 would sit on joint 2's axis, inside module M2 (after its offset):

    >>> modules_to_dh(arm, "standard")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: modules[1]: module M2 is offset along x before its row's ...
    >>> modules_to_dh(rc.preset("paper"))
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: modules[1]: module M2 turns about the y axis, but a DH table ...
    """
    convention = check_convention(convention)
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a Robot")
    pieces = _pieces(robot, _constant_indices(robot, constant))
    joints = [k for k, piece in enumerate(pieces) if piece.joint]
    if not joints:
        raise InvalidInputError(
            "robot", robot.name or "robot", "at least one joint module", problem="has no joint:"
        )
    try:
        for piece in pieces[: joints[-1] + 1]:  # what no row can hold, wherever it goes
            for op in piece.ops:
                _check_axes(op)
        rows, tail = _fit_rows(pieces, joints, convention)
    except _Misfit as misfit:
        raise _error(robot, misfit, convention) from None
    point = _tail_matrix(tail) @ np.append(robot.end_effector_point, 1.0)
    links = [_dh_link(robot, r, convention) for r in rows]
    return Robot(links, end_effector=point[:3], name=robot.name)


def _constant_indices(robot: Robot, constant: Any) -> set[int]:
    items = (
        constant if isinstance(constant, Iterable) and not isinstance(constant, str) else [constant]
    )
    return {robot.index(item, "constant") for item in items}


#: Where each convention's frame i sits on link i.
_END = {
    "standard": "far end of its link (on the next joint's axis)",
    "modified": "near end of its link (on its own joint's axis)",
}


def _error(robot: Robot, misfit: _Misfit, convention: str) -> InvalidInputError:
    link = robot.modules[misfit.link]
    label = robot.module_names[misfit.link]
    problem = f"module {label} {misfit.problem}"
    if isinstance(link, DHLink) and link.convention != convention:
        problem = (
            f"module {label} is a {link.convention} DH row, whose frame sits at the "
            f"{_END[link.convention]}; "
            f"a {convention} DH frame sits at the {_END[convention]}. "
            f"convert_dh(robot, {convention!r}) gives the same robot in {convention} DH"
        )
    return InvalidInputError(
        f"modules[{misfit.link}]", link, _PATTERN[convention], problem=f"{problem}:"
    )


def _tail_matrix(pieces: list[_Piece]) -> np.ndarray:
    matrix = np.eye(4)
    for op in (op for piece in pieces for op in piece.ops):
        if op.kind == _T:
            matrix = matrix @ Module("fixed", a=op.vector).matrix()
        else:
            matrix = matrix @ Module(_ROTATION[op.axis], q=op.value).matrix()
    return matrix


def _dh_link(robot: Robot, row: _Row, convention: str) -> DHLink:
    joint = row.joint
    assert joint is not None  # every finished row has its joint
    source = robot.modules[joint.link]
    return DHLink(
        row.theta,
        row.d,
        row.a,
        row.alpha,
        joint.kind,  # a joint op's kind is its joint letter
        convention,
        q=joint.value,
        name=source.name,
        limits=getattr(source, "limits", None),
    )
