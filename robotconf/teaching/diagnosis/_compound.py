"""The same slip in every module of a kind: a rule learnt wrong rather than a one-off slip.

A student who learnt R_y with the signs of R_x and R_z (−sin above the diagonal) writes
every R_y of the chain that way; one who forgets offsets forgets them all. One module
turned the wrong way does not explain such an answer, and neither does any other single
slip, so these candidates apply one link mistake to every module of a kind at once (every
``Ry`` module, every DH row with the parameter), and to every module that allows it when
the kinds differ.
"""

from __future__ import annotations

from typing import Any

from ...kinematics import Module
from ._candidate import COMPOUND, ROTATION_PATTERN, Candidate
from ._context import LINK_CODES, MistakeContext, link_mistakes

__all__ = ["compound_candidates"]

_EVERY_ROTATION = (
    "a positive rotation about x has −sin in entry (2,3), about y +sin in entry (1,3), "
    "about z −sin in entry (1,2)"
)


def _kind(link: Any) -> str:
    return link.kind if isinstance(link, Module) else "DH"


def _labels(modules: list[int]) -> str:
    names = [f"A{j + 1}" for j in modules]
    return ", ".join(names[:-1]) + " and " + names[-1]


def _where(kind: str | None, modules: list[int]) -> str:
    if kind == "DH":  # the rows with the parameter, not necessarily every row
        return f"rows {_labels(modules)}"
    return f"every {kind + ' ' if kind else ''}module ({_labels(modules)})"


def _message(mistake: str, kind: str | None, modules: list[int], axis: str | None) -> str:
    where = _where(kind, modules)
    if mistake == "rotation_direction":
        pattern = (
            f"a positive rotation about {axis} has {ROTATION_PATTERN[axis]}"
            if axis is not None
            else _EVERY_ROTATION
        )
        return (
            f"The sine terms of {where} have the wrong sign — the same slip in each, so these "
            f"joints turn the wrong way: {pattern}."
        )
    if mistake == "offset_after_rotation":
        return (
            f"In {where} the offset is applied after the rotation (Rot·Trans) instead of "
            "before it (Trans·Rot) — the same slip in each: a module first moves its origin "
            "by a in the parent frame, then rotates."
        )
    if mistake == "missing_offset":
        return (
            f"The offsets of {where} are all missing: every module first translates by its "
            "a = (ax, ay, az) in the parent frame — put it in the last column of its matrix."
        )
    if mistake == "missing_d":
        return f"The link offsets d of {where} are all missing: Tz(d) moves along z by d."
    if mistake == "missing_a":
        return f"The link lengths a of {where} are all missing: Tx(a) moves along x by a."
    if mistake == "alpha_sign":
        return (
            f"The twists α of {where} all have the wrong sign: α is measured about x by the "
            "right-hand rule, and Rx(α) has −sin α in entry (2,3) and +sin α in entry (3,2)."
        )
    return (
        f"In {where} the link offset d and the link length a are swapped: d is the distance "
        "along z (Tz(d)), a the distance along x (Tx(a))."
    )


_READINGS = {
    "rotation_direction": "turning {where} the other way",
    "offset_after_rotation": "applying the offset after the rotation in {where}",
    "missing_offset": "leaving out the offsets of {where}",
    "missing_d": "leaving out d in {where}",
    "missing_a": "leaving out a in {where}",
    "alpha_sign": "giving α the wrong sign in {where}",
    "swapped_d_a": "swapping d and a in {where}",
}


def compound_candidates(context: MistakeContext) -> list[Candidate]:
    """One link mistake made in every module of a kind (and in every module allowing it).

    Parameters
    ----------
    context : MistakeContext

    Returns
    -------
    list of Candidate
        Code ``<code>_all`` (``"rotation_direction_all"``, ``"missing_offset_all"``,
        ``"sign_error_all"`` for the twists, …); only groups of at least two modules.

    Examples
    --------
    >>> from robotconf.kinematics import Robot
    >>> from robotconf.teaching import expected_matrix, sample_points
    >>> robot = Robot([Module("Rz"), Module("Ry", a=(0, 0, 20)), Module("Ry", a=(30, 0, 0))])
    >>> env = sample_points(["q1", "q2", "q3"], 2, 0)
    >>> context = MistakeContext(expected_matrix(robot, "M3"), env, 2)
    >>> sorted({c.code for c in compound_candidates(context)})
    ['missing_offset_all', 'offset_after_rotation_all', 'rotation_direction_all']
    """
    robot = context.robot
    by_mistake: dict[str, list[int]] = {}
    for j in context.modules:
        for mistake in link_mistakes(robot.modules[j]):
            by_mistake.setdefault(mistake, []).append(j)
    candidates = []
    for mistake, modules in by_mistake.items():
        by_kind: dict[str, list[int]] = {}
        for j in modules:
            by_kind.setdefault(_kind(robot.modules[j]), []).append(j)
        groups: list[tuple[str | None, list[int]]] = [
            (kind, js) for kind, js in by_kind.items() if len(js) >= 2
        ]
        if len(by_kind) > 1 and len(modules) >= 2:  # the kinds differ: all of them too
            groups.append((None, modules))
        for kind, js in groups:
            axes = {getattr(robot.modules[j], "axis", None) for j in js}
            axis = axes.pop() if len(axes) == 1 else None
            message = _message(mistake, kind, js, axis)
            reading = _READINGS[mistake].format(where=_where(kind, js))
            values = context.value(dict.fromkeys(js, mistake))
            code = LINK_CODES.get(mistake, mistake) + "_all"
            candidates.append(Candidate(code, message, values, reading, COMPOUND))
    return candidates
