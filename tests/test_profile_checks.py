"""Checks for motion-profile answers: right numbers by hand, slips named, hostile input refused.

The references are worked out here by hand (trapezoid ``t_a = v/a``, ``T = d/v + v/a``;
triangle ``t_a = √(d/a)``; the cubic's and quintic's coefficients and peaks) and compared
with an independent computation: the durations and joint velocities that
``robotconf.programs`` plans and samples for the same moves.
"""

from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest

import robotconf as rc
from robotconf.teaching import PROFILE_DIAGNOSES, PROFILE_FORMS

TRAPEZOID = rc.ProfileTask(2.0, speed=1.0, accel=2.0)  # t_a 0.5, T 2.5, v 1
TRIANGLE = rc.ProfileTask(0.125, speed=1.0, accel=2.0)  # d < v²/a = 0.5: t_a 0.25, T 0.5
QUINTIC = rc.ProfileTask(0.6, kind="quintic", duration=2.0, start=0.1)
CUBIC = rc.ProfileTask(0.6, kind="cubic", duration=2.0)
SYNC = rc.ProfileTask([0.5, -1.0, 1.5], speed=1.0, accel=2.0)  # alone: 1, 1.5, 2 s
# joint 1's speed limit and joint 2's acceleration limit both bind: V = 1, A = 2
MIXED = rc.ProfileTask([1.0, 1.0], speed=[1.0, 10.0], accel=[10.0, 2.0])


# -- the right numbers -------------------------------------------------------------------


def test_trapezoid_by_hand():
    assert TRAPEZOID.shape == "trapezoid"
    assert TRAPEZOID.expected().tolist() == [0.5, 2.5, 1.0]
    assert float(TRAPEZOID.expected("peak_accel")) == 2.0
    # d = 3, v = 1.5, a = 1: v²/a = 2.25 ≤ 3, t_a = 1.5 s, T = 2 + 1.5 s; backwards too
    task = rc.ProfileTask(-3.0, speed=1.5, accel=1.0)
    assert task.expected().tolist() == [1.5, 3.5, 1.5]
    # cruise at -1.5 rad/s from 1.5 s to 2 s, ramp down after
    velocity = task.velocity([0.0, 0.75, 1.5, 2.0, 2.75, 3.5, 4.0])
    assert velocity.tolist() == [0.0, -0.75, -1.5, -1.5, -0.75, 0.0, 0.0]


def test_triangle_by_hand():
    assert TRIANGLE.shape == "triangle"
    assert TRIANGLE.expected().tolist() == [0.25, 0.5, 0.5]  # √(d/a), 2√(d/a), √(d·a)
    # at d = v²/a both formulas agree: t_a = 0.5, T = 1, the peak just reaches v
    edge = rc.ProfileTask(0.5, speed=1.0, accel=2.0)
    assert edge.expected().tolist() == [0.5, 1.0, 1.0]


def test_polynomials_by_hand():
    # q = 0.1 + 0.6·(10τ³ − 15τ⁴ + 6τ⁵), τ = t/2
    assert QUINTIC.expected() == pytest.approx([0.1, 0, 0, 0.75, -0.5625, 0.1125], abs=1e-15)
    assert float(QUINTIC.expected("peak_speed")) == 15 / 8 * 0.6 / 2
    assert float(QUINTIC.expected("peak_accel")) == pytest.approx(10 / math.sqrt(3) * 0.6 / 4)
    assert CUBIC.expected() == pytest.approx([0, 0, 0.45, -0.15], abs=1e-15)  # 3d/T², −2d/T³
    assert float(CUBIC.expected("peak_speed")) == 1.5 * 0.6 / 2
    assert float(CUBIC.expected("peak_accel")) == 6 * 0.6 / 4
    # the coefficients' derivative is the velocity, and its maximum the peak
    t = np.linspace(0, 2, 2001)
    for task in (QUINTIC, CUBIC):
        derivative = np.polynomial.polynomial.polyval(
            t, np.polynomial.polynomial.polyder(task.expected())
        )
        assert np.allclose(derivative, task.velocity(t), atol=1e-12)
        assert task.velocity(t).max() == pytest.approx(float(task.expected("peak_speed")), rel=1e-6)
    # by limits: T = max(15d/(8v), √(10d/(√3·a)))
    by_limits = rc.ProfileTask(1.0, kind="quintic", speed=1.0, accel=1.0)
    assert by_limits.duration == pytest.approx(math.sqrt(10 / math.sqrt(3)))


