"""The hint sentences of :func:`~robotconf.teaching.check_dh_table`.

They name the row and the parameter to look at and say what it measures, never the right
value (unless the check reveals). Parameter names follow the convention: a standard row i
holds ``a_i, α_i``, a modified row i holds ``a_{i-1}, α_{i-1}``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._dh_table_text import DHRow

__all__ = [
    "NO_ANSWER",
    "convention_hint",
    "degrees_hint",
    "exchanged_hint",
    "generic_hint",
    "joint_type_hint",
    "negative_lengths_hint",
    "repair_hint",
    "row_count_hint",
    "swapped_columns_hint",
]


NO_ANSWER = "No answer yet: replace None with your DH table, one row per joint."
_JOINT_WORDS = {"R": "revolute", "P": "prismatic"}
_FORMULAS = {"standard": "Rz(θ)·Tz(d)·Tx(a)·Rx(α)", "modified": "Rx(α)·Tx(a)·Rz(θ)·Tz(d)"}


@dataclass(frozen=True)
class _Names:
    """What row i's parameters are called, and the axes they are measured along."""

    theta: str
    d: str
    a: str
    alpha: str
    z_from: str  # α turns this z axis …
    z_to: str  # … onto this one, which is joint `joint`'s axis
    x_about: str  # α is measured about, a along this x axis
    z_d: str  # d is measured along this z axis
    joint: int


def _names(r: int, convention: str) -> _Names:
    i = r + 1
    if convention == "standard":
        return _Names(
            f"θ{i}", f"d{i}", f"a{i}", f"α{i}", f"z{i - 1}", f"z{i}", f"x{i}", f"z{i - 1}", i + 1
        )
    return _Names(
        f"θ{i}", f"d{i}", f"a{i - 1}", f"α{i - 1}", f"z{i - 1}", f"z{i}", f"x{i - 1}", f"z{i}", i
    )


def _number(value: float) -> str:
    for k, text in ((0.5, "pi/2"), (-0.5, "-pi/2"), (1.0, "pi"), (-1.0, "-pi")):
        if np.isclose(value, k * np.pi, rtol=0, atol=1e-12):
            return text
    return f"{value:.6g}"


def repair_hint(
    code: str,
    r: int,
    convention: str,
    repaired: DHRow | None = None,
    *,
    written: float | None = None,
) -> str:
    """The hint for a single-row mistake (``code`` as in ``DHTableCheck.diagnosis``);
    ``written``: for ``d_value``/``a_value``, the length the row holds where another
    belongs (None: the row has 0 there, a constant left out).

    >>> print(repair_hint("alpha_sign", 0, "standard"))  # doctest: +ELLIPSIS
    Row 1: check the sign of α1. With it, z1 points the wrong way, so joint 2 turns ...
    """
    n = _names(r, convention)
    i = r + 1
    texts = {
        "alpha_sign": (
            f"Row {i}: check the sign of {n.alpha}. With it, {n.z_to} points the wrong way, "
            f"so joint {n.joint} turns backwards. {n.alpha} is the angle from {n.z_from} to "
            f"{n.z_to}, measured about {n.x_about} by the right-hand rule."
        ),
        "swapped_a_d": (
            f"Row {i}: {n.a} and {n.d} look swapped. {n.d} is the distance along {n.z_d} "
            f"(between x{i - 1} and x{i}); {n.a} is the distance along {n.x_about} "
            f"(between {n.z_from} and {n.z_to})."
        ),
        "theta_offset": (
            f"Row {i}: at q{i} = 0 your frame {i} is turned about {n.z_d} against the "
            f"robot's zero position (the joint's zero moved): check the constant in "
            f"{n.theta}, the angle from x{i - 1} to x{i} when q{i} = 0."
        ),
        "twist": (
            f"Row {i}: {n.alpha} does not turn {n.z_from} onto joint {n.joint}'s axis: "
            f"{n.z_to} must lie along that axis, pointing the way the joint turns."
        ),
        "a_sign": (
            f"Row {i}: check the sign of {n.a}: it is measured along {n.x_about}, "
            f"from {n.z_from} to {n.z_to}."
        ),
        "d_sign": (
            f"Row {i}: check the sign of {n.d}: it is measured along {n.z_d}, "
            f"from x{i - 1} to x{i}."
        ),
        "d_value": (
            f"Row {i}: {n.d} misses a constant: the distance along {n.z_d} from x{i - 1} to "
            f"x{i} at q = 0 (a height, or where a slide starts) belongs in {n.d}, besides "
            "the joint variable of a slide."
        ),
        "a_value": (
            f"Row {i}: {n.a} misses a constant: the distance along {n.x_about} from "
            f"{n.z_from} to {n.z_to} (a link's length) belongs in {n.a}."
        ),
    }
    text = texts[code]
    if written is not None and code in ("d_value", "a_value"):
        field, along = (
            (n.d, f"{n.z_d} from x{i - 1} to x{i}")
            if code == "d_value"
            else (
                n.a,
                f"{n.x_about} from {n.z_from} to {n.z_to}",
            )
        )
        text = (
            f"Row {i}: {field} = {_number(written)} is not the robot's: {field} is the "
            f"distance along {along} at q = 0 — check which length of the drawing goes "
            "there (another link's length, or one measured from another joint?)."
        )
    if repaired is not None:
        theta, d, a, alpha, joint = repaired
        text += (
            f" A right row {i}: θ = {_number(theta)}, d = {_number(d)}, a = {_number(a)}, "
            f"α = {_number(alpha)} ({joint}; q{i} added to {'θ' if joint == 'R' else 'd'})."
        )
    return text


