"""The check for every inverse-kinematics solution of a target, in any order.

The reference is the list of closed-form solutions of :func:`robotconf.ik_all`. Each
element of the answer is judged by forward kinematics first (does it reach the target?),
then paired with the closed-form row it equals (revolute angles modulo a full turn). A
missing row is named by its branch ("elbow up") without its values, an element that
misses the target gets the diagnosis of :func:`~robotconf.teaching.check_ik_solution`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_flag, one_line
from ...inverse_kinematics import IKSolutions, ik_all
from ..checks._input import check_text
from ..diagnosis._components import names_text
from ..reading._parser import ParserLimits
from ..reading._shown import number_text
from ..reading._tolerance import REL_TOL
from ..reading._wrapper import answer_check, passed
from ._check import read_answer
from ._diagnosis import SLIP_TOL, diagnose, elbow_joints, joint_before
from ._problem import IKProblem
from ._result import IKCheck, verdict

__all__ = ["assert_ik_solutions", "check_ik_solutions"]

#: Labels of rows that stand for infinitely many solutions (a joint left free).
_FREE_WORDS = ("free", "singular")


def _reference(problem: IKProblem, within_limits: bool) -> tuple[IKSolutions, np.ndarray]:
    """Every closed-form solution and which of them the answer must hold."""
    solutions = problem.solutions
    if solutions is None:  # ik_all again, for its own explanation of what it cannot solve
        solutions = ik_all(
            problem.robot, problem.target if problem.mode == "pose" else problem.point
        )
    target = one_line(problem.target)
    if not len(solutions):
        raise InvalidInputError(
            "target", target, "a target the robot can reach", problem=f"{solutions.reason}:"
        )
    if any(word in label for label in solutions.labels for word in _FREE_WORDS):
        raise InvalidInputError(
            "target",
            target,
            "a target with finitely many solutions (not at a singularity)",
            problem=f"{solutions.reason}:",
        )
    wanted = np.asarray(solutions.within_limits) if within_limits else np.ones(len(solutions), bool)
    if not wanted.any():
        raise InvalidInputError(
            "target",
            target,
            "a target reachable within the joint ranges",
            problem="no solution is:",
        )
    return solutions, wanted


def _elements(
    values: np.ndarray, entries: list[str], n: int
) -> tuple[np.ndarray, list[str]] | None:
    """The answer's solutions, shape (k, n), and each as typed; ``None`` for a wrong layout."""
    rows, cols = values.shape
    if cols == n:
        return values, [f"[{', '.join(entries[r * cols : (r + 1) * cols])}]" for r in range(rows)]
    if rows == n and cols == 1:  # one solution written as a column (a plain list)
        return values.reshape(1, n), [f"[{', '.join(entries)}]"]
    return None


def _missing_hint(
    problem: IKProblem, missing: list[int], found: int, total: int, reveal: bool
) -> str:
    solutions = problem.solutions
    assert solutions is not None
    named = []
    for j in missing:
        label = solutions.labels[j]
        if reveal:
            values = ", ".join(number_text(x + 0.0) for x in np.round(solutions.q[j], 12))
            label += f" [{values}]"
        named.append(label)
    verb = "is" if len(missing) == 1 else "are"
    text = f"You gave {found} of the {total} solutions; {names_text(named)} {verb} missing."
    for j in elbow_joints(solutions, problem.revolute)[:1]:
        i = joint_before(problem, j)
        own = f", with its own {problem.names[i]}" if i is not None else ""
        name = problem.names[j]
        text += (
            f" The law of cosines fixes cos {name}, so {name} = ±arccos(…): each sign gives a "
            f"solution{own}."
        )
    return text


def _explained(
    problem: IKProblem, rows: np.ndarray, slips: list[tuple[int, np.ndarray]], given: set[int]
) -> set[int]:
    """The rows the slipped elements stand for, whose absence needs no hint of its own.

    A slip undone gives a row; when another element already gives that row, the slip
    was meant for a missing one, the row it shares a joint value with (a q2 written for
    the elbow up with the elbow-down q1 stands for the elbow up).
    """
    explained: set[int] = set()
    for row, element in slips:
        if row not in given:
            explained.add(row)
            continue
        shares = (problem.gap(element[None, :], rows) <= SLIP_TOL) & problem.moving
        for j in map(int, np.flatnonzero(shares.any(axis=1))):
            if j not in given and j not in explained:
                explained.add(j)
                break
    return explained


