"""Lesson 12's exercises: time laws, a synchronized PTP, a LIN into a near-singular pose.

The profile answers are checked by :func:`~robotconf.teaching.check_profile`, whose own
slips (:mod:`robotconf.teaching.profiles`) are this lesson's typical mistakes: a triangle
taken for a trapezoid, ``2v/a``, a forgotten synchronization, the largest move taken for
the slowest, the slowest joint's own time where two joints' limits bind. The numbers of
the synchronized PTP are screened so that each of these gives a refused answer.
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np

from ...inverse_kinematics import ik
from ...kinematics import jacobian
from ...presets import preset
from ...programs import LIN, PTP, Program
from ..profiles import ProfileTask
from ..profiles._slips import profile_slips
from ._exercise import Exercise, checkers, register
from ._kinds import EXERCISE_SLIPS, matches, name_slip, value_exercise

__all__ = ["program_5", "profile_exercise"]

LESSON = "12_trajectories"
_FORM_NAMES = {"parameters": "the trapezoid", "peak_speed": "the peak speed"}


def profile_exercise(
    number: int,
    title: str,
    draw: Any,
    task: Any,
    options: Any,
    answer: Any,
    shows: Any = None,
) -> Exercise:
    """An exercise checked by :func:`check_profile` against ``task(numbers)``; its slips
    are the profile checker's own."""

    def check(given: Any, numbers: Any) -> Any:
        return checkers().check_profile(given, task(numbers), **options(numbers))

    def form(numbers: Any) -> str:
        return str(options(numbers).get("form") or task(numbers).default_form())

    def fast(given: Any, numbers: Any) -> bool:
        right = task(numbers).expected(form(numbers))
        values = np.asarray(given, dtype=float)
        if values.size != right.size and form(numbers) == "duration" and right.ndim == 0:
            return bool(values.size > 1 and matches(values, np.full(values.size, right)))
        return matches(values, right)

    def slips(numbers: Any) -> dict[str, Any]:
        found: dict[str, Any] = {}
        for slip in profile_slips(task(numbers), form(numbers), None, keep_equal=True):
            key = slip.code if slip.code not in found else f"{slip.code}[{len(found)}]"
            found[key] = slip.values.tolist()
        return found

    return Exercise(LESSON, number, title, draw, answer, check, slips, shows, fast)


def _limits(variant: Any, _: Any) -> dict[str, Any]:
    return {
        "d1": variant.length("d1", 1.0, 2.5, step=0.1),  # rad
        "v_max": variant.length("v_max", 0.5, 1.0, step=0.1),  # rad/s
        "a_max": variant.length("a_max", 1.0, 2.5, step=0.5),  # rad/s²
    }


def _short(variant: Any, earlier: Any) -> dict[str, Any]:
    share = variant.choice("d2 share", [0.25, 0.36, 0.49, 0.64])
    return {"d2": float(f"{share * earlier['v_max'] ** 2 / earlier['a_max']:.3g}")}


def _quintic(variant: Any, _: Any) -> dict[str, Any]:
    return {
        "d3": variant.length("d3", 0.5, 2.0, step=0.1),  # rad
        "T3": variant.choice("T3", [1.5, 2.0, 2.5, 3.0, 4.0]),  # s
    }


_STEPS = [-1.2, -1.0, -0.8, -0.6, -0.4, 0.4, 0.6, 0.8, 1.0, 1.2]


def _ptp(variant: Any, _: Any) -> dict[str, Any]:
    delta = [variant.choice(f"delta q{j}", _STEPS) for j in (1, 2, 3)]  # rad
    speed = [variant.choice(f"speed q{j}", [0.5, 0.8, 1.0, 1.2, 1.5]) for j in (1, 2, 3)]
    accel = [variant.choice(f"accel q{j}", [0.6, 1.0, 1.5, 2.0, 3.0]) for j in (1, 2, 3)]
    return {"robot": preset("paper"), "delta_4": delta, "speed_4": speed, "accel_4": accel}


def _ptp_table(n: Any) -> str:
    rows = "".join(
        f"| q{j + 1} | {n['delta_4'][j]:g} | {n['speed_4'][j]:g} | {n['accel_4'][j]:g} |\n"
        for j in range(3)
    )
    return "| joint | Δ (rad) | v (rad/s) | a (rad/s²) |\n|---|---|---|---|\n" + rows