def test_synchronized_by_hand():
    assert SYNC.own_durations.tolist() == [1.0, 1.5, 2.0]
    assert SYNC.duration == 2.0
    assert SYNC.peak_speed == pytest.approx([1 / 3, 2 / 3, 1.0])
    # alone 1 + 0.1 = 1.1 s and 2·√0.5 = 1.414 s; together V = 1, A = 2: 1 + 0.5 s
    assert MIXED.own_durations == pytest.approx([1.1, math.sqrt(2)])
    assert MIXED.duration == 1.5


@pytest.mark.parametrize("kind", ["trapezoidal", "quintic"])
def test_agrees_with_the_programs_planner(kind):
    """An independent computation: the PTP planner of robotconf.programs."""
    robot = rc.preset("paper")
    rng = np.random.default_rng(12)
    for _ in range(4):
        delta = rng.choice([-1.0, 1.0], 3) * rng.uniform(0.05, 1.2, 3)
        speed, accel = rng.uniform(0.3, 2.0, 3), rng.uniform(0.3, 4.0, 3)
        task = rc.ProfileTask(delta, kind=kind, speed=speed, accel=accel)
        program = rc.Program(
            robot, [rc.PTP(q=delta, profile=kind)], joint_speed=speed, joint_accel=accel
        )
        assert task.duration == pytest.approx(program.duration, rel=1e-12)
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the move must be clean
            motion = program.simulate(dt=0.01)
        assert np.allclose(task.velocity(motion.t), motion.qd, atol=1e-9)


# -- answers that pass --------------------------------------------------------------------


@pytest.mark.parametrize(
    ("task", "answer", "options"),
    [
        (TRAPEZOID, [0.5, 2.5, 1.0], {}),
        (TRAPEZOID, "[1/2, 2/1 + 1/2, 1]", {}),  # text, the formula typed in
        (TRAPEZOID, [[0.5], [2.5], [1.0]], {}),  # a column
        (TRAPEZOID, {"v_peak": 1, "t_total": "5/2", "t_accel": 0.5}, {}),
        (TRAPEZOID, [0.5004, 2.502, 1.0009], {}),  # within 0.1 %
        (TRIANGLE, "[sqrt(0.125/2), 2*sqrt(0.125/2), sqrt(0.125*2)]", {}),
        (QUINTIC, "15/8*0.6/2", {"form": "peak_speed"}),
        (CUBIC, [0, 0, 0.45, -0.15, 0, 0], {}),  # a4 = a5 = 0: the same polynomial
        (SYNC, 2.0, {}),
        (SYNC, [2.0, 2.0, 2.0], {}),  # the one duration, for every joint
        (SYNC, np.array([1, 2, 3]) / 3, {"form": "peak_speed"}),
        (TRAPEZOID, [0, 0.5, 1, 0.5, 0], {"form": "velocity", "times": [0, 0.25, 1, 2.25, 2.5]}),
    ],
)
def test_right_answers_pass(task, answer, options):
    result = rc.check_profile(answer, task, **options)
    assert result.ok, result
    assert result.diagnosis is None and result.hints == []


def test_a_velocity_table_passes_either_way_round():
    times = [0.0, 0.5, 1.0, 2.0]
    table = SYNC.expected("velocity", times)  # (4 times, 3 joints)
    assert table[1].tolist() == pytest.approx([1 / 3, -2 / 3, 1.0])
    assert rc.check_profile(table, SYNC, form="velocity", times=times).ok
    assert rc.check_profile(table.T, SYNC, form="velocity", times=times).ok


# -- slips, each named --------------------------------------------------------------------

