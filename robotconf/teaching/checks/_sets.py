"""The check for a set of solutions, in any order (both IK solutions, every singular pose).

It reads the answer as :func:`~robotconf.teaching.check_value` does (the whitelist parser
and numeric judge of :func:`~robotconf.teaching.check_matrix`) and compares with the same
tolerance, ``max(tol, rel·|expected|)`` per number; the elements are paired with the
solutions by a largest matching, so the order is free and a repeat is seen as one.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ..diagnosis._components import (
    Setting,
    allowed,
    close,
    keep_digits,
    length_unit,
    names_text,
    rounded,
    wrap,
)
from ..reading._parser import ParserLimits
from ..reading._shown import number_text, sentence
from ..reading._tolerance import ABS_TOL, REL_TOL
from ..reading._wrapper import answer_check
from ._input import NO_ANSWER, expected_numbers, parse_answer, read_options
from ._numbers import finish
from ._result import AnswerCheck

__all__ = ["check_set"]

#: Most solutions an expected set may hold (an answer is capped by the parser's entries).
MAX_SOLUTIONS = 400


def _matching(fits: np.ndarray) -> dict[int, int]:
    """A largest pairing of answer elements i with solutions j where ``fits[i, j]``.

    Each element takes a free solution it fits when there is one; only the rest search
    for augmenting paths (Kuhn). With distinct solutions an element fits one or two, so
    the search is short. Returns ``{solution j: element i}``.
    """
    owner: dict[int, int] = {}
    free = np.ones(fits.shape[1], dtype=bool)

    def augment(i: int, seen: set[int]) -> bool:
        for j in map(int, np.flatnonzero(fits[i])):
            if j not in seen:
                seen.add(j)
                if j not in owner or augment(owner[j], seen):
                    owner[j] = i
                    return True
        return False

    waiting = []
    for i in range(fits.shape[0]):
        open_ = np.flatnonzero(fits[i] & free)
        if open_.size:
            owner[int(open_[0])] = i
            free[open_[0]] = False
        else:
            waiting.append(i)
    for i in waiting:
        augment(i, set())
    return owner


def _distinct(solutions: np.ndarray, setting: Setting, expected_set: Any) -> None:
    """Refuse a set whose solutions are equal within the tolerance: one would be unfindable."""
    gap = np.abs(wrap(solutions[:, None, :] - solutions[None, :, :], setting.period))
    same = np.all(gap <= allowed(solutions, setting.tol, setting.rel)[None], axis=2)
    same[np.diag_indices(len(solutions))] = False
    if same.any():
        i, j = sorted(map(int, np.argwhere(same)[0]))
        raise InvalidInputError(
            "expected_set",
            expected_set,
            "distinct solutions",
            problem=f"solutions {i + 1} and {j + 1} are equal within the tolerance:",
        )


def _elements(
    values: np.ndarray, entries: list[str], dim: int
) -> tuple[np.ndarray, list[str]] | None:
    """The answer's elements, shape (k, dim), and their text; ``None`` for a wrong layout."""
    rows, cols = values.shape
    if dim == 0:
        if min(rows, cols) != 1:
            return None
        return values.reshape(-1, 1), entries
    if cols == dim:
        texts = [f"[{', '.join(entries[r * cols : (r + 1) * cols])}]" for r in range(rows)]
        return values, texts
    if rows == dim and cols == 1:  # one vector written as a column
        return values.reshape(1, dim), [f"[{', '.join(entries)}]"]
    return None


def _pick(found: np.ndarray, open_: np.ndarray) -> int | None:
    """The first solution in ``found``, a missing one if possible."""
    for mask in (found & open_, found):
        index = np.flatnonzero(mask)
        if index.size:
            return int(index[0])
    return None


#: Slips an element may be away from a solution: (code, hint for one, hint for several).
_SLIPS = {
    "degrees": (
        "degrees_as_radians",
        "{} looks like a solution in degrees: give it in radians (180° = π).",
        "{} look like solutions in degrees: give them in radians (180° = π).",
    ),
    "sign": ("sign_error", "{} has the wrong sign.", "{} have the wrong sign."),
    "large": ("unit_factor", "{} is 1000 times too large.", "{} are 1000 times too large."),
    "small": ("unit_factor", "{} is 1000 times too small.", "{} are 1000 times too small."),
    "rounded": ("too_rounded", "{} is rounded too much: {}.", "{} are rounded too much: {}."),
}


