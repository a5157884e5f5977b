"""A corpus of realistic answers to the course's matrix exercises, and the outcome each
should get from the homework checker: accepted, or refused with a named primary diagnosis.

One data module per mistake family (plus the right answers); the expected matrices are
built as the exercises build them (:mod:`.references`). ``python -m tests.diagnosis_corpus``
prints the per-family table (family, count, right primary, vague, wrong).
"""

from __future__ import annotations

from . import (
    angles,
    blind,
    dh,
    heldout,
    joints,
    layout,
    lengths,
    offsets,
    right_answers,
    signs,
    unexplained,
)
from .case import Case

__all__ = ["CASES", "Case"]

CASES: list[Case] = [
    *right_answers.CASES,
    *signs.CASES,
    *layout.CASES,
    *offsets.CASES,
    *angles.CASES,
    *joints.CASES,
    *lengths.CASES,
    *dh.CASES,
    *unexplained.CASES,
    *heldout.CASES,
    *blind.CASES,
]
