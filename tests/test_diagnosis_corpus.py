"""The checker against a corpus of realistic answers (tests/diagnosis_corpus).

Every right answer is accepted, every wrong one refused, and the primary diagnosis is the
expected one for at least 90 % of the wrong answers and for every case marked "must"
(the failures seen in the study of real answers and the course's own wrong answers).
``python -m tests.diagnosis_corpus`` prints the per-family table.
"""

from __future__ import annotations

import pytest

from .diagnosis_corpus import CASES
from .diagnosis_corpus.case import Case, right, wrong
from .diagnosis_corpus.measure import Outcome, family_table, format_table, judge, primary_rate


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
    assert sum(isinstance(case.answer, str) for case in CASES) > len(CASES) / 2  # text mostly


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
    rate = primary_rate(outcomes)
    print(f"\nprimary diagnosis right for {rate:.1%} of the wrong answers")
    print(format_table(family_table(outcomes)))
    missed = [o for o in outcomes if not o.case.ok and o.grade != "right"]
    assert rate >= 0.9, _listed(missed)


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
