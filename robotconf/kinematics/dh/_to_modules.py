"""DH rows ⇄ the paper's modules: the same chain written two ways (a teaching aid).

A module is ``Trans(a)·Rot/Trans_axis(q)`` with one coordinate. A standard DH row is
``Rz(θ+q)·Tz(d)·Tx(a)·Rx(α)`` (revolute), so it needs two or three modules: the joint,
plus the *constant* rotations θ (offset) and α (twist). The paper's modules have no
constant-rotation kind, so a constant rotation is a rotation module whose coordinate is
**held** at the constant — an honest reading of the paper's model, where a module turns
only when its coordinate is driven. Such modules are named ``"… (constant)"``; pass their
positions as ``constant=`` to :func:`~robotconf.kinematics.modules_to_dh` to convert back.
"""

from __future__ import annotations

from typing import Any

from ..._errors import InvalidInputError
from ..conventions._conventions import (
    AXIS_NAMES,
    DH_FACTORS,
    DH_SYMBOLS,
    kind_axis,
    kind_joint_type,
)
from ..links._dh import DHLink, check_convention, dh_link_from_row
from ..links._module import Module

__all__ = ["dh_to_modules"]

_X, _Y, _Z = (AXIS_NAMES.index(axis) for axis in ("x", "y", "z"))
#: Each DH parameter's elementary movement type: θ → Rz, d → Tz, a → Tx, α → Rx.
_FACTOR_KIND = {name: kind for kind, name in DH_FACTORS["standard"]}
#: A DH row's joint module by joint type: its factor about or along z (Rz or Tz).
_JOINT_KIND = {
    kind_joint_type(kind): kind for kind in _FACTOR_KIND.values() if kind_axis(kind) == _Z
}


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
    >>> import numpy as np
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
