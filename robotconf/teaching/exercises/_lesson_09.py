"""Lesson 9's exercises: DH tables of drawn arms, with the student's lengths.

A table is judged by the robot it describes (:func:`~robotconf.teaching.check_dh_table`),
so any right frame choice passes; the slips are the usual one-row slips undone by the
checker's repairs (α's sign, a and d swapped, a θ offset forgotten, a's sign), applied
to the solution's table.
"""

from __future__ import annotations

from typing import Any

from ...kinematics import Module, Robot
from ..checks._dh_table import describes
from ._exercise import Exercise, checkers, register
from ._mistake_models import dh_table_slips

__all__: list[str] = []

LESSON = "09_dh_frame_assignment"


def _dh_exercise(
    number: int,
    title: str,
    draw: Any,
    robot: Any,
    rows: Any,
    shows: Any,
    options: Any = None,
) -> Exercise:
    def settings(numbers: Any) -> dict[str, Any]:
        return options(numbers) if options is not None else {}

    def check(given: Any, numbers: Any) -> Any:
        return checkers().check_dh_table(given, robot(numbers), **settings(numbers))

    def fast(given: Any, numbers: Any) -> bool:
        return describes(given, robot(numbers), **settings(numbers))

    return Exercise(
        LESSON,
        number,
        title,
        draw,
        rows,
        check,
        lambda n: dh_table_slips(rows(n)),
        shows,
        fast,
    )


def _planar(variant: Any, _: Any) -> dict[str, Any]:
    l1 = variant.length("l1", 20, 60, step=5)
    l2 = variant.length("l2", 15, 45, step=5)
    planar = Robot([Module("Rz"), Module("Rz", a=(l1, 0, 0))], end_effector=(l2, 0, 0))
    return {"l1": l1, "l2": l2, "planar": planar}


def _rzrxrx(variant: Any, _: Any) -> dict[str, Any]:
    h = variant.length("h", 15, 40, step=5)
    u = variant.length("u", 20, 50, step=5)
    f = variant.length("f", 20, 50, step=5)
    arm = Robot(
        [Module("Rz"), Module("Rx", a=(0, 0, h)), Module("Rx", a=(0, u, 0))],
        end_effector=(0, f, 0),
    )
    return {"h": h, "u": u, "f": f, "arm": arm}


def _cylindrical(variant: Any, _: Any) -> dict[str, Any]:
    h3 = variant.length("h3", 10, 30, step=5)
    e = variant.length("e", 5, 20, step=5)
    cylindrical = Robot(
        [Module("Rz"), Module("Tz", a=(0, 0, h3)), Module("Tx")], end_effector=(e, 0, 0)
    )
    return {"h3": h3, "e": e, "cylindrical": cylindrical}


register(
    _dh_exercise(
        1,
        "a planar arm's DH table",
        _planar,
        lambda n: n["planar"],
        lambda n: [("q1", 0, n["l1"], 0), ("q2", 0, n["l2"], 0)],
        lambda n: f"Your arm: $l_1 = {n['l1']:g}$ mm, $l_2 = {n['l2']:g}$ mm.",
    ),
    _dh_exercise(
        2,
        "a twist and a θ offset",
        _rzrxrx,
        lambda n: n["arm"],
        lambda n: [("q1 + pi/2", n["h"], 0, "pi/2"), ("q2", 0, n["u"], 0), ("q3", 0, n["f"], 0)],
        lambda n: f"Your arm: $h = {n['h']:g}$ mm, $u = {n['u']:g}$ mm, $f = {n['f']:g}$ mm.",
    ),
    _dh_exercise(
        3,
        "prismatic joints and a θ offset",
        _cylindrical,
        lambda n: n["cylindrical"],
        lambda n: [
            ("q1", 0, 0, 0),
            ("pi/2", f"q2 + {n['h3']:g}", 0, "pi/2"),
            (0, f"q3 + {n['e']:g}", 0, 0),
        ],
        lambda n: f"Your arm: $h = {n['h3']:g}$ mm, $e = {n['e']:g}$ mm.",
    ),
    _dh_exercise(
        4,
        "exercise 2 in the modified convention",
        lambda v, earlier: {},
        lambda n: n["arm"],
        lambda n: [("q1 + pi/2", n["h"], 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, n["u"], 0)],
        None,
        lambda n: {"convention": "modified", "end_effector": (n["f"], 0, 0)},
    ),
)