VELOCITY = {"form": "velocity", "times": [0, 0.25, 1, 2.25, 2.5]}
SLIPS = [
    # (task, answer, options, diagnosis, words of the hint)
    (TRAPEZOID, [1.0, 3.0, 1.0], {}, "accel_time_factor", "twice too long"),  # 2v/a, T with it
    (TRAPEZOID, [1.0, 2.5, 1.0], {}, "accel_time_factor", "twice too long"),  # 2v/a alone
    (TRAPEZOID, [0.25, 2.25, 1.0], {}, "accel_time_factor", "half what it should be"),
    (TRAPEZOID, [0.5, 2.0, 1.0], {}, "ramps_forgotten", "jumped to full speed"),  # T = d/v
    (TRAPEZOID, [0.5, 2.25, 1.0], {}, "not_at_rest_end", "does not come to rest"),  # no ramp down
    # T = d/v + v/(2a): no ramp down, or t_a = v/(2a): both hints
    (TRAPEZOID, 2.25, {"form": "duration"}, "not_at_rest_end", "does not come to rest"),
    (TRAPEZOID, 2.25, {"form": "duration"}, "not_at_rest_end", "half what it should be"),
    (TRAPEZOID, [0, 0.5, 1, 1, 1], VELOCITY, "not_at_rest_end", "does not come back to zero"),
    (TRAPEZOID, [1, 1, 1, 0.5, 0], VELOCITY, "not_at_rest_start", "does not start at zero"),
    (
        TRAPEZOID,
        [0.5, 2.5, 1.2],
        {},
        "distance_not_covered",
        "covers v_peak·(t_total − t_accel) = 2.4",
    ),
    # the triangle from the acceleration limit alone: t_a = √(d/a) = 1, T = 2, peak √(d·a) = 2
    (TRAPEZOID, [1.0, 2.0, 2.0], {}, "one_limit", "from the acceleration limit alone"),
    # the average speed d/T = 2/2.5 for the peak, the times right
    (TRAPEZOID, [0.5, 2.5, 0.8], {}, "average_speed", "That is the average speed d/T"),
    # the trapezoid formulas on a triangle: t_a = v/a, T = d/v + v/a, v_peak = v
    (TRIANGLE, [0.5, 0.625, 1.0], {}, "triangle_as_trapezoid", "the profile is a triangle"),
    (TRIANGLE, [0.25, 0.5, 1.0], {}, "triangle_as_trapezoid", "the profile is a triangle"),
    (TRIANGLE, 1.0, {"form": "peak_speed"}, "triangle_as_trapezoid", "is a triangle"),
    # d = ½·a·t_a² over the whole distance: t_a = √(2d/a)
    (
        TRIANGLE,
        [0.25 * 2**0.5, 0.5 * 2**0.5, 0.5 * 2**0.5],
        {},
        "accel_time_factor",
        "half the distance",
    ),
    (SYNC, [1.0, 1.5, 2.0], {}, "not_synchronized", "Each joint got its own duration"),
    (SYNC, 1.5, {}, "not_synchronized", "duration of q2 moving alone"),
    (SYNC, 1.0, {}, "not_synchronized", "duration of q1 moving alone"),
    (SYNC, [1.0, 1.0, 1.0], {"form": "peak_speed"}, "not_synchronized", "its own profile"),
    (MIXED, math.sqrt(2), {}, "mixed_limits", "both bind"),
    # the largest move (q1: 1.2/1.5 + 1.5/3 = 1.3 s) is not the slowest (q2: 1.467 s)
    (
        rc.ProfileTask([1.2, 0.8], speed=[1.5, 1.0], accel=[3.0, 1.5]),
        1.3,
        {"form": "duration"},
        "largest_move",
        "largest",
    ),
    (QUINTIC, [0.1, 0, 0.45, -0.15], {}, "cubic_quintic_swapped", "These are the cubic's numbers"),
    (CUBIC, [0, 0, 0, 0.75, -0.5625, 0.1125], {}, "cubic_quintic_swapped", "the quintic's numbers"),
    (QUINTIC, 1.5 * 0.3, {"form": "peak_speed"}, "cubic_quintic_swapped", "cubic's numbers"),
    (CUBIC, 10 / math.sqrt(3) * 0.15, {"form": "peak_accel"}, "cubic_quintic_swapped", "quintic"),
    (QUINTIC, 0.3, {"form": "peak_speed"}, "average_speed", "the average speed d/T"),
    # 15/8·d: the peak of dq/dτ, not divided by T = 2 (the right peak is 15/8·0.6/2)
    (QUINTIC, 15 / 8 * 0.6, {"form": "peak_speed"}, "normalized_time", "divided by T"),
    (QUINTIC, [0.1, 0, 0, 6, -9, 3.6], {}, "normalized_time", "in τ = t/T"),
    (QUINTIC, [0.1125, -0.5625, 0.75, 0, 0, 0.1], {}, "descending_order", "reverse order"),
    # the speed limit alone gives 15/8 s; the acceleration limit asks for longer
    (
        rc.ProfileTask(1.0, kind="quintic", speed=1.0, accel=1.0),
        15 / 8,
        {"form": "duration"},
        "one_limit",
        "Both limits must hold",
    ),
]


