"""Checks for answers that are not matrices: values, vectors, angles, sets, intervals.

Every expected number here is derived by hand in the comment beside it; the tolerance
rule is ``|answer − expected| ≤ max(tol, rel·|expected|)`` with tol = rel = 0.001.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.teaching import AnswerCheck

PI = math.pi


# -- values ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("answer", "expected"),
    [
        (3.1416, PI),  # |3.1416 − π| = 7.3e-6 ≤ 0.0031
        (3.142, PI),  # 4.1e-4
        (1.5708, PI / 2),  # 3.7e-6 ≤ 0.0016
        ("pi", PI),
        ("pi/2", PI / 2),
        ("sqrt(2)/2", 0.70710678),  # cos 45°
        ("(0.01 - 1.99) / (2 * 0.01)", -99.0),  # the central difference of lesson 7
        (np.float64(-99.05), -99.0),  # 0.05 ≤ 0.099
        ([-199], -199.0),  # a one-element list is one number too
        (sympy.pi, PI),
        (0.0009, 0.0),  # near 0 the absolute 0.001 counts
    ],
)
def test_right_values_pass(answer, expected):
    result = rc.check_value(answer, expected)
    assert result.ok and result.diagnosis is None and result.hints == []
    assert str(result) == "the value: correct."


@pytest.mark.parametrize(
    ("answer", "expected"),
    [(3.2, PI), (1.59, PI / 2), (100.6, 100.0), (0.0011, 0.0), ("pi/3", PI / 2)],
)
def test_wrong_values_fail(answer, expected):
    # 3.2 − π = 0.058 > 0.016; 1.59 − π/2 = 0.019 > 0.0079; 100.6 − 100 = 0.6 > 0.5;
    # 0.0011 > 0.001 near 0
    result = rc.check_value(answer, expected)
    assert not result.ok and result.diagnosis == "wrong"


def test_tolerances_are_options():
    assert rc.check_value(100.4, 100, rel=0.005).ok  # 0.4 ≤ 0.5
    assert not rc.check_value(100.4, 100, rel=0.0, tol=0.3).ok
    assert rc.check_value(100.4, 100, rel=0.0, tol=0.5).ok


@pytest.mark.parametrize(
    ("answer", "expected", "code", "words"),
    [
        ("-pi", PI, "sign_error", "has the wrong sign"),
        (180, PI, "degrees_as_radians", "You gave degrees"),
        (70000, 70, "unit_factor", "1000 times too large"),
        (0.07, 70, "unit_factor", "1000 times too small"),
        (3.1, PI, "too_rounded", "rounded too much"),  # π to 2 significant digits
        ([1, 2], 70, "shape", "one number; you gave 2"),
        ("2*q1", 70, "not_a_number", "still holds q1"),
    ],
)
def test_value_mistakes_are_named(answer, expected, code, words):
    result = rc.check_value(answer, expected)
    assert not result.ok and result.diagnosis == code
    assert words in " ".join(result.hints), result.hints


def test_value_hints_hide_the_expected_value_unless_revealed():
    hidden = rc.check_value(3.3, PI, name="q2", unit="rad")
    assert str(hidden) == "q2: not right yet.\n- 3.3 rad is not right."
    shown = rc.check_value(3.3, PI, name="q2", unit="rad", reveal=True)
    assert shown.hints == ["q2: expected 3.142 rad, you wrote 3.3 rad."]


def test_missing_answer_and_exercise_hint():
    result = rc.check_value(None, 1.0, hint="Use the central difference.")
    assert result.diagnosis == "no_answer" and result.student is None
    assert result.hints == ["No answer yet: replace None with your answer."]
    wrong = rc.check_value(1.0, -99, name="dq3/dt", hint="Use the central difference.")
    assert wrong.hints == ["1 is not right.", "Use the central difference."]


# -- refused input: nothing is evaluated, nothing non-finite, imaginary or huge ------------


@pytest.mark.parametrize(
    ("answer", "field", "words"),
    [
        (float("nan"), "student", "must be finite"),
        (float("inf"), "student", "must be finite"),
        ("1e400", "student", "not a finite number"),
        ("1e200**2", "student[0][0]", "too large to check"),
        ("10**400", "student", "exponent larger than 64"),
        (1j, "student", "a complex number"),
        ("sqrt(-1)", "student[0][0]", "imaginary unit"),
        ("I", "student", "unknown name"),
        (True, "student", "a boolean"),
        ("cos q2", "student", "write cos(q2)"),
        ("rc.jacobian(robot)", "student", "asks robotconf for the answer"),
        ("__import__('os').system('true')", "student", "is not allowed"),
    ],
)
def test_bad_answers_are_refused(answer, field, words):
    with pytest.raises(InvalidInputError) as error:
        rc.check_value(answer, 1.0)
    assert error.value.field == field and words in str(error.value)


def test_robotconf_objects_are_refused():
    with pytest.raises(InvalidInputError, match="robotconf's own result"):
        rc.check_vector(rc.Robot([rc.Module("Rz")]), [0, 0, 0])


def test_text_is_never_evaluated(tmp_path):
    marker = tmp_path / "written"
    text = f"open({str(marker)!r}, 'w')"
    for check, expected in ((rc.check_value, 1), (rc.check_vector, [1, 2]), (rc.check_set, [1])):
        with pytest.raises(InvalidInputError):
            check(text, expected)
    assert not marker.exists()


@pytest.mark.parametrize(
    ("entry", "words"),
    [
        ("(-8)**(1/3)", "is not real"),  # the principal cube root is complex
        (sympy.factorial(3, evaluate=False), "cannot evaluate"),
        ("sqrt(-4)", "imaginary unit"),
    ],
)
def test_bad_entries_of_a_list_are_named(entry, words):
    with pytest.raises(InvalidInputError) as error:
        rc.check_vector([1, entry], [1, 2])
    assert error.value.field == "student[1][0]" and words in str(error.value)


def test_too_many_entries_are_refused():
    with pytest.raises(InvalidInputError, match="too many entries"):
        rc.check_set([0.0] * 1000, [0, PI])


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: rc.check_value(1, 1, tol=-1), "tol"),
        (lambda: rc.check_value(1, 1, rel=1), "rel"),
        (lambda: rc.check_value(1, "pi"), "expected"),
        (lambda: rc.check_value(1, float("nan")), "expected"),
        (lambda: rc.check_value(1, sympy.Symbol("q1")), "expected"),
        (lambda: rc.check_value(1, [1, 2]), "expected"),
        (lambda: rc.check_value(1, 1, name=3), "name"),
        (lambda: rc.check_vector([1, 2], [1, 2], components=["x"]), "components"),
        (lambda: rc.check_angle(1, 1, period=0), "period"),
        (lambda: rc.check_set([1], [1, 2], labels=["one"]), "labels"),
        (lambda: rc.check_set([1], [1, 1.0005]), "expected_set"),  # equal within 0.1 %
        (lambda: rc.check_set([1], [0, 2 * PI], period=2 * PI), "expected_set"),
        (lambda: rc.check_interval([1, 2], (2, 1)), "expected_lo_hi"),
    ],
)
def test_bad_options_are_refused(call, field):
    with pytest.raises(InvalidInputError) as error:
        call()
    assert error.value.field == field


# -- vectors -----------------------------------------------------------------------------

VELOCITY = [0.0, 35.0, -40.0]  # lesson 7: 0.5·z × (70, 0, 20) + 1·y × (40, 0, 0)


@pytest.mark.parametrize(
    "answer",
    [[0, 35, -40], "[0, 35, -40.03]", np.array([[0], [35], [-40]]), [[0, 35, -40]], "(0,35,-40)"],
)
def test_right_vectors_pass(answer):
    assert rc.check_vector(answer, VELOCITY).ok


@pytest.mark.parametrize(
    ("answer", "code", "wrong", "hint"),
    [
        ([0, 35, 40], "sign_error", [2], "The sign of z is wrong."),
        ([0, -35, 40], "sign_flipped", [1, 2], "every component has the wrong sign"),
        ([35, 0, -40], "swapped_components", [0, 1], "x and y are swapped."),
        ([0, 35000, -40000], "unit_factor", [1, 2], "1000 times too large"),
        ([0, 36, -40], "wrong", [1], "y is wrong."),
        ([1, 36, -40], "wrong", [0, 1], "x and y are wrong."),
    ],
)
def test_vector_mistakes_name_the_components(answer, code, wrong, hint):
    result = rc.check_vector(answer, VELOCITY, name="the velocity")
    assert (result.diagnosis, result.wrong) == (code, wrong)
    assert hint in result.hints[0]
    count = len(wrong)
    assert str(result).startswith(f"the velocity: {count} wrong component")


def test_vector_in_degrees_and_shapes():
    result = rc.check_vector([90, 0, 180], [PI / 2, 0, PI])
    assert result.diagnosis == "degrees_as_radians"
    assert result.hints == ["You gave degrees: write the vector in radians (180° = π)."]
    short = rc.check_vector([70, 0], [70, 0, 20])
    assert short.diagnosis == "shape" and "3 components (x, y, z); you gave 2" in short.hints[0]
    homogeneous = rc.check_vector([70, 0, 20, 1], [70, 0, 20])
    assert "Leave out the homogeneous 1" in homogeneous.hints[0]
    assert rc.check_vector(70, [70, 0, 20]).diagnosis == "shape"


def test_vector_reveal_and_component_names():
    result = rc.check_vector([71, 0, 20], [70, 0, 20], unit="mm", reveal=True)
    assert result.hints == ["x: expected 70 mm, you wrote 71 mm."]
    named = rc.check_vector([1, 2, 9], [1, 2, 3, 4][:3], components=["vx", "vy", "vz"])
    assert named.hints == ["vz is wrong."]
    assert "70" not in " ".join(rc.check_vector([71, 0, 20], [70, 0, 20]).hints)


# -- angles ------------------------------------------------------------------------------

ELBOW = math.acos(-0.75)  # lesson 8: 30 + 40 cos q3 = 0, q3 = 2.41886 rad = 138.59°


@pytest.mark.parametrize(
    ("answer", "expected"),
    [
        (1.5708, PI / 2),
        ("-3*pi/2", PI / 2),  # a full turn away
        (2.4189, ELBOW),
        (2.42, ELBOW),  # 0.0011 ≤ 0.1 % of 2.419
        (ELBOW - 2 * PI, ELBOW),
        ([0.5, 1.0 + 2 * PI], [0.5, 1.0]),
    ],
)
def test_right_angles_pass(answer, expected):
    assert rc.check_angle(answer, expected).ok


@pytest.mark.parametrize(
    ("answer", "code", "words"),
    [
        (138.59, "degrees_as_radians", "You gave degrees: write q3 in radians"),
        (138.59 - 360, "degrees_as_radians", "You gave degrees"),
        (-2.4189, "sign_error", "q3 has the wrong sign"),
        (2.4189 - PI, "half_turn", "off by half a turn (π)"),
        (2.4, "too_rounded", "rounded too much"),  # 2.41886 to 2 significant digits
        (PI, "wrong", "pi is not right"),
    ],
)
def test_angle_mistakes(answer, code, words):
    result = rc.check_angle("pi" if answer == PI else answer, ELBOW, name="q3")
    assert result.diagnosis == code and words in result.hints[0], result.hints


def test_angles_in_degrees_and_other_periods():
    assert rc.check_angle(-90, 270, degrees=True).ok
    result = rc.check_angle(PI / 2, 90, degrees=True)
    assert result.diagnosis == "radians_as_degrees" and "You gave radians" in result.hints[0]
    assert rc.check_angle(0.5 + PI, 0.5, period=PI).ok  # an axis direction
    vector = rc.check_angle([0.5, -1.0], [0.5, 1.0])
    assert vector.wrong == [1] and vector.hints == ["The sign of angle 2 is wrong."]
    assert str(vector).startswith("the angles: 1 wrong angle (angle 2).")


# -- sets --------------------------------------------------------------------------------

SINGULAR_Q2 = [0.0, PI]  # lesson 8: det J = l1·l2·sin q2 = 0


@pytest.mark.parametrize("answer", [[0, PI], [PI, 0], "[3.1416, 0]", "[pi, 0]", (0, "pi")])
def test_sets_pass_in_any_order(answer):
    assert rc.check_set(answer, SINGULAR_Q2).ok


def test_missing_solution_is_named_without_its_value():
    labels = ["the arm stretched", "the arm folded"]
    result = rc.check_set([0], SINGULAR_Q2, labels=labels)
    assert (result.diagnosis, result.wrong, result.extra) == ("missing", [1], [])
    assert result.hints == ["You gave 1 of the 2 solutions; 1 is missing: the arm folded."]
    plain = rc.check_set(0, SINGULAR_Q2)
    assert plain.hints == ["You gave 1 of the 2 solutions; 1 is missing."]
    revealed = rc.check_set([PI], SINGULAR_Q2, labels=labels, reveal=True)
    assert revealed.hints[0].endswith("missing: the arm stretched (0).")
    nothing = rc.check_set([], SINGULAR_Q2)
    assert nothing.wrong == [0, 1] and "2 are missing" in nothing.hints[0]


def test_set_mistakes():
    degrees = rc.check_set([0, 180], SINGULAR_Q2)
    assert degrees.diagnosis == "degrees_as_radians" and degrees.extra == [1]
    assert degrees.hints == ["180 looks like a solution in degrees: give it in radians (180° = π)."]
    twice = rc.check_set([0, 0], SINGULAR_Q2)
    assert twice.diagnosis == "duplicate" and "0 is given more than once" in twice.hints[0]
    extra = rc.check_set([0, PI, 1], SINGULAR_Q2)
    assert (extra.diagnosis, extra.extra) == ("extra", [2])
    assert extra.hints == ["1 is not a solution."]
    assert str(extra).startswith("the set of solutions: 2 of 2 solutions right, 1 not.")


def test_a_zero_in_a_set_is_never_a_unit_slip():
    # A thousandth of 1 is near 0 (0.001 absolute near zero): 0 is simply not a solution,
    # while 2000 is 2 written in the wrong unit.
    result = rc.check_set([0, 3], [1, 3])
    assert result.diagnosis == "extra" and result.hints[0] == "0 is not a solution."
    assert rc.check_set([2000, 3], [2, 3]).diagnosis == "unit_factor"


def test_large_sets_are_judged_element_by_element():
    solutions = 1 + np.arange(400) / 100  # 1, 1.01, …, 4.99: distinct within 0.1 %
    assert rc.check_set(solutions[::-1], solutions, rel=1e-3).ok
    answer = solutions * 1000
    answer[0] = 1.0  # right; the rest are ×1000
    result = rc.check_set(answer, solutions, rel=1e-3)
    assert result.diagnosis == "unit_factor" and len(result.extra) == 399
    assert len(result.wrong) == 399 and result.wrong[:2] == [1, 2]
    assert result.hints == [
        "1010, 1020, 1030, 1040, 1050, 1060 and 393 more are 1000 times too large."
    ]
    repeated = rc.check_set([0.0] * 400, np.arange(400.0), rel=1e-3)
    assert repeated.hints[0] == "0 is given more than once: give each solution once."


def test_long_lists_of_components_are_cut():
    result = rc.check_vector(np.arange(400.0) + 0.5, np.arange(400.0) + 1, rel=1e-3)
    assert result.hints[-1].endswith("component 6 and 394 more are wrong.")
    assert str(result).startswith("the vector: 400 wrong components (component 1, ")


def test_angle_sets_modulo_a_turn():
    turn = 2 * PI
    assert rc.check_set([turn, -PI], SINGULAR_Q2, period=turn).ok
    same = rc.check_set([0, turn], SINGULAR_Q2, period=turn)
    assert same.diagnosis == "duplicate"
    assert same.hints[0].startswith("2*pi repeats a solution you gave, a whole number of turns")
    assert rc.check_set([0, turn], SINGULAR_Q2).diagnosis == "extra"  # without a period


def test_sets_of_vectors():
    # two-link planar arm, l1 = l2 = 1, tip at (1, 1): (cos q1 + cos(q1+q2), sin q1 + …)
    # is (1, 1) for q = (0, π/2) and for q = (π/2, −π/2)
    solutions = [[0, PI / 2], [PI / 2, -PI / 2]]
    assert rc.check_set("[[pi/2, -pi/2], [0, pi/2]]", solutions).ok
    assert rc.check_set([[0, PI / 2], [PI / 2, 3 * PI / 2]], solutions, period=2 * PI).ok
    one = rc.check_set([1.5708, -1.5708], solutions)
    assert (one.diagnosis, one.wrong) == ("missing", [0])
    layout = rc.check_set([0.5, 1.2, 3.0], solutions)
    assert layout.diagnosis == "shape" and "lists" in layout.hints[0]


# -- intervals ---------------------------------------------------------------------------

REACH = (10.0, 70.0)  # lesson 8: |l3 − l2| … l2 + l3 from the shoulder, l2 = 30, l3 = 40


def test_intervals():
    assert rc.check_interval("[40 - 30, 40 + 30]", REACH).ok
    swapped = rc.check_interval([70, 10], REACH)
    assert (swapped.diagnosis, swapped.wrong) == ("swapped_ends", [0, 1])
    upper = rc.check_interval([10, 60], REACH, name="the reach")
    assert (upper.diagnosis, upper.wrong) == ("wrong", [1])
    assert upper.hints == ["The upper end is wrong."]
    assert str(upper).startswith("the reach: 1 wrong end (the upper end).")
    assert rc.check_interval([0.01, 0.07], REACH).diagnosis == "unit_factor"
    three = rc.check_interval([10, 40, 70], REACH)
    assert three.diagnosis == "shape" and "[lo, hi]: two numbers" in three.hints[0]


# -- the assert forms and the result -----------------------------------------------------


@pytest.mark.parametrize(
    ("check", "right", "wrong", "expected", "headline"),
    [
        (rc.assert_value, "pi", 3.2, PI, "the value: not right yet."),
        (rc.assert_vector, VELOCITY, [0, 35, 40], VELOCITY, "the vector: 1 wrong component (z)."),
        (rc.assert_angle, "pi/2", 90, PI / 2, "the angle: not right yet."),
        (rc.assert_set, [PI, 0], [0], SINGULAR_Q2, "the set of solutions: 1 of 2 solutions"),
        (rc.assert_interval, [10, 70], [70, 10], REACH, "the interval: the ends are swapped."),
    ],
)
def test_assert_forms(check, right, wrong, expected, headline):
    assert isinstance(check(right, expected), AnswerCheck)
    with pytest.raises(AssertionError) as error:
        check(wrong, expected)
    message = str(error.value)
    assert message.startswith(headline) and "\n- " in message
    assert error.value._render_traceback_()[0].startswith("AssertionError: ")
    assert "3.14" not in message  # the expected values stay hidden
    with pytest.raises(AssertionError, match="No answer yet"):
        check(None, expected)


def test_result_object():
    result = rc.check_value(3.2, PI, name="<b>q</b>")
    assert not result and repr(result) == "<AnswerCheck ok=False diagnosis='wrong'>"
    assert "&lt;b&gt;" in result._repr_html_() and "<b>q</b>" not in result._repr_html_()
    assert result.student == pytest.approx(3.2) and result.expected == pytest.approx(PI)
    assert np.shape(result.student) == ()
    with pytest.raises(AttributeError):
        result.ok = True  # type: ignore[misc]


def test_exported_from_rc():
    names = ["check_value", "check_vector", "check_angle", "check_set", "check_interval"]
    names += [name.replace("check", "assert") for name in names] + ["AnswerCheck"]
    assert set(names) <= set(rc.__all__)
