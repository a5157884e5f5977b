"""DH rows ⇄ the paper's modules: the same chain written two ways (a teaching aid).

A module is ``Trans(a)·Rot/Trans_axis(q)`` with one coordinate. A standard DH row is
``Rz(θ+q)·Tz(d)·Tx(a)·Rx(α)`` (revolute), so it needs two or three modules: the joint,
plus the *constant* rotations θ (offset) and α (twist). The paper's modules have no
constant-rotation kind, so a constant rotation is a rotation module whose coordinate is
**held** at the constant — an honest reading of the paper's model, where a module turns
only when its coordinate is driven. Such modules are named ``"… (constant)"``; pass their
positions as ``constant=`` to :func:`modules_to_dh` to convert back.

:func:`modules_to_dh` rewrites a module chain into DH rows using only exact identities
(Rz and Tz commute, Tx and Rx commute, translations commute); it never moves a frame. So it
succeeds exactly when every joint turns about or slides along its own z axis and the
constant parts between joints have the DH order, and otherwise says which module breaks
the pattern and why.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from ._conventions import (
    AXIS_NAMES,
    DH_CONVENTIONS,
    DH_FACTORS,
    DH_SYMBOLS,
    JOINT_LETTERS,
    ROTATION_KINDS,
    dh_formula,
    kind_axis,
    kind_joint_type,
)
from ._dh import DHLink, check_convention, dh_link_from_row
from ._module import Module
from ._robot import Robot

__all__ = ["dh_to_modules", "modules_to_dh"]

_X, _Y, _Z = (AXIS_NAMES.index(axis) for axis in ("x", "y", "z"))
#: Each DH parameter's elementary movement type: θ → Rz, d → Tz, a → Tx, α → Rx.
_FACTOR_KIND = {name: kind for kind, name in DH_FACTORS["standard"]}
#: A DH row's joint module by joint type: its factor about or along z (Rz or Tz).
_JOINT_KIND = {
    kind_joint_type(kind): kind for kind in _FACTOR_KIND.values() if kind_axis(kind) == _Z
}
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
        f"per row: {first}, then {then} ({convention} DH: {dh_formula(convention)}); "
        "no y, no joint about/along x"
    )


_PATTERN = {convention: _pattern(convention) for convention in DH_CONVENTIONS}


def _constant(parameter: str, value: float, owner: str | None, a: Any = (0, 0, 0)) -> Module:
    """A rotation module held at a DH row's constant θ or α."""
    return Module(_FACTOR_KIND[parameter], a=a, q=value, name=_label(DH_SYMBOLS[parameter], owner))


def dh_to_modules(row: Any, convention: str | None = None) -> list[Module]:
    """The elementary modules of one DH row; a robot made of them has the same poses.

    Parameters
    ----------
    row : DHLink, (theta, d, a, alpha, joint) or dict
        Angles in radians, lengths in length units.
    convention : {"standard", "modified"}, optional
        For a tuple or dict row (default ``"standard"``, the paper's eq. 9); a DHLink
        keeps its own, and a different value here is an error.

    Returns
    -------
    list of Module
        Standard, revolute: ``[Rz θ (constant)], Rz q, [Rx α (constant) with a = (a, 0, d)]``;
        prismatic: ``[Rz θ (constant)], Tz q with a = (0, 0, d), [Rx α (constant), a = (a, 0, 0)]``.
        Modified: ``[Rx α (constant)], [Rz θ (constant), a = (a, 0, 0)], joint, [fixed d]``.
        Parts in brackets appear only when non-zero (a ``fixed`` module replaces the Rx
        when only its offset is). The joint module has the row's ``q``, name and range;
        the constant modules' coordinates must be held at their values. The last module's
        frame is the DH frame.

    Raises
    ------
    InvalidInputError
        For a malformed row or a convention that contradicts the DHLink's.

    Examples
    --------
    >>> for module in dh_to_modules((0.5, 0.1, 0.4318, np.pi / 2, "R")):
    ...     print(module)
    Module('Rz', q=0.5, name='θ (constant)')
    Module('Rz')
    Module('Rx', a=(0.4318, 0.0, 0.1), q=1.5707963267948966, name='α (constant)')
    """
    return _expand(_as_link(row, convention))[0]


