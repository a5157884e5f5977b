"""The homework checker: verdicts, tolerance, inputs, and one test per recognised mistake."""

from __future__ import annotations

import numpy as np
import pytest
import sympy

from robotconf import Module, Robot
from robotconf.teaching import (
    ExpectedMatrix,
    MatrixCheck,
    as_expected,
    assert_matrix,
    check_matrix,
    derivation,
    dh_factors,
    elementary_matrix,
    evaluate,
    expected_matrix,
    module_matrix,
)

q1, q2, q3, l1, l2, l3 = sympy.symbols("q1 q2 q3 l1 l2 l3", real=True)
A1 = module_matrix("Rz", q1, (0, 0, 0))
A2 = module_matrix("Ry", q2, (0, 0, l1))
A3 = module_matrix("Ry", q3, (l2, 0, 0))
P = sympy.Matrix([l3, 0, 0, 1])


@pytest.fixture(scope="module")
def robot() -> Robot:
    return Robot(
        [Module("Rz"), Module("Ry", a=(0, 0, 20)), Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


@pytest.fixture(scope="module")
def dh_arm() -> Robot:
    return Robot.from_dh([(0, 0.5, 1, np.pi / 2, "R"), (0, 0, 2, 0, "R")])


def expected(robot: Robot, name: str, **kw) -> ExpectedMatrix:
    return expected_matrix(robot, name, lengths=True, **kw)


def product(*matrices):
    out = sympy.eye(4)
    for m in matrices:
        out = out * m
    return out


def dh_product(theta, d, a, alpha, convention):
    return product(*(m for _, m in dh_factors(theta, d, a, alpha, convention)))


# -- correct answers, written differently, pass without hints ----------------------------

M3_TEXT = (
    "[[cos(q1)*(cos(q2)*cos(q3) - sin(q2)*sin(q3)), -sin(q1), "
    "cos(q1)*(sin(q2)*cos(q3) + cos(q2)*sin(q3)), l2*cos(q1)*cos(q2)],"
    " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), l2*sin(q1)*cos(q2)],"
    " [-sin(q2)*cos(q3) - cos(q2)*sin(q3), 0, cos(q2 + q3), l1 - l2*sin(q2)],"
    " [0, 0, 0, 1]]"
)


@pytest.mark.parametrize(
    ("name", "student"),
    [
        ("M3", M3_TEXT),
        ("M3", sympy.expand(sympy.expand_trig(product(A1, A2, A3)))),
        ("M2", product(A1, A2).applyfunc(lambda e: e * (sympy.sin(q3) ** 2 + sympy.cos(q3) ** 2))),
        (
            "A2",
            "[[cos(q2), 0, sin(q2), 0], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
        ),
        ("p_EE", list((product(A1, A2, A3) * P)[:3])),
        (
            "p_EE",
            "[[(l2*cos(q2) + l3*cos(q2 + q3))*cos(q1), (l2*cos(q2) + l3*cos(q2+q3))*sin(q1),"
            " l1 - l2*sin(q2) - l3*sin(q2 + q3), 1]]",
        ),
    ],
)
def test_correct_but_differently_written_passes(robot, name, student):
    result = check_matrix(student, expected(robot, name))
    assert result.ok, result.hints
    assert result.wrong_entries == [] and result.hints == [] and result.mistakes == []
    assert bool(result) is True


def test_correct_numeric_with_plain_and_context_references(robot):
    q = [np.pi / 2, np.pi / 6, np.pi / 4]
    answer = np.round(robot.frame_poses(q)[2], 4)
    for reference in (
        expected_matrix(robot, "M3", q=q),
        derivation(robot, q=q)["M3"],
        robot.frame_poses(q)[2],
        sympy.Matrix(robot.frame_poses(q)[2]),
    ):
        result = check_matrix(answer, reference)
        assert result.ok and result.hints == []


# -- each mistake is recognised ---------------------------------------------------------


def _transposed_rotation(m):
    m = m.copy()
    m[:3, :3] = m[:3, :3].T
    return m


def _row_swap(m):
    m = m.copy()
    m.row_swap(0, 1)
    return m


def _col_swap(m):
    m = m.copy()
    m.col_swap(0, 2)
    return m


@pytest.mark.parametrize(
    ("name", "student", "code", "words"),
    [
        ("M3", _transposed_rotation(product(A1, A2, A3)), "transposed_rotation", "transposed"),
        ("M2", product(A2, A1), "wrong_order", "A2·A1 instead of A1·A2"),
        ("M3", product(A3, A2, A1), "wrong_order", "A3·…·A1 instead of A1·…·A3"),
        ("p_EE", product(A3, A2, A1) * P, "wrong_order", "wrong order"),
        (
            "A3",
            elementary_matrix("Ry", q3) * elementary_matrix("Tx", l2),
            "offset_after_rotation",
            "A3 (module M3",
        ),
        (
            "M3",
            product(A1, A2, elementary_matrix("Ry", q3), elementary_matrix("Tx", l2)),
            "offset_after_rotation",
            "after the rotation",
        ),
        (
            "M3",
            product(A1, module_matrix("Ry", -q2, (0, 0, l1)), A3),
            "rotation_direction",
            "A2 (module M2, Ry",
        ),
        (
            "A2",
            module_matrix("Ry", -q2, (0, 0, l1)),
            "rotation_direction",
            "+sin in entry (1,3) and −sin in entry (3,1)",
        ),
        (
            "M3",
            product(A1, module_matrix("Ry", q2, (0, 0, 0)), A3),
            "missing_offset",
            "offset of A2 (module M2",
        ),
        ("p_EE", product(A1, A2, A3)[:, 3], "missing_offset", "end-effector point P = (40, 0, 0)"),
        ("M3", _row_swap(product(A1, A2, A3)), "row_swap", "Rows 1 and 2 are swapped"),
        ("M3", _col_swap(product(A1, A2, A3)), "column_swap", "Columns 1 and 3 are swapped"),
    ],
)
def test_symbolic_mistakes_are_recognised(robot, name, student, code, words):
    result = check_matrix(student, expected(robot, name))
    assert not result.ok
    assert result.mistakes[0] == code, result.hints
    assert words in result.hints[0]
    assert result.wrong_entries  # and the entries are named
    assert "Wrong entries: " in result.hints[-1]


def test_single_sine_sign_error_names_the_entry(robot):
    student = A2.copy()
    student[0, 2] = -student[0, 2]
    result = check_matrix(student, expected(robot, "A2"), reveal=True)
    assert result.wrong_entries == [(0, 2)]
    assert result.mistakes == ["sign_error"]
    assert result.hints[0].startswith(
        "entry (1,3): expected sin(q2), you wrote -sin(q2) — a sign error on a sine term"
    )


def test_sign_error_without_context():
    reference = sympy.Matrix([[sympy.cos(q1), -sympy.sin(q1)], [sympy.sin(q1), sympy.cos(q1)]])
    result = check_matrix("[[cos(q1), sin(q1)], [sin(q1), cos(q1)]]", reference)
    assert result.wrong_entries == [(0, 1)]
    assert "sign_error" in result.mistakes


@pytest.mark.parametrize(
    ("convert", "code", "words"),
    [
        (np.degrees, "degrees_as_radians", "radian mode"),
        (np.radians, "radians_as_degrees", "degree mode"),
    ],
)
def test_angle_units_are_recognised(robot, convert, code, words):
    q = [np.pi / 2, np.pi / 6, np.pi / 4]
    student = robot.frame_poses(convert(q))[2]
    result = check_matrix(student, expected_matrix(robot, "M3", q=q))
    assert result.mistakes[0] == code and words in result.hints[0]


def test_dh_convention_is_recognised(dh_arm):
    student = dh_product(q1, sympy.Rational(1, 2), 1, sympy.pi / 2, "modified")
    result = check_matrix(student, expected_matrix(dh_arm, "A1"))
    assert result.mistakes[0] == "dh_convention"
    assert "modified DH convention (Rx(α)·Tx(a)·Rz(θ)·Tz(d))" in result.hints[0]
    assert "standard DH" in result.hints[0]


def test_dh_twist_in_degrees_is_recognised(dh_arm):
    student = dh_product(q1, sympy.Rational(1, 2), 1, 90, "standard")
    result = check_matrix(student, expected_matrix(dh_arm, "A1"))
    assert result.mistakes[0] == "degrees_as_radians"


def test_dh_missing_offset(dh_arm):
    student = dh_product(q1, 0, 1, sympy.pi / 2, "standard")
    result = check_matrix(student, expected_matrix(dh_arm, "A1"))
    assert result.mistakes[0] == "missing_offset"
    assert "link offset d of A1" in result.hints[0]


def test_context_free_hints_with_plain_reference(robot):
    plain = sympy.Matrix(expected(robot, "M3").matrix)
    result = check_matrix(_transposed_rotation(product(A1, A2, A3)), plain)
    assert result.mistakes[0] == "transposed_rotation"
    result = check_matrix(product(A3, A2, A1), plain)  # no context: no order hint
    assert "wrong_order" not in result.mistakes and not result.ok


def test_missing_offset_without_context():
    reference = np.array([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 2], [0, 0, 0, 1]])
    result = check_matrix(np.eye(4), reference)
    assert result.wrong_entries == [(0, 3), (2, 3)]
    assert result.mistakes == ["missing_offset"]
    assert "(1,4), (3,4)" in result.hints[0]


def test_hints_do_not_fire_on_unrelated_errors(robot):
    student = product(A1, A2, A3)
    student[2, 3] = l1 + 7
    result = check_matrix(student, expected(robot, "M3"), reveal=True)
    assert result.wrong_entries == [(2, 3)]
    assert result.mistakes == []
    assert result.hints == ["entry (3,4): expected l1 - l2*sin(q2), you wrote l1 + 7."]


def test_reveal_false_hides_expected(robot):
    student = product(A1, A2, A3)
    student[2, 3] = l1 + 7
    result = check_matrix(student, expected(robot, "M3"), reveal=False)
    assert result.hints == ["entry (3,4) is wrong (you wrote l1 + 7)."]
    assert "expected" not in result._repr_html_()


# -- tolerance, equivalence, inputs -----------------------------------------------------


def test_numeric_tolerance():
    reference = np.array([[np.sqrt(2) / 2, 70.71068]])
    assert check_matrix([[0.7071, 70.71]], reference).ok
    assert not check_matrix([[0.7071, 70.71]], reference, tol=1e-6).ok
    assert check_matrix([[0.7071068, 70.710679]], reference, tol=1e-6).ok
    result = check_matrix([[0.70, 70.71]], reference)
    assert result.wrong_entries == [(0, 0)]


def test_symbolic_equivalence_by_evaluation_and_simplification():
    reference = sympy.Matrix([[sympy.cos(q1 + q2), sympy.sqrt(q1 - 10)]])
    student = "[[cos(q1)*cos(q2) - sin(q1)*sin(q2), sqrt(q1 - 10)*(sin(q2)**2 + cos(q2)**2)]]"
    # sqrt(q1 - 10) is undefined at the sample points: simplification decides
    assert check_matrix(student, reference).ok
    assert not check_matrix("[[cos(q1 - q2), sqrt(q1 - 10)]]", reference).ok
    assert not check_matrix("[[cos(q1 + q2), sqrt(q1 - 11)]]", reference).ok


def test_student_input_forms(robot):
    reference = expected(robot, "A2")
    text = "[[cos(q2), 0, sin(q2), 0], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]"
    loose = [sympy.Symbol("q2"), sympy.Symbol("l1")]  # no real=True: same names still match
    forms = [
        text,
        [
            ["cos(q2)", 0, "sin(q2)", 0],
            [0, 1, 0, 0],
            ["-sin(q2)", 0, "cos(q2)", "l1"],
            [0, 0, 0, 1],
        ],
        A2,
        module_matrix("Ry", loose[0], (0, 0, loose[1])),
        np.array(A2, dtype=object),
    ]
    for form in forms:
        assert check_matrix(form, reference).ok


def test_vector_forms(robot):
    reference = expected_matrix(robot, "p_EE", q=[0, 0, 0])
    assert sympy.Matrix([[70, 0, 20, 1]]) == reference.matrix.T
    for student in (
        [70, 0, 20],
        [70, 0, 20, 1],
        np.array([[70], [0], [20]]),
        "[70, 0, 20]",
        "[[70, 0, 20, 1]]",
    ):
        assert check_matrix(student, reference).ok, student
    assert not check_matrix([70, 20, 0], reference).ok


def test_shape_mismatch(robot):
    result = check_matrix(np.eye(3), expected(robot, "A1"))
    assert not result.ok and result.mistakes == ["shape"]
    assert "rotation part only" in result.hints[0]
    result = check_matrix(np.eye(2), np.eye(3))
    assert result.hints == ["Expected a 3×3 matrix, you gave 2×2."]


def test_result_rendering(robot):
    student = product(A2, A1)
    result = check_matrix(student, expected(robot, "M2"))
    page = result._repr_html_()
    assert page.count("✗") == len(result.wrong_entries) == 6
    assert page.count('style="background:#efe"') == 10
    assert "wrong order" in page
    assert str(result).startswith("M2: 6 wrong entries.\n- You multiplied in the wrong order")
    assert repr(result).startswith("<MatrixCheck ok=False")
    ok = check_matrix(A1, expected(robot, "A1"))
    assert str(ok) == "A1: correct." and "✔ correct" in ok._repr_html_()
    assert isinstance(ok, MatrixCheck)


def test_assert_matrix(robot):
    assert assert_matrix(A1, expected(robot, "A1")).ok
    with pytest.raises(AssertionError, match="You multiplied in the wrong order"):
        assert_matrix(product(A2, A1), expected(robot, "M2"))


def test_expected_matrix_names(robot):
    assert expected_matrix(robot, "m2").name == "M2"
    assert expected_matrix(robot, "EE").name == "p_EE"
    assert expected_matrix(robot, "p_EE").index == 3
    assert expected(robot, "A2").symbol_names() == ["l1", "q1", "q2", "q3"]
    assert as_expected(derivation(robot, symbolic=True)["M1"]).has_context


def test_evaluate_walks_tree_without_codegen():
    env = {"q1": np.array([0.0, np.pi / 2]), "l1": np.array([2.0, 3.0])}
    got = evaluate(l1 * sympy.cos(q1) + sympy.sqrt(l1) ** 2 + sympy.tan(0 * q1), env, 2)
    np.testing.assert_allclose(got, [4.0, 3.0], atol=1e-12)
    assert np.isnan(evaluate(sympy.sqrt(q1 - 10), env, 2)).all()
    np.testing.assert_allclose(evaluate(sympy.Abs(q1 - 1), env, 2), [1.0, np.pi / 2 - 1])


# -- errors -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("student", "message"),
    [
        ([[1, 2], [3]], r"student: rows of lengths \[1, 2\]"),
        ([[1, 2], 3], "student: mixes rows and single entries"),
        ([], "student: not a matrix"),
        (42, "student: not a matrix"),
        (b"[[1]]", "student: bytes, not text"),
        ([[float("nan"), 0], [0, 1]], r"student\[0\]\[0\]: must be finite"),
        ([[True, 0], [0, 1]], r"student\[0\]\[0\]: a boolean"),
        ([[object(), 0], [0, 1]], r"student\[0\]\[0\]: not a number"),
        ([[sympy.Eq(q1, 1), 0], [0, 1]], r"student\[0\]\[0\]: not a formula"),
        ("[[__import__('os'), 0], [0, 1]]", 'student: character "\'" is not allowed'),
        ([["q1.real", 0], [0, 1]], r"student\[0\]\[0\]: attribute access"),
        ("[[q7, 0], [0, 1]]", "student: unknown name 'q7'"),
    ],
)
def test_malformed_student_input_raises(robot, student, message):
    with pytest.raises(ValueError, match=message):
        check_matrix(student, expected(robot, "A1") if "q7" in str(student) else np.eye(2))


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"tol": -1}, "tol: invalid value -1"),
        ({"tol": True}, "tol: a boolean is not a number: True"),
        ({"tol": 2}, "tol: invalid value 2"),
        ({"samples": 0}, "samples: out of range: 0; allowed: an integer ≥ 1"),
        ({"samples": 2.5}, "samples: not an integer: 2.5"),
        ({"symbols": ["a b"]}, "symbols: invalid value 'a b'"),
    ],
)
def test_bad_options_raise(kwargs, message):
    with pytest.raises(ValueError, match=message):
        check_matrix(np.eye(2), np.eye(2), **kwargs)