def _diagnose_extra(
    element: np.ndarray, solutions: np.ndarray, setting: Setting, open_: np.ndarray
) -> tuple[str, int] | None:
    """(slip, solution) for an element that is a known slip (:data:`_SLIPS`) away from a
    solution.

    ``element`` has shape (d,), ``solutions`` (m, d), ``open_`` marks the m solutions no
    element matched; all m are compared at once.
    """
    period = setting.period
    degrees_period = None if period is None else math.degrees(period)
    candidates = [
        ("degrees", np.degrees(solutions), degrees_period),
        ("sign", -solutions, period),
    ]
    # A zero is no length off by a factor of 1000 (a thousandth of a small number is near
    # zero too): only an element with a nonzero entry can show a unit slip.
    if period is None and length_unit(setting.unit) and np.any(element != 0):
        candidates += [("large", solutions * 1000, None), ("small", solutions / 1000, None)]
    for slip, candidate, candidate_period in candidates:
        found = np.all(close(element[None, :], candidate, setting, candidate_period), axis=1)
        j = _pick(found, open_)
        if j is not None:
            return slip, j
    if element.size == 1:
        e = solutions[:, 0]
        nearest = e if period is None else e + period * np.round((element[0] - e) / period)
        j = _pick(rounded(np.full(len(e), element[0]), nearest), open_)
        if j is not None:
            return "rounded", j
    return None


def _grouped(texts: list[str], one: str, several: str, *more: str) -> str:
    template = one if len(texts) == 1 else several
    return template.format(names_text(texts), *more)


def _missing_hint(
    missing: list[int],
    found: int,
    solutions: np.ndarray,
    labels: list[str] | None,
    setting: Setting,
) -> str:
    total = len(solutions)
    verb = "is" if len(missing) == 1 else "are"
    text = f"You gave {found} of the {total} solutions; {len(missing)} {verb} missing"
    named = []
    for j in missing:
        shown = [number_text(x) for x in solutions[j]]
        value = shown[0] if len(shown) == 1 else f"[{', '.join(shown)}]"
        if labels and setting.reveal:
            named.append(f"{labels[j]} ({value})")
        elif labels:
            named.append(labels[j])
        elif setting.reveal:
            named.append(value)
    return text + (f": {names_text(named)}." if named else ".")


def _unmatched(
    elements: np.ndarray,
    texts: list[str],
    fits: np.ndarray,
    owner: dict[int, int],
    solutions: np.ndarray,
    setting: Setting,
) -> tuple[list[str], list[str], set[int]]:
    """Hints on the answer's elements left unpaired: repeats, slips and strays.

    Returns the hints, their codes and the solutions a diagnosed slip accounts for (their
    absence needs no hint of its own).
    """
    matched = set(owner.values())
    is_open = ~np.isin(np.arange(len(solutions)), list(owner))
    hints: list[str] = []
    codes: list[str] = []
    explained: set[int] = set()
    slips: dict[str, list[str]] = {}
    twice: list[str] = []
    same: list[str] = []
    strays: list[str] = []
    for i in range(len(elements)):
        if i in matched:
            continue
        if fits[i].any():
            twin = next(owner[j] for j in map(int, np.flatnonzero(fits[i])) if j in owner)
            equal = np.abs(elements[i] - elements[twin]) <= allowed(
                elements[twin], setting.tol, setting.rel
            )
            (twice if equal.all() else same).append(texts[i])
            continue
        found = _diagnose_extra(elements[i], solutions, setting, is_open)
        if found is None:
            strays.append(texts[i])
        else:
            slips.setdefault(found[0], []).append(texts[i])
            explained.add(found[1])
    for slip, listed in slips.items():
        code, one, several = _SLIPS[slip]
        hints.append(_grouped(listed, one, several, keep_digits(setting)))
        codes.append(code)
    if twice:
        unique = list(dict.fromkeys(twice))
        given = _grouped(unique, "{} is given more than once", "{} are given more than once")
        hints.append(given + ": give each solution once.")
    if same:
        hints.append(
            _grouped(same, "{} repeats", "{} repeat") + " a solution you gave, a whole number of "
            "turns away: give each solution once."
        )
    codes += ["duplicate"] if twice or same else []
    if strays:
        hints.append(_grouped(strays, "{} is not a solution.", "{} are not solutions."))
        codes.append("extra")
    return hints, codes, explained


