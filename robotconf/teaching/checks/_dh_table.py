"""Check a student's DH table by the robot it describes, not by its numbers.

Frame assignment leaves choices (where x_0 points, how an offset along two parallel z axes
is split between rows, α = π or −π), so two correct tables may differ in their numbers.
What must agree is the robot: at seeded random joint values, every joint's axis (as a
line with a direction: Plücker coordinates ``(u, p × u)``, so a joint turning backwards
counts as wrong) and the end-effector position. These are exactly the columns of the
end-effector Jacobian plus the position, so a table passes when it moves the tool like
the robot does for every ``q``.

A wrong table is explained by repairing it: each usual mistake is undone in turn (the
other convention, degrees, the sign of one α, a and d swapped in one row, a θ offset of
a quarter turn, …) and the first repair that gives the robot names the mistake. Nothing
is evaluated: text goes through the whitelist parser.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from ..._errors import InvalidInputError
from ..._validation import check_finite_number, check_integer
from ...kinematics import (
    Robot,
    check_convention,
    check_parameter_vector,
)
from ..reading._tolerance import REL_TOL
from ..reading._wrapper import answer_check, passed
from ._dh_repairs import Reference, compare, diagnose, reference
from ._dh_table_text import (
    NO_ANSWER,
    DHRow,
    joint_type_hint,
    parse_dh_rows,
    row_count_hint,
)

__all__ = ["DH_DIAGNOSES", "DHTableCheck", "assert_dh_table", "check_dh_table", "describes"]

#: Every diagnosis code a :class:`DHTableCheck` may carry, with what it means.
DH_DIAGNOSES = {
    "no_answer": "the answer is still None",
    "row_count": "a row missing, or a row for a constant offset that is no joint",
    "joint_variable": "q in the wrong column, another row's q, or no q",
    "joint_direction": "−q where the joint turns with +q",
    "joint_type": "a revolute joint written as prismatic, or back",
    "convention": "standard and modified DH mixed up",
    "degrees": "angles in degrees",
    "alpha_sign": "one α with the wrong sign",
    "swapped_a_d": "a and d of one row exchanged",
    "theta_offset": "a θ offset missing or extra (the joint's zero moved)",
    "twist": "a z axis not turned onto the next joint's axis (a wrong α)",
    "a_sign": "one a with the wrong sign",
    "d_sign": "one d with the wrong sign",
    "d_value": "a wrong constant in one d (a forgotten height or slide start, another "
    "length written there, or two rows' d exchanged)",
    "a_value": "a wrong constant in one a (a forgotten link length, another length written "
    "there, or two rows' a exchanged)",
    "axis": "a joint axis in the wrong place, no single slip recognised",
    "reversed_axis": "a joint axis on the right line, pointing the other way",
    "end_effector": "every axis right, the end-effector not",
}

#: Diagnoses that only say where the table goes wrong, not which slip made it.
_UNEXPLAINED = ("no_answer", "axis", "reversed_axis", "end_effector")


@dataclass(frozen=True, eq=False)
class DHTableCheck:
    """The verdict on one DH table.

    Attributes
    ----------
    ok : bool
        The table describes the robot: the same joint axes (line and direction) and the
        same end-effector position at every sampled ``q``.
    hints : list of str
        What is most likely wrong, without giving the right numbers away (unless
        ``reveal=True``).
    diagnosis : str or None
        The code of the recognised mistake: ``"no_answer"``, ``"row_count"``,
        ``"joint_variable"``, ``"joint_direction"``, ``"joint_type"``, ``"convention"``,
        ``"degrees"``, ``"alpha_sign"``, ``"swapped_a_d"``, ``"theta_offset"``,
        ``"twist"``, ``"a_sign"``, ``"d_sign"``, ``"axis"`` (a z axis not along its
        joint's axis), ``"reversed_axis"`` (along it, pointing the other way),
        ``"end_effector"``; ``None`` when ok.
    wrong_joints : list of int
        1-based joints whose axis the table puts in the wrong place.
    rows : tuple of (θ, d, a, α, joint)
        The table as understood (offsets of θ and d, radians); empty when it could not
        be read as DH rows.
    convention : str
        The convention the table was read in.
    end_effector_ok : bool
        The table puts the end-effector where the robot has it (at every sampled ``q``);
        False too when the table could not be compared.
    complete : bool
        The diagnosis explains the whole mistake: undoing it gives the robot (a repaired
        row, the other convention, degrees), or it is the table's only problem.
    """

    ok: bool
    hints: list[str]
    diagnosis: str | None
    wrong_joints: list[int]
    rows: tuple[DHRow, ...]
    convention: str
    end_effector_ok: bool = False
    complete: bool = False

    @property
    def kind(self) -> str:
        """``"dh_table"``: which check made the verdict."""
        return "dh_table"

    def __bool__(self) -> bool:
        return self.ok

    def __str__(self) -> str:
        head = f"DH table ({self.convention}): "
        if self.ok:
            return head + "correct."
        return "\n".join([head + "not yet right.", *(f"- {hint}" for hint in self.hints)])

    def __repr__(self) -> str:
        return f"<DHTableCheck ok={self.ok} diagnosis={self.diagnosis!r}>"

    def _repr_html_(self) -> str:
        import html

        head, *hints = str(self).split("\n")
        mark = "✔" if self.ok else "✗"
        items = "".join(f"<li>{html.escape(hint[2:])}</li>" for hint in hints)
        return (
            f"<div><b>{mark} {html.escape(head)}</b>"
            + (f"<ul>{items}</ul>" if items else "")
            + "</div>"
        )


@answer_check
def check_dh_table(
    answer: Any,
    expected: Any,
    *,
    convention: str = "standard",
    end_effector: Any = (0.0, 0.0, 0.0),
    values: Mapping[str, Any] | None = None,
    tol: float = REL_TOL,
    samples: int = 8,
    seed: int = 0,
    reveal: bool = False,
) -> DHTableCheck:
    """Check a DH table against a robot: right when it describes the same robot.

    Parameters
    ----------
    answer : list of rows, str or None
        One row per joint: ``(θ, d, a, α)`` with the joint variable in θ (revolute) or d
        (prismatic), e.g. ``[("q1", 20, 0, "-pi/2"), ("q2", 0, 30, 0)]``; or robotconf
        rows ``(θ, d, a, α, "R"/"P")`` with θ and d as offsets; or the same as text
        ``"[[q1, 20, 0, -pi/2], [q2, 0, 30, 0]]"``. Text is parsed by the whitelist
        parser (never evaluated). Angles in radians. ``None``: not answered yet.
    expected : Robot or list of rows
        The robot the table must describe (modules or DH links, any convention), or its
        table in ``convention`` with the tool point ``end_effector``.
    convention : {"standard", "modified"}
        The convention the exercise asks for; the answer is read in it.
    end_effector : array-like, shape (3,)
        The tool point in the answer's last frame (length): 0 for a standard table
        whose last frame sits at the tool; in a modified table the last link's length
        goes here, e.g. ``(l3, 0, 0)``.
    values : dict of str to float, optional
        Names a student may write instead of numbers, e.g. ``{"l1": 20}``.
    tol : float
        Relative tolerance, 0 < tol < 1: axis directions within ``tol``, positions and
        axis moments within ``tol`` times the robot's size (the sum of its lengths).
    samples : int
        Random joint values compared (besides the zero position), ≥ 1.
    seed : int
        Seed of those joint values.
    reveal : bool
        Whether a hint may show a corrected row.

    Returns
    -------
    DHTableCheck

    Raises
    ------
    InvalidInputError
        For an answer that is not a table (not a list of rows of 4 or 5 entries, text
        outside the whitelist, entries that are not real numbers), a bad expected robot,
        convention, tolerance or sample count.

    Examples
    --------
    The paper's R_zR_yR_y arm (modules) and its standard table from lesson 5; another
    correct table splits nothing differently but writes α as ``-pi/2`` text:

    >>> import robotconf as rc
    >>> paper = rc.preset("paper")
    >>> check_dh_table([("q1", 20, 0, "-pi/2"), ("q2", 0, 30, 0), ("q3", 0, 40, 0)], paper).ok
    True
    >>> result = check_dh_table([("q1", 20, 0, "pi/2"), ("q2", 0, 30, 0), ("q3", 0, 40, 0)], paper)
    >>> result.ok, result.diagnosis, result.wrong_joints
    (False, 'alpha_sign', [2, 3])
    >>> check_dh_table(None, paper).hints
    ['No answer yet: replace None with your DH table, one row per joint.']
    """
    return _check(answer, expected, convention, end_effector, values, tol, samples, seed, reveal)


def _expected_robot(
    expected: Any, convention: str, end_effector: Any, values: Mapping[str, Any] | None
) -> Robot:
    if isinstance(expected, Robot):
        return expected
    parsed = parse_dh_rows(expected, values, field="expected")
    if parsed.issues:
        raise InvalidInputError("expected", expected, "a DH table", problem=parsed.issues[0][1])
    return Robot.from_dh(parsed.rows, convention=convention, end_effector=end_effector)


def _check(
    answer: Any,
    expected: Any,
    convention: str,
    end_effector: Any,
    values: Mapping[str, Any] | None,
    tol: float,
    samples: int,
    seed: int,
    reveal: bool,
) -> DHTableCheck:
    convention = check_convention(convention)
    tol = check_finite_number(tol, "tol")
    if not 0 < tol < 1:
        raise InvalidInputError("tol", tol, "a number between 0 and 1 (relative tolerance)")
    samples = check_integer(samples, "samples", 1, 1000, "an integer from 1 to 1000")
    seed = check_integer(seed, "seed", 0)
    end_effector = check_parameter_vector(end_effector, "end_effector")
    robot = _expected_robot(expected, convention, end_effector, values)
    ref = reference(robot, samples, seed, tol)

    def fail(
        code: str, hints: list[str], rows: Any = (), wrong: Any = (), tool: bool = False
    ) -> DHTableCheck:
        joints = sorted(j + 1 for j in wrong)
        whole = len(hints) == 1 and code not in _UNEXPLAINED
        return DHTableCheck(False, hints, code, joints, tuple(rows), convention, tool, whole)

    if answer is None:
        return fail("no_answer", [NO_ANSWER])
    parsed = parse_dh_rows(answer, values)
    if parsed.issues:
        given = len(answer) if isinstance(answer, (list, tuple)) else 0
        codes = {code for code, _ in parsed.issues}
        if given != len(ref.letters) and codes == {"joint_variable"}:
            # Too long: a constant offset written as a row of its own, not a variable
            # forgotten. Too short: the rows keep their joints' names (q2 in row 1), so
            # the variables are off by the row that is missing.
            return fail("row_count", [row_count_hint(given, len(ref.letters))])
        return fail(parsed.issues[0][0], [hint for _, hint in parsed.issues])
    rows = parsed.rows
    if len(rows) != len(ref.letters):
        return fail("row_count", [row_count_hint(len(rows), len(ref.letters))], rows)
    for r, (row, letter) in enumerate(zip(rows, ref.letters, strict=True)):
        if row[4] != letter:
            return fail("joint_type", [joint_type_hint(r, letter)], rows)
    own = compare(ref, rows, convention, end_effector)
    if own is None:  # a table the robot class refuses (numbers beyond 1e150)
        raise InvalidInputError("answer", answer, "numbers of at most 1e150")
    if own.ok:
        return DHTableCheck(True, [], None, [], rows, convention, True)
    code, hint = diagnose(ref, rows, convention, end_effector, own, reveal)
    return fail(code, [hint], rows, own.wrong, own.end_effector_ok)


def _numeric_rows(answer: Any) -> bool:
    return isinstance(answer, (list, tuple)) and all(
        isinstance(row, tuple)
        and len(row) == 5
        and row[4] in ("R", "P")
        and all(isinstance(x, float) for x in row[:4])
        for row in answer
    )


#: The sampled robots :func:`describes` compares with, by robot and tolerance.
_REFERENCES: dict[tuple[str, float], Reference] = {}


def describes(
    answer: Any,
    expected: Robot,
    *,
    convention: str = "standard",
    end_effector: Any = (0.0, 0.0, 0.0),
    tol: float = REL_TOL,
) -> bool:
    """Whether a table describes ``expected`` as :func:`check_dh_table` judges it, without
    its diagnosis (for screening an exercise's numbers against many tables).

    >>> import robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 40, 0, "R"), (0, 0, 30, 0, "R")])
    >>> describes([("q1", 0, 40, 0), ("q2", 0, 30, 0)], arm)
    True
    >>> describes([("q1", 40, 0, 0), ("q2", 0, 30, 0)], arm)
    False
    """
    convention = check_convention(convention)
    end_effector = check_parameter_vector(end_effector, "end_effector")
    key = (repr(expected), tol)
    if key not in _REFERENCES:
        if len(_REFERENCES) >= 64:
            del _REFERENCES[next(iter(_REFERENCES))]
        _REFERENCES[key] = reference(expected, 8, 0, tol)  # check_dh_table's samples, seed
    ref = _REFERENCES[key]
    if _numeric_rows(answer):  # rows as numbers with their joint letter: nothing to parse
        rows = tuple(tuple(row) for row in answer)
    else:
        parsed = parse_dh_rows(answer, None)
        if parsed.issues:
            return False
        rows = parsed.rows
    if len(rows) != len(ref.letters):
        return False
    if any(row[4] != letter for row, letter in zip(rows, ref.letters, strict=True)):
        return False
    match = compare(ref, rows, convention, end_effector)  # type: ignore[arg-type]
    return bool(match is not None and match.ok)


def assert_dh_table(answer: Any, expected: Any, **options: Any) -> DHTableCheck:
    """Like :func:`check_dh_table`, but raise ``AssertionError`` with the hints if wrong.

    Made for the check cells of exercises (nbgrader autograder cells): the message is
    what the student reads.

    Parameters
    ----------
    answer, expected
        As in :func:`check_dh_table`.
    **options
        ``convention``, ``end_effector``, ``values``, ``tol``, ``samples``, ``seed``,
        ``reveal``.

    Returns
    -------
    DHTableCheck
        When the table is right.

    Raises
    ------
    AssertionError
        When it is wrong or missing.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 40, 0, "R"), (0, 0, 30, 0, "R")])
    >>> assert_dh_table([("q1", 0, 40, 0), ("q2", 0, 30, 0)], arm).ok
    True
    >>> assert_dh_table([("q1", 40, 0, 0), ("q2", 0, 30, 0)], arm)
    Traceback (most recent call last):
    ...
    AssertionError: DH table (standard): not yet right.
    - Row 1: a1 and d1 look swapped. ...
    """
    return passed(check_dh_table(answer, expected, **options))
