"""Lesson 11's exercises: inverse kinematics, now with each student's arm and targets.

Any joint values that reach the target pass (the IK checks run forward kinematics), each
angle within the joint range (−π, π] as the exercises ask: 3.18 rad is the pose of
3.18 − 2π = −3.10 rad, but a value the joint cannot be set to. The
typical slips are the IK checker's own (atan for atan2, the cosine-law sign, degrees, the
second solution lost) and the numeric steps' own, named by the checks: the step Δq
given without q_k, the error e reversed, Jᵀe for the solve, λ² for λ, no damping, the
damping added outside JᵀJ; and for the reach, the inner radius 0, measuring from the
base, the joints counted from 0.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from ...inverse_kinematics import ik, ik_all
from ...kinematics import jacobian
from ...presets import preset
from ..ik_answers._problem import IKProblem
from ..reading import number_text
from ..reading._tolerance import REL_TOL
from ._exercise import Exercise, checkers, register
from ._kinds import EXERCISE_SLIPS, matches, name_slip, value_exercise

__all__: list[str] = []

LESSON = "11_inverse_kinematics"

EXERCISE_SLIPS.update(
    {
        "step_without_q": "the step Δq given instead of q_k + Δq",
        "error_reversed": "the error taken as p(q_k) − p*, the step going away from the target",
        "transpose_for_inverse": "Jᵀe where J⁻¹e is asked (the gradient, not Newton's step)",
        "inverse_transposed": "J⁻ᵀe: the system J·Δq = e solved with J transposed",
        "lambda_squared": "λ² on the diagonal where the exercise's λ is meant",
        "no_damping": "the undamped Newton step where the damped one is asked",
        "transpose_left_out": "(JᵀJ + λI)⁻¹e without the Jᵀ in front of e",
        "inner_radius_zero": "0 for the inner radius of the reach, where it is |l1 − l2|",
        "from_the_base": "the distance measured from the base, not from the shoulder",
        "radius_with_l1": "l1 + l2 + l3 as the radius: the shoulder does not reach out",
        "counted_from_0": "joints counted from 0 where the course counts from 1",
        "cause_for_joints": "the joint causing the singularity given for those that lose rank",
    }
)


def _arm(variant: Any, _: Any) -> dict[str, Any]:
    l1 = variant.choice("l1", [1.5, 2.0, 2.5])
    l2 = variant.choice("l2", [1.0, 1.2, 1.5])
    # a target with x < 0 (atan(y/x) loses the quadrant there), inside the reach
    angle = np.radians(variant.choice("target angle", [100, 115, 130, 145, 160, 200, 215]))
    share = variant.choice("target reach", [0.45, 0.55, 0.65, 0.75, 0.85])
    r = abs(l1 - l2) + share * (l1 + l2 - abs(l1 - l2))
    target = np.round([r * np.cos(angle), r * np.sin(angle), 0.0], 2) + 0.0
    return {
        "l1": l1,
        "l2": l2,
        "arm": preset("planar_2r", l1=l1, l2=l2),
        "target": target,
    }


#: Both solutions of an arm and target, computed once (screening asks many times).
_SOLUTIONS: dict[tuple[float, ...], np.ndarray] = {}


def _solutions(n: Any) -> np.ndarray:
    """The arm's IK solutions for the target, shape (2, 2) (a read-only array)."""
    key = (float(n["l1"]), float(n["l2"]), *(float(x) for x in n["target"]))
    if key not in _SOLUTIONS:
        if len(_SOLUTIONS) >= 1024:
            _SOLUTIONS.clear()
        solutions = np.array(ik_all(n["arm"], n["target"]).q, dtype=float)
        solutions.flags.writeable = False
        _SOLUTIONS[key] = solutions
    return _SOLUTIONS[key]


def _ik_slips(n: Any) -> dict[str, Any]:
    """One solution with a slip: atan for atan2, the other branch's q2, degrees, inner angle."""
    solutions = _solutions(n)
    right = solutions[0]
    x, y = n["target"][:2]
    return {
        "atan_quadrant": [right[0] + np.pi, right[1]],
        "cosine_law_sign": [right[0], -right[1]],
        "degrees_as_radians": np.degrees(right).tolist(),
        "inner_angle": [right[0], np.pi - right[1]],
        "target_swapped": ik_all(n["arm"], [y, x, 0]).q[0].tolist(),
        "atan_unwrapped": [
            np.arctan(y / x)
            - np.arctan2(n["l2"] * np.sin(right[1]), n["l1"] + n["l2"] * np.cos(right[1])),
            right[1],
        ],
    }