register(
    profile_exercise(
        1,
        "a trapezoid",
        _limits,
        lambda n: ProfileTask(n["d1"], speed=n["v_max"], accel=n["a_max"]),
        lambda n: {
            "name": "the trapezoid",
            "hint": "On a ramp the speed grows as a·t; the distance is the area under the "
            "velocity: two ramps and the cruise between them.",
        },
        lambda n: [
            n["v_max"] / n["a_max"],
            n["d1"] / n["v_max"] + n["v_max"] / n["a_max"],
            n["v_max"],
        ],
        lambda n: f"$d_1 = {n['d1']:g}$ rad",
    ),
    profile_exercise(
        2,
        "a short move: a triangle",
        _short,
        lambda n: ProfileTask(n["d2"], speed=n["v_max"], accel=n["a_max"]),
        lambda n: {
            "name": "the profile of the short move",
            "hint": "Is the speed limit reached at all? Compare d with v²/a.",
        },
        lambda n: [
            np.sqrt(n["d2"] / n["a_max"]),
            2 * np.sqrt(n["d2"] / n["a_max"]),
            np.sqrt(n["d2"] * n["a_max"]),
        ],
        lambda n: f"$d_2 = {n['d2']:g}$ rad",
    ),
    profile_exercise(
        3,
        "a quintic's peak speed",
        _quintic,
        lambda n: ProfileTask(n["d3"], kind="quintic", duration=n["T3"]),
        lambda n: {
            "form": "peak_speed",
            "name": "the quintic's peak speed",
            "unit": "rad/s",
            "hint": "Differentiate with respect to t (dτ/dt = 1/T) and take the middle, τ = 1/2.",
        },
        lambda n: 15 / 8 * n["d3"] / n["T3"],
        lambda n: f"$d_3 = {n['d3']:g}$ rad, $T_3 = {n['T3']:g}$ s",
    ),
    profile_exercise(
        4,
        "a synchronized PTP",
        _ptp,
        lambda n: ProfileTask(n["delta_4"], speed=n["speed_4"], accel=n["accel_4"]),
        lambda n: {
            "form": "duration",
            "name": "the duration of the PTP",
            "unit": "s",
            "hint": "Work out each joint's own time first (trapezoid or triangle?), then "
            "synchronize: V = min v_j/|Δ_j|, A = min a_j/|Δ_j|.",
        },
        lambda n: ProfileTask(n["delta_4"], speed=n["speed_4"], accel=n["accel_4"]).duration,
        _ptp_table,
    ),
)

# -- exercise 5: which moves does check() report? -----------------------------------------


def _arm(variant: Any, _: Any) -> dict[str, Any]:
    l1 = variant.length("l1", 0.6, 1.0, step=0.1)
    l2 = variant.length("l2", 0.4, 0.8, step=0.1)
    return {"l1": l1, "l2": l2, "L": l1 + l2, "program_5": program_5(l1, l2)}


@functools.lru_cache(maxsize=32)
def program_5(l1: float, l2: float) -> Program:
    """The program of exercise 5 for an arm with links ``l1``, ``l2`` (m)."""
    arm = preset("planar_2r", l1=l1, l2=l2)
    length = l1 + l2
    inside, stretched, aside = (
        [0.55 * length, 0, 0],
        [0.995 * length, 0, 0],
        [
            0.55 * length,
            0.3 * length,
            0,
        ],
    )
    moves = [
        PTP(position=inside),
        PTP(position=stretched),
        PTP(position=inside),
        LIN(position=stretched, speed=0.2 * length, accel=0.5 * length),
        PTP(position=inside),
        LIN(position=aside, speed=0.1 * length, accel=0.2 * length),
    ]
    return Program(arm, moves, start=[0.4, 1.4])


@functools.lru_cache(maxsize=32)
def flagged_moves(l1: float, l2: float) -> tuple[int, ...]:
    """The moves (from 0) ``program_5(l1, l2).check(dt=0.01)`` reports."""
    return tuple(sorted({v.move for v in program_5(l1, l2).check(dt=0.01)}))


EXERCISE_SLIPS.update(
    {
        "counted_from_1": "move indices counted from 1 where the list counts from 0",
        "ptp_counted": "the PTP into the stretched pose counted too",
        "joint_1_speed": "joint 1's speed where joint 2's is asked",
        "x_left_out": "v/(l1·l2·sin q2): the factor x* of J⁻¹ left out",
        "length_for_x": "a length (L, l1 or l2) where the tip's x* belongs",
        "cos_for_sin": "cos q2 where det J = l1·l2·sin q2",
    }
)


