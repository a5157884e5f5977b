"""Why a configuration misses an IK target: the usual slips, undone and tried by number.

Each slip is undone on the answer (a half turn taken back, a sign flipped back, degrees
read as degrees) and the result is run through the forward kinematics: if it reaches the
target, that slip is the explanation. Where the undoing needs the geometry (the inner
angle of the elbow triangle taken for the joint angle), the slip is instead rebuilt from
the closed-form solutions and compared with the answer. The first slip found is the
diagnosis; a hint never quotes a solution (the caller adds one with ``reveal=True``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from ...inverse_kinematics import IKSolutions, ik
from ...kinematics import joint_axes
from ..diagnosis._components import rounded
from ..reading._shown import number_text
from ..reading._tolerance import REL_TOL, SCALE_FLOOR
from ._problem import IKProblem

__all__ = [
    "Finding",
    "SLIP_TOL",
    "capital",
    "diagnose",
    "elbow_joints",
    "joint_before",
    "nearest_solution",
    "rounded_past_the_rule",
]

#: How far (rad) an answer may sit from a rebuilt slip and still be that slip: typed
#: values keep about 3 decimals, and a slip is a large difference, so this is loose.
SLIP_TOL = 5e-3

#: The most (rad, or fraction of the size for slides) rounding may move a joint value.
ROUNDING_GAP = 0.06


@dataclass(frozen=True)
class Finding:
    """One diagnosed slip.

    Attributes
    ----------
    code : str
        The diagnosis (see :data:`robotconf.teaching.ik_answers._result.IK_DIAGNOSES`).
    hint : str
        A sentence the student can act on; it quotes no solution.
    fixed : ndarray, shape (n,), or None
        The solution the answer is a slip of, when there is one.
    """

    code: str
    hint: str
    fixed: np.ndarray | None = None


def nearest_solution(problem: IKProblem, q: np.ndarray) -> tuple[np.ndarray, str] | None:
    """The solution nearest to ``q`` and its label: a closed-form row, or else what the
    numeric solver finds starting from ``q`` (label ``""``); ``None`` if it finds none.

    >>> import robotconf as rc
    >>> problem = IKProblem(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0], "position", 1e-3)
    >>> q, label = nearest_solution(problem, np.array([1.4, -1.4]))
    >>> q.round(4) + 0.0, label
    (array([ 1.5708, -1.5708]), 'elbow up')
    """
    solutions = problem.solutions
    if solutions is not None and len(solutions):
        row, _ = problem.closest(q, solutions.q)
        return solutions.q[row], solutions.labels[row]
    goal = problem.target if problem.mode == "pose" else problem.point
    result = ik(problem.robot, goal, q0=q, mode=problem.mode, seeds=1, respect_limits=False)
    return (np.asarray(result.q), "") if result.success else None


def capital(text: str) -> str:
    """``text`` with a capital first letter: hints start with their subject."""
    return text[:1].upper() + text[1:]


def rounded_past_the_rule(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    """An answer that reaches the target, but with a joint value rounded further than the
    course's rule allows (3 significant digits: within ``tol·max(0.2, |value|)`` of the
    closed-form solution it stands for, a whole turn aside). The end effector's tolerance
    alone would let a 2-digit answer through when the arm happens to forgive it.

    Only at the course's tolerance (a ``tol`` a teacher sets is about the end effector
    and replaces the rule), where the closed form lists every solution (no free joint),
    and for an answer near one of them: an answer on a continuum of solutions is judged
    by its end effector.

    >>> import robotconf as rc
    >>> problem = IKProblem(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0], "position", REL_TOL)
    >>> rounded_past_the_rule(problem, np.array([1.57, -1.571]), "your answer") is None
    True
    >>> rounded_past_the_rule(problem, np.array([1.6, -1.6]), "your answer").code
    'too_rounded'
    """
    if problem.tol != REL_TOL:
        return None
    solutions = problem.solutions
    if solutions is None or not len(solutions) or solutions.reason:
        return None
    row, spread = problem.closest(q, solutions.q)
    if spread > ROUNDING_GAP:
        return None
    solution = solutions.q[row]
    near = problem.turned_to(solution, q)
    allowed = problem.tol * np.maximum(SCALE_FLOOR, np.abs(near))
    coarse = problem.moving & (problem.gap(q, near) > allowed)
    if not coarse.any():
        return None
    names = ", ".join(problem.names[i] for i in np.flatnonzero(coarse))
    return Finding(
        "too_rounded",
        f"{capital(subject)} is a solution rounded too much: {names} lies more than "
        f"{number_text(100 * problem.tol)} % from the exact value; keep 3 significant digits.",
        near,
    )


def _rounded(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    found = nearest_solution(problem, q)
    if found is None:
        return None
    solution = found[0]
    near = problem.turned_to(solution, q)
    gap = problem.gap(q, near)
    exact = gap <= 1e-9 * max(1.0, problem.size)
    # Rounding to one decimal moves an angle by 0.05 at most; more is another mistake.
    slips = rounded(q, near) & problem.moving & (gap <= ROUNDING_GAP)
    if not np.all(exact | slips) or not slips.any():
        return None
    miss = float(problem.misses(q)[0])
    return Finding(
        "too_rounded",
        f"{capital(subject)} is a solution rounded too much: its end effector misses the "
        f"target by {number_text(miss)} (within {number_text(problem.reach_tol)} passes); "
        "keep 3 significant digits.",
        solution,
    )


def _degrees(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    if not problem.revolute.any():
        return None
    radians = np.where(problem.revolute, np.radians(q), q)
    if not problem.reaches(radians):
        return None
    return Finding(
        "degrees_as_radians",
        f"{capital(subject)} is in degrees: give the joint angles in radians (180° = π).",
        radians,
    )


def _one_joint(problem: IKProblem, q: np.ndarray, change: str) -> Iterator[tuple[int, np.ndarray]]:
    """Each revolute joint j, with ``q`` where only joint j was turned back by half a turn
    (``change="half"``) or had its sign flipped (``"sign"``), when that reaches the target."""
    joints = np.flatnonzero(problem.revolute)
    if not joints.size:
        return
    tries = np.repeat(q[None, :], joints.size, axis=0)
    rows = np.arange(joints.size)
    tries[rows, joints] = q[joints] + math.pi if change == "half" else -q[joints]
    for k in np.flatnonzero(problem.reaches(tries)):
        yield int(joints[k]), tries[k]


def joint_before(problem: IKProblem, j: int) -> int | None:
    """The revolute joint before joint j (the one its value enters the formula of)."""
    earlier = np.flatnonzero(problem.revolute[:j])
    return int(earlier[-1]) if earlier.size else None


def _half_turn(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    for j, fixed in _one_joint(problem, q, "half"):
        name = problem.names[j]
        return Finding(
            "atan_quadrant",
            f"In {subject}, {name} is off by half a turn (π) from a solution: the quadrant is "
            f"lost. atan(y/x) cannot tell (x, y) from (−x, −y); use atan2(y, x) for {name}.",
            fixed,
        )
    return None


def _first_sign(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    for j, fixed in _one_joint(problem, q, "sign"):
        if joint_before(problem, j) is None:
            name = problem.names[j]
            return Finding(
                "sign_error",
                f"Flip the sign of {name} in {subject} and it is a solution: check the "
                f"direction in which {name} turns.",
                fixed,
            )
    return None


def _branch_mix(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    for j, fixed in _one_joint(problem, q, "sign"):
        name, i = problem.names[j], joint_before(problem, j)
        if i is None:
            continue
        first = problem.names[i]
        return Finding(
            "cosine_law_sign",
            f"Flip the sign of {name} in {subject} and it is a solution: {first} and {name} "
            f"come from different elbow solutions. The sign you pick for {name} = ±arccos(…) "
            f"changes {first} too ({first} depends on it through atan2(b sin {name}, "
            f"a + b cos {name}) for links a, b): compute both from one branch.",
            fixed,
        )
    return None


_ELBOW_WORDS = ("elbow up", "elbow down", "elbow left", "elbow right")


def elbow_joints(solutions: IKSolutions, revolute: np.ndarray) -> list[int]:
    """The law-of-cosines joints: those whose values are opposite in two solutions that
    differ only in the elbow (labels "elbow up" / "elbow down", or left / right).

    >>> import robotconf as rc
    >>> from robotconf.inverse_kinematics import ik_all
    >>> elbow_joints(ik_all(rc.preset("paper"), [30, 20, 50]), np.ones(3, bool))
    [2]
    """
    plain = []
    for label in solutions.labels:
        for word in _ELBOW_WORDS:
            label = label.replace(word, "elbow")
        plain.append(label)
    rows, found = solutions.q, set[int]()
    for a in range(len(rows)):
        for b in range(a + 1, len(rows)):
            if plain[a] != plain[b] or solutions.labels[a] == solutions.labels[b]:
                continue
            opposite = np.abs(rows[a] + rows[b]) < 1e-6
            bent = (np.abs(rows[a]) > 1e-6) & (np.abs(rows[a]) < math.pi - 1e-6)
            found.update(int(j) for j in np.flatnonzero(opposite & bent & revolute))
    return sorted(found)


def _reaim(problem: IKProblem, q: np.ndarray, i: int) -> np.ndarray | None:
    """``q`` with joint i turned so that the end effector points at the target, seen
    along joint i's axis (how q1 follows from a wrong q2 in the 2R formula)."""
    axes = joint_axes(problem.robot, q)
    pivot, axis = axes.point[i], axes.direction[i]
    now, goal = problem.reached(q) - pivot, problem.point - pivot
    now, goal = now - (now @ axis) * axis, goal - (goal @ axis) * axis
    floor = 1e-9 * problem.size
    if np.linalg.norm(now) < floor or np.linalg.norm(goal) < floor:
        return None
    turned = q.copy()
    turned[i] += math.atan2(float(axis @ np.cross(now, goal)), float(now @ goal))
    return turned


