"""The check for an interval [lo, hi]: a reach range, a joint range.

Each end is judged as :func:`~robotconf.teaching.check_vector` judges a component (the
same parser, tolerance and diagnoses); an answer written [hi, lo] is named as such.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..diagnosis._components import close
from ..reading._parser import ParserLimits
from ..reading._tolerance import ABS_TOL, REL_TOL
from ..reading._wrapper import answer_check
from ._input import expected_numbers, read_options
from ._numbers import finish, judge_components
from ._result import AnswerCheck

__all__ = ["check_interval"]


@answer_check(kind="interval")
def check_interval(
    answer: Any,
    expected_lo_hi: Any,
    *,
    tol: float = ABS_TOL,
    rel: float = REL_TOL,
    unit: str | None = None,
    name: str | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> AnswerCheck:
    """Check an interval ``[lo, hi]``: a reach range, a joint range.

    Parameters
    ----------
    answer : list, text or None
        Two numbers, the smaller first: ``[10, 70]`` or ``"[40 - 30, 40 + 30]"``; text
        still holding symbols (``"[l3 - l2, l2 + l3]"``) gets the hint to work it out.
    expected_lo_hi : array-like, shape (2,)
        ``(lo, hi)`` with ``lo ≤ hi``.
    tol, rel, unit, name, reveal, hint, limits
        As in :func:`check_value`; ``name`` defaults to ``"the interval"``.

    Returns
    -------
    AnswerCheck
        ``wrong`` lists the wrong ends (0 lower, 1 upper). Diagnoses: ``swapped_ends``,
        and those of :func:`check_vector` for the ends (``sign_error``,
        ``unit_factor``, ``degrees_as_radians``, ``too_rounded``, ``shape``, …).

    Raises
    ------
    InvalidInputError
        As :func:`check_value`, and for ``lo > hi``.

    Examples
    --------
    >>> check_interval([10, 70], (10, 70)).ok
    True
    >>> check_interval([70, 10], (10, 70)).hints
    ['The ends are swapped: write the smaller one first, [lo, hi].']
    >>> check_interval([10, 60], (10, 70)).hints
    ['The upper end is wrong.']
    """
    options = read_options(
        name, "the interval", tol=tol, rel=rel, unit=unit, reveal=reveal, hint=hint
    )
    name, setting, hint = options.name, options.setting, options.hint
    ends = expected_numbers(expected_lo_hi, "expected_lo_hi").reshape(-1)
    if ends.size != 2 or ends[0] > ends[1]:
        raise InvalidInputError("expected_lo_hi", expected_lo_hi, "[lo, hi] with lo ≤ hi")
    names = ["the lower end", "the upper end"]
    result = judge_components(answer, ends, setting, names, name, hint, limits, part="end")
    student = result.student
    if result.diagnosis == "shape":
        count = np.size(student)
        text = f"Give {name} as [lo, hi]: two numbers, the smaller first; you gave {count}."
        return finish(False, [text], ["shape"], name, student, ends, hint)
    if result.ok or student is None or np.shape(student) != (2,):
        return result
    if close(student[::-1], ends, setting, None).all():
        text = "The ends are swapped: write the smaller one first, [lo, hi]."
        return finish(
            False,
            [text],
            ["swapped_ends"],
            name,
            student,
            ends,
            hint,
            wrong=[0, 1],
            headline=f"{name}: the ends are swapped.",
            reveal=setting.reveal,
        )
    return result
