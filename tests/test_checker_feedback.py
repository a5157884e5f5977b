"""Feedback of the homework checker: no answers given away, decimals, one-line slips."""

from __future__ import annotations

import math
import re

import pytest
import sympy

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.teaching.reading import format_decimal, show_entry, show_expected

#: A1 of the paper robot with (1,1) using the wrong joint and (2,1) of the wrong sign.
WRONG_A1 = [
    ["cos(q2)", "-sin(q1)", 0, 0],
    ["-sin(q1)", "cos(q1)", 0, 0],
    [0, 0, 1, 0],
    [0, 0, 0, 1],
]


@pytest.fixture(scope="module")
def paper_a1():
    return rc.expected_matrix(rc.preset("paper"), "A1")


def test_default_hints_name_entries_and_mistake_without_the_answer(paper_a1):
    result = rc.check_matrix(WRONG_A1, paper_a1)
    text = str(result)
    assert result.wrong_entries == [(0, 0), (1, 0)]
    assert "sign_error" in result.mistakes
    assert "entry (1,1)" in text and "entry (2,1)" in text
    assert "sign error" in text
    assert "cos(q1)" not in text  # the expected (1,1)
    assert "expected" not in text
    assert "you wrote cos(q2)" in text


def test_reveal_shows_expected_and_written(paper_a1):
    text = str(rc.check_matrix(WRONG_A1, paper_a1, reveal=True))
    assert "entry (1,1): expected cos(q1), you wrote cos(q2)" in text
    assert "entry (2,1): expected sin(q1), you wrote -sin(q1)" in text


def test_assert_matrix_message_follows_reveal(paper_a1):
    with pytest.raises(AssertionError) as hidden:
        rc.assert_matrix(WRONG_A1, paper_a1)
    assert "entry (1,1)" in str(hidden.value)
    assert "cos(q1)" not in str(hidden.value)
    with pytest.raises(AssertionError) as shown:
        rc.assert_matrix(WRONG_A1, paper_a1, reveal=True)
    assert "expected cos(q1)" in str(shown.value)


def test_html_tip_follows_reveal(paper_a1):
    assert "expected cos(q1)" not in rc.check_matrix(WRONG_A1, paper_a1)._repr_html_()
    assert "expected cos(q1)" in rc.check_matrix(WRONG_A1, paper_a1, reveal=True)._repr_html_()


def test_student_decimals_show_as_decimals():
    result = rc.check_matrix([[-0.81725, "138.59*cos(q1)"]], [[0.5, sympy.Integer(2)]])
    text = str(result)
    assert "-0.8173" in text and "138.59*cos(q1)" in text
    assert "/4000" not in text and "13859" not in text


def test_revealed_numbers_are_decimals_without_float_noise():
    text = str(rc.check_matrix([[0.3]], [[sympy.sqrt(2) / 2 * 1.0]], reveal=True))
    assert "expected 0.7071, you wrote 0.3" in text


@pytest.mark.parametrize(
    ("value", "shown"),
    [(-0.81725, "-0.8173"), (138.59, "138.59"), (0.1 + 0.2, "0.3"), (1e-20, "1e-20"), (20.0, "20")],
)
def test_format_decimal(value, shown):
    assert format_decimal(value) == shown


def test_expected_entries_are_simplified_when_small():
    q1, q2 = sympy.symbols("q1 q2", real=True)
    entry = sympy.sin(q1) * sympy.cos(q2) + sympy.cos(q1) * sympy.sin(q2)
    assert show_expected(entry) == "sin(q1 + q2)"
    big = sum(sympy.cos(k * q1) * sympy.sin(q2) for k in range(1, 12))
    assert show_expected(big) == show_entry(big)  # too large: shown as it is


@pytest.mark.parametrize(
    ("text", "advice", "under"),
    [
        ("cos q2", "write cos(q2)", "q"),
        ("2 q1", "multiplication needs *: write 2*q1", "q"),
        ("2q1", "multiplication needs *: write 2*q1", "q"),
        ("sin(q1", "this ( is never closed: add )", "("),
        ("q1^2", "use ** for powers: q1**2", "^"),
        ("[[1,2],[3,4]", "this [ is never closed: add ]", "["),
        ("[[1,2] [3,4]]", "a comma is missing between ] and [", "["),
        ("cos(q1))", "this ) has no matching (", ")"),
        ("q1 *", "something is missing after *", "*"),
        ("[[1, 2], [3 4]]", "a comma is missing between entries: 3, 4", "4"),
    ],
)
def test_syntax_slips_get_one_line_and_a_caret(text, advice, under):
    with pytest.raises(InvalidInputError) as caught:
        rc.check_matrix(text, [[1, 2], [3, 4]])
    error = caught.value
    assert error.field == "student"
    first, caret = str(error).split("\n")
    assert first == f"student: `{text}`: {advice}"
    assert caret.strip() == "^"
    assert first[caret.index("^")] == under
    frames = []
    tb = error.__traceback__
    while tb is not None:
        frames.append(tb.tb_frame.f_code.co_name)
        tb = tb.tb_next
    assert frames[-1] == "check_matrix"  # no internal frames below the public call
    assert error.__suppress_context__