def _expand(link: DHLink) -> tuple[list[Module], int]:
    """The modules of a DH link and the position of its joint module among them."""
    theta, d, a, alpha, owner = link.theta, link.d, link.a, link.alpha, link.name
    kind = _JOINT_KIND[link.joint_type]
    revolute = link.joint_type == "revolute"
    modules: list[Module] = []
    if link.convention == "standard":
        if theta != 0.0:
            modules.append(_constant("theta", theta, owner))
        joint_offset = (0.0, 0.0, 0.0) if revolute else (0.0, 0.0, d)
        joint = len(modules)
        modules.append(Module(kind, joint_offset, link.q, owner, link.limits))
        tail = (a, 0.0, d if revolute else 0.0)
        if alpha != 0.0:
            modules.append(_constant("alpha", alpha, owner, tail))
        elif any(tail):
            modules.append(Module("fixed", tail, name=_label("a, d", owner)))
        return modules, joint
    if alpha != 0.0:
        modules.append(_constant("alpha", alpha, owner))
    joint_offset = (a, 0.0, 0.0 if revolute else d)
    if theta != 0.0:
        modules.append(_constant("theta", theta, owner, (a, 0.0, 0.0)))
        joint_offset = (0.0, 0.0, joint_offset[2])
    joint = len(modules)
    modules.append(Module(kind, joint_offset, link.q, owner, link.limits))
    if revolute and d != 0.0:
        modules.append(Module("fixed", (0.0, 0.0, d), name=_label("d", owner)))
    return modules, joint


def _label(symbol: str, owner: str | None) -> str:
    return f"{symbol} (constant)" if owner is None else f"{owner}: {symbol} (constant)"


def _as_link(row: Any, convention: str | None) -> DHLink:
    if isinstance(row, DHLink):
        if convention is not None and check_convention(convention) != row.convention:
            raise InvalidInputError(
                "convention",
                convention,
                f"None or the link's own '{row.convention}'",
                problem="contradicts the DHLink's convention:",
            )
        return row
    try:
        return dh_link_from_row(row, check_convention(convention or "standard"), 0)
    except InvalidInputError as error:
        field_name = error.field.replace("rows[0]", "row", 1)
        raise InvalidInputError(field_name, error.value, error.allowed, error.problem) from None


# -- modules → DH --------------------------------------------------------------------------


@dataclass
class _Op:
    """One elementary transform: a translation vector, or a rotation/slide along an axis."""

    kind: str  # _T: constant translation by `vector`; _R/_P: rotate/slide along `axis`
    link: int
    axis: int = 2
    value: float = 0.0
    joint: bool = False
    vector: tuple[float, float, float] = (0.0, 0.0, 0.0)


@dataclass
class _Row:
    stage: str
    theta: float = 0.0
    d: float = 0.0
    a: float = 0.0
    alpha: float = 0.0
    joint: _Op | None = None
    links: list[int] = field(default_factory=list)


class _Misfit(Exception):
    """An op cannot join the current row (carries the explanation)."""

    def __init__(self, link: int, problem: str):
        self.link = link
        self.problem = problem


