"""Points, the rubric's credit and the hidden recheck of a graded check cell (no kernel).

``Credit`` is what a released autograder cell runs; nbgrader grades the cell by its last
output (the score), or 0 when it raises or writes to standard error. The expected
scores below are counted by hand from the rubric
(``robotconf/grading/rubric/_rubric.py``): a wrong answer earns the larger of a named
slip's share (half by default) and the share of its numbers that count and are right
(at most 3/4).
"""

from __future__ import annotations

import sys
import warnings

import numpy as np
import pytest

import robotconf as rc
from robotconf import teaching
from robotconf.grading import (
    Credit,
    Rubric,
    award,
    credit_counts,
    find_exercises,
    graded_entries,
    points_for,
)
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
    ("answer", "counts", "score", "slip"),
    [
        (A1, None, 2.0, None),
        # one sine wrong of 6 graded entries: 5/6 right, capped at 3/4
        (ONE_SIGN, (1, 6), 1.5, None),
        # the rotation turned the other way (both sines): named, but 4/6 numbers is more
        (TRANSPOSED, (2, 6), 1.33, None),
        (np.eye(4), (6, 6), 0.0, None),  # all 6 graded entries wrong, no slip
        (np.zeros((4, 4)), (6, 6), 0.0, None),  # 6 graded + 2 ones of the diagonal
        (np.eye(3), None, 0.0, None),  # wrong shape
    ],
)
def test_matrix_credit_by_the_rubric(answer, counts, score, slip):
    result = rc.check_matrix(answer, rc.expected_matrix(FRAME, "A1"))
    if not result.ok:
        assert credit_counts(result) == counts
    assert award(result, Rubric(2)).score == score


def test_a_named_slip_earns_its_share_and_the_numbers_theirs():
    # Turned the other way (equivalently, transposed): max(1/2, 4/6) = 4/6 of 2 points.
    turned = rc.check_matrix(TRANSPOSED, rc.expected_matrix(FRAME, "A1"))
    assert turned.diagnosis == "rotation_direction" and turned.complete
    assert award(turned, Rubric(2)).score == 1.33
    assert award(turned, Rubric(2, slips={"rotation_direction": 0.9})).score == 1.8
    # A blank identity: "at q = 0" explains the sines and cosines, not 30 and 20.
    blank = rc.check_matrix(np.eye(4), rc.expected_matrix(FRAME, "A1"))
    assert not blank.complete and award(blank, Rubric(2)).score == 0.0
    # One number: only a named slip earns anything.
    sign = award(rc.check_value(-99, 99), Rubric(1))
    assert (sign.score, sign.slip) == (0.5, "sign_error") and "sign" in sign.reason
    assert award(rc.check_value(-98, -99), Rubric(1)).score == 0.0
    assert award(rc.check_angle(1.0, 2.0), Rubric(1)).score == 0.0
    assert award(rc.check_value(None, 1), Rubric(1)).reason == "no answer yet: no points."


def test_credit_of_other_answer_kinds():
    assert award(rc.check_vector([0, 35, 40], [0, 35, -40]), Rubric(1)).score == 0.5
    assert award(rc.check_vector([0, 35], [0, 35, -40]), Rubric(1)).score == 0.0
    assert award(rc.check_set([np.pi], [0, np.pi]), Rubric(1)).score == 0.5
    assert award(rc.check_set([np.pi, 0], [0, np.pi]), Rubric(1)).score == 1.0
    # one of the two right, a wrong one in the other's place: half
    assert award(rc.check_set([0, 2], [0, np.pi]), Rubric(1)).score == 0.5
    assert award(rc.check_set([0, 2, 5], [0, np.pi]), Rubric(1)).score == 0.0
    # 3 is π to one digit: a named slip (too rounded) that explains the whole answer
    assert award(rc.check_set([0, 3], [0, np.pi]), Rubric(1)).score == 0.5
    # A trapezoid with t_a = 2v/a: a named slip (1 of 3 numbers right would be 1/3).
    task = rc.ProfileTask(2.0, speed=1.0, accel=2.0)
    slipped = rc.check_profile([1.0, 3.0, 1.0], task)
    assert credit_counts(slipped) == (2, 3)
    assert award(slipped, Rubric(1)).slip == "accel_time_factor"
    assert award(slipped, Rubric(1)).score == 0.5
    # One IK solution of two: per solution.
    arm = rc.preset("planar_2r", l1=1, l2=1)
    one = rc.check_ik_solutions([[0, np.pi / 2]], arm, [1, 1, 0])
    assert credit_counts(one) == (1, 2) and award(one, Rubric(2)).score == 1.0
    # A DH table with one α sign: a named slip of one row.
    paper = rc.Robot.from_dh([(0, 20, 0, -np.pi / 2, "R"), (0, 0, 30, 0, "R"), (0, 0, 40, 0, "R")])
    rows = [("q1", 20, 0, "pi/2"), ("q2", 0, 30, 0), ("q3", 0, 40, 0)]
    table = rc.check_dh_table(rows, paper)
    assert table.diagnosis == "alpha_sign"
    assert award(table, Rubric(2)).score == 1.0