def _inner_angle(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    solutions = problem.solutions
    if problem.mode != "position" or solutions is None or not len(solutions):
        return None
    rows = solutions.q
    for j in elbow_joints(solutions, problem.revolute):
        i = joint_before(problem, j)
        for row in rows:
            for value in (math.pi - row[j], row[j] - math.pi):
                slip = row.copy()
                slip[j] = value
                tries = [slip] + ([] if i is None else [_reaim(problem, slip, i)])
                for candidate in tries:
                    if candidate is not None and problem.gap(q, candidate).max() <= SLIP_TOL:
                        name = problem.names[j]
                        return Finding(
                            "cosine_law_sign",
                            f"In {subject}, {name} looks like the inner angle γ of the elbow "
                            f"triangle, not the joint angle. The law of cosines gives cos {name}"
                            " = (r² − a² − b²)/(2ab) for links a, b and the distance r to the "
                            "target; the inner angle has cos γ = (a² + b² − r²)/(2ab), the "
                            f"opposite sign, so {name} = ±(π − γ). Your end effector lands at "
                            "the wrong distance from the shoulder.",
                            row,
                        )
    return None


_SWAPS = ((0, 1, "x and y swapped"), (0, 2, "x and z swapped"), (1, 2, "y and z swapped"))


def _other_target(problem: IKProblem, q: np.ndarray, subject: str) -> Finding | None:
    reached, point = problem.reached(q), problem.point
    candidates = []
    for a, b, words in _SWAPS:
        swapped = point.copy()
        swapped[[a, b]] = point[[b, a]]
        candidates.append((swapped, words))
    for axis, letter in enumerate("xyz"):
        flipped = point.copy()
        flipped[axis] = -flipped[axis]
        candidates.append((flipped, f"the sign of {letter} changed"))
    for other, words in candidates:
        moved = np.linalg.norm(other - point) > problem.reach_tol
        if moved and np.linalg.norm(reached - other) <= problem.reach_tol:
            advice = " (atan2 takes y first: atan2(y, x))" if "x and y" in words else ""
            return Finding(
                "wrong_target",
                f"{capital(subject)} reaches the target with {words}: check which coordinate "
                f"goes where{advice}.",
            )
    return None


def _miss(problem: IKProblem, q: np.ndarray, subject: str) -> Finding:
    distance, turn = (float(x) for x in problem.misses(q))
    where = problem.point_text(problem.reached(q))
    if distance > problem.reach_tol:
        text = (
            f"{capital(subject)} puts the end effector at {where}, {number_text(distance)} "
            f"from the target (within {number_text(problem.reach_tol)} passes)."
        )
    else:
        text = f"{capital(subject)} reaches the target point but not its orientation"
        text += f": it is turned {number_text(math.degrees(turn))}° away from it."
    return Finding("wrong", text + " Check it with the forward kinematics.")


def diagnose(problem: IKProblem, q: np.ndarray, subject: str) -> Finding:
    """The most likely reason why configuration ``q`` (n,) misses the target.

    Parameters
    ----------
    problem : IKProblem
    q : ndarray, shape (n,)
        A configuration that does not reach the target.
    subject : str
        How hints name it: ``"your answer"``, or an element of a set as typed.

    Returns
    -------
    Finding
        Tried in order: degrees, rounded too much, the sign of one joint after the first
        (the elbow branches mixed), a half turn (atan for atan2), the sign of the first
        joint, the inner angle for the joint angle, the target with coordinates swapped or
        a sign changed; else ``"wrong"``, with where the answer's end effector lands.

    Examples
    --------
    >>> import robotconf as rc
    >>> problem = IKProblem(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0], "position", 1e-3)
    >>> diagnose(problem, np.array([np.pi, np.pi / 2]), "your answer").code
    'atan_quadrant'
    >>> diagnose(problem, np.array([0, 90]), "your answer").code
    'degrees_as_radians'
    """
    slips = (_degrees, _rounded, _branch_mix, _half_turn, _first_sign, _inner_angle, _other_target)
    for slip in slips:
        found = slip(problem, q, subject)
        if found is not None:
            return found
    return _miss(problem, q, subject)