def _ops(robot: Robot, constant: set[int]) -> list[_Op]:
    ops: list[_Op] = []
    for i, link in enumerate(robot.modules[: robot.active]):
        if isinstance(link, DHLink):
            modules, joint = _expand(link)
            for k, module in enumerate(modules):
                ops.extend(_module_ops(module, i, k == joint))
        elif isinstance(link, Module):
            ops.extend(_module_ops(link, i, link.is_joint and i not in constant))
        else:
            raise InvalidInputError(f"modules[{i}]", link, "Module or DHLink")
    return ops


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
    """Absorb ``op`` into a standard row; return what must start the next row."""
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
        else:
            row.a += x  # Tx commutes with Rx
            if z != 0.0:
                if row.alpha != 0.0:  # Tz cannot pass the twist: it opens the next row
                    return _Op(_T, op.link, vector=(0.0, 0.0, z))
                row.d += z  # …but passes Tx back to the row's Tz(d)
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
    """Absorb ``op`` into a modified (Craig) row; return what must start the next row."""
    _check_axes(op)
    if op.kind == _T:
        x, _, z = op.vector
        if row.stage == "Z" and x != 0.0:
            if row.joint is None:
                raise _Misfit(
                    op.link,
                    "is offset along x after a constant turn about z but "
                    "before any joint, which modified DH cannot express",
                )
            row.d += z  # Tz commutes with the row's Rz and Tz
            return _Op(_T, op.link, vector=(x, 0.0, 0.0))
        row.a += x
        if z != 0.0:
            row.d, row.stage = row.d + z, "Z"
        return None
    if op.axis == _X:
        if row.stage == "Z":
            if row.joint is None:
                raise _Misfit(
                    op.link,
                    "twists about x after a constant turn about z but "
                    "before any joint, which modified DH cannot express",
                )
            return op
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


def modules_to_dh(robot: Robot, convention: str = "standard", *, constant: Any = ()) -> Robot:
    """The same robot as a DH table, when its modules follow the DH pattern.

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
        modules and held modules have none). End-effector positions agree at every q;
        each DH frame is the module frame where its row ends (exactly the group-end
        frames for chains from :func:`dh_to_modules`). Constant transforms after the
        last row that DH cannot hold are folded into the end-effector point.

    Raises
    ------
    InvalidInputError
        Naming the first module that breaks the pattern (``modules[i]``) and why — e.g.
        a joint about y, or an offset along x before its row's joint.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))],
    ...                end_effector=(40, 0, 0))
    >>> modules_to_dh(arm).modules
    (DHLink(theta=0.0, d=20.0, a=30.0, alpha=0.0, joint='R', convention='standard'), \
DHLink(theta=0.0, d=0.0, a=0.0, alpha=0.0, joint='R', convention='standard'))
    >>> modules_to_dh(rc.preset("paper"))
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: modules[1]: module M2 turns about the y axis, but a DH table ...
    """
    convention = check_convention(convention)
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a Robot")
    held = _constant_indices(robot, constant)
    ops = _ops(robot, held)
    joints = [k for k, op in enumerate(ops) if op.joint]
    if not joints:
        raise InvalidInputError(
            "robot", robot.name or "robot", "at least one joint module", problem="has no joint:"
        )
    feed = _feed_standard if convention == "standard" else _feed_modified
    start = "Z" if convention == "standard" else "X"
    rows: list[_Row] = []
    row = _Row(start)
    tail: list[_Op] = []
    for k, op in enumerate(ops):
        trailing = k > joints[-1]
        try:
            rest = feed(row, op)
        except _Misfit as misfit:
            if trailing:
                tail = ops[k:]
                break
            raise _error(robot, misfit, convention) from None
        if rest is None:
            continue
        if trailing:
            tail = [rest, *ops[k + 1 :]]
            break
        rows.append(row)
        row = _Row(start)
        try:
            if feed(row, rest) is not None:  # pragma: no cover - a fresh row takes any op
                raise _Misfit(rest.link, "cannot start a row")
        except _Misfit as misfit:
            raise _error(robot, misfit, convention) from None
    rows.append(row)
    point = _tail_matrix(tail) @ np.append(robot.end_effector_point, 1.0)
    links = [_dh_link(robot, r, convention) for r in rows]
    return Robot(links, end_effector=point[:3], name=robot.name)


def _constant_indices(robot: Robot, constant: Any) -> set[int]:
    items = (
        constant if isinstance(constant, Iterable) and not isinstance(constant, str) else [constant]
    )
    return {robot.index(item, "constant") for item in items}


def _error(robot: Robot, misfit: _Misfit, convention: str) -> InvalidInputError:
    link = robot.modules[misfit.link]
    label = robot.module_names[misfit.link]
    return InvalidInputError(
        f"modules[{misfit.link}]",
        link,
        _PATTERN[convention],
        problem=f"module {label} {misfit.problem}:",
    )


def _tail_matrix(ops: list[_Op]) -> np.ndarray:
    matrix = np.eye(4)
    for op in ops:
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