def _judge_set(
    problem: IKProblem,
    values: np.ndarray,
    entries: list[str],
    name: str,
    within_limits: bool,
    reveal: bool,
    hint: str | None,
) -> IKCheck:
    solutions, wanted = _reference(problem, within_limits)
    target, n = problem.target, problem.n
    layout = _elements(values, entries, n)
    if layout is None:
        text = f"Give {name} as a list of [{n} joint values] lists, one per solution."
        return verdict([text], ["shape"], name, values, target, hint)
    elements, texts = layout
    reaches = problem.reaches(elements)
    owner: dict[int, int] = {}
    hints: list[str] = []
    codes: list[str] = []
    slips: list[tuple[int, np.ndarray]] = []  # (the row a slip was made from, the element)
    branches = []
    for k, q in enumerate(elements):
        if not reaches[k]:
            found = diagnose(problem, q, texts[k])
            hints.append(found.hint)  # every hint names the element
            codes.append(found.code)
            if found.fixed is not None:
                slips.append((problem.closest(found.fixed, solutions.q)[0], q))
            branches.append("")
            continue
        row = problem.closest(q, solutions.q)[0]
        branches.append(solutions.labels[row])
        if row in owner:
            hints.append(
                f"{texts[k]} is the same solution as {texts[owner[row]]} "
                "(angles a whole number of turns apart count once): give each solution once."
            )
            codes.append("duplicate")
        elif not wanted[row]:
            words = "; ".join(problem.outside_limits(q))
            hints.append(
                f"{texts[k]} reaches the target, but {words}: only solutions within the "
                "joint ranges count."
            )
            codes.append("outside_limits")
        else:
            owner[row] = k
    total = int(wanted.sum())
    explained = _explained(problem, solutions.q, slips, set(owner))
    missing = [j for j in np.flatnonzero(wanted) if j not in owner and j not in explained]
    if missing:
        hints.append(_missing_hint(problem, [int(j) for j in missing], len(owner), total, reveal))
        codes.append("missing")
    headline = f"{name}: {len(owner)} of {total} solution{'s' if total != 1 else ''} right."
    if len(elements) > len(owner):
        headline = headline[:-1] + f", {len(elements) - len(owner)} not."
    notes = [
        f"Note: {texts[k]} ({branches[k]}) lies outside the joint ranges: "
        + "; ".join(problem.outside_limits(elements[k]))
        + "."
        for k in owner.values()
        if not solutions.within_limits[problem.closest(elements[k], solutions.q)[0]]
    ]
    return verdict(
        hints,
        codes,
        name,
        elements,
        target,
        hint,
        reached=problem.reached(elements),
        branches=tuple(branches),
        notes=notes,
        headline=headline,
        reveal=reveal,
        wrong=[int(j) for j in np.flatnonzero(wanted) if j not in owner],
        extra=[k for k in range(len(elements)) if k not in owner.values()],
    )


@answer_check(kind="ik_solutions")
def check_ik_solutions(
    answer_set: Any,
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
    """Check a set of IK solutions: every closed-form solution of the target, any order.

    Parameters
    ----------
    answer_set : list, ndarray, text or None, shape (k, n)
        One list of joint values per solution: ``[[0, 1.5708], [1.5708, -1.5708]]`` or
        ``"[[0, pi/2], [pi/2, -pi/2]]"``; one list alone is a set of one. Angles equal
        modulo a full turn are the same solution.
    robot : Robot
        A robot with closed-form solutions (:func:`robotconf.ik_all`: planar 2R/3R,
        SCARA, 3R elbow, spherical-wrist 6R, UR).
    target : array-like, shape (3,) or (4, 4)
        A reachable point, or a pose (6R arms need one: ``mode="pose"``).
    tol, mode, name, reveal, hint, limits
        As in :func:`check_ik_solution`; ``name`` defaults to ``"the solutions"``. With
        ``reveal=True`` the missing solutions are quoted with their values.
    within_limits : bool
        ``True``: the set holds only the solutions within ``robot.joint_limits()`` (one
        outside them is flagged ``"outside_limits"``); ``False`` (default): all of them.

    Returns
    -------
    IKCheck
        ``student`` (k, n), ``reached`` (k, 3), ``branches`` (the label of each element
        that is a solution), ``wrong`` the missing closed-form rows, ``extra`` the
        elements that are not (new) solutions. Diagnoses: those of
        :func:`check_ik_solution` for an element that misses the target, then
        ``duplicate``, ``outside_limits``, ``missing`` (named by branch: "elbow up").

    Raises
    ------
    InvalidInputError
        As :func:`check_ik_solution`, and for a robot without a closed form, a target out
        of reach or at a singularity (infinitely many solutions).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> check_ik_solutions("[[pi/2, -pi/2], [0, pi/2]]", arm, [1, 1, 0]).ok
    True
    >>> check_ik_solutions([0, np.pi / 2], arm, [1, 1, 0]).hints[0]
    'You gave 1 of the 2 solutions; elbow up is missing. The law of cosines fixes ...'
    """
    problem = IKProblem(robot, target, mode, tol)
    name = check_text(name, "name") or "the solutions"
    within_limits = check_flag(within_limits, "within_limits")
    reveal = check_flag(reveal, "reveal")
    hint = check_text(hint, "hint")
    _reference(problem, within_limits)  # a bad target is the teacher's, even for None
    empty_text = isinstance(answer_set, str) and answer_set.replace(" ", "") in ("", "[]")
    empty = isinstance(answer_set, (list, tuple, np.ndarray)) and np.size(answer_set) == 0
    if empty or empty_text:
        read: Any = (np.zeros((0, problem.n)), [])
    else:
        read = read_answer(answer_set, problem, name, hint, limits)
    if isinstance(read, IKCheck):
        return read
    return _judge_set(problem, read[0], read[1], name, within_limits, reveal, hint)


def assert_ik_solutions(answer_set: Any, robot: Any, target: Any, **options: Any) -> IKCheck:
    """Like :func:`check_ik_solutions`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer_set, robot, target
        As in :func:`check_ik_solutions`.
    **options
        ``tol``, ``mode``, ``within_limits``, ``name``, ``reveal``, ``hint``, ``limits``.

    Returns
    -------
    IKCheck

    Raises
    ------
    AssertionError

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> assert_ik_solutions([[0, np.pi / 2]], arm, [1, 1, 0], name="both solutions")
    Traceback (most recent call last):
    ...
    AssertionError: both solutions: 1 of 2 solutions right.
    - You gave 1 of the 2 solutions; elbow up is missing. ...
    """
    return passed(check_ik_solutions(answer_set, robot, target, **options))
