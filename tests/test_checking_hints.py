"""The checker's hints on non-square, non-rotation, DH, missing and scalar answers."""

from __future__ import annotations

import numpy as np
import pytest
import sympy

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.teaching import assert_matrix, check_matrix, generic_candidates, is_rotation_like

q1, q2, q3 = sympy.symbols("q1 q2 q3", real=True)
ROTATION_WORDS = ("rotation", "axis", "axes")


@pytest.fixture(scope="module")
def paper_robot() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


@pytest.fixture(scope="module")
def jacobian_6x3(paper_robot) -> np.ndarray:
    return rc.jacobian(paper_robot, [0.3, -0.4, 0.7])


@pytest.fixture(scope="module")
def symbolic_jacobian(paper_robot) -> sympy.Matrix:
    chain = rc.symbolic_chain(paper_robot)
    return chain.end_effector()[:3, :].jacobian(chain.q_symbols)


def _no_rotation_words(hints: list[str]) -> None:
    text = " ".join(hints)
    assert not any(word in text for word in ROTATION_WORDS), hints


# -- 1. non-square answers: hints, never a numpy broadcast error --------------------------


def test_wrong_non_square_answer_gets_hints(jacobian_6x3):
    student = jacobian_6x3.copy()
    student[:, [1, 2]] = student[:, [2, 1]]  # joints 2 and 3 exchanged
    result = check_matrix(student, jacobian_6x3)
    assert result.mistakes[0] == "column_swap"
    assert result.hints[0].startswith("Columns 2 and 3 are swapped")
    student = jacobian_6x3.copy()
    student[2, 0] += 5.0
    result = check_matrix(student, jacobian_6x3, reveal=True)
    assert result.wrong_entries == [(2, 0)]
    assert result.hints[0].startswith("entry (3,1): expected")


def test_transposed_non_square_answer_is_named(jacobian_6x3):
    result = check_matrix(np.round(jacobian_6x3.T, 4), jacobian_6x3)
    assert not result.ok and result.mistakes == ["transposed_matrix"]
    assert result.hints == [
        "Your matrix is the transpose of the expected one: expected 6×3 (6 rows of 3 "
        "entries), you gave 3×6 — write each row as a row, not as a column."
    ]
    student = jacobian_6x3.T.copy()
    student[0, 1] += 1.0  # also one wrong entry: (2,1) once transposed back
    result = check_matrix(student, jacobian_6x3)
    assert result.hints[0].startswith("Your matrix looks transposed: expected 6×3")
    assert result.hints[0].endswith(
        "Transposed back, entries (2,1) (numbered as in the expected matrix) are still wrong."
    )
    result = check_matrix(np.eye(3), jacobian_6x3)  # another shape: no transposition hint
    assert result.hints == ["Expected a 6×3 matrix, you gave 3×3."]


def test_generic_candidates_handle_non_square_values():
    values = np.arange(2 * 6 * 3, dtype=float).reshape(2, 6, 3)
    codes = {candidate.code for candidate in generic_candidates(values)}
    assert codes == {"row_swap", "column_swap"}


# -- 2. rotation wording only for rotations and homogeneous transforms -------------------


def test_transposed_non_rotation_3x3_gets_a_generic_hint(symbolic_jacobian):
    result = check_matrix(symbolic_jacobian.T, symbolic_jacobian)
    assert result.mistakes[0] == "transposed_matrix"
    assert result.hints[0] == (
        "The whole matrix is transposed (yours is the transpose of the expected one): "
        "write each row as a row, not as a column."
    )
    _no_rotation_words(result.hints)


def test_transposed_rotation_keeps_the_frame_axes_hint():
    rotation = sympy.Matrix(
        [[sympy.cos(q1), -sympy.sin(q1), 0], [sympy.sin(q1), sympy.cos(q1), 0], [0, 0, 1]]
    )
    result = check_matrix(rotation.T, rotation)
    assert result.mistakes[0] == "transposed_rotation"
    assert "write the axes as columns, not as rows" in result.hints[0]


def test_transposed_general_4x4_is_not_a_homogeneous_transform():
    matrix = np.arange(16, dtype=float).reshape(4, 4)
    result = check_matrix(matrix.T, matrix)
    assert result.mistakes == ["transposed_matrix"]
    assert "translation" not in result.hints[0]
    _no_rotation_words(result.hints)


