"""Points, partial credit and the hidden recheck of a graded check cell (no kernel).

``Credit`` is what a released autograder cell runs; nbgrader grades the cell by its last
output (the score), or 0 when it raises or writes to standard error. The expected
scores below are counted by hand from the graded-entry rule in
``robotconf/grading/_points.py``.
"""

from __future__ import annotations

import sys
import warnings

import numpy as np
import pytest

import robotconf as rc
from robotconf import teaching
from robotconf.grading import Credit, answer_credit, find_exercises, graded_entries, points_for
from robotconf.grading._nbgrader_cells import answer_source, autograder_source

FRAME = rc.Robot([rc.Module("Rz", a=(30, 0, 20))], end_effector=(40, 0, 0))
#: A1 of FRAME: the graded entries are cos, -sin, sin, cos, 30 and 20 (6 of 16).
A1 = "[[cos(q1), -sin(q1), 0, 30], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]"
ONE_SIGN = A1.replace("[sin(q1), cos(q1)", "[-sin(q1), cos(q1)")
TRANSPOSED = A1.replace("-sin(q1), 0, 30], [sin(q1)", "sin(q1), 0, 30], [-sin(q1)")


def _fitted_a1() -> str:
    """A1 with (1,1) = cos(q1) + ∏(q1 − p): right at the checker's 8 seeded points p only."""
    points = teaching.sample_points(["q1"], 8, 0)["q1"]
    bump = "*".join(f"(q1 - {float(p)!r})" for p in points)
    return A1.replace("[[cos(q1),", f"[[cos(q1) + {bump},", 1)


def test_points_rule():
    assert points_for("matrix", (4, 4)) == 2
    assert [points_for("matrix", s) for s in [(4, 1), (3, 3), (2, 2), (1, 1)]] == [1, 1, 1, 1]
    assert points_for("vector", (4, 4)) == points_for(None, None) == 1


def test_graded_entries_leave_out_what_a_blank_guess_gets_right():
    expected = rc.expected_matrix(FRAME, "A1").matrix
    assert graded_entries(expected).tolist() == [
        [True, True, False, True],
        [True, True, False, False],
        [False, False, False, True],
        [False, False, False, False],
    ]
    # At q1 = 90° the cosines are 0: only -1, 30, 1 and 20 count.
    at_90 = rc.expected_matrix(FRAME, "A1", q=[np.pi / 2]).matrix
    assert int(graded_entries(at_90).sum()) == 4
    # A position (x, y, z, 1): the homogeneous 1 never counts, zeros neither.
    assert graded_entries([[30], [0], [20], [1]]).ravel().tolist() == [True, False, True, False]
    assert not graded_entries(np.eye(3)).any()


@pytest.mark.parametrize(
    ("answer", "credit"),
    [
        (A1, 1.0),
        (ONE_SIGN, 5 / 6),  # one sine wrong of 6 graded entries
        (TRANSPOSED, 4 / 6),  # both sines wrong
        (np.eye(4), 0.0),  # all 6 graded entries wrong
        (np.zeros((4, 4)), 0.0),  # 6 graded + 2 ones of the diagonal: clipped at 0
        (np.eye(3), 0.0),  # wrong shape
    ],
)
def test_matrix_credit_per_graded_entry(answer, credit):
    result = rc.check_matrix(answer, rc.expected_matrix(FRAME, "A1"))
    assert answer_credit("matrix", result) == pytest.approx(credit)


def test_credit_of_other_answer_kinds():
    assert answer_credit("vector", rc.check_vector([0, 35, 40], [0, 35, -40])) == 0.5
    assert answer_credit("vector", rc.check_vector([0, 35], [0, 35, -40])) == 0.0
    assert answer_credit("set", rc.check_set([np.pi], [0, np.pi])) == 0.5
    assert answer_credit("set", rc.check_set([np.pi, 0], [0, np.pi])) == 1.0
    assert answer_credit("value", rc.check_value(-98, -99)) == 0.0
    assert answer_credit("angle", rc.check_angle(1.0, 2.0)) == 0.0


