"""The homework checker: compare a student's matrix with the expected one and say why not.

Student answers are untrusted text graded on the teacher's machine, so every step is
bounded (see :func:`check_matrix`, "Budget"): numbers decide first (both matrices at
``samples`` seeded random points, in complex arithmetic:
:mod:`robotconf.teaching.reading._numeric_judge`); only an entry the numbers cannot decide gets
symbolic work, and only within :mod:`robotconf.teaching.reading._budget_rules`. Wrong entries are
then explained by rebuilding the usual mistakes (see :mod:`robotconf.teaching.diagnosis._mistakes`),
keeping the ones the student's answer matches, numerically too, and ranking them
(:mod:`robotconf.teaching.diagnosis._diagnose`): the hints name one primary diagnosis.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number, check_integer
from ..derivation._expected import ExpectedMatrix, as_expected, sample_points
from ..diagnosis._diagnose import diagnose
from ..diagnosis._hints import NO_ANSWER, entries_text, shape_hint
from ..reading._budget_rules import Allowance
from ..reading._numeric_eval import MAX_EVALUATED_NODES
from ..reading._numeric_judge import (
    MAX_ANSWER_NODES,
    TOO_LARGE,
    WRONG,
    Judgement,
    check_size,
    judge,
)
from ..reading._parser import DEFAULT_SYMBOL_NAMES, ParserLimits, parse_expression, parse_matrix
from ..reading._slips import slip_in_entry
from ..reading._tolerance import REL_TOL
from ..reading._wrapper import answer_check, passed
from ._matrix_result import MatrixCheck

if TYPE_CHECKING:  # pragma: no cover
    import sympy

__all__ = ["MatrixCheck", "check_matrix", "assert_matrix"]

_STUDENT_ALLOWED = "a matrix: nested lists, a numpy array, a sympy Matrix or text '[[…], …]'"


# -- student input ----------------------------------------------------------------------


def _student_entry(value: Any, table: dict[str, Any], limits: ParserLimits, where: str) -> Any:
    import sympy

    from ..derivation._symbolic import exact_number

    if isinstance(value, str):
        try:
            return parse_expression(value, table.values(), limits)
        except InvalidInputError as error:  # name the entry, as for a number there
            raise slip_in_entry(error, where) from None
    if isinstance(value, (bool, np.bool_)):
        raise InvalidInputError(where, value, "a number or a formula", problem="a boolean:")
    if isinstance(value, sympy.Basic):
        if not isinstance(value, sympy.Expr):
            raise InvalidInputError(where, value, "a number or a formula", problem="not a formula:")
        return value
    if isinstance(value, (int, np.integer)):
        return sympy.Integer(int(value))
    if isinstance(value, (float, np.floating)):
        if not np.isfinite(value):
            raise InvalidInputError(where, value, "a finite number", problem="must be finite, got")
        return exact_number(float(value))
    raise InvalidInputError(where, value, "a number or a formula", problem="not a number:")


#: Text that calls robotconf instead of stating a matrix: ``rc.derivation(robot)``,
#: ``expected_matrix(…)``, ``robot.frame_poses()``.
_LIBRARY_CALL = re.compile(
    r"\b(?:rc|robotconf|robot|panel)\s*\.|\b(?:derivation|expected_matrix)\s*\("
)
_OWN_WORK = "the matrix you derived, written out: [[…], …] with numbers, q1, q2, …, sin, cos"


def _refuse_library_answer(student: Any) -> None:
    """A robotconf result or call handed in as the answer checks nothing: say so kindly."""
    if type(student).__module__.startswith("robotconf."):
        raise InvalidInputError(
            "student",
            type(student).__name__,
            _OWN_WORK,
            problem="this is robotconf's own result, not your answer:",
        )
    if isinstance(student, str) and _LIBRARY_CALL.search(student[:2000]):
        raise InvalidInputError(
            "student",
            student,
            _OWN_WORK,
            problem="this asks robotconf for the answer instead of giving yours:",
        )


def _parse_text(text: str, table: dict[str, Any], limits: ParserLimits, scalar: bool) -> Any:
    """Parse a typed answer; for a 1×1 answer a bare formula such as ``2*sin(q2)`` is fine."""
    import sympy

    head = text.lstrip()
    if scalar and not head.startswith(("[", "Matrix")):
        if not head.startswith("("):
            return sympy.Matrix([[parse_expression(text, table.values(), limits)]])
        try:  # "(2*sin(q2))" is a formula, "((1,),)" a matrix
            return sympy.Matrix([[parse_expression(text, table.values(), limits)]])
        except InvalidInputError as as_formula:
            try:
                return parse_matrix(text, table.values(), limits)
            except InvalidInputError:
                raise as_formula from None  # it was meant as a formula: say what is wrong
    return parse_matrix(text, table.values(), limits)


def _student_matrix(
    student: Any, table: dict[str, Any], limits: ParserLimits, scalar: bool = False
) -> sympy.Matrix:
    import sympy

    if isinstance(student, np.ndarray) and student.ndim == 0:
        student = student.item()
    _refuse_library_answer(student)
    if isinstance(student, str):
        matrix = _parse_text(student, table, limits, scalar)
    elif isinstance(student, sympy.MatrixBase):
        matrix = sympy.Matrix(student)
    elif isinstance(student, bytes):
        raise InvalidInputError("student", student, _STUDENT_ALLOWED, problem="bytes, not text:")
    elif scalar and isinstance(student, (int, float, np.number, sympy.Expr)):
        matrix = sympy.Matrix([[_student_entry(student, table, limits, "student")]])
    else:
        rows = student.tolist() if isinstance(student, np.ndarray) else student
        if not isinstance(rows, (list, tuple)) or not rows:
            raise InvalidInputError("student", student, _STUDENT_ALLOWED, problem="not a matrix:")
        if all(not isinstance(r, (list, tuple, np.ndarray)) for r in rows):
            rows = [[r] for r in rows]
        elif not all(isinstance(r, (list, tuple, np.ndarray)) for r in rows):
            raise InvalidInputError(
                "student", student, _STUDENT_ALLOWED, problem="mixes rows and single entries:"
            )
        widths = {len(r) for r in rows}
        if len(widths) != 1 or 0 in widths:
            raise InvalidInputError(
                "student", student, _STUDENT_ALLOWED, problem=f"rows of lengths {sorted(widths)}:"
            )
        if len(rows) * len(rows[0]) > limits.max_entries:
            raise InvalidInputError(
                "student", student, _STUDENT_ALLOWED, problem="too many entries:"
            )
        matrix = sympy.Matrix(
            [
                [_student_entry(v, table, limits, f"student[{r}][{c}]") for c, v in enumerate(row)]
                for r, row in enumerate(rows)
            ]
        )
    total = 0
    for r in range(matrix.rows):  # before sympy itself walks (recursively) over them
        for c in range(matrix.cols):
            total += check_size(matrix[r, c], f"student[{r}][{c}]", f"entry ({r + 1},{c + 1})")
    if total > MAX_ANSWER_NODES:
        raise InvalidInputError(
            "student",
            f"{total} parts",
            f"at most {MAX_ANSWER_NODES} parts: simplify the entries first",
            problem="the answer is too large to check:",
        )
    # Same-named symbols are the same symbol, whatever assumptions the student used.
    renames = {
        s: table[s.name] for s in matrix.free_symbols if s.name in table and s != table[s.name]
    }
    return matrix.xreplace(renames) if renames else matrix


def _symbol_table(expected: ExpectedMatrix, symbols: Iterable[Any] | None) -> dict[str, Any]:
    import sympy

    table = {s.name: s for s in expected.matrix.free_symbols if isinstance(s, sympy.Symbol)}
    names = list(expected.symbol_names())
    if expected.robot is None:
        names += list(DEFAULT_SYMBOL_NAMES)
    for item in symbols or ():
        names.append(item.name if isinstance(item, sympy.Symbol) else item)
    for name in names:
        if not isinstance(name, str) or not name.isidentifier():
            raise InvalidInputError("symbols", name, "names such as 'q1' or 'l2'")
        table.setdefault(name, sympy.Symbol(name, real=True))
    return table


def _fit_shapes(student: Any, expected: Any) -> Any:
    """Vectors: accept a row for a column and (x, y, z) for a homogeneous (x, y, z, 1)."""
    import sympy

    if expected.cols != 1 or min(student.shape) != 1:
        return student
    column = student.reshape(len(student), 1)
    if expected.rows == 4 and column.rows == 3 and expected[3, 0] == 1:
        column = column.col_join(sympy.Matrix([[1]]))
    return column


def _compare(
    matrix: Any,
    reference: ExpectedMatrix,
    tol: float,
    samples: int,
    seed: int,
    transposed: bool = False,
) -> tuple[dict[str, np.ndarray], int, Judgement, set[tuple[int, int]], dict[tuple[int, int], str]]:
    """Sample both matrices (same shape), judge every entry, decide the undecided ones.

    Returns the sample points, their number K, the numeric judgement (values of shape
    (K, rows, cols)), the wrong entries (0-based) and the entries too complicated to
    check, each with the reason. ``transposed``: ``matrix`` is the student's transposed
    (for naming entries in errors).
    """
    expected_m = reference.matrix
    names = sorted(
        {s.name for s in matrix.free_symbols | expected_m.free_symbols}
        | set(reference.robot.coordinate_names if reference.robot is not None else ())
    )
    k = int(samples) if names else 1
    env = sample_points(names, k, seed)

    def field_of(r: int, c: int) -> str:
        return f"student[{c}][{r}]" if transposed else f"student[{r}][{c}]"

    judgement = judge(matrix, expected_m, env, k, tol, field_of)
    wrong: set[tuple[int, int]] = set()
    unchecked: dict[tuple[int, int], str] = {}
    allowance = Allowance()
    for (r, c), verdict in sorted(judgement.verdicts.items()):
        if verdict == WRONG:
            wrong.add((r, c))
        elif verdict == TOO_LARGE:
            unchecked[(r, c)] = f"it has more than {MAX_EVALUATED_NODES} parts"
        else:  # undefined at some points: algebra decides, within the budget
            equal, why_not = allowance.verdict(matrix[r, c], expected_m[r, c])
            if equal is None:
                unchecked[(r, c)] = why_not or "it is over the checker's budget"
            elif not equal:
                wrong.add((r, c))
    return env, k, judgement, wrong, unchecked


def _unchecked_hints(unchecked: dict[tuple[int, int], str]) -> list[str]:
    entries = sorted(unchecked)
    hints = [
        f"entry ({r + 1},{c + 1}) is too complicated to check: simplify it first "
        f"({unchecked[(r, c)]})."
        for r, c in entries[:4]
    ]
    if len(entries) > 4:
        hints.append(
            f"Entries {entries_text(entries[4:])} are too complicated to check as well: "
            "simplify them first."
        )
    return hints


@answer_check
def check_matrix(
    student: Any,
    expected: Any,
    *,
    tol: float = REL_TOL,
    samples: int = 8,
    seed: int = 0,
    symbols: Iterable[Any] | None = None,
    reveal: bool = False,
    limits: ParserLimits | None = None,
) -> MatrixCheck:
    """Check a student's matrix against the expected one and explain the mistakes.

    Parameters
    ----------
    student : str, nested lists, ndarray, sympy.Matrix or None, shape (r, c)
        Text such as ``"[[cos(q1), -sin(q1), 0, 0], …]"`` is parsed by a whitelist
        parser (never evaluated); list entries may be numbers, sympy expressions or text.
        A vector may be given as a row or a column, and ``(x, y, z)`` for ``p_EE``.
        When a 1×1 matrix is expected, a plain number or formula (``"2*sin(q2)"``) will
        do. ``None`` (an exercise not answered yet) fails with a hint saying so.
    expected : ExpectedMatrix, DerivationStep, sympy.Matrix, array-like or scalar
        With context (``expected_matrix(robot, "M2")`` or ``derivation(...)["M2"]``) the
        hints name modules and recognise order, convention, offset and unit mistakes; a
        bare matrix gets context-free hints only (rotation wording only when it is a
        rotation or a homogeneous transform). A scalar is a 1×1 matrix.
    tol : float
        An entry is right when ``|student − expected| ≤ tol·max(0.2, |expected|)`` at every
        sample point (numbers rounded to about 3 significant decimals pass).
    samples : int
        Random points at which symbolic entries are compared (K ≥ 1).
    seed : int
        Seed of those points (results are reproducible).
    symbols : iterable of str or sympy.Symbol, optional
        Extra names the student may use.
    reveal : bool
        Whether hints may quote the expected entries ("expected X, you wrote Y"). By
        default they do not: they name the wrong entries and the diagnosed mistake, so a
        student still has something to work out; a solution notebook may reveal.
    limits : ParserLimits, optional
        Caps for parsing text.

    Returns
    -------
    MatrixCheck
        Not ok, with the entry in ``unchecked_entries`` and a hint "too complicated to
        check: simplify it first", for an entry the budget below cannot judge.

    Raises
    ------
    InvalidInputError
        For malformed student input (ragged rows, text outside the whitelist, NaN) or a
        bad ``tol``/``samples``. A typing slip (``cos q2``, ``2 q1``, ``q1^2``, an
        unclosed bracket) gets one line of advice and a caret under the spot, with
        field ``"student"`` or, for one text entry of a list, ``"student[r][c]"``;
        IPython shows the message without the checker's internal frames.
        Also naming the entry (field ``"student[r][c]"``, 0-based) for
        an entry that is not real (``I``, ``sqrt(-1)``, ``(-8)**(1/3)``, ``sqrt(q1)`` at a
        negative sample of ``q1``: entries must be real), holds a number over about 1233
        digits or an infinity, uses a function the checker cannot evaluate (``factorial``,
        ``Integral``), or, as a sympy object, is nested over 100 levels deep or has over
        20 000 parts (40 000 for the whole answer).

    Notes
    -----
    **Budget.** An answer cannot make the check hang or run out of memory:

    1. Numbers first. Both sides are evaluated at the sample points by a numpy walk of
       the expression tree (linear in its size, no symbolic work). An entry is right when
       it agrees everywhere, wrong as soon as it differs at one point (or overflows to
       infinity where the expected value is finite): ``sin(1000000*q1)`` is simply wrong.
    2. Only an entry undefined (NaN) at some points goes to
       ``expand(expand_trig(student − expected))``, and only when one walk of its tree
       shows the work is small: powers of formulas with exponent ≤ 8
       (``MAX_EXPAND_EXPONENT``); in ``sin``/``cos`` integer multiples adding up to ≤ 8
       (``MAX_TRIG_MULTIPLE``), ``tan`` of a single angle; ≤ 200 nodes, depth ≤ 20, only
       ``+ * **``, numbers, symbols, ``sin``, ``cos``, ``tan``; an estimated ≤ 200
       expanded terms per entry (``MAX_EXPANDED_TERMS``) and ≤ 300 for the whole answer
       (``MAX_CHECK_TERMS``), for at most 4 entries (``MAX_SYMBOLIC_ENTRIES``); all in
       :mod:`robotconf.teaching.reading._budget_rules`. Anything else is "too complicated to
       check".
    3. Hints compare numbers only: every candidate mistake is rebuilt at the same points,
       the ones that fit are ranked (all wrong entries explained first, then how many,
       then how specific; a match resting on one coincidental entry is dropped), and the
       hints name one primary diagnosis (``MatrixCheck.diagnosis``), mentioning an
       equivalent reading of the same numbers in the same sentence.

    Worst case: ≤ 2 s per call for a 4×4 answer (typed text up to ``max_length``, or
    sympy objects within the caps above) on a 2-core machine; ``benchmarks/
    bench_checker.py`` times correct, wrong and hostile answers (worst measured about
    0.6 s).

    Examples
    --------
    >>> from robotconf import Module, Robot
    >>> from robotconf.teaching import expected_matrix
    >>> robot = Robot([Module("Rz"), Module("Ry", a=(0, 0, 20))])
    >>> wrong = "[[cos(q2), 0, -sin(q2), 0], [0, 1, 0, 0], [sin(q2), 0, cos(q2), 20], [0, 0, 0, 1]]"
    >>> result = check_matrix(wrong, expected_matrix(robot, "A2"))
    >>> result.ok, result.wrong_entries
    (False, [(0, 2), (2, 0)])
    >>> print(result.hints[0])  # doctest: +ELLIPSIS
    The sine terms of A2 (module M2, Ry with a = (0, 0, 20)) have the wrong sign, ...
    >>> result.diagnosis
    'rotation_direction'
    >>> check_matrix([[1, 0], [0, 1]], np.eye(2)).ok
    True
    >>> check_matrix("1/2", 0.5).ok  # a 1×1 answer needs no brackets
    True
    >>> check_matrix(None, np.eye(2)).hints
    ['No answer yet: replace None with your matrix.']
    >>> check_matrix("cos q2", 0.5)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: student: `cos q2`: write cos(q2)
                  ^
    """
    return _check(student, expected, tol, samples, seed, symbols, reveal, limits)


def _check(
    student: Any,
    expected: Any,
    tol: float,
    samples: int,
    seed: int,
    symbols: Iterable[Any] | None,
    reveal: bool,
    limits: ParserLimits | None,
) -> MatrixCheck:
    """:func:`check_matrix` itself (its errors still carrying their internal frames)."""
    tol = check_finite_number(tol, "tol")
    if not 0 <= tol < 1:
        raise InvalidInputError("tol", tol, "a number from 0 to 1 (relative tolerance)")
    samples = check_integer(samples, "samples", 1)
    limits = limits or ParserLimits()
    reference = as_expected(expected)
    if student is None:  # the exercise's placeholder: not answered yet
        return MatrixCheck(
            False, [], [NO_ANSWER], ["no_answer"], None, reference, reveal, diagnoses=("no_answer",)
        )
    table = _symbol_table(reference, symbols)
    expected_m = reference.matrix
    scalar = expected_m.shape == (1, 1)
    matrix = _fit_shapes(_student_matrix(student, table, limits, scalar), expected_m)
    if matrix.shape != expected_m.shape:
        transposed_wrong = None
        if matrix.shape == expected_m.T.shape:  # only a non-square matrix gets here
            *_, still_wrong, unclear = _compare(matrix.T, reference, tol, samples, seed, True)
            transposed_wrong = still_wrong | set(unclear)
        hint = shape_hint(matrix.shape, expected_m, transposed_wrong)
        code = "shape" if transposed_wrong is None else "transposed_matrix"
        return MatrixCheck(False, [], [hint], [code], matrix, reference, reveal, diagnoses=(code,))
    env, k, judgement, wrong, unchecked = _compare(matrix, reference, tol, samples, seed)
    if not wrong and not unchecked:
        return MatrixCheck(True, [], [], [], matrix, reference, reveal)
    if not wrong:
        only = _unchecked_hints(unchecked)
        return MatrixCheck(
            False, [], only, ["too_complicated"], matrix, reference, reveal, sorted(unchecked)
        )
    s_values, e_values = judgement.student, judgement.expected
    found = diagnose(reference, env, k, wrong, matrix, s_values, e_values, tol, reveal)
    hints, codes = list(found.hints), list(found.mistakes)
    if unchecked:
        at = len(hints) - 1 if hints and hints[-1].startswith("Wrong entries: ") else len(hints)
        hints[at:at] = _unchecked_hints(unchecked)
        codes.append("too_complicated")
    complete = bool(found.ranked) and found.ranked[0].full and not unchecked
    return MatrixCheck(
        False,
        sorted(wrong),
        hints,
        codes,
        matrix,
        reference,
        reveal,
        sorted(unchecked),
        diagnoses=found.codes,
        complete=complete,
    )


def assert_matrix(student: Any, expected: Any, **options: Any) -> MatrixCheck:
    """Like :func:`check_matrix`, but raise ``AssertionError`` with the hints if wrong.

    Made for nbgrader autograder cells: the failure message is what the student reads.

    Parameters
    ----------
    student, expected
        As in :func:`check_matrix`.
    **options
        ``tol``, ``samples``, ``seed``, ``symbols``, ``reveal``, ``limits``.

    Returns
    -------
    MatrixCheck
        When the matrix is right.

    Raises
    ------
    AssertionError
        When it is wrong or missing (``None``); the message lists the wrong entries and
        the hints, quoting expected entries only with ``reveal=True``.

    Examples
    --------
    >>> assert_matrix([[1, 2], [3, 4]], [[3, 4], [1, 2]])
    Traceback (most recent call last):
    ...
    AssertionError: the matrix: 4 wrong entries.
    - Rows 1 and 2 are swapped: check which coordinate (x, y, z) each row stands for.
    - Wrong entries: (1,1), (1,2), (2,1), (2,2).
    """
    return passed(check_matrix(student, expected, **options))