def test_a_rubric_refuses_codes_that_name_no_slip():
    with pytest.raises(ValueError, match="slips"):
        Rubric(1, slips={"wrong": 0.5})
    with pytest.raises(ValueError, match="share"):
        Rubric(1, share=1.5)


def test_a_right_answer_earns_the_points(capsys):
    with Credit(2) as credit:
        rc.assert_matrix(A1, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 2.0
    assert capsys.readouterr().out == ""


def test_a_partly_right_matrix_earns_partial_credit_and_prints_why(capsys):
    with Credit(2) as credit:
        rc.assert_matrix(ONE_SIGN, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 1.5  # 5 of 6 numbers right, capped at 3/4 of 2 points
    out = capsys.readouterr().out
    assert out.startswith("A1: 1 wrong entry.")
    assert (
        "Credit: 1.5 points of 2 points: 5 of the 6 numbers that count are right "
        "(a wrong answer earns at most 75%)." in out
    )


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


def test_a_check_of_several_parts_counts_a_named_slip_only():
    off = A1.replace("30]", "31]")  # one number off, no slip: 5 of 6 numbers right
    with pytest.raises(AssertionError), Credit(2, several=True) as credit:
        rc.assert_matrix(off, rc.expected_matrix(FRAME, "A1"))
    assert credit.score == 0.0
    with Credit(2, several=True) as credit:
        rc.assert_value(-1.0, 1.0)  # a named sign slip
    assert credit.score == 1.0


def test_hint_checks_do_not_decide_the_credit():
    """``check_*`` calls that only choose a hint are not the verdict: the assert is."""
    with Credit(1) as credit:
        if rc.check_vector([0, 35, 40], [0, -35, 40]).ok:  # a hint check that fails
            pass
        rc.assert_vector([0, 35, 40], [0, 35, -40])
    assert credit.score == 0.5  # z wrong, of the 2 non-zero components; a sign slip too


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
    assert credit.score == 1.5  # entry (1,1) wrong: 5 of 6 right, capped at 3/4
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


def test_an_autograder_cell_hides_the_whole_check():
    check = 'assert answer_1 is not None, "not yet"\nrc.assert_matrix(answer_1, expected_1)'
    source, graded = autograder_source(
        check, Rubric(2, slips={"too_rounded": 0.75}), variable="answer_1", recheck=True
    )
    assert graded
    lines = source.splitlines()
    assert (
        lines[0] == "answer_1  # your answer, worth 2 points: checked when your notebook is graded"
    )
    assert lines[1] == "### BEGIN HIDDEN TESTS" and lines[-1] == "### END HIDDEN TESTS"
    assert "with Credit(2, slips={'too_rounded': 0.75}) as credit:" in lines
    assert "    credit.own_work('answer_1')" in lines
    assert lines[-3:-1] == [
        "    credit.recheck()  # the same check at 32 other values of the symbols",
        "credit.score",
    ]
    # Two asserts: a named slip only. A multi-line string cannot be indented: hidden as
    # it is, whole points.
    two, graded = autograder_source(
        f"{check}\nrc.assert_value(1, 1)", Rubric(1), variable="answer_1", recheck=False
    )
    assert graded and "Credit(1, several=True)" in two
    text = 'rc.assert_matrix(answer_1, """[[1,\n2]]""")'
    hidden, graded = autograder_source(text, Rubric(1), variable="answer_1", recheck=True)
    assert not graded and hidden.splitlines()[2:-1] == text.splitlines()


def test_an_answer_cell_that_asks_robotconf_is_flagged(capsys):
    arm = rc.preset("planar_2r", l1=1, l2=1)
    history = ["", "answer_2 = [list(q) for q in rc.ik_all(arm, [1, 1, 0]).q]"]
    namespace = {"In": history, "rc": rc, "arm": arm}
    answer_2 = [list(q) for q in rc.ik_all(arm, [1, 1, 0]).q]
    with Credit(2) as credit:
        assert credit.own_work("answer_2", namespace) == ["rc.ik_all"]
        rc.assert_ik_solutions(answer_2, arm, [1, 1, 0])
    assert credit.score == 0.0 and credit.flagged == ["rc.ik_all"]
    assert "Flagged for manual grading: your answer cell calls robotconf (rc.ik_all)" in (
        capsys.readouterr().out
    )
    # The student's own numbers are not flagged, and the last assignment counts.
    history += ["answer_2 = [[0, 1.5708], [1.5708, -1.5708]]"]
    with Credit(2) as credit:
        assert credit.own_work("answer_2", namespace) == []
        rc.assert_ik_solutions([[0, 1.5708], [1.5708, -1.5708]], arm, [1, 1, 0])
    assert credit.score == 2.0


def test_markers_in_course_cells_are_refused():
    with pytest.raises(ValueError, match="BEGIN SOLUTION"):
        answer_source("answer_1 = None", "### BEGIN SOLUTION\nanswer_1 = 1")


@pytest.mark.parametrize(
    ("cells", "message"),
    [
        ([("answer", "a = 1\nb = 2")], "one answer_ variable"),
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
