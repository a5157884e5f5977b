"""A corpus of realistic answers to the course's exercises, and the outcome each should
get from the checker: accepted, or refused with a named primary diagnosis.

One data module per mistake family (plus the right answers); the expected matrices of
lessons 1–8 are built as the exercises build them (:mod:`.references`); a reference
``"L12.ex4"`` of lessons 9–12 is that exercise's check with the demo student's numbers
(``rc.Assignment``). ``python -m tests.diagnosis_corpus`` prints the tables: in-sample,
held-out, and both, per family and per lesson group.

**Adding a held-out family.** Write one module ``heldout_<name>.py`` here with
``CASES = [...]`` built with :func:`.case.right` and :func:`.case.wrong`; it is found by
its name and every case in it counts as held-out. The label of a wrong answer is the
diagnosis code a teacher would name (the codes and their meanings:
``robotconf course rubric LESSON``, ``rc.teaching.DIAGNOSES``, ``MATRIX_DIAGNOSES``,
``DH_DIAGNOSES``, ``IK_DIAGNOSES``, ``PROFILE_DIAGNOSES``, ``EXERCISE_SLIPS``), or
``None`` when no single slip explains it. ``blind.py`` is the first held-out family
(lessons 1–8). A held-out module whose cases the checks were then fixed against is
in-sample from then on: renamed (``lessons_9_12_blind.py``, ``lessons_9_12_second.py``
and ``lessons_9_12_third.py``, each measured held-out once before its fixes) with that
history in its docstring.
"""

from __future__ import annotations

import dataclasses
import importlib
from pathlib import Path

from . import (
    angles,
    blind,
    dh,
    heldout,
    joints,
    layout,
    lengths,
    lessons_9_12,
    lessons_9_12_blind,
    lessons_9_12_second,
    lessons_9_12_third,
    offsets,
    right_answers,
    signs,
    unexplained,
)
from .case import Case

__all__ = ["CASES", "Case", "held_out_modules"]

#: Modules written after the checker's ranking, by someone who did not read its code.
HELD_OUT = ["blind"]


def held_out_modules() -> list[str]:
    """``blind`` and every ``heldout_<name>`` module of this folder, sorted."""
    found = sorted(p.stem for p in Path(__file__).parent.glob("heldout_*.py"))
    return HELD_OUT + found


def _held_out(name: str) -> list[Case]:
    module = importlib.import_module(f"{__name__}.{name}")
    return [dataclasses.replace(case, split="held-out") for case in module.CASES]


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
    *lessons_9_12.CASES,
    *lessons_9_12_blind.CASES,
    *lessons_9_12_second.CASES,
    *lessons_9_12_third.CASES,
    *(case for name in held_out_modules() for case in _held_out(name)),
]
del blind  # read through held_out_modules