def test_slip_in_one_text_entry_names_the_entry():
    with pytest.raises(InvalidInputError) as caught:
        rc.check_matrix([[1, "cos q2"]], [[1, 2]])
    first, caret = str(caught.value).split("\n")
    assert caught.value.field == "student[0][1]"
    assert first == "student[0][1]: `cos q2`: write cos(q2)"
    assert first[caret.index("^")] == "q"


def test_long_answer_quotes_the_line_around_the_slip():
    text = "[[" + ", ".join(["cos(q1)"] * 20) + ", sin q1]]"
    with pytest.raises(InvalidInputError) as caught:
        rc.check_matrix(text, sympy.ones(1, 21))
    first, caret = str(caught.value).split("\n")
    assert len(first) < 130 and "write sin(q1)" in first
    assert first[caret.index("^")] == "q"


def test_ipython_shows_the_message_only():
    pytest.importorskip("IPython")
    from IPython.core.interactiveshell import InteractiveShell
    from IPython.utils.capture import capture_output

    shell = InteractiveShell.instance()
    shell.run_cell("import robotconf as rc", store_history=False)
    with capture_output() as captured:
        shell.run_cell('rc.check_matrix("cos q2", [[1]])', store_history=False)
    shown = re.sub(r"\x1b\[[0-9;]*m", "", captured.stdout + captured.stderr)
    lines = [line for line in shown.splitlines() if line.strip()]
    assert "write cos(q2)" in shown
    assert "_checker.py" not in shown and "_student_parser.py" not in shown
    assert "robotconf/" not in shown and "site-packages" not in shown
    assert len(lines) <= 8
    # The caret still points at the spot under the type name the shell prints.
    first = next(line for line in lines if "write cos(q2)" in line)
    caret = lines[lines.index(first) + 1]
    assert first[caret.index("^")] == "q"


@pytest.mark.parametrize(
    "pasted",
    [
        lambda robot: rc.expected_matrix(robot, "A1"),
        lambda robot: rc.derivation(robot),
        lambda robot: rc.derivation(robot).steps[0],
        lambda robot: "rc.derivation(robot).matrices[0]",
        lambda robot: 'expected_matrix(robot, "A1")',
        lambda robot: "robot.frame_poses()[0]",
    ],
)
def test_a_library_call_pasted_as_the_answer_is_refused_kindly(pasted) -> None:
    robot = rc.preset("paper")
    expected = rc.expected_matrix(robot, "A1")
    with pytest.raises(rc.InvalidInputError, match="robotconf") as error:
        rc.check_matrix(pasted(robot), expected)
    assert error.value.field == "student"
    assert "the matrix you derived" in str(error.value)
    # The same matrix written out is graded as usual.
    written = "[[cos(q1), -sin(q1), 0, 0], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]"
    assert rc.check_matrix(written, expected).ok


# -- numbers rounded too coarsely ---------------------------------------------------------


@pytest.fixture(scope="module")
def thirty_degrees():
    link = rc.Robot.from_dh([(0, 0, 2, 0, "R")])
    return rc.expected_matrix(link, "A1", q=[math.radians(30)])  # cos 30° = 0.8660, 2 cos = 1.7321


ONE_DECIMAL = [[0.9, -0.5, 0, 1.7], [0.5, 0.9, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]


def test_coarse_rounding_is_named_without_the_answer(thirty_degrees):
    result = rc.check_matrix(ONE_DECIMAL, thirty_degrees)
    assert not result.ok and result.diagnosis == "coarse_rounding"
    assert result.wrong_entries == [(0, 0), (0, 3), (1, 1)]
    assert result.hints == [
        "Entries (1,1), (1,4), (2,2) are rounded too coarsely: keep 3 significant "
        "digits (to the digits you kept, they are right)."
    ]
    revealed = str(rc.check_matrix(ONE_DECIMAL, thirty_degrees, reveal=True))
    assert "entry (1,1): expected 0.866, you wrote 0.9" in revealed
    assert "rounded too coarsely" in revealed


def test_three_significant_digits_pass_and_a_wrong_digit_is_not_rounding(thirty_degrees):
    assert rc.check_matrix(
        [[0.866, -0.5, 0, 1.73], [0.5, 0.866, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]],
        thirty_degrees,
    ).ok
    result = rc.check_matrix(  # 0.85 is not 0.866 to two decimals
        [[0.85, -0.5, 0, 1.7321], [0.5, 0.866, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], thirty_degrees
    )
    assert result.wrong_entries == [(0, 0)] and result.diagnosis is None


def test_no_default_hint_of_the_corpus_quotes_an_expected_entry():
    from .diagnosis_corpus import CASES
    from .diagnosis_corpus.measure import verdict

    for case in CASES:
        if not case.ok:
            assert not re.search(r"\): expected ", str(verdict(case))), case.id