def test_sine_sign_error_outside_a_rotation_is_a_plain_sign_error(symbolic_jacobian):
    determinant = sympy.Matrix([[2 * sympy.sin(q2)]])
    result = check_matrix("[[-2*sin(q2)]]", determinant, reveal=True)
    assert result.mistakes == ["sign_error"]
    assert result.hints == [
        "entry (1,1): expected 2*sin(q2), you wrote -2*sin(q2) — a sign error: the whole "
        "entry has the opposite sign."
    ]
    student = symbolic_jacobian.copy()
    student[0, 0] = -student[0, 0]
    result = check_matrix(student, symbolic_jacobian)
    assert result.mistakes == ["sign_error"] and "opposite sign" in result.hints[0]
    _no_rotation_words(result.hints)


def test_is_rotation_like():
    assert is_rotation_like(np.eye(3)[np.newaxis])
    assert is_rotation_like(np.eye(4)[np.newaxis])
    skewed = np.eye(4)
    skewed[3, 0] = 1.0
    assert not is_rotation_like(skewed[np.newaxis])
    assert not is_rotation_like(2 * np.eye(3)[np.newaxis])
    assert not is_rotation_like(np.zeros((1, 3, 4)))


# -- 3. DH rows: the twist's sign, d and a swapped ---------------------------------------


def _dh_row(alpha: float, d: float = 0.5, a: float = 1.0, **kw) -> rc.Robot:
    return rc.Robot.from_dh([(0, d, a, alpha, "R")], **kw)


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_alpha_sign_error_is_named(convention):
    expected = rc.expected_matrix(_dh_row(np.pi / 2, convention=convention), "A1")
    student = rc.expected_matrix(_dh_row(-np.pi / 2, convention=convention), "A1").matrix
    result = check_matrix(student, expected)
    assert result.mistakes == ["sign_error"]
    assert result.hints[0].startswith(
        "The twist α of A1 (module M1, DH row θ=0, d=0.5, a=1, α=1.5708) has the wrong sign"
    )


def test_d_and_a_swapped_is_named():
    expected = rc.expected_matrix(_dh_row(np.pi / 2), "A1")
    student = rc.expected_matrix(_dh_row(np.pi / 2, d=1.0, a=0.5), "A1").matrix
    result = check_matrix(student, expected)
    assert result.mistakes == ["swapped_d_a"]
    assert result.hints[0] == (
        "The link offset d and the link length a of A1 (module M1, DH row θ=0, d=0.5, a=1, "
        "α=1.5708) are swapped: d is the distance along z (Tz(d)), a the distance along x "
        "(Tx(a))."
    )


def test_d_and_a_swapped_in_a_chain_with_symbolic_lengths():
    robot = rc.Robot.from_dh([(0, 0.5, 1, np.pi / 2, "R"), (0, 0, 2, 0, "R")])
    swapped = rc.Robot.from_dh([(0, 1, 0.5, np.pi / 2, "R"), (0, 0, 2, 0, "R")])
    result = check_matrix(rc.expected_matrix(swapped, "M2").matrix, rc.expected_matrix(robot, "M2"))
    assert result.mistakes[0] == "swapped_d_a" and "of A1 (module M1" in result.hints[0]
    student = (  # lengths as symbols: d1 = l1, a1 = l2, written the other way round
        "[[cos(q1), 0, sin(q1), l1*cos(q1)], [sin(q1), 0, -cos(q1), l1*sin(q1)],"
        " [0, 1, 0, l2], [0, 0, 0, 1]]"
    )
    result = check_matrix(student, rc.expected_matrix(robot, "A1", lengths=True))
    assert result.mistakes == ["swapped_d_a"]


# -- 4. an exercise not answered yet -----------------------------------------------------


def test_no_answer_yet(paper_robot):
    reference = rc.expected_matrix(paper_robot, "A2")
    result = check_matrix(None, reference)
    assert not result.ok and result.mistakes == ["no_answer"] and result.wrong_entries == []
    assert result.hints == ["No answer yet: replace None with your matrix."]
    assert str(result) == "A2:\n- No answer yet: replace None with your matrix."
    assert "No answer yet" in result._repr_html_()
    with pytest.raises(AssertionError, match="No answer yet: replace None with your matrix"):
        assert_matrix(None, reference)
    with pytest.raises(InvalidInputError, match="student: not a matrix"):
        assert_matrix(42, np.eye(2))  # malformed input is still an input error


# -- 5. scalar answers -------------------------------------------------------------------


@pytest.mark.parametrize(
    "student", ["2*sin(q2)", "  (2*sin(q2))", "sin(q2) * 2", "[[2*sin(q2)]]", "[2*sin(q2)]"]
)
def test_scalar_formula_answers(student):
    assert check_matrix(student, sympy.Matrix([[2 * sympy.sin(q2)]])).ok
    assert check_matrix(student, 2 * sympy.sin(q2)).ok  # a scalar reference is 1×1


