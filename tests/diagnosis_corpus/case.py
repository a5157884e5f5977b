"""One corpus case: a student's answer to an exercise and the outcome it should get."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

__all__ = ["Case", "right", "wrong"]


@dataclass(frozen=True)
class Case:
    """A realistic answer and what the checker should make of it.

    Attributes
    ----------
    id : str
        Unique, e.g. ``"signs/L2.ex2-ry-pattern-of-rx"``.
    family : str
        The mistake family (or ``"right"``) the table groups by.
    reference : str
        Key of the expected matrix in :data:`~tests.diagnosis_corpus.references.REFERENCES`.
    answer : object
        What the student typed: text mostly, or nested lists of numbers.
    ok : bool
        Whether the answer is right.
    diagnosis : str or None
        For a wrong answer, the primary diagnosis it should get (``None``: no diagnosis is
        right to give, the hints should only name the wrong entries).
    must : bool
        A case the checker must get right (the failures seen in the study, and the
        course's own wrong-answer tests); the others count toward the measured rate.
    options : dict
        Extra keyword arguments of ``check_matrix`` (``tol`` for the numeric exercises).
    split : str
        ``"in-sample"`` (written while the diagnoses were built) or ``"held-out"`` (written
        afterwards by someone who did not read the diagnosis code; set by the module).
    student : str
        The student id of an exercise with per-student numbers (``"L12.ex4"``).
    """

    id: str
    family: str
    reference: str
    answer: Any
    ok: bool
    diagnosis: str | None = None
    must: bool = False
    options: dict[str, Any] = field(default_factory=dict)
    split: str = "in-sample"
    student: str = "demo"


def right(family: str, name: str, reference: str, answer: Any, **options: Any) -> Case:
    """A right answer (written in some other form than the solution's)."""
    return Case(f"{family}/{name}", family, reference, answer, True, options=options)


def wrong(
    family: str,
    name: str,
    reference: str,
    answer: Any,
    diagnosis: str | None,
    *,
    must: bool = False,
    **options: Any,
) -> Case:
    """A wrong answer with the primary diagnosis it should get."""
    return Case(f"{family}/{name}", family, reference, answer, False, diagnosis, must, options)
