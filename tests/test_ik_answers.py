"""The IK answer checks: any solution passes, every closed-form solution for a set, slips named.

The reference numbers are derived by hand for the planar 2R arm (law of cosines and
atan2, written out below), independently of the solvers; the checker itself judges
by forward kinematics.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.inverse_kinematics import ik, ik_all
from robotconf.teaching import IK_DIAGNOSES, IKCheck

ARM = rc.preset("planar_2r", l1=1, l2=1)
ONE_ONE = [1, 1, 0]
ELBOW_DOWN, ELBOW_UP = [0, math.pi / 2], [math.pi / 2, -math.pi / 2]

# A target with x < 0, where atan(y/x) loses the quadrant.
X, Y = -1.2, 0.5
R2 = X * X + Y * Y


def by_hand(x: float, y: float, sign: float, l1: float = 1.0, l2: float = 1.0) -> list[float]:
    """The textbook 2R solution: cos q2 from the law of cosines, q1 by atan2."""
    q2 = sign * math.acos((x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2))
    return [math.atan2(y, x) - math.atan2(l2 * math.sin(q2), l1 + l2 * math.cos(q2)), q2]


def reach(q: list[float]) -> np.ndarray:
    """Forward kinematics of the unit 2R arm, written out."""
    return np.array(
        [math.cos(q[0]) + math.cos(q[0] + q[1]), math.sin(q[0]) + math.sin(q[0] + q[1])]
    )


def test_hand_solutions_reach_their_targets():
    assert np.allclose(reach(ELBOW_DOWN), [1, 1]) and np.allclose(reach(ELBOW_UP), [1, 1])
    for sign in (1, -1):
        assert np.allclose(reach(by_hand(X, Y, sign)), [X, Y])


@pytest.mark.parametrize(
    ("answer", "branch"),
    [
        (ELBOW_DOWN, "elbow down"),
        (ELBOW_UP, "elbow up"),
        ("[0, pi/2]", "elbow down"),
        ("[pi/2, -pi/2]", "elbow up"),
        ([0, 1.5708], "elbow down"),  # four digits
        (np.array([math.pi / 2 + 2 * math.pi, 3 * math.pi / 2]), "elbow up"),  # whole turns
        ([[0], [math.pi / 2]], "elbow down"),  # a column
    ],
)
def test_any_solution_passes_and_is_named(answer, branch):
    result = rc.check_ik_solution(answer, ARM, ONE_ONE)
    assert isinstance(result, IKCheck) and result.ok, str(result)
    assert result.branches == (branch,)
    assert np.allclose(result.reached, [1, 1, 0])
    assert str(result) == "the solution: correct."


def test_a_target_with_x_below_zero_accepts_both_hand_solutions():
    for sign in (1, -1):
        assert rc.check_ik_solution(by_hand(X, Y, sign), ARM, [X, Y, 0]).ok


def test_tolerance_is_relative_to_the_robot_size():
    # L = 2, tol 5e-3: within 0.01 of the target (angles with 3 significant digits).
    assert rc.check_ik_solution([0, 1.57], ARM, ONE_ONE).ok  # 0.0008 away
    assert rc.check_ik_solution([0, 1.575], ARM, ONE_ONE).ok  # 0.0042 away
    assert not rc.check_ik_solution([0, 1.585], ARM, ONE_ONE).ok  # 0.014 away
    assert rc.check_ik_solution([0, 1.585], ARM, ONE_ONE, tol=8e-3).ok


def test_atan_for_atan2_is_named_without_the_answer():
    slip = by_hand(X, Y, 1)
    slip[0] = math.atan(Y / X) - math.atan2(math.sin(slip[1]), 1 + math.cos(slip[1]))
    result = rc.check_ik_solution(slip, ARM, [X, Y, 0])
    assert result.diagnosis == "atan_quadrant"
    assert "q1 is off by half a turn" in result.hints[0] and "atan2(y, x)" in result.hints[0]
    right = by_hand(X, Y, 1)
    assert f"{right[0]:.4g}" not in str(result) and f"{right[1]:.4g}" not in str(result)


def test_the_mixed_elbow_branch_is_the_cosine_law_sign():
    # q1 of the elbow-down solution with the elbow-up q2: lands at (1, -1), not (1, 1).
    result = rc.check_ik_solution([0, -math.pi / 2], ARM, ONE_ONE)
    assert result.diagnosis == "cosine_law_sign"
    assert "Flip the sign of q2" in result.hints[0]
    assert "different elbow solutions" in result.hints[0]


def test_the_inner_angle_for_the_joint_angle_is_the_cosine_law_sign():
    # cos γ = (l1² + l2² − r²)/(2 l1 l2): the sign slip in the law of cosines, q1 computed
    # consistently from it, so the tip lands on the target's line at another distance.
    gamma = math.acos((2 - R2) / 2)
    slip = [math.atan2(Y, X) - math.atan2(math.sin(gamma), 1 + math.cos(gamma)), gamma]
    landed = reach(slip)
    assert not np.isclose(np.hypot(*landed), math.sqrt(R2))
    assert np.isclose(math.atan2(landed[1], landed[0]), math.atan2(Y, X))
    result = rc.check_ik_solution(slip, ARM, [X, Y, 0])
    assert result.diagnosis == "cosine_law_sign"
    assert "inner angle" in result.hints[0]


def test_degrees_rounding_and_a_swapped_target():
    assert rc.check_ik_solution([0, 90], ARM, ONE_ONE).diagnosis == "degrees_as_radians"
    assert rc.check_ik_solution([90, -90], ARM, ONE_ONE).diagnosis == "degrees_as_radians"
    assert rc.check_ik_solution([0, 1.6], ARM, ONE_ONE).diagnosis == "too_rounded"
    swapped = rc.check_ik_solution(by_hand(Y, X, 1), ARM, [X, Y, 0])
    assert swapped.diagnosis == "wrong_target" and "x and y swapped" in swapped.hints[0]


def test_a_plain_miss_says_where_the_answer_lands():
    result = rc.check_ik_solution([0.3, 0.2], ARM, ONE_ONE)
    tip = reach([0.3, 0.2])  # (1.8329, 0.7749)
    assert result.diagnosis == "wrong"
    assert f"({tip[0]:.4g}, {tip[1]:.4g}, 0)" in result.hints[0]
    assert f"{np.hypot(tip[0] - 1, tip[1] - 1):.4g} from the target" in result.hints[0]


def test_reveal_quotes_the_nearest_solution():
    hidden = rc.check_ik_solution([0.1, 1.4], ARM, ONE_ONE)
    shown = rc.check_ik_solution([0.1, 1.4], ARM, ONE_ONE, reveal=True)
    assert "1.571" not in str(hidden)
    assert shown.hints[-1] == "One solution: [0, 1.571] (elbow down)."


def test_exercise_hint_follows_the_diagnosis():
    result = rc.check_ik_solution([0, 90], ARM, ONE_ONE, hint="Use radians.")
    assert result.hints[-1] == "Use radians." and len(result.hints) == 2


def test_blank_symbols_and_shapes():
    blank = rc.check_ik_solution(None, ARM, ONE_ONE)
    assert blank.diagnosis == "no_answer" and "replace None" in blank.hints[0]
    assert rc.check_ik_solution("[q1, 0]", ARM, ONE_ONE).diagnosis == "not_a_number"
    three = rc.check_ik_solution([0, 1, 2], ARM, ONE_ONE)
    assert three.diagnosis == "shape" and "2 joint values [q1, q2]" in three.hints[0]
    two = rc.check_ik_solution([ELBOW_DOWN, ELBOW_UP], ARM, ONE_ONE)
    assert "you gave 2 solutions" in two.hints[0]


@pytest.mark.parametrize(
    "answer",
    [
        "[nan, 0]",
        [float("nan"), 0],
        [math.inf, 0],
        "[1e400, 0]",
        [1e12, 0],  # an angle too large to judge modulo a full turn
        "[sqrt(-1), 0]",
        "[I, 0]",
        [1j, 0],
        1j,
        "__import__('os').system('echo hacked')",
        "[0, (lambda: 1)()]",
    ],
)
def test_hostile_or_non_real_answers_are_refused(answer):
    with pytest.raises(InvalidInputError):
        rc.check_ik_solution(answer, ARM, ONE_ONE)


def test_bad_teacher_input_is_refused():
    with pytest.raises(InvalidInputError, match="robot"):
        rc.check_ik_solution(ELBOW_DOWN, "arm", ONE_ONE)
    with pytest.raises(InvalidInputError, match="mode"):
        rc.check_ik_solution(ELBOW_DOWN, ARM, ONE_ONE, mode="orientation")
    with pytest.raises(InvalidInputError, match="target"):
        rc.check_ik_solution(ELBOW_DOWN, ARM, [1, 1])
    with pytest.raises(InvalidInputError, match="target"):
        rc.check_ik_solution(ELBOW_DOWN, ARM, ONE_ONE, mode="pose")
    with pytest.raises(InvalidInputError, match="target"):  # out of reach: no set to give
        rc.check_ik_solutions([ELBOW_DOWN], ARM, [3, 0, 0])
    with pytest.raises(InvalidInputError, match="robot"):  # no closed form
        rc.check_ik_solutions([[0, 0, 0]], rc.preset("cartesian"), [0.1, 0.1, 0.1])


@pytest.mark.parametrize(
    "answer",
    [
        [ELBOW_DOWN, ELBOW_UP],
        [ELBOW_UP, ELBOW_DOWN],
        "[[pi/2, -pi/2], [0, pi/2]]",
        [[2 * math.pi, math.pi / 2], [-3 * math.pi / 2, -math.pi / 2]],
    ],
)
def test_the_set_of_both_solutions_in_any_order(answer):
    result = rc.check_ik_solutions(answer, ARM, ONE_ONE)
    assert result.ok, str(result)
    assert sorted(result.branches) == ["elbow down", "elbow up"]


def test_the_lost_second_solution_is_named_by_its_label_only():
    result = rc.check_ik_solutions([ELBOW_DOWN], ARM, ONE_ONE)
    assert result.diagnosis == "missing" and result.wrong == [1]
    assert "You gave 1 of the 2 solutions; elbow up is missing." in result.hints[0]
    assert "1.571" not in str(result)
    shown = rc.check_ik_solutions("[0, pi/2]", ARM, ONE_ONE, reveal=True)
    assert "elbow up [1.571, -1.571]" in shown.hints[0]


def test_set_slips_duplicates_and_blanks():
    # The elbow-down q1 with q2 written for the elbow-up: that element explains the gap.
    mixed = rc.check_ik_solutions([ELBOW_DOWN, [math.pi / 2, math.pi / 2]], ARM, ONE_ONE)
    assert mixed.diagnosis == "cosine_law_sign" and len(mixed.hints) == 1
    assert mixed.headline == "the solutions: 1 of 2 solutions right, 1 not."
    # The other mix: the elbow-down q1 with the elbow-up q2 stands for the elbow up.
    other = rc.check_ik_solutions([ELBOW_DOWN, [0, -math.pi / 2]], ARM, ONE_ONE)
    assert other.diagnosis == "cosine_law_sign" and len(other.hints) == 1
    atan = rc.check_ik_solutions([ELBOW_DOWN, [math.pi, math.pi / 2]], ARM, ONE_ONE)
    assert atan.diagnosis == "atan_quadrant" and atan.extra == [1]
    assert "elbow up is missing" in atan.hints[-1]  # (π, π/2) is no slip of the elbow up
    twice = rc.check_ik_solutions([ELBOW_DOWN, [2 * math.pi, math.pi / 2]], ARM, ONE_ONE)
    assert twice.diagnosis == "duplicate" and "missing" in twice.hints[-1]
    degrees = rc.check_ik_solutions([[0, 90], [90, -90]], ARM, ONE_ONE)
    assert degrees.diagnosis == "degrees_as_radians" and len(degrees.hints) == 2
    for empty in ([], "[]"):
        nothing = rc.check_ik_solutions(empty, ARM, ONE_ONE)
        assert nothing.diagnosis == "missing" and "elbow down and elbow up" in nothing.hints[0]
    assert rc.check_ik_solutions(None, ARM, ONE_ONE).diagnosis == "no_answer"
    shape = rc.check_ik_solutions([[0, 1, 2]], ARM, ONE_ONE)
    assert shape.diagnosis == "shape"


PAPER = rc.preset("paper")  # shoulder at (0, 0, 20), l2 = 30, l3 = 40 (mm)


def paper_by_hand(x: float, y: float, z: float, sign: float) -> list[float]:
    """Shoulder front: q1 faces the target; q2, q3 solve the 2R arm in the vertical plane.

    The Ry joints turn the arm downwards for q > 0, so the planar angle is −q2 − q3.
    """
    r, h = math.hypot(x, y), z - 20
    down = by_hand(r, h, sign, 30, 40)
    return [math.atan2(y, x), -down[0], -down[1]]


def test_the_paper_robot_accepts_a_solution_outside_its_ranges_with_a_note():
    target = [30, 20, 50]
    for sign in (1, -1):
        q = paper_by_hand(*target, sign)
        assert np.allclose(PAPER.end_effector(q), target)
        assert rc.check_ik_solution(q, PAPER, target).ok
    up = paper_by_hand(*target, -1)  # q2 ≈ -1.703, below the shoulder's -π/2
    result = rc.check_ik_solution(up, PAPER, target)
    assert result.ok and "q2 = -1.703 is below its lower limit -1.571" in result.notes[0]
    assert "Note:" in str(result)
    strict = rc.check_ik_solution(up, PAPER, target, within_limits=True)
    assert strict.diagnosis == "outside_limits"
    assert rc.check_ik_solution(paper_by_hand(*target, 1), PAPER, target, within_limits=True).ok


def test_the_paper_robot_set_within_its_ranges():
    target = [30, 20, 50]
    every = ik_all(PAPER, target)
    inside = every.q[every.within_limits]
    assert len(every) == 4 and len(inside) == 2
    assert rc.check_ik_solutions(inside, PAPER, target, within_limits=True).ok
    flagged = rc.check_ik_solutions(every.q, PAPER, target, within_limits=True)
    assert flagged.diagnosis == "outside_limits"
    three = rc.check_ik_solutions(every.q[:3], PAPER, target)
    assert "shoulder back, elbow up is missing" in three.hints[0]
    assert "q3 = ±arccos(…)" in three.hints[0]


def test_the_paper_robot_atan_slip():
    target = [-30, 20, 50]
    q = paper_by_hand(*target, 1)
    q[0] = math.atan(20 / -30)
    assert rc.check_ik_solution(q, PAPER, target).diagnosis == "atan_quadrant"


def test_puma_pose_answers():
    puma = rc.preset("puma560")
    goal = puma.end_effector_pose([0.3, 0.6, -0.9, 0.4, 0.7, 0.2])
    numeric = ik(puma, goal, mode="pose")
    assert numeric.success
    assert rc.check_ik_solution(numeric.q, puma, goal, mode="pose").ok
    turned = np.array([0.3, 0.6, -0.9, 0.4, 0.7, 0.5])  # q6 off by 0.3 rad: the point stays
    wrong = rc.check_ik_solution(turned, puma, goal, mode="pose")
    assert wrong.diagnosis == "wrong" and "turned 17.19° away" in wrong.hints[0]
    assert rc.check_ik_solution(turned, puma, goal).ok  # mode "position": the point only
    every = ik_all(puma, goal)
    assert rc.check_ik_solutions(every.q[::-1], puma, goal, mode="pose").ok
    seven = rc.check_ik_solutions(every.q[1:], puma, goal, mode="pose")
    assert seven.hints[0] == (f"You gave 7 of the 8 solutions; {every.labels[0]} is missing.")


def test_assert_forms():
    assert rc.assert_ik_solution(ELBOW_UP, ARM, ONE_ONE).ok
    assert rc.assert_ik_solutions([ELBOW_DOWN, ELBOW_UP], ARM, ONE_ONE).ok
    with pytest.raises(AssertionError, match=r"^q: not right yet\.\n- Your answer is in degrees"):
        rc.assert_ik_solution([0, 90], ARM, ONE_ONE, name="q")
    with pytest.raises(AssertionError, match="elbow up is missing"):
        rc.assert_ik_solutions([ELBOW_DOWN], ARM, ONE_ONE)


def test_every_diagnosis_code_is_documented():
    cases = [
        rc.check_ik_solution(None, ARM, ONE_ONE),
        rc.check_ik_solution([0, 90], ARM, ONE_ONE),
        rc.check_ik_solution([0, -math.pi / 2], ARM, ONE_ONE),
        rc.check_ik_solution([0.3, 0.2], ARM, ONE_ONE),
        rc.check_ik_solutions([ELBOW_DOWN], ARM, ONE_ONE),
    ]
    assert all(case.diagnosis in IK_DIAGNOSES for case in cases)


def test_html_shows_the_note_of_a_right_answer():
    result = rc.check_ik_solution(paper_by_hand(30, 20, 50, -1), PAPER, [30, 20, 50])
    assert "✔" in result._repr_html_() and "below its lower limit" in result._repr_html_()


def test_an_angle_rounded_past_three_digits_is_too_rounded_even_when_the_tip_forgives_it():
    # Exact: (0, π/2). 1.58 is 0.6 % from π/2 (past the 0.5 % of 3 significant digits),
    # yet the tip misses by only 0.0092 of the 0.01 allowed for L = 2.
    result = rc.check_ik_solution([0, 1.58], ARM, ONE_ONE)
    assert not result.ok and result.diagnosis == "too_rounded", str(result)
    assert "q2" in result.hints[0] and "keep 3 significant digits" in result.hints[0]
    assert rc.check_ik_solution([0.0004, 1.571], ARM, ONE_ONE).ok  # 3 digits; 0.001 near 0
    assert rc.check_ik_solution([2 * math.pi, 1.57 - 2 * math.pi], ARM, ONE_ONE).ok  # turns
    # a teacher's own tolerance is about the tip alone
    assert rc.check_ik_solution([0, 1.58], ARM, ONE_ONE, tol=8e-3).ok
