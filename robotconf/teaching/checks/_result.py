"""The verdict on one non-matrix answer: a value, vector, angle, set or interval."""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from typing import Any

__all__ = ["AnswerCheck", "DIAGNOSES", "UNNAMED", "explains_all"]

#: Every diagnosis code an :class:`AnswerCheck` may carry, with what it means.
DIAGNOSES = {
    "no_answer": "the answer is still None",
    "not_a_number": "the answer holds symbols (q1, l2, …) where numbers are asked",
    "too_complicated": "an entry is too large for the checker to evaluate",
    "shape": "the wrong number of components (or a list where one number is asked)",
    "sign_error": "a value or some components with the wrong sign",
    "sign_flipped": "a whole vector pointing the opposite way",
    "swapped_components": "two components exchanged",
    "swapped_ends": "an interval written [hi, lo]",
    "degrees_as_radians": "degrees given where radians are asked",
    "radians_as_degrees": "radians given where degrees are asked",
    "unit_factor": "off by a unit factor (1000: mm and m; 100: cm and m)",
    "half_turn": "an angle off by half a turn (π or 180°)",
    "too_rounded": "the right value rounded to too few digits",
    "missing": "solutions of a set left out",
    "duplicate": "one solution of a set given twice",
    "extra": "a value that is not a solution",
    "wrong": "wrong, with no recognised mistake",
}


#: Codes that name no mistake: nothing to read, the wrong layout, or wrong without a reason.
UNNAMED = frozenset(
    {"no_answer", "not_a_number", "too_complicated", "shape", "wrong", "missing", "extra"}
)


def explains_all(codes: list[str]) -> bool:
    """Whether the hints' codes are one named mistake, which explains the whole answer.

    >>> explains_all(["sign_error"]), explains_all(["sign_error", "wrong"]), explains_all(["wrong"])
    (True, False, False)
    """
    return len(set(codes)) == 1 and codes[0] not in UNNAMED


@dataclass(frozen=True, eq=False)
class AnswerCheck:
    """The verdict of :func:`check_value`, :func:`check_vector`, :func:`check_angle`,
    :func:`check_set` or :func:`check_interval`.

    Attributes
    ----------
    ok : bool
        The answer is right within the tolerance.
    hints : list of str
        What is wrong and the likely mistake, in sentences a student can act on; empty
        when ``ok``. Expected values are quoted only with ``reveal=True``.
    diagnosis : str or None
        The code of the main recognised mistake (see :data:`DIAGNOSES`), ``"wrong"`` when
        none is recognised, ``None`` when ``ok``.
    name : str
        What was checked, as the messages call it (``"the velocity"``, ``"q3"``).
    student : ndarray or None
        The answer as numbers: shape () for a value, (n,) for a vector or an interval,
        (m,) or (m, d) for a set; ``None`` when there is no answer or it holds symbols.
    expected : ndarray
        The reference, in the same layout.
    wrong : list of int
        0-based components that are wrong (vector, angles, interval ends) or, for a set,
        the expected solutions missing from the answer.
    extra : list of int
        For a set: the answer's elements (0-based) that are no solution or repeat one.
    headline : str
        The first line of the message (``"the velocity: 1 wrong component (z)."``).
    kind : str
        Which check made the verdict: ``"value"``, ``"vector"``, ``"angle"``, ``"set"``,
        ``"interval"``, ``"profile"``, ``"ik_solution"`` or ``"ik_solutions"``.
    complete : bool
        The diagnosis explains every wrong number: one slip, nothing else wrong (what a
        rubric may credit as "a right method with one slip").
    """

    ok: bool
    hints: list[str]
    diagnosis: str | None
    name: str
    student: Any
    expected: Any
    wrong: list[int] = field(default_factory=list)
    extra: list[int] = field(default_factory=list)
    headline: str = ""
    reveal: bool = field(default=False, repr=False)
    kind: str = "value"
    complete: bool = False

    def __bool__(self) -> bool:
        return self.ok

    def __str__(self) -> str:
        if self.ok:
            return f"{self.name}: correct."
        head = self.headline or f"{self.name}: not right yet."
        return "\n".join([head, *(f"- {hint}" for hint in self.hints)])

    def __repr__(self) -> str:
        return f"<AnswerCheck ok={self.ok} diagnosis={self.diagnosis!r}>"

    def _repr_html_(self) -> str:
        if self.ok:
            return f"<div><b>✔ {html.escape(self.name)}: correct</b></div>"
        head = html.escape(str(self).split("\n")[0])
        items = "".join(f"<li>{html.escape(hint)}</li>" for hint in self.hints)
        return (
            f'<div><b style="color:#c00">✗ {head}</b>' + (f"<ul>{items}</ul>" if items else "")
        ) + "</div>"