def _moves_named(n: Any) -> dict[str, tuple[Any, str]]:
    flagged = list(flagged_moves(n["l1"], n["l2"]))
    return {
        "counted_from_1": (
            [m + 1 for m in flagged],
            "Give indices from 0, like the list (violation.move): moves_5[0] is index 0.",
        ),
        "ptp_counted": (
            sorted({1, *flagged}),
            "moves_5[1] is a PTP: it interpolates the joints and reaches the stretched pose "
            "within their limits. A LIN must follow the tip's straight line, whatever the "
            "joints need for it.",
        ),
    }


def _moves_check(given: Any, n: Any) -> Any:
    result = checkers().check_set(
        given,
        list(flagged_moves(n["l1"], n["l2"])),
        name="the moves check() reports",
        hint="Which move makes the tip follow a straight line into an almost stretched arm?",
    )
    return name_slip(result, n, _moves_named, lambda v, a: sorted(v.reshape(-1)) == sorted(a))


def _moves_fast(given: Any, n: Any) -> bool:
    return sorted(np.asarray(given, dtype=float).reshape(-1).tolist()) == sorted(
        flagged_moves(n["l1"], n["l2"])
    )


register(
    Exercise(
        LESSON,
        5,
        "which moves check() reports",
        _arm,
        lambda n: list(flagged_moves(n["l1"], n["l2"])),
        _moves_check,
        lambda n: {
            **{k: v for k, (v, _) in _moves_named(n).items()},
            "none": [],
            "all": [0, 1, 2, 3, 4, 5],
        },
        lambda n: f"$l_1 = {n['l1']:g}$ m, $l_2 = {n['l2']:g}$ m, $L = {n['L']:g}$ m",
        _moves_fast,
    )
)

# -- exercise 6: the joint speed on the way out ------------------------------------------


def _speeds(n: Any) -> np.ndarray:
    """|q̇1|, |q̇2| when the tip passes (x*, 0) at v = 0.2 L along x."""
    arm = preset("planar_2r", l1=n["l1"], l2=n["l2"])
    q = ik(arm, [n["x_star"], 0, 0]).q
    return np.abs(np.linalg.solve(jacobian(arm, q)[:2], [n["v_6"], 0]))


def _speed_named(n: Any) -> dict[str, tuple[Any, str]]:
    l1, l2, x_star, v = n["l1"], n["l2"], n["x_star"], n["v_6"]
    q2 = float(np.arccos((x_star**2 - l1**2 - l2**2) / (2 * l1 * l2)))
    det = l1 * l2 * np.sin(q2)
    return {
        "joint_1_speed": (
            float(_speeds(n)[0]),
            "That is joint 1's speed: the question asks for joint 2.",
        ),
        "x_left_out": (
            float(v / det),
            "The second row of J⁻¹ (v, 0) is v·x/det J: the tip's x* is part of it.",
        ),
        "length_for_x": (
            float(v * (l1 + l2) / det),
            "Use the tip's x* where it passes, not the arm's length L.",
        ),
        "length_for_x[l1]": (
            float(v * l1 / det),
            "Use the tip's x* where it passes, not the first link's length l1.",
        ),
        "length_for_x[l2]": (
            float(v * l2 / det),
            "Use the tip's x* where it passes, not the second link's length l2.",
        ),
        "cos_for_sin": (
            float(v * x_star / (l1 * l2 * np.cos(q2))),
            "det J = l1·l2·sin q2 (the arm is singular stretched, at q2 = 0), not cos q2.",
        ),
    }


def _x_star(variant: Any, earlier: Any) -> dict[str, Any]:
    length = earlier["L"]
    x_star = round(variant.choice("x* share", [0.85, 0.88, 0.9, 0.92, 0.94]) * length, 4)
    return {"x_star": x_star, "v_6": 0.2 * length}


register(
    value_exercise(
        LESSON,
        6,
        "the joint speed near the stretched arm",
        _x_star,
        lambda n: float(_speeds(n)[1]),
        "check_value",
        lambda n: {
            "name": "|dq2/dt| at x*",
            "unit": "rad/s",
            "hint": "Solve J·dq = (v, 0) at the pose with the tip at (x*, 0): det J = "
            "l1·l2·sin q2, and q2 from the law of cosines (lesson 11).",
        },
        named=_speed_named,
        length=False,
        shows=lambda n: f"$x^* = {n['x_star']:g}$ m, $v = {n['v_6']:.4g}$ m/s",
    )
)