#: The largest angle the exercises take: π with the rounding rule's margin.
_EDGE = np.pi * (1 + REL_TOL)


def _reaches(given: Any, n: Any) -> bool:
    q = np.asarray(given, dtype=float).reshape(-1)
    problem = IKProblem(n["arm"], n["target"], "position", 5e-3)
    return q.size == 2 and bool(np.all(np.abs(q) <= _EDGE)) and bool(problem.reaches(q))


def _both_fast(given: Any, n: Any) -> bool:
    rows = np.asarray(given, dtype=float).reshape(-1, 2)
    problem = IKProblem(n["arm"], n["target"], "position", 5e-3)
    solutions = _solutions(n)
    if np.any(np.abs(rows) > _EDGE):
        return False
    if len(rows) != len(solutions) or not problem.reaches(rows).all():
        return False
    found = {problem.closest(row, solutions)[0] for row in rows}
    return len(found) == len(solutions)


def _both_slips(n: Any) -> dict[str, Any]:
    first = _solutions(n)[0].tolist()
    found: dict[str, Any] = {"one_missing": [first], "the_same_twice": [first, first]}
    found.update({k: [first, v] for k, v in _ik_slips(n).items()})
    return found


def _wrapped(result: Any) -> Any:
    """``result``, refused when it reaches the target with an angle outside (−π, π].

    The arm's joints turn within ±π (``arm.joint_limits()``) and the exercises ask for
    values in that range: the same pose a whole turn away is not a value the joint takes.
    The edge gets the rounding rule's margin (3.142 for π passes).
    """
    if not result.ok:
        return result
    rows = np.atleast_2d(np.asarray(result.student, dtype=float))
    outside = sorted({(i, q) for row in rows for i, q in enumerate(row) if abs(q) > _EDGE})
    if not outside:
        return result
    words = "; ".join(
        f"q{i + 1} = {number_text(q)} is outside (−π, π]: wrap q{i + 1} into (−π, π] "
        f"({'subtract' if q > 0 else 'add'} 2π: {number_text(q - np.copysign(2 * np.pi, q))})"
        for i, q in outside
    )
    hint = f"{words}. It is the same pose, but the joint turns within ±π (arm.joint_limits())."
    return dataclasses.replace(
        result,
        ok=False,
        hints=[hint],
        diagnosis="outside_limits",
        headline=f"{result.name}: not right yet.",
        complete=True,
    )


def _shows_target(n: Any) -> str:
    x, y, _ = n["target"]
    return f"$l_1 = {n['l1']:g}$, $l_2 = {n['l2']:g}$; target $({x:g}, {y:g})$"


register(
    Exercise(
        LESSON,
        1,
        "one IK solution by hand",
        _arm,
        lambda n: _solutions(n)[0].tolist(),
        lambda given, n: _wrapped(
            checkers().check_ik_solution(
                given,
                n["arm"],
                n["target"],
                name="q",
                hint="cos q2 = (r² − l1² − l2²)/(2 l1 l2), then q1 = atan2(y, x) − "
                "atan2(l2 sin q2, l1 + l2 cos q2) with the same q2.",
            )
        ),
        _ik_slips,
        _shows_target,
        _reaches,
    ),
    Exercise(
        LESSON,
        2,
        "both IK solutions",
        lambda v, earlier: {},
        lambda n: _solutions(n).tolist(),
        lambda given, n: _wrapped(
            checkers().check_ik_solutions(
                given,
                n["arm"],
                n["target"],
                name="the two solutions",
                hint="Check each solution with arm.end_effector(q) before you hand it in.",
            )
        ),
        lambda n: {
            "one_missing": [_solutions(n)[0].tolist()],
            "the_same_twice": [_solutions(n)[0].tolist()] * 2,
            **{k: [_solutions(n)[0].tolist(), v] for k, v in _ik_slips(n).items()},
        },
        None,
        _both_fast,
    ),
)


def _reach_named(n: Any) -> dict[str, tuple[Any, str]]:
    return {
        "inner_radius_zero": (
            [0.0, n["l1"] + n["l2"]],
            "The inner radius is not 0: with the elbow folded back the tip stays |l1 − l2| "
            "from the base (cos q2 = −1 in the law of cosines).",
        )
    }


def _reach_check(given: Any, n: Any) -> Any:
    result = checkers().check_interval(
        given,
        [abs(n["l1"] - n["l2"]), n["l1"] + n["l2"]],
        name="the reach of the arm",
        hint="The arm folded back reaches the inner circle, stretched out the outer one: "
        "−1 ≤ cos q2 ≤ 1 in the law of cosines.",
    )
    return name_slip(result, n, _reach_named, lambda values, answer: matches(values, answer))


