"""Builders of the usual kinds of exercise: a matrix of a robot at numbers, a number, a
vector, an angle; each with its check, its fast numeric acceptance and its slips.

The fast acceptance (:attr:`Exercise.accepts_numbers`) is the checker's own rule on
numbers a slip gives (an answer written as floats): the matrix judge's
``|s − e| ≤ tol·max(0.2, |e|)``, the answer checks' ``max(tol, rel·|e|)``. It lets a
lesson screen its draws, and a test sweep hundreds of ids, without parsing every slip as
text; a test compares it with the full check on sampled ids.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from ...kinematics import Robot
from ..diagnosis._components import Setting, close
from ..reading._numeric_judge import agrees
from ..reading._tolerance import ABS_TOL, REL_TOL
from ._exercise import Exercise, checkers
from ._mistake_models import component_slips, configuration_hints, matrix_at, matrix_slips

__all__ = [
    "EXERCISE_SLIPS",
    "Named",
    "matches",
    "matrix_exercise",
    "name_slip",
    "per_numbers",
    "reference",
    "value_exercise",
]

Numbers = Mapping[str, Any]
#: An exercise's own slips: ``{code: (the answer it gives, the hint naming it)}``.
Named = Callable[[Numbers], dict[str, tuple[Any, str]]]


def per_numbers(function: Callable[[Numbers], Any]) -> Callable[[Numbers], Any]:
    """``function(numbers)`` computed once per numbers: a screened draw asks for the right
    answer once for each slip it compares, with the same numbers each time."""
    recent: list[tuple[Numbers, Any]] = []

    def cached(numbers: Numbers) -> Any:
        for seen, value in recent:
            if seen is numbers:
                return value
        value = function(numbers)
        recent.insert(0, (numbers, value))
        del recent[4:]
        return value

    return cached


#: The codes of the exercises' own slips, with what each means (the rubric's words).
EXERCISE_SLIPS: dict[str, str] = {}


def name_slip(result: Any, numbers: Numbers, named: Named | None, equal: Any) -> Any:
    """``result`` with the exercise's own slip as its diagnosis, when the answer is one.

    A verdict that is ok, or whose diagnosis already explains the whole answer, is kept
    (unless that diagnosis is only a guess of too coarse rounding: the exercise's own slip,
    matched to 3 digits, says more). ``equal(student, answer)`` says whether the parsed
    answer is a slip's answer.
    """
    if named is None or result.ok:
        return result
    codes = set(getattr(result, "mistakes", None) or [getattr(result, "diagnosis", None)])
    if getattr(result, "complete", False) and codes != {"too_rounded"}:
        return result
    student = getattr(result, "student", None)
    if student is None:
        return result
    try:
        values = np.asarray(student.tolist() if hasattr(student, "tolist") else student, float)
    except (TypeError, ValueError):
        return result
    for key, (answer, hint) in named(numbers).items():
        if not equal(values, answer):
            continue
        code = key.partition("[")[0]  # "joint_left_out[q2]": one joint's slip
        if hasattr(result, "diagnoses"):  # a MatrixCheck
            return dataclasses.replace(
                result, hints=[hint], mistakes=[code], diagnoses=(code,), complete=True
            )
        return dataclasses.replace(result, hints=[hint], diagnosis=code, complete=True)
    return result


#: References built so far, by robot, step and pose (a screened draw checks the same one
#: against every slip); kept small, oldest dropped first.
_REFERENCES: dict[tuple[str, str, tuple[float, ...]], Any] = {}
_MAX_REFERENCES = 64


def reference(robot: Robot, step: str, q: Any) -> Any:
    """The checker's reference of step ``step`` at ``q``, built once per robot and pose."""
    key = (repr(robot), step, tuple(float(x) for x in np.asarray(q, dtype=float).reshape(-1)))
    if key not in _REFERENCES:
        if len(_REFERENCES) >= _MAX_REFERENCES:
            del _REFERENCES[next(iter(_REFERENCES))]
        _REFERENCES[key] = checkers().expected_matrix(robot, step, q=list(key[2]))
    return _REFERENCES[key]


def matches(answer: Any, expected: Any, **setting: Any) -> bool:
    """The answer checks' rule: every number within ``max(tol, rel·|e|)`` (mod a period)."""
    values = np.asarray(answer, dtype=float)
    target = np.asarray(expected, dtype=float)
    if values.size != target.size:
        return False
    period = setting.pop("period", None)
    rule = Setting(setting.pop("tol", ABS_TOL), setting.pop("rel", REL_TOL), period)
    return bool(close(values.reshape(-1), target.reshape(-1), rule, period).all())