@pytest.mark.parametrize(
    ("reference", "message"),
    [
        ("[[1, 0], [0, 1]]", "expected: text is not accepted"),
        ([[1, 0], [0]], "expected: not a matrix"),
        ([[np.inf, 0], [0, 1]], "expected: shape"),
        (np.zeros((2, 2, 2)), "expected: shape"),
    ],
)
def test_bad_reference_raises(reference, message):
    with pytest.raises(ValueError, match=message):
        check_matrix(np.eye(2), reference)


def test_bad_matrix_name_raises(robot):
    with pytest.raises(ValueError, match="name: unknown matrix name 'M4'"):
        expected_matrix(robot, "M4")
    with pytest.raises(ValueError, match="name: not a matrix name: 3"):
        expected_matrix(robot, 3)


def test_partial_explanation_plus_another_error(robot):
    student = product(A3, A2, A1)
    student[3, 0] = 5  # a second, unrelated mistake in the bottom row
    result = check_matrix(student, expected(robot, "M3"), reveal=True)
    assert result.mistakes[0] == "wrong_order"
    assert "(entries (1,2), (1,3), (1,4), (2,1)" in result.hints[0]
    assert result.hints[1] == "entry (4,1): expected 0, you wrote 5."
    assert (3, 0) in result.wrong_entries and len(result.wrong_entries) == 10