register(
    Exercise(
        LESSON,
        3,
        "the reach",
        lambda v, earlier: {},
        lambda n: [abs(n["l1"] - n["l2"]), n["l1"] + n["l2"]],
        _reach_check,
        lambda n: {
            **{k: v for k, (v, _) in _reach_named(n).items()},
            "ends_swapped": [n["l1"] + n["l2"], abs(n["l1"] - n["l2"])],
            "l1_alone": [n["l1"], n["l1"] + n["l2"]],
        },
        None,
        lambda given, n: matches(given, [abs(n["l1"] - n["l2"]), n["l1"] + n["l2"]]),
    )
)

# -- the numeric steps -----------------------------------------------------------------


def _start(variant: Any, earlier: Any) -> dict[str, Any]:
    q_k = np.array(
        [variant.choice("q1_k", [0.6, 0.8, 1.0, 1.2]), variant.choice("q2_k", [0.6, 0.8, 1.0, 1.2])]
    )
    arm = earlier["arm"]
    J_k = np.asarray(jacobian(arm, q_k)[:2])
    e_k = np.asarray(earlier["target"][:2] - arm.end_effector(q_k)[:2])
    return {"q_k": q_k, "J_k": J_k, "e_k": e_k}


def _newton(n: Any) -> np.ndarray:
    return n["q_k"] + np.linalg.solve(n["J_k"], n["e_k"])


def _damped(n: Any, lam: float) -> np.ndarray:
    J, e = n["J_k"], n["e_k"]
    return n["q_k"] + np.linalg.solve(J.T @ J + lam * np.eye(2), J.T @ e)


def _newton_named(n: Any) -> dict[str, tuple[Any, str]]:
    J, e, q = n["J_k"], n["e_k"], n["q_k"]
    step = np.linalg.solve(J, e)
    return {
        "step_without_q": (
            step.tolist(),
            "That is the step Δq: add it to q_k, q_(k+1) = q_k + Δq.",
        ),
        "error_reversed": (
            (q - step).tolist(),
            "The step goes away from the target: e = p* − p(q_k), the target minus the tip.",
        ),
        "transpose_for_inverse": (
            (q + J.T @ e).tolist(),
            "Jᵀe is the gradient step; Newton's step solves J·Δq = e (np.linalg.solve).",
        ),
        "inverse_transposed": (
            (q + np.linalg.solve(J.T, e)).tolist(),
            "Solve J·Δq = e with J itself, not its transpose (rows x, y; columns q1, q2).",
        ),
    }


def _damped_named(n: Any) -> dict[str, tuple[Any, str]]:
    J, e, q, lam = n["J_k"], n["e_k"], n["q_k"], n["lam"]
    step = _damped(n, lam) - q
    return {
        "step_without_q": (
            step.tolist(),
            "That is the step Δq: add it to q_k, q_(k+1) = q_k + Δq.",
        ),
        "error_reversed": (
            (q - step).tolist(),
            "The step goes away from the target: e = p* − p(q_k), the target minus the tip.",
        ),
        "lambda_squared": (
            _damped(n, lam**2).tolist(),
            f"Add λ = {lam:g} to the diagonal of JᵀJ as the exercise writes it, not λ².",
        ),
        "no_damping": (
            _newton(n).tolist(),
            "That is the undamped Newton step (exercise 4): add λI to JᵀJ before you solve.",
        ),
        "transpose_left_out": (
            (q + np.linalg.solve(J.T @ J + lam * np.eye(2), e)).tolist(),
            "Multiply e by Jᵀ first: Δq = (JᵀJ + λI)⁻¹ Jᵀe.",
        ),
        "transpose_for_inverse": (
            (q + J.T @ e).tolist(),
            "Jᵀe alone is the gradient step: solve (JᵀJ + λI)·Δq = Jᵀe.",
        ),
    }


_STEP_OPTIONS = {"name": "q_(k+1)", "components": ["q1", "q2"]}