@pytest.mark.parametrize(("task", "answer", "options", "code", "words"), SLIPS)
def test_each_slip_is_named(task, answer, options, code, words):
    result = rc.check_profile(answer, task, **options)
    assert not result.ok
    assert result.diagnosis == code, result
    assert words in " ".join(result.hints), result.hints
    assert code in PROFILE_DIAGNOSES


def test_hints_keep_the_answer_unless_revealed():
    for task, answer, options, _, _ in SLIPS:
        right = np.atleast_1d(task.expected(options.get("form"), options.get("times")))
        text = " ".join(rc.check_profile(answer, task, **options).hints)
        quoted = [f"{x:.4g}" for x in right if x != 0 and f"{x:.4g}" not in str(answer)]
        found = [q for q in quoted if re.search(rf"(?<![\w.]){re.escape(q)}(?![\w.])", text)]
        assert not found, (text, found)
    shown = rc.check_profile([1.0, 3.0, 1.0], TRAPEZOID, reveal=True)
    assert "[0.5, 2.5, 1]" in shown.hints[0]


def test_plain_slips_of_numbers_still_named():
    assert rc.check_profile([0.5, 2.5, -1.0], TRAPEZOID).diagnosis == "sign_error"
    assert rc.check_profile(2500, TRAPEZOID, form="duration").diagnosis == "unit_factor"
    assert rc.check_profile([0.5, 2.5, 1.0, 0.0], TRAPEZOID).diagnosis == "shape"
    result = rc.check_profile([2.0, 2.0], SYNC)
    assert result.diagnosis == "shape" and "one number" in result.hints[0]


def test_blank_and_symbolic_answers_fail_kindly():
    blank = rc.check_profile(None, TRAPEZOID)
    assert blank.diagnosis == "no_answer" and "replace None" in blank.hints[0]
    symbolic = rc.check_profile("[q1/2, 2.5, 1]", TRAPEZOID)
    assert symbolic.diagnosis == "not_a_number" and "q1" in symbolic.hints[0]
    keys = rc.check_profile({"t_a": 0.5, "T": 2.5, "v": 1.0}, TRAPEZOID)
    assert keys.diagnosis == "shape" and "t_accel, t_total, v_peak" in keys.hints[0]


def test_assert_profile_raises_the_verdict():
    assert rc.assert_profile("[0.5, 2.5, 1]", TRAPEZOID).ok
    with pytest.raises(
        AssertionError, match="the trapezoid: not right yet.\n- The acceleration time"
    ):
        rc.assert_profile([1.0, 3.0, 1.0], TRAPEZOID)
    with pytest.raises(AssertionError, match="exercise hint"):
        rc.assert_profile(3.0, SYNC, hint="exercise hint")