def matrix_exercise(
    lesson: str,
    number: int,
    title: str,
    draw: Callable[[Any, Numbers], dict[str, Any]],
    robot: Callable[[Numbers], Robot],
    step: str,
    q: Callable[[Numbers], Any],
    *,
    free: Sequence[int] | None = None,
    named: Named | None = None,
    shows: Callable[[Numbers], str] | None = None,
    xyz: bool = False,
) -> Exercise:
    """An exercise asking for step ``step`` (``"A2"``, ``"M3"``, ``"p_EE"``) of a robot at
    numbers: checked by :func:`~robotconf.teaching.check_matrix` against the derivation,
    its slips from :func:`matrix_slips` for the joints the exercise draws (``free``,
    0-based; default every joint; ``[]`` when the pose is part of the task).

    ``xyz``: the text asks for the position as ``[x, y, z]``, so the homogeneous point
    ``[x, y, z, 1]`` — right numbers, another answer's shape — is refused as
    ``"homogeneous_coordinate"`` (``check_matrix`` itself takes either for a point)."""
    named = per_numbers(named) if named is not None else None

    def answer(numbers: Numbers) -> Any:
        return matrix_at(robot(numbers), step, q(numbers)).tolist()

    def equal(values: np.ndarray, expected: Any) -> bool:
        target = np.asarray(expected, dtype=float)
        if values.size not in (target.size, target.size + 1):
            return False
        values = values.reshape(-1)[: target.size].reshape(target.shape)
        return bool(agrees(values, target, REL_TOL).all())

    def check(given: Any, numbers: Numbers) -> Any:
        at = q(numbers)
        if step.startswith("J"):  # a Jacobian: a bare matrix, as the notebook gives it
            result = checkers().check_matrix(given, matrix_at(robot(numbers), step, at))
        else:
            result = checkers().check_matrix(given, reference(robot(numbers), step, at))
        if xyz and result.ok:
            return _refuse_homogeneous(result, given, matrix_at(robot(numbers), step, at))
        result = name_slip(result, numbers, named, equal)
        return name_slip(result, numbers, configurations, equal)

    def configurations(numbers: Numbers) -> dict[str, tuple[Any, str]]:
        arm, at = robot(numbers), q(numbers)
        found = configuration_hints(arm, at, free)
        return {k: (matrix_at(arm, step, v), hint) for k, (v, hint) in found.items()}

    def fast(given: Any, numbers: Numbers) -> bool:
        values, target = np.asarray(given, dtype=float), matrix_at(robot(numbers), step, q(numbers))
        return (not xyz or values.size == target.size) and equal(values, target)

    def slips(numbers: Numbers) -> dict[str, Any]:
        found = matrix_slips(robot(numbers), step, q(numbers), free)
        mine = {k: v for k, (v, _) in named(numbers).items()} if named else {}
        return {**{k: v.tolist() for k, v in found.items()}, **mine}

    return Exercise(lesson, number, title, draw, answer, check, slips, shows, fast)


def _refuse_homogeneous(result: Any, given: Any, position: np.ndarray) -> Any:
    """``result`` refused when the accepted ``given`` is not the asked 3-vector."""
    if checkers().check_matrix(given, position).diagnosis != "shape":
        return result
    hint = (
        "The exercise asks for the position [x, y, z]: your numbers are right, but drop the "
        "homogeneous coordinate 1 — [x, y, z, 1] is the point written for a 4×4 product."
    )
    codes = ("homogeneous_coordinate",)
    return dataclasses.replace(
        result, ok=False, hints=[hint], mistakes=list(codes), diagnoses=codes, complete=True
    )


def value_exercise(
    lesson: str,
    number: int,
    title: str,
    draw: Callable[[Any, Numbers], dict[str, Any]],
    expected: Callable[[Numbers], Any],
    checker: str,
    options: Callable[[Numbers], dict[str, Any]],
    *,
    named: Named | None = None,
    angle: bool = False,
    length: bool = True,
    shows: Callable[[Numbers], str] | None = None,
) -> Exercise:
    """An exercise whose answer is a number, a vector or an angle, checked by
    ``checker`` (``"check_value"``, ``"check_vector"``, ``"check_angle"``) with
    ``options(numbers)``; its slips are the component slips (sign, degrees, units, half a
    turn) and the exercise's own (``named``), which the check names with their hint."""
    expected = per_numbers(expected)
    named = per_numbers(named) if named is not None else None

    def answer(numbers: Numbers) -> Any:
        value = np.asarray(expected(numbers), dtype=float)
        return value.tolist() if value.ndim else float(value)

    def rule(numbers: Numbers) -> dict[str, Any]:
        found = {k: v for k, v in options(numbers).items() if k in ("tol", "rel", "period")}
        if angle and "period" not in found:
            found["period"] = 2 * np.pi
        return found

    def check(given: Any, numbers: Numbers) -> Any:
        result = getattr(checkers(), checker)(given, expected(numbers), **options(numbers))
        return name_slip(
            result, numbers, named, lambda values, answer: matches(values, answer, **rule(numbers))
        )

    def fast(given: Any, numbers: Numbers) -> bool:
        return matches(given, expected(numbers), **rule(numbers))

    def slips(numbers: Numbers) -> dict[str, Any]:
        found = {
            k: v.tolist() if v.ndim else float(v)
            for k, v in component_slips(expected(numbers), angle=angle, length=length).items()
        }
        if named is not None:
            found.update({k: v for k, (v, _) in named(numbers).items()})
        return found

    return Exercise(lesson, number, title, draw, answer, check, slips, shows, fast)