register(
    value_exercise(
        LESSON,
        4,
        "one Newton step",
        _start,
        _newton,
        "check_vector",
        lambda n: {
            **_STEP_OPTIONS,
            "hint": "Solve J Δq = e with e = p* − p(q_k), the target minus the tip "
            "(np.linalg.solve or the 2×2 inverse), then add Δq to q_k.",
        },
        named=_newton_named,
        angle=False,
        length=False,
        shows=lambda n: f"$q_k = ({n['q_k'][0]:g}, {n['q_k'][1]:g})$",
    ),
    value_exercise(
        LESSON,
        5,
        "one damped least-squares step",
        lambda v, earlier: {"lam": v.choice("lambda", [0.1, 0.25, 0.5, 1.0])},
        lambda n: _damped(n, n["lam"]),
        "check_vector",
        lambda n: {
            **_STEP_OPTIONS,
            "hint": "Add λ to the diagonal of JᵀJ, multiply e by Jᵀ, solve, and add Δq to q_k.",
        },
        named=_damped_named,
        length=False,
        shows=lambda n: f"$\\lambda = {n['lam']:g}$",
    ),
)

# -- out of reach, and a singular PUMA -------------------------------------------------


def _far(variant: Any, _: Any) -> dict[str, Any]:
    point = variant.choice(
        "far point", [(60, 45, 80), (70, -30, 60), (-50, 60, 70), (80, 20, -20), (40, 70, 55)]
    )
    return {"robot": preset("paper"), "far": np.array(point, dtype=float)}


def _far_named(n: Any) -> dict[str, tuple[Any, str]]:
    far = n["far"]
    return {
        "from_the_base": (
            float(np.linalg.norm(far) - 70),
            "Measure from the shoulder (0, 0, 20), where joint 2 sits on joint 1's axis, not "
            "from the base.",
        ),
        "radius_with_l1": (
            float(np.linalg.norm(far - [0, 0, 20]) - 90),
            "The radius is l2 + l3 = 70 mm: the 20 mm of l1 lift the shoulder, they do not "
            "reach out.",
        ),
    }


def _wrist(variant: Any, _: Any) -> dict[str, Any]:
    q_w = [
        variant.choice("q1_w", [0.2, 0.4, -0.3]),
        variant.choice("q2_w", [0.5, -0.2, 0.3]),
        variant.choice("q3_w", [-0.4, 0.6, -0.8]),
        variant.choice("q4_w", [0.7, -0.5, 1.1]),
        0.0,  # the wrist straight: joints 4 and 6 turn about one line
        variant.choice("q6_w", [0.3, -0.6, 0.9]),
    ]
    return {"puma": preset("puma560"), "q_w": q_w}


def _rank_joints(n: Any) -> list[int]:
    null = np.linalg.svd(jacobian(n["puma"], n["q_w"]))[2][-1]
    return [int(i) + 1 for i in np.flatnonzero(null**2 >= 0.1)]


register(
    value_exercise(
        LESSON,
        6,
        "how far out of reach",
        _far,
        lambda n: float(ik(n["robot"], n["far"]).distance_to_reach),
        "check_value",
        lambda n: {
            "name": "the distance beyond the reach",
            "unit": "mm",
            "hint": "Measure from the shoulder (0, 0, 20), where joint 2 sits on joint 1's "
            "axis, not from the base; the radius is l2 + l3 = 70 mm.",
        },
        named=_far_named,
        shows=lambda n: "target $({:g}, {:g}, {:g})$ mm".format(*n["far"]),
    ),
)


def _rank_named(n: Any) -> dict[str, tuple[Any, str]]:
    joints = _rank_joints(n)
    return {
        "counted_from_0": (
            [j - 1 for j in joints],
            "Number the joints from 1, as the course does.",
        ),
        "cause_for_joints": (
            [5],
            "q5 = 0 is the cause, not one of the dependent joints: with the wrist straight, "
            "two other axes line up.",
        ),
    }


def _rank_check(given: Any, n: Any) -> Any:
    result = checkers().check_set(
        given,
        _rank_joints(n),
        name="the joints that lose rank",
        hint="Look at the last row of Vᵀ in np.linalg.svd(J): the joints with a real share "
        "in the motion that moves nothing.",
    )
    return name_slip(
        result, n, _rank_named, lambda values, answer: sorted(values.reshape(-1)) == sorted(answer)
    )


register(
    Exercise(
        LESSON,
        7,
        "the joints that lose rank",
        _wrist,
        _rank_joints,
        _rank_check,
        lambda n: {
            **{k: v for k, (v, _) in _rank_named(n).items()},
            "with_the_cause": sorted({5, *_rank_joints(n)}),
        },
        lambda n: "$q_w = (" + ", ".join(f"{x:g}" for x in n["q_w"]) + ")$",
        lambda given, n: (
            sorted(np.asarray(given, dtype=float).reshape(-1).tolist()) == _rank_joints(n)
        ),
    )
)