# -- refused ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "answer",
    [
        float("nan"),
        [0.5, float("inf"), 1.0],
        [0.5, 2.5, 1j],
        "[0.5, 2.5, sqrt(-1)]",
        "[0.5, 2.5, 1e400]",
        "[0.5, 2.5, 10**400]",
        "1e308*1e308",
        "__import__('os').system('true')",
        {"t_accel": float("nan"), "t_total": 2.5, "v_peak": 1.0},
    ],
)
def test_nan_huge_imaginary_and_code_are_refused(answer):
    with pytest.raises(rc.InvalidInputError):
        rc.check_profile(answer, TRAPEZOID)


@pytest.mark.parametrize(
    ("arguments", "field"),
    [
        ({"distance": 0.0, "speed": 1, "accel": 1}, "distance"),
        ({"distance": float("nan"), "speed": 1, "accel": 1}, "distance"),
        ({"distance": "1", "speed": 1, "accel": 1}, "distance"),
        ({"distance": 1, "speed": -1, "accel": 1}, "speed"),
        ({"distance": 1, "speed": 1}, "accel"),
        ({"distance": 1, "speed": 1, "accel": 1, "duration": 2}, "duration"),
        ({"distance": 1, "kind": "quintic"}, "duration"),
        ({"distance": 1, "kind": "linear", "speed": 1, "accel": 1}, "kind"),
        ({"distance": [1, 2], "speed": [1, 2, 3], "accel": 1}, "speed"),
        ({"distance": 1e300, "speed": 1e-300, "accel": 1e-300}, "distance"),
        ({"distance": 1, "kind": "quintic", "duration": 1e-200}, "duration"),
    ],
)
def test_bad_tasks_are_refused(arguments, field):
    distance = arguments.pop("distance")
    with pytest.raises(rc.InvalidInputError) as error:
        rc.ProfileTask(distance, **arguments)
    assert error.value.field == field


def test_bad_forms_and_options_are_refused():
    for call, field in (
        (lambda: rc.check_profile(1.0, TRAPEZOID, form="coefficients"), "form"),
        (lambda: rc.check_profile(1.0, TRAPEZOID, form="velocity"), "times"),
        (lambda: rc.check_profile(1.0, TRAPEZOID, times=[0, 1]), "times"),
        (lambda: rc.check_profile(1.0, [0.5, 2.5, 1.0]), "expected"),
        (lambda: rc.check_profile(1.0, TRAPEZOID, tol=-1), "tol"),
        (lambda: rc.check_profile({"t_total": 1}, SYNC), "answer"),
    ):
        with pytest.raises(rc.InvalidInputError) as error:
            call()
        assert error.value.field == field
    assert set(TRAPEZOID.forms()) <= set(PROFILE_FORMS)


def test_a_single_slip_outranks_the_distance_it_misses():
    """d = 1, v = 0.7, a = 1.3: by hand t_a = v/a = 0.5385 s, T = d/v + v/a = 1.967 s.
    [0.54, 2.0, 0.7] keeps two digits of T: 0.7·(2.0 − 0.54) = 1.022 ≠ 1, a distance
    missed because of the rounding alone. Swapped times cover a negative distance."""
    task = rc.ProfileTask(1.0, speed=0.7, accel=1.3)
    assert np.allclose(task.expected(), [0.7 / 1.3, 1 / 0.7 + 0.7 / 1.3, 0.7])
    rounded = rc.check_profile([0.54, 2.0, 0.7], task)
    assert rounded.diagnosis == "too_rounded" and rounded.complete
    assert "rounded too much" in rounded.hints[0] and "covers" in rounded.hints[1]
    swapped = rc.check_profile([1.967, 0.5385, 0.7], task)
    assert swapped.diagnosis == "swapped_components" and "swapped" in swapped.hints[0]
    assert "covers v_peak·(t_total − t_accel) = -1" in swapped.hints[1]
    # numbers no single slip explains: the distance they miss is the diagnosis
    apart = rc.check_profile([0.5385, 1.8, 0.7], task)
    assert apart.diagnosis == "distance_not_covered" and not apart.complete