@pytest.mark.parametrize("student", [0.5, 1 / 2, np.float64(0.5), np.array(0.5), "1/2", "0.5"])
def test_scalar_number_answers(student):
    assert check_matrix(student, 0.5).ok
    assert check_matrix(student, np.array([[0.5]])).ok


def test_wrong_scalar_answer_gets_a_hint():
    result = check_matrix("2*cos(q2)", 2 * sympy.sin(q2), reveal=True)
    assert result.hints == ["entry (1,1): expected 2*sin(q2), you wrote 2*cos(q2)."]
    with pytest.raises(InvalidInputError, match="unknown name 'x'"):
        check_matrix("2*x", 2 * sympy.sin(q2))
    with pytest.raises(InvalidInputError, match="student: not a matrix"):
        check_matrix(0.5, np.eye(2))  # a scalar is no answer to a 2×2 matrix


def test_hint_helpers_stay_numpy_only_and_never_evaluate_text():
    import pathlib
    import re
    import subprocess
    import sys

    source = (pathlib.Path(rc.__file__).parent / "teaching" / "diagnosis" / "_hints.py").read_text()
    assert not re.search(r"\b(eval|exec|sympify|parse_expr)\(", source)
    code = "import sys, robotconf.teaching; assert 'sympy' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True)


def test_rotation_pattern_names_where_the_kernel_puts_the_sines():
    import re

    from robotconf.teaching import ROTATION_PATTERN

    for axis, text in ROTATION_PATTERN.items():
        matrix = rc.transfer_matrix(f"R{axis}", 0.3)
        found = re.findall(r"([−+])sin in entry \((\d),(\d)\)", text)
        assert len(found) == 2
        for sign, row, col in found:
            expected = np.sin(0.3) * (-1 if sign == "−" else 1)
            assert matrix[int(row) - 1, int(col) - 1] == pytest.approx(expected, abs=1e-15)


# -- 6. one primary diagnosis, ranked; equivalent readings in the same sentence ------------


def _paper_reference(name: str, **kw) -> rc.ExpectedMatrix:
    robot = rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )
    return rc.expected_matrix(robot, name, **kw)


def test_one_sign_slip_gets_one_diagnosis_and_names_the_equivalent_reading():
    reference = rc.expected_matrix(rc.Robot([rc.Module("Ry", a=(30, 0, 0))]), "A1")
    student = "[[cos(q1), 0, -sin(q1), 30], [0, 1, 0, 0], [sin(q1), 0, cos(q1), 0], [0, 0, 0, 1]]"
    result = check_matrix(student, reference)
    assert result.diagnosis == "rotation_direction"
    assert result.diagnoses[:2] == ("rotation_direction", "transposed_rotation")
    assert result.mistakes == ["rotation_direction"]  # one diagnosis, not two
    assert result.hints == [
        "The sine terms of A1 (module M1, Ry with a = (30, 0, 0)) have the wrong sign, so the "
        "joint turns the wrong way: a positive rotation about y has +sin in entry (1,3) and "
        "−sin in entry (3,1); here that gives the same numbers as writing the rotation part "
        "transposed (its axes as rows).",
        "Wrong entries: (1,3), (3,1).",
    ]


def test_every_ry_with_flipped_sines_is_one_compound_slip():
    student = (
        "[[cos(q1)*cos(q2 + q3), -sin(q1), -cos(q1)*sin(q2 + q3), 30*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2 + q3), cos(q1), -sin(q1)*sin(q2 + q3), 30*sin(q1)*cos(q2)],"
        " [sin(q2 + q3), 0, cos(q2 + q3), 20 + 30*sin(q2)], [0, 0, 0, 1]]"
    )
    result = check_matrix(student, _paper_reference("M3"))
    assert result.diagnosis == "rotation_direction_all"
    assert result.hints[0].startswith("The sine terms of every Ry module (A2 and A3) have the")
    assert result.hints[1] == "Wrong entries: (1,3), (2,3), (3,1), (3,4)."
    assert len(result.hints) == 2


def test_an_answer_at_q_0_is_the_parking_pose_not_degree_mode():
    reference = rc.expected_matrix(rc.Robot([rc.Module("Rz")]), "A1", q=[0.5])
    result = check_matrix(np.eye(4), reference)
    assert result.diagnosis == "parking_pose"
    assert "radians_as_degrees" in result.diagnoses  # it fits two entries only: ranked lower
    assert result.hints[0] == (
        "Your numbers are those of the parking pose q = 0 (every joint at 0), but this "
        "exercise asks for q = (0.5): put the joint values in."
    )


