"""Numbers first: the checker's verdict on each entry from its values at sample points.

Both matrices are evaluated at the same seeded random points in complex arithmetic
(:mod:`robotconf.teaching.reading._numeric_eval`), which is linear in the size of the answer and
cannot hang. Per entry:

- **right** when student and expected agree within ``tol`` at every point;
- **wrong** when they differ at a point where both are finite, or one side overflows to
  infinity where the other is finite: no symbolic work is needed to say so;
- **undecided** otherwise (a side is undefined, NaN, at some points); only these go on
  to the symbolic check within the budget of :mod:`robotconf.teaching.reading._budget_rules`.

Before any of that a student's entry is screened: the imaginary unit, an infinite value,
a number over ``MAX_NUMBER_BITS`` bits (as in the parser) or a function outside the
numeric whitelist is refused with an :class:`~robotconf.InvalidInputError` naming the
entry, and so is an entry whose value is not real at a sample point where the expected
one is (``sqrt(-1)``, ``log(-2)``, ``asin(3)``, ``(-1)**(1/3)``): entries must be real.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ._numeric_eval import MAX_EVALUATED_NODES, NotEvaluable, TooLarge, complex_values, is_real
from ._parser import MAX_NUMBER_BITS
from ._shown import show_entry
from ._tolerance import SCALE_FLOOR

__all__ = [
    "MAX_ANSWER_NODES",
    "MAX_ENTRY_DEPTH",
    "RIGHT",
    "WRONG",
    "UNDECIDED",
    "TOO_LARGE",
    "Judgement",
    "agrees",
    "check_size",
    "judge",
    "screen_entry",
]

#: Deepest nesting of a student's entry handed in as a sympy object.
MAX_ENTRY_DEPTH = 100
#: Most parts (tree nodes) of a whole answer: two of the longest typed answers.
MAX_ANSWER_NODES = 40_000

RIGHT, WRONG, UNDECIDED, TOO_LARGE = "right", "wrong", "undecided", "too large"

_REAL = (
    "real numbers and formulas with real values: no I, no square root, logarithm or "
    "fractional power of a negative number (entries must be real)"
)
_EVALUABLE = (
    "numbers, symbols, + - * / **, and elementary functions (sin, cos, tan, sqrt, exp, "
    "log, asin, acos, atan, atan2, sinh, cosh, tanh, Abs, sign, Min, Max, floor, ceiling)"
)


@dataclass(frozen=True)
class Judgement:
    """The numeric verdict on a matrix.

    Attributes
    ----------
    student, expected : ndarray, shape (K, rows, cols)
        Real values at the sample points, NaN where not real or undefined (what the
        hints compare).
    verdicts : dict of (int, int) to str
        :data:`WRONG`, :data:`UNDECIDED` or :data:`TOO_LARGE` for every entry that is not
        :data:`RIGHT` (0-based).
    """

    student: np.ndarray
    expected: np.ndarray
    verdicts: dict[tuple[int, int], str] = field(default_factory=dict)


def _entry_name(r: int, c: int) -> str:
    return f"entry ({r + 1},{c + 1})"


def short_text(expr: Any) -> str:
    """An entry quoted in an error message: short, and cheap even for a huge one."""
    return show_entry(expr, limit=80)


def check_size(expr: Any, where: str, name: str) -> int:
    """Refuse an entry over :data:`MAX_ENTRY_DEPTH` levels or ``MAX_EVALUATED_NODES`` parts.

    Typed text is bounded by the parser already; a sympy object handed in as the answer
    is not, and sympy itself recurses over it (``free_symbols``, printing) or takes
    seconds to rebuild it. One iterative walk that stops at the first excess.

    Parameters
    ----------
    expr : sympy.Expr
    where : str
        The field, e.g. ``"student[0][2]"``.
    name : str
        The entry in words, e.g. ``"entry (1,3)"``.

    Returns
    -------
    int
        The number of parts (nodes of the tree).

    Raises
    ------
    InvalidInputError
        Naming ``where``.

    Examples
    --------
    >>> import sympy
    >>> deep = sympy.Symbol("q1")
    >>> for _ in range(200):
    ...     deep = sympy.sin(deep, evaluate=False)
    >>> check_size(deep, "student[0][0]", "entry (1,1)")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: student[0][0]: entry (1,1) is nested more than 100 levels ...
    """
    count = 0
    stack = [(expr, 1)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if depth > MAX_ENTRY_DEPTH or count > MAX_EVALUATED_NODES:
            problem = (
                f"is nested more than {MAX_ENTRY_DEPTH} levels deep:"
                if depth > MAX_ENTRY_DEPTH
                else f"has more than {MAX_EVALUATED_NODES} parts:"
            )
            raise InvalidInputError(
                where,
                f"{type(expr).__name__}(…)",
                "a formula the checker can evaluate: simplify it first",
                problem=f"{name} {problem}",
            )
        stack.extend((a, depth + 1) for a in node.args)
    return count


def _float_too_large(number: Any) -> bool:
    """Whether a sympy Float needs over ``MAX_NUMBER_BITS`` bits of mantissa, exponent or
    precision (printing ``Float("1e1000000")`` alone takes half a minute)."""
    _, _, exponent, bits = number._mpf_  # sympy's mpmath value: sign, mantissa, exp, size
    return max(number._prec, bits, abs(exponent + bits)) > MAX_NUMBER_BITS


def screen_entry(expr: Any, where: str, name: str) -> None:
    """Refuse what no comparison should see: ``I``, infinities, huge numbers.

    Parameters
    ----------
    expr : sympy.Expr
        A student's entry.
    where : str
        Its field, e.g. ``"student[0][2]"``.
    name : str
        Its name in words, e.g. ``"entry (1,3)"``.

    Raises
    ------
    InvalidInputError
        Naming ``where``.

    Examples
    --------
    >>> import sympy
    >>> screen_entry(sympy.cos(sympy.Symbol("q1")), "student[0][0]", "entry (1,1)")
    >>> screen_entry(1 + sympy.I, "student[0][1]", "entry (1,2)")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: student[0][1]: entry (1,2) holds the imaginary unit I: ...
    """
    import sympy

    seen: set[Any] = set()
    stack = [expr]
    while stack and len(seen) <= MAX_EVALUATED_NODES:  # the evaluation stops there too
        node = stack.pop()
        if node not in seen:
            seen.add(node)
            stack.extend(node.args)
    # Numbers first: quoting the entry in any other message prints them.
    for node in seen:
        if node.is_Rational:
            bits = max(int(node.p).bit_length(), int(node.q).bit_length())
            if bits > MAX_NUMBER_BITS:
                raise InvalidInputError(
                    where,
                    f"a number of about {int(bits * 0.30103) + 1} digits",
                    f"numbers of at most {int(MAX_NUMBER_BITS * 0.30103)} digits",
                    problem=f"{name} holds a number too large to check:",
                )
        elif node.is_Float and _float_too_large(node):
            raise InvalidInputError(
                where,
                "a floating-point number beyond 10^±1233 or with over 1233 digits",
                f"numbers of at most {int(MAX_NUMBER_BITS * 0.30103)} digits",
                problem=f"{name} holds a number too large to check:",
            )
    for node in seen:
        if node is sympy.I:
            raise InvalidInputError(
                where, short_text(expr), _REAL, problem=f"{name} holds the imaginary unit I:"
            )
        if not node.args and (node.is_number and node.is_finite is False or node is sympy.nan):
            raise InvalidInputError(
                where, short_text(expr), "finite numbers", problem=f"{name} is not finite:"
            )


def _point_text(expr: Any, env: dict[str, np.ndarray], i: int) -> str:
    names = sorted(s.name for s in expr.free_symbols if s.name in env)
    return ", ".join(f"{n} = {env[n][i]:.3g}" for n in names)


def _values(
    expr: Any, env: dict[str, np.ndarray], k: int, strict: bool, where: str, name: str
) -> np.ndarray | None:
    """Values at the points, or ``None`` when the entry is too large to evaluate."""
    try:
        return complex_values(expr, env, k, strict=strict)
    except TooLarge:
        return None
    except NotEvaluable as refusal:
        raise InvalidInputError(
            where,
            short_text(expr),
            _EVALUABLE,
            problem=f"{name} uses {refusal.what}, which the checker cannot evaluate:",
        ) from None


def agrees(s: np.ndarray, e: np.ndarray, tol: float) -> np.ndarray:
    """Entry-wise: a student's number is the expected one, ``|s − e| ≤ tol·max(0.2, |e|)``.

    The matrix checker's rule (:data:`~._tolerance.SCALE_FLOOR`): within ``tol`` of the
    value, or of 0.2 near zero. NaN agrees with nothing.

    >>> agrees(np.array([0.866, 0.87, 0.0009]), np.array([0.8660254, 0.8660254, 0.0]), 0.005)
    array([ True,  True,  True])
    """
    with np.errstate(invalid="ignore", over="ignore"):
        return np.asarray(np.abs(s - e) <= tol * np.maximum(SCALE_FLOOR, np.abs(e)))


def _verdict(s: np.ndarray, e: np.ndarray, tol: float) -> str:
    finite_s, finite_e = np.isfinite(s), np.isfinite(e)
    both = finite_s & finite_e
    agree = agrees(s, e, tol)
    if both.all() and agree.all():
        return RIGHT
    infinite_s = np.isinf(s.real) | np.isinf(s.imag)
    infinite_e = np.isinf(e.real) | np.isinf(e.imag)
    # An overflow to ±inf is a value far beyond any finite one; NaN says nothing.
    if (both & ~agree).any() or (infinite_s & finite_e).any() or (infinite_e & finite_s).any():
        return WRONG
    return UNDECIDED


def judge(
    student: Any,
    expected: Any,
    env: dict[str, np.ndarray],
    k: int,
    tol: float,
    field_of: Callable[[int, int], str],
) -> Judgement:
    """Evaluate both matrices at the sample points and give each entry a verdict.

    Parameters
    ----------
    student, expected : sympy.Matrix, same shape
    env : dict of str to ndarray, shape (K,)
        The sample points.
    k : int
        K.
    tol : float
        Relative tolerance: ``|s − e| ≤ tol·max(0.2, |e|)`` (:data:`SCALE_FLOOR`).
    field_of : callable (row, col) -> str
        The field naming a student's entry in errors, e.g. ``"student[0][2]"``.

    Returns
    -------
    Judgement

    Raises
    ------
    InvalidInputError
        For an entry refused by :func:`screen_entry`, one the checker cannot evaluate, or
        one that is not real where the expected entry is.

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1", real=True)
    >>> env = {"q1": np.array([0.3, 1.2])}
    >>> student = sympy.Matrix([[sympy.sin(2 * q1), sympy.cos(q1)]])
    >>> expected = sympy.Matrix([[2 * sympy.sin(q1) * sympy.cos(q1), sympy.sin(q1)]])
    >>> judge(student, expected, env, 2, 1e-3, lambda r, c: f"student[{r}][{c}]").verdicts
    {(0, 1): 'wrong'}
    """
    rows, cols = expected.shape
    s_values = np.full((k, rows, cols), np.nan)
    e_values = np.full((k, rows, cols), np.nan)
    verdicts: dict[tuple[int, int], str] = {}
    for r in range(rows):
        for c in range(cols):
            where, name = field_of(r, c), _entry_name(r, c)
            screen_entry(student[r, c], where, name)
            s = _values(student[r, c], env, k, True, where, name)
            e = _values(expected[r, c], env, k, False, "expected", name)
            if s is None or e is None:
                verdicts[(r, c)] = TOO_LARGE
                continue
            real_e = is_real(e, tol)
            imaginary = np.isfinite(s) & ~is_real(s, tol) & real_e
            if imaginary.any():
                i = int(np.argmax(imaginary))
                point = _point_text(student[r, c], env, i)
                raise InvalidInputError(
                    where,
                    short_text(student[r, c]),
                    _REAL,
                    problem=f"{name} is not real" + (f" at {point}:" if point else ":"),
                )
            s_values[:, r, c] = np.where(is_real(s, tol), s.real, np.nan)
            e_values[:, r, c] = np.where(real_e, e.real, np.nan)
            verdict = _verdict(s, e, tol)
            if verdict != RIGHT:
                verdicts[(r, c)] = verdict
    return Judgement(s_values, e_values, verdicts)
