"""The checker against a corpus of realistic answers (tests/diagnosis_corpus).

Every right answer is accepted, every wrong one refused, and the primary diagnosis is the
expected one for at least 90 % of the wrong answers and for every case marked "must"
(the failures seen in the study of real answers and the course's own wrong answers).
``python -m tests.diagnosis_corpus`` prints the per-family table.
"""

from __future__ import annotations

import pytest

from .diagnosis_corpus import CASES, held_out_modules
from .diagnosis_corpus.case import Case, right, wrong
from .diagnosis_corpus.measure import (
    Outcome,
    family_table,
    format_table,
    judge,
    lesson_group,
    primary_rate,
)


@pytest.fixture(scope="module")
def outcomes() -> list[Outcome]:
    return [judge(case) for case in CASES]


def _listed(outcomes: list[Outcome]) -> str:
    return "\n".join(
        f"{o.case.id}: expected {o.case.diagnosis}, got {o.diagnosis} ({o.grade}); {o.hints[:1]}"
        for o in outcomes
    )


def test_the_corpus_is_large_and_varied():
    ids = [case.id for case in CASES]
    assert len(ids) == len(set(ids)), "case ids must be unique"
    assert len(CASES) >= 150
    assert sum(case.ok for case in CASES) >= 30
    families = {case.family for case in CASES if not case.ok}
    assert len(families) >= 8
    assert all(not case.ok or case.diagnosis is None for case in CASES)
    assert sum(case.must for case in CASES) >= 30
    # lessons 1–8 ask for matrices typed as text; lessons 9–12 for tables, lists and numbers
    typed = [case for case in CASES if lesson_group(case) == "lessons 1–8"]
    assert sum(isinstance(case.answer, str) for case in typed) > len(typed) / 2  # text mostly


def test_no_false_accepts(outcomes):
    accepted = [o for o in outcomes if o.grade == "false accept"]
    assert not accepted, _listed(accepted)


def test_no_false_rejects(outcomes):
    rejected = [o for o in outcomes if o.grade == "false reject"]
    assert not rejected, _listed(rejected)


def test_every_must_case_gets_its_primary_diagnosis(outcomes):
    missed = [o for o in outcomes if o.case.must and o.grade != "right"]
    assert not missed, _listed(missed)


def test_primary_diagnosis_rate(outcomes):
    """In-sample (the cases the diagnoses were built against) and held-out, apart."""
    inside = [o for o in outcomes if o.case.split == "in-sample"]
    held = [o for o in outcomes if o.case.split == "held-out"]
    late = [o for o in inside if lesson_group(o.case) == "lessons 9–12"]
    for name, part in (("in-sample", inside), ("lessons 9–12", late), ("held-out", held)):
        print(f"\n{name}: primary diagnosis right for {primary_rate(part):.1%}")
        print(format_table(family_table(part)))
    missed = [o for o in inside if not o.case.ok and o.grade != "right"]
    assert primary_rate(inside) >= 0.95, _listed(missed)
    assert primary_rate(late) >= 0.9, _listed([o for o in missed if o in late])
    assert primary_rate(held) >= 0.85, _listed([o for o in held if o.grade != "right"])


def test_lessons_9_to_12_are_in_the_corpus():
    """Every exercise of lessons 9–12 has at least one right and one wrong answer."""
    seen: dict[str, set[bool]] = {}
    for case in CASES:
        if lesson_group(case) == "lessons 9–12":
            seen.setdefault(case.reference, set()).add(case.ok)
    counts = {"L9": 4, "L10": 5, "L11": 7, "L12": 6}
    expected = {f"{lesson}.ex{k}" for lesson, n in counts.items() for k in range(1, n + 1)}
    assert set(seen) == expected
    assert all(found == {True, False} for found in seen.values()), seen


def test_a_held_out_family_is_a_file_of_its_own():
    """``heldout_<name>.py`` modules are found by name; their cases count as held-out."""
    names = held_out_modules()
    assert names[0] == "blind" and all(n.startswith("heldout_") for n in names[1:])
    held = {case.id.split("/")[0] for case in CASES if case.split == "held-out"}
    assert {case.split for case in CASES} <= {"in-sample", "held-out"}
    assert sum(case.split == "held-out" for case in CASES) >= 80 and held


def test_family_table_counts_by_hand():
    cases = [
        right(
            "right", "a", "L2.ex3", "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1 + 20], [0, 0, 0, 1]]"
        ),
        wrong(
            "x",
            "b",
            "L2.ex3",
            "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1], [0, 0, 0, 1]]",
            "missing_offset",
        ),
        wrong(
            "x",
            "c",
            "L2.ex3",
            "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1], [0, 0, 0, 1]]",
            "wrong_order",
        ),
        wrong(
            "x",
            "d",
            "L2.ex3",
            "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1 - 20], [0, 0, 0, 1]]",
            "missing_offset",
        ),
        wrong(
            "x",
            "e",
            "L2.ex3",
            "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1 + 20], [0, 0, 0, 1]]",
            None,
        ),
    ]
    found = [judge(case) for case in cases]
    assert [o.grade for o in found] == ["right", "right", "wrong", "vague", "false accept"]
    assert family_table(found) == [("right", 1, 1, 0, 0), ("x", 4, 1, 1, 2), ("total", 5, 2, 1, 2)]
    assert primary_rate(found) == 0.25
    text = format_table(family_table(found))
    assert text.splitlines()[0] == "| family | count | right primary | vague | wrong |"
    assert "| total | 5 | 2 | 1 | 2 |" in text


def test_a_case_records_its_expectation():
    case = wrong("signs", "n", "L2.ex2", "[[1]]", "rotation_direction", must=True, tol=1e-2)
    assert isinstance(case, Case) and case.id == "signs/n" and case.options == {"tol": 1e-2}
    assert not case.ok and case.must