def test_a_forgotten_joint_is_not_a_missing_point():
    result = check_matrix(
        "[70*cos(q1)*cos(q2), 70*sin(q1)*cos(q2), 20 - 70*sin(q2)]", _paper_reference("p_EE")
    )
    assert result.diagnoses == ("joint_left_out",)
    assert result.hints[0].startswith(
        "q3 is missing from your answer: it is what you get with q3 = 0"
    )


@pytest.mark.parametrize(
    ("q", "student", "other"),
    [
        # the point turned by R3 only: R3·(40, 0, 0) = (0, 0, 40) at q = (90°, 0, -90°)
        ([np.pi / 2, 0, -np.pi / 2], [0, 0, 40], "missing_offset_all"),
        ([0, 0, 0], [40, 0, 0], "missing_offset_all"),
    ],
)
def test_homogeneous_coordinate_0_is_named(q, student, other):
    result = check_matrix(student, _paper_reference("p_EE", q=q))
    assert result.diagnoses[:2] == ("homogeneous_coordinate", other)
    assert result.hints[0].startswith(
        "You multiplied M3 by [Px, Py, Pz, 0]ᵀ: a point's homogeneous"
    )
    assert "the same numbers as leaving out the offsets of every Ry module" in result.hints[0]


def test_two_joint_values_exchanged():
    student = rc.Robot(  # the same robot, evaluated with q2 and q3 exchanged
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    ).end_effector([0.3, 0.7, -0.4])
    result = check_matrix(np.round(student, 4), _paper_reference("p_EE", q=[0.3, -0.4, 0.7]))
    assert result.diagnosis == "swapped_joints"
    assert result.hints[0].startswith("q2 and q3 are exchanged")


def test_lengths_in_millimetres_for_metres():
    reference = rc.expected_matrix(rc.preset("ur5"), "p_EE", q=np.zeros(6))
    result = check_matrix([-817.25, -191.45, -5.491], reference)
    assert result.diagnosis == "unit_slip"
    assert result.hints[0] == (
        "All your lengths are 1000 times too large: millimetres where the exercise's data are "
        "in metres? Keep the unit of the exercise."
    )


def test_degrees_for_the_joint_angle_only():
    reference = rc.expected_matrix(rc.preset("puma560"), "A1", q=[np.pi / 6, 0, 0, 0, 0, 0])
    joint_only = np.round(rc.dh_matrix(30, 0, 0, np.pi / 2), 4)  # α = π/2 read right
    result = check_matrix(joint_only, reference)
    assert result.diagnosis == "degrees_as_radians"
    assert "the joint angles in degrees" in result.hints[0]
    everything = np.round(rc.dh_matrix(30, 0, 0, 90), 4)  # α typed as 90 too
    result = check_matrix(everything, reference)
    assert result.diagnosis == "degrees_as_radians"
    assert "angles in degrees fed to sin and cos" in result.hints[0]
    assert "joint angles" not in result.hints[0]


def test_a_single_coincidental_entry_is_no_diagnosis():
    frame = rc.Robot([rc.Module("Rz", a=(30, 0, 20))], end_effector=(40, 0, 0))
    reference = rc.expected_matrix(frame, "p_EE", q=[np.pi / 2])  # (30, 40, 20)
    degree_mode = frame.end_effector([np.radians(np.pi / 2)])  # (69.985, 1.0965, 20)
    result = check_matrix([degree_mode[0], 7, 20], reference)  # x happens to match, y not
    assert result.wrong_entries == [(0, 0), (1, 0)]
    assert result.diagnosis is None and result.mistakes == []
    assert not any("degree mode" in hint for hint in result.hints)
    # one coarse number (0.1 for 0.0892, z without the offset d5) proves nothing either
    ur5 = rc.expected_matrix(rc.preset("ur5"), "p_EE", q=np.zeros(6))
    assert check_matrix([-0.81725, -0.19145, 0.1], ur5).diagnosis is None


def test_a_rounded_wrong_result_still_names_the_mistake():
    reference = rc.expected_matrix(rc.Robot.from_dh([(0, 0, 2, 0, "R")]), "A1", q=[np.pi / 6])
    degrees = np.round(rc.dh_matrix(30, 0, 2, 0), 2)  # cos(30 rad) = 0.15, …
    assert degrees[0, 0] == 0.15 and degrees[1, 3] == -1.98
    assert check_matrix(degrees, reference).diagnosis == "degrees_as_radians"


def test_right_and_unanswered_results_have_no_or_their_own_diagnosis():
    reference = rc.expected_matrix(rc.Robot([rc.Module("Rz")]), "A1")
    assert check_matrix(rc.transfer_matrix("Rz", 0) * 0 + np.eye(4), np.eye(4)).diagnoses == ()
    assert check_matrix(None, reference).diagnosis == "no_answer"
    assert check_matrix(np.eye(3), reference).diagnosis == "shape"
