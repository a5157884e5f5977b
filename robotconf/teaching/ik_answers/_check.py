"""The check for an inverse-kinematics answer: ANY joint values that reach the target.

An IK exercise has many right answers (the elbow up and the elbow down, any angle plus
whole turns), so :func:`check_ik_solution` never compares with one stored solution: it
runs the answer through the robot's forward kinematics and compares the end effector with
the target. Only a wrong answer is compared with the closed-form solutions of
:func:`robotconf.ik_all`, to name the slip (:mod:`._ik_answers_diagnosis`). Sets of
solutions are checked by :func:`~robotconf.teaching.check_ik_solutions`
(:mod:`._ik_answers_sets`).

The answer is read like every other answer check: through the whitelist parser and
numeric judge of :func:`~robotconf.teaching.check_matrix` (text is never evaluated; NaN,
infinities and imaginary values are refused).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._validation import check_flag
from ..checks._input import NO_ANSWER, check_text, parse_answer
from ..reading._parser import ParserLimits
from ..reading._shown import number_text, sentence
from ..reading._tolerance import REL_TOL
from ..reading._wrapper import answer_check, passed
from ._diagnosis import SLIP_TOL, diagnose, nearest_solution, rounded_past_the_rule
from ._problem import IKProblem
from ._result import IKCheck, verdict

__all__ = ["assert_ik_solution", "check_ik_solution", "read_answer", "reveal_text"]


def read_answer(
    answer: Any, problem: IKProblem, name: str, hint: str | None, limits: ParserLimits | None
) -> tuple[np.ndarray, list[str]] | IKCheck:
    """The answer as a matrix of numbers and its entries as typed, or the verdict when
    there are no numbers to judge (no answer yet, symbols left, too complicated)."""
    target = problem.target
    if answer is None:
        return IKCheck(
            False, [NO_ANSWER], "no_answer", name, None, target, headline=f"{name}: no answer yet."
        )
    parsed = parse_answer(answer, limits)
    if parsed.symbols:
        text = f"{sentence(name)} still holds {', '.join(parsed.symbols)}: give numbers."
        return verdict([text], ["not_a_number"], name, None, target, hint)
    if parsed.values is None:
        text = f"{sentence(name)} is too complicated to check: simplify it first."
        return verdict([text], ["too_complicated"], name, None, target, hint)
    if parsed.values.size % problem.n == 0:  # else the layout is refused with a hint
        problem.check_sizes(parsed.values.reshape(-1, problem.n), parsed.entries)
    return parsed.values, parsed.entries


def reveal_text(problem: IKProblem, q: np.ndarray) -> str | None:
    """``"One solution: [0, 1.571] (elbow down)."``, the solution nearest to ``q``."""
    found = nearest_solution(problem, q)
    if found is None:
        return None
    values = ", ".join(number_text(x + 0.0) for x in np.round(found[0], 12))
    return f"One solution: [{values}]" + (f" ({found[1]})." if found[1] else ".")


def _branch(problem: IKProblem, q: np.ndarray) -> str:
    solutions = problem.solutions
    if solutions is None or not len(solutions):
        return ""
    row, spread = problem.closest(q, solutions.q)
    return solutions.labels[row] if spread <= SLIP_TOL else ""


def _judge(
    problem: IKProblem,
    values: np.ndarray,
    name: str,
    within_limits: bool,
    reveal: bool,
    hint: str | None,
) -> IKCheck:
    n, target = problem.n, problem.target
    if values.size != n or min(values.shape) != 1:
        joints = ", ".join(problem.names)
        if values.shape[1] == n and values.shape[0] > 1:
            got = f"{values.shape[0]} solutions"
        else:
            got = f"{values.size} number{'s' if values.size != 1 else ''}"
        text = f"Give one solution, {n} joint values [{joints}]; you gave {got}."
        return verdict([text], ["shape"], name, values, target, hint)
    q = values.reshape(-1)
    reached = problem.reached(q)
    more: dict[str, Any] = {"reached": reached, "headline": f"{name}: not right yet."}
    if problem.reaches(q):
        more["branches"] = (_branch(problem, q),)
        coarse = rounded_past_the_rule(problem, q, "your answer")
        if coarse is not None:
            return verdict([coarse.hint], [coarse.code], name, q, target, hint, **more)
        outside = problem.outside_limits(q)
        if not outside:
            return verdict([], [], name, q, target, hint, **more)
        words = "; ".join(outside)
        if not within_limits:
            note = f"Note: {words}: the real arm cannot take this solution."
            return verdict([], [], name, q, target, hint, notes=[note], **more)
        text = (
            f"Your answer reaches the target, but {words}: the arm cannot get there. "
            "Give a solution within the joint ranges (robot.joint_limits())."
        )
        return verdict([text], ["outside_limits"], name, q, target, hint, **more)
    found = diagnose(problem, q, "your answer")
    hints = [found.hint]
    shown = reveal_text(problem, q) if reveal else None
    hints += [shown] if shown else []
    return verdict(hints, [found.code], name, q, target, hint, reveal=reveal, **more)


@answer_check(kind="ik_solution")
def check_ik_solution(
    answer: Any,
    robot: Any,
    target: Any,
    *,
    tol: float = REL_TOL,
    mode: str = "position",
    within_limits: bool = False,
    name: str | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> IKCheck:
    """Check joint values that should put the end effector on ``target``: any solution.

    Parameters
    ----------
    answer : list, ndarray, text or None, n numbers
        The joint values ``[q1, …, qn]`` (radians for revolute joints): ``[0, 1.5708]``,
        ``"[0, pi/2]"``, an array. Text is parsed by the whitelist parser, never
        evaluated. ``None`` (not answered yet) fails with a hint.
    robot : Robot
    target : array-like, shape (3,) or (4, 4)
        The point to reach, or a pose (in mode ``"position"`` only its point counts).
    tol : float
        Relative to the robot's size ``L = rc.characteristic_length(robot)``: right when
        the end effector lies within ``tol·L`` of the target (by default 0.5 % of the
        size, so angles typed with 3 significant digits pass) and, in mode ``"pose"``,
        its orientation within ``tol`` rad.
    mode : {"position", "pose"}
    within_limits : bool
        Whether the joint ranges matter: ``False`` (default) accepts a solution outside
        ``robot.joint_limits()`` with a note; ``True`` fails it (``"outside_limits"``).
    name : str, optional
        What the messages call the answer (default ``"the solution"``).
    reveal : bool
        Whether a failing verdict may quote the solution nearest to the answer.
    hint : str, optional
        The exercise's own advice, added after the diagnosis when the answer is wrong.
    limits : ParserLimits, optional
        Caps for parsing text.

    Returns
    -------
    IKCheck
        ``reached`` is where the answer's end effector lands. Diagnoses (see
        :data:`IK_DIAGNOSES`): ``atan_quadrant`` (a joint off by π: atan for atan2),
        ``cosine_law_sign`` (the elbow branches mixed, or the inner angle taken for the
        joint angle), ``degrees_as_radians``, ``wrong_target`` (coordinates swapped),
        ``too_rounded``, ``sign_error``, ``outside_limits``, ``shape``,
        ``not_a_number``, ``no_answer``, else ``wrong``.

    Raises
    ------
    InvalidInputError
        For input :func:`check_matrix` refuses (text outside the whitelist, NaN,
        infinities, imaginary values), angles beyond ±1e9 rad, and a bad robot, target,
        mode or option.

    Examples
    --------
    The planar arm with two unit links reaches (1, 1) with the elbow down, (0, π/2), or
    up, (π/2, −π/2); both pass, and so does either plus a whole turn:

    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> check_ik_solution("[0, pi/2]", arm, [1, 1, 0]).ok
    True
    >>> check_ik_solution([1.5708, -1.5708 + 2 * np.pi], arm, [1, 1, 0]).branches
    ('elbow up',)
    >>> check_ik_solution([0, 90], arm, [1, 1, 0]).diagnosis
    'degrees_as_radians'
    """
    problem = IKProblem(robot, target, mode, tol)
    name = check_text(name, "name") or "the solution"
    within_limits = check_flag(within_limits, "within_limits")
    reveal = check_flag(reveal, "reveal")
    hint = check_text(hint, "hint")
    read = read_answer(answer, problem, name, hint, limits)
    if isinstance(read, IKCheck):
        return read
    return _judge(problem, read[0], name, within_limits, reveal, hint)


def assert_ik_solution(answer: Any, robot: Any, target: Any, **options: Any) -> IKCheck:
    """Like :func:`check_ik_solution`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, robot, target
        As in :func:`check_ik_solution`.
    **options
        ``tol``, ``mode``, ``within_limits``, ``name``, ``reveal``, ``hint``, ``limits``.

    Returns
    -------
    IKCheck
        When the answer is right (its notes say, e.g., that it lies outside the ranges).

    Raises
    ------
    AssertionError
        When it is wrong or missing (``None``).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> assert_ik_solution([0, np.pi / 2], arm, [-1, -1, 0], name="q")
    Traceback (most recent call last):
    ...
    AssertionError: q: not right yet.
    - In your answer, q1 is off by half a turn (π) from a solution: the quadrant is lost. ...
    """
    return passed(check_ik_solution(answer, robot, target, **options))