def _check_set(
    answer: Any,
    expected_set: Any,
    setting: Setting,
    name: str,
    labels: list[str] | None,
    hint: str | None,
    limits: ParserLimits | None,
) -> AnswerCheck:
    solutions = expected_numbers(expected_set, "expected_set")
    if solutions.ndim not in (1, 2) or len(solutions) > MAX_SOLUTIONS:
        raise InvalidInputError(
            "expected_set", expected_set, f"a list of at most {MAX_SOLUTIONS} numbers or vectors"
        )
    dim = 0 if solutions.ndim == 1 else solutions.shape[1]
    solutions = solutions.reshape(len(solutions), -1)
    _distinct(solutions, setting, expected_set)
    total = len(solutions)
    if labels is not None and (len(labels) != total or not all(isinstance(x, str) for x in labels)):
        raise InvalidInputError("labels", labels, f"{total} names (text), one per solution")
    reference = solutions.reshape(-1) if dim == 0 else solutions
    if answer is None:
        return AnswerCheck(
            False,
            [NO_ANSWER],
            "no_answer",
            name,
            None,
            reference,
            headline=f"{name}: no answer yet.",
        )
    empty = (isinstance(answer, (list, tuple, np.ndarray)) and np.size(answer) == 0) or (
        isinstance(answer, str) and answer.replace(" ", "") in ("[]", "()", "")
    )
    if empty:
        nothing = [_missing_hint(list(range(total)), 0, solutions, labels, setting)]
        return finish(
            False, nothing, ["missing"], name, None, reference, hint, wrong=list(range(total))
        )
    parsed = parse_answer(answer, limits)
    if parsed.symbols or parsed.values is None:
        problem = (
            f"still holds {', '.join(parsed.symbols)}: give numbers, worked out"
            if parsed.symbols
            else "is too complicated to check: simplify it first"
        )
        code = "not_a_number" if parsed.symbols else "too_complicated"
        return finish(False, [f"{sentence(name)} {problem}."], [code], name, None, reference, hint)
    layout = _elements(parsed.values, parsed.entries, dim)
    if layout is None:
        shape = "a list of numbers [a, b, …]" if dim == 0 else f"a list of [{dim} numbers] lists"
        text = f"Give {name} as {shape}, one entry per solution."
        return finish(False, [text], ["shape"], name, parsed.values, reference, hint)
    elements, texts = layout
    period = setting.period
    gap = np.abs(wrap(elements[:, None, :] - solutions[None, :, :], period))
    fits = np.all(gap <= np.maximum(setting.tol, setting.rel * np.abs(solutions))[None], axis=2)
    owner = _matching(fits)
    matched = {i: j for j, i in owner.items()}
    open_ = [j for j in range(total) if j not in owner]
    hints, codes, explained = _unmatched(elements, texts, fits, owner, solutions, setting)
    missing = [j for j in open_ if j not in explained]
    if missing:
        hints.append(_missing_hint(missing, len(owner), solutions, labels, setting))
        codes.append("missing")
    student = elements.reshape(-1) if dim == 0 else elements
    headline = f"{name}: {len(owner)} of {total} solution{'s' if total != 1 else ''} right."
    if len(elements) > len(owner):
        headline = headline[:-1] + f", {len(elements) - len(owner)} not."
    return finish(
        not hints,
        hints,
        codes,
        name,
        student,
        reference,
        hint,
        wrong=open_,
        extra=sorted(set(range(len(elements))) - set(matched)),
        headline=headline,
        reveal=setting.reveal,
    )


@answer_check(kind="set")
def check_set(
    answer: Any,
    expected_set: Any,
    *,
    tol: float = ABS_TOL,
    rel: float = REL_TOL,
    period: float | None = None,
    unit: str | None = None,
    name: str | None = None,
    labels: Sequence[str] | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> AnswerCheck:
    """Check a set of solutions in any order: both IK solutions, every singular pose.

    Parameters
    ----------
    answer : list, ndarray, text or None
        The solutions: ``[0, pi]``, ``"[3.1416, 0]"``, or for vector solutions one list per
        solution, ``[[0.5, 1.2], [0.5, -1.2]]``. One number (or one vector) counts as a
        set of one.
    expected_set : array-like, shape (m,) or (m, d)
        The m solutions: numbers, or vectors of d numbers.
    tol, rel : float
        A number is right within ``max(tol, rel·|expected|)`` (0.5 %, or 0.001 near zero:
        3 significant digits pass).
    period : float, optional
        For angles: solutions equal modulo ``period`` (``2*np.pi``) are the same.
    unit, name, reveal, hint, limits
        As in :func:`check_value`; ``name`` defaults to ``"the set of solutions"``.
    labels : sequence of str, optional
        A name per solution (``"the arm stretched"``), which the hint for a missing one
        may use without giving the value away.

    Returns
    -------
    AnswerCheck
        ``wrong`` lists the missing solutions, ``extra`` the answer's elements that are
        no solution or repeat one. Diagnoses: ``degrees_as_radians``, ``sign_error``,
        ``unit_factor``, ``too_rounded`` (for an element a slip away from a missing
        solution), ``duplicate``, ``extra``, ``missing``, ``shape``, ``not_a_number``,
        ``no_answer``.

    Raises
    ------
    InvalidInputError
        As :func:`check_value`.

    Examples
    --------
    >>> check_set("[3.1416, 0]", [0, np.pi]).ok
    True
    >>> check_set([0], [0, np.pi], labels=["stretched", "folded"]).hints
    ['You gave 1 of the 2 solutions; 1 is missing: folded.']
    >>> check_set([0, 180], [0, np.pi]).hints
    ['180 looks like a solution in degrees: give it in radians (180° = π).']
    >>> check_set([0, 2 * np.pi], [0, np.pi], period=2 * np.pi).diagnosis
    'duplicate'
    """
    if period is not None:
        period = check_finite_number(period, "period")
        if period <= 0:
            raise InvalidInputError("period", period, "a positive number (a full turn)")
    options = read_options(
        name,
        "the set of solutions",
        tol=tol,
        rel=rel,
        unit=unit,
        reveal=reveal,
        hint=hint,
        period=period,
    )
    labels = None if labels is None else list(labels)
    return _check_set(
        answer, expected_set, options.setting, options.name, labels, options.hint, limits
    )