def exchanged_hint(code: str, rows: tuple[int, int], convention: str) -> str:
    """Two rows' a (or d) exchanged: each row holds the other's length (rows 0-based).

    >>> exchanged_hint("a_value", (0, 1), "standard")  # doctest: +ELLIPSIS
    'Rows 1 and 2: a1 and a2 look exchanged: ...'
    """
    first, second = (_names(r, convention) for r in rows)
    if code == "d_value":
        names, what = (first.d, second.d), "d is the distance along the joint's z axis"
    else:
        names, what = (first.a, second.a), "a is the length of the link along its x axis"
    return (
        f"Rows {rows[0] + 1} and {rows[1] + 1}: {names[0]} and {names[1]} look exchanged: "
        f"{what}, so each row takes the length of its own link (which link comes after "
        "which joint?)."
    )


def swapped_columns_hint(rows: list[int], convention: str) -> str:
    """a and d swapped in several rows: the table's columns mixed up.

    >>> swapped_columns_hint([1, 2], "standard")  # doctest: +ELLIPSIS
    'In rows 1 and 2, a and d look swapped: ...'
    """
    listed = ", ".join(str(r) for r in rows[:-1]) + f" and {rows[-1]}"
    along = "z_(i-1)" if convention == "standard" else "z_i"
    return (
        f"In rows {listed}, a and d look swapped: the columns are (θ, d, a, α) — d is the "
        f"distance along {along} (between the x axes), a the distance along the common "
        "normal x (between the z axes)."
    )


def convention_hint(asked: str, other: str, whole: bool) -> str:
    """The table fits the robot when read in the other convention."""
    fits = "describe the robot" if whole else "put every joint axis in the right place"
    return (
        f"Your rows {fits} when read as a {other} DH table, but this exercise asks for the "
        f"{asked} convention, {_FORMULAS[asked]}. In a standard table row i holds a_i and "
        f"α_i of the link after joint i; in a modified table row i holds a_(i-1) and "
        f"α_(i-1) of the link before it, and the last link's length goes into the tool "
        f"point."
    )


def negative_lengths_hint(rows: list[int], convention: str) -> str:
    """Several rows' a negative (1-based rows): the lengths' sign, not the frames.

    >>> negative_lengths_hint([1, 2], "standard")  # doctest: +ELLIPSIS
    'Rows 1 and 2: check the sign of a1 and a2: ...'
    """
    names = [_names(r - 1, convention).a for r in rows]
    listed = ", ".join(str(r) for r in rows[:-1]) + f" and {rows[-1]}"
    fields = ", ".join(names[:-1]) + f" and {names[-1]}"
    return (
        f"Rows {listed}: check the sign of {fields}: a is the distance along the common "
        "normal x, from one joint axis to the next, and your x axes point that way — so "
        "the lengths are positive."
    )


def degrees_hint() -> str:
    """The angles were typed in degrees."""
    return (
        "Your angles look like degrees: a DH table takes radians (write -pi/2, not -90; "
        "pi/6, not 30)."
    )


def row_count_hint(rows: int, joints: int) -> str:
    """The table has too few or too many rows."""
    plural = "s" if rows != 1 else ""
    text = (
        f"Your table has {rows} row{plural}, but the robot has {joints} joints: one row per joint."
    )
    if rows < joints:
        return text + " A row is missing."
    return text + (
        " A constant offset between two joints goes into d or a of a neighbouring row, "
        "not into a row of its own."
    )


def joint_type_hint(r: int, letter: str) -> str:
    """Row r's joint has the wrong type."""
    i = r + 1
    place = "θ" if letter == "R" else "d"
    return (
        f"Row {i}: joint {i} is {_JOINT_WORDS[letter]}, so its variable q{i} belongs in "
        f"{place} (a revolute joint moves θ, a prismatic joint moves d)."
    )


def generic_hint(
    first_wrong: int | None, reversed_axis: bool, convention: str, rows: int, tool: bool
) -> tuple[str, str]:
    """(code, hint) when no single repair explains the table.

    ``first_wrong``: 0-based first joint whose axis is wrong (None: all right, the
    end-effector is not); ``reversed_axis``: that axis is the right line, pointing the
    other way; ``tool``: the exercise gives a tool point.
    """
    if first_wrong is None:
        if convention == "standard":
            where = f"check the constants of the last row (d{rows} and a{rows})" + (
                " and the tool point" if tool else f": the tool sits at the origin of frame {rows}"
            )
        else:
            where = (
                f"check d{rows} and the tool point: in a modified table the last link's "
                "length goes into the tool point"
            )
        return "end_effector", f"Every joint axis is right, but the end-effector is not: {where}."
    j = first_wrong + 1
    z = f"z{j - 1}" if convention == "standard" else f"z{j}"
    last = j - 1 if convention == "standard" else j
    rows_text = "row 1" if last == 1 else f"rows 1-{last}"
    if reversed_axis:
        return "reversed_axis", (
            f"Joint {j}: your {z} lies along the right line but points the other way, so a "
            f"positive q{j} turns the robot backwards (look at the twists α in {rows_text})."
        )
    if convention == "standard" and j == 1:
        return "axis", "Joint 1's axis must be z0, the base frame's z axis."
    start = "" if last == 1 else f"; start with row {last}"
    return "axis", (
        f"Joint {j}'s axis is not where your table puts {z}: {z} must lie along joint "
        f"{j}'s axis. It is placed by {rows_text}{start}."
    )