def test_a_right_answer_earns_the_points(capsys):
    with Credit(2) as credit:
        rc.assert_matrix(A1, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 2.0
    assert capsys.readouterr().out == ""


def test_a_partly_right_matrix_earns_partial_credit_and_prints_why(capsys):
    with Credit(2) as credit:
        rc.assert_matrix(ONE_SIGN, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 1.67  # 2 × 5/6, rounded to 0.01
    out = capsys.readouterr().out
    assert out.startswith("A1: 1 wrong entry.")
    assert "Partial credit: 1.67 of 2 points (1 of the 6 entries that count is wrong)." in out


@pytest.mark.parametrize(
    ("answer", "error"),
    [
        (np.eye(4), AssertionError),  # no graded entry right: 0, the error stays
        (None, AssertionError),  # not answered
        ("[[cos q1]]", ValueError),  # a typing slip: the parser's error
        (np.eye(3), AssertionError),  # wrong shape
    ],
)
def test_no_credit_lets_the_error_through(answer, error):
    with pytest.raises(error), Credit(2) as credit:
        assert answer is not None, "Exercise 1 is not answered yet."
        rc.assert_matrix(answer, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 0.0


def test_whole_points_only_when_partial_is_off():
    with pytest.raises(AssertionError), Credit(2, partial=False) as credit:
        rc.assert_matrix(ONE_SIGN, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 0.0


def test_hint_checks_do_not_decide_the_credit():
    """``check_*`` calls that only choose a hint are not the verdict: the assert is."""
    with Credit(1) as credit:
        if rc.check_vector([0, 35, 40], [0, -35, 40]).ok:  # a hint check that fails
            pass
        rc.assert_vector([0, 35, 40], [0, 35, -40])
    assert credit.score == 0.5  # z wrong, of the 2 non-zero components


def test_a_plain_assert_after_a_check_earns_nothing():
    with pytest.raises(AssertionError), Credit(1) as credit:
        result = rc.check_vector([0, 35, 40], [0, 35, -40])
        assert result.ok, "the velocity is wrong"
    assert credit.score == 0.0


def test_the_hidden_recheck_catches_an_answer_fitted_to_the_visible_points(capsys):
    fitted = _fitted_a1()
    assert rc.check_matrix(fitted, rc.expected_matrix(FRAME, "A1")).ok  # the visible check
    with Credit(2) as credit:
        rc.assert_matrix(fitted, rc.expected_matrix(FRAME, "A1"))
        credit.recheck()
    assert credit.score == 1.67  # entry (1,1) wrong: 2 × 5/6
    assert "not everywhere" in capsys.readouterr().out
    with Credit(2) as credit:  # the right answer passes the recheck
        rc.assert_matrix(A1, rc.expected_matrix(FRAME, "A1"))
        credit.recheck()
    assert credit.score == 2.0


def test_standard_error_and_warnings_cannot_cost_points(capsys):
    with Credit(1) as credit:
        print("noise", file=sys.stderr)
        warnings.warn("something old", DeprecationWarning, stacklevel=1)
        rc.assert_matrix([[1]], [[1]])
    assert credit.score == 1.0
    captured = capsys.readouterr()
    assert captured.err == ""
    assert "noise" in captured.out and "DeprecationWarning: something old" in captured.out


def test_the_checkers_are_restored_after_the_block():
    before = (rc.assert_matrix, rc.check_vector, teaching.assert_matrix)
    with pytest.raises(AssertionError), Credit(1):
        rc.assert_matrix([[2]], [[1]])
    assert (rc.assert_matrix, rc.check_vector, teaching.assert_matrix) == before


@pytest.mark.parametrize("points", [-1, float("nan"), True, "2"])
def test_points_must_be_a_number(points):
    with pytest.raises(ValueError, match="points"):
        Credit(points)


def test_an_autograder_cell_runs_the_check_unchanged():
    check = 'assert answer_1 is not None, "not yet"\nrc.assert_matrix(answer_1, expected_1)'
    source, partial = autograder_source(check, 2, hidden=True)
    assert partial
    assert "    ### BEGIN HIDDEN TESTS\n    credit.recheck()" in source
    assert source.splitlines()[2] == (
        "with Credit(2) as credit:  # partial credit per entry (docs/grading.md)"
    )
    assert source.endswith("\n    ### END HIDDEN TESTS\ncredit.score")
    # Two asserts: whole points. A multi-line string cannot be indented: left as it is.
    two, partial = autograder_source(f"{check}\nrc.assert_value(1, 1)", 1, hidden=False)
    assert not partial and "Credit(1, partial=False)" in two
    text = 'rc.assert_matrix(answer_1, """[[1,\n2]]""")'
    assert autograder_source(text, 1, hidden=True) == (text, False)


def test_markers_in_course_cells_are_refused():
    with pytest.raises(ValueError, match="BEGIN SOLUTION"):
        answer_source("answer_1 = None", "### BEGIN SOLUTION\nanswer_1 = 1")


@pytest.mark.parametrize(
    ("cells", "message"),
    [
        ([("answer", "a = 1\nb = 2")], "exactly one variable"),
        ([("answer", "answer_1 = 1")], "followed by its check cell"),
        ([("check", "f(answer_9)")], "check cells that use an answer variable"),
    ],
)
def test_malformed_exercises_are_named(cells, message):
    notebook = {
        "cells": [
            {"cell_type": "code", "metadata": {"tags": [tag]}, "source": source}
            for tag, source in cells
        ]
    }
    with pytest.raises(ValueError, match=message):
        find_exercises(notebook, "lesson")
