"""Overflow, tiny durations, memory budgets and slow parsing: refused early, by name.

Finite inputs whose results would leave the float range end in an
``rc.InvalidInputError`` naming the input responsible, never in inf, NaN or a
``ZeroDivisionError``; sizes are checked against the memory budget before anything is
allocated; text parsing takes linear time. Risky cases run in a child process under a
hard time limit and an address-space limit, so a regression fails instead of hanging or
exhausting the machine.
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
import tracemalloc

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals as sg
from robotconf.kinematics import MAX_MODULES, MAX_PARAMETER, kernel_bytes, workspace_bytes

# -- running a risky call in a child ---------------------------------------------------

_CHILD = """
import json, resource, sys, time
import numpy as np
import robotconf as rc
from robotconf import signals as sg

# Address space already mapped (numpy, robotconf) plus what the case may add.
with open("/proc/self/statm", encoding="ascii") as statm:
    mapped = int(statm.read().split()[0]) * resource.getpagesize()
limit = mapped + {extra}
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
{setup}
start = time.perf_counter()
try:
    result = ({call})
except rc.InvalidInputError as error:
    out = {{"kind": "refused", "field": error.field, "message": str(error)}}
except BaseException as error:
    out = {{"kind": "raised", "type": type(error).__name__, "message": str(error)[:500]}}
else:
    out = {{"kind": "returned", "value": repr(result)[:500]}}
out["seconds"] = time.perf_counter() - start
print(json.dumps(out))
"""


def in_child(call: str, *, setup: str = "", seconds: float = 20.0, extra_mb: int = 1024) -> dict:
    """Run the expression ``call`` in a fresh Python with limits; return what happened."""
    code = _CHILD.format(call=call, setup=textwrap.dedent(setup), extra=extra_mb * 1024**2)
    # The code goes in on stdin: a megabyte of text is too long for one argument.
    done = subprocess.run(
        [sys.executable, "-"], input=code, capture_output=True, text=True, timeout=seconds
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def assert_refused(outcome: dict, field: str, words: str = "") -> None:
    assert outcome["kind"] == "refused", outcome
    assert field in outcome["field"], outcome
    assert words in outcome["message"], outcome


# -- robots: bounded constants ---------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: rc.Module("Tx", a=(1e308, 0, 0)), "a"),
        (lambda: rc.Module("Tz", q=-1e151), "q"),
        (lambda: rc.Module("Tz", limits=(-1e200, 0)), "limits[0]"),
        (lambda: rc.DHLink(a=2e150), "a"),
        (lambda: rc.DHLink(theta=1e300), "theta"),
        (lambda: rc.Robot.from_dh([(0, 1e308, 1e308, 0, "R")]), "rows[0].d"),
        (lambda: rc.Robot([rc.Module("Rz")], end_effector=(0, 0, 1e200)), "end_effector"),
        (lambda: rc.preset("paper").with_q([1e200, 0, 0]), "modules[0].q"),
        (lambda: rc.Robot([rc.Module("Rz")] * (MAX_MODULES + 1)), "modules"),
        (lambda: rc.workspace(rc.Robot([rc.Module("Tx")]), 10, ranges=[(0, 1e200)]), "ranges"),
    ],
)
def test_constants_beyond_the_bound_are_refused_at_construction(call, field):
    with pytest.raises(rc.InvalidInputError, match=r"too (large|many)") as caught:
        call()
    assert caught.value.field == field


def test_the_examples_that_once_overflowed_are_refused_by_name():
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Robot([rc.Module("Tx", a=(1e308, 0, 0)), rc.Module("Tx", a=(1e308, 0, 0))])
    assert caught.value.field == "a"
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Robot.from_dh([(0, 1e308, 1e308, 0, "R"), (0, 1e308, 1e308, 0, "R")])
    assert caught.value.field == "rows[0].d"


def test_the_longest_chain_at_the_bound_stays_finite_and_exact():
    robot = rc.Robot(
        [rc.Module("Tx", a=(MAX_PARAMETER, MAX_PARAMETER, -MAX_PARAMETER))] * MAX_MODULES,
        end_effector=(MAX_PARAMETER, 0, 0),
    )
    q = np.full(MAX_MODULES, MAX_PARAMETER)
    ee = robot.end_effector(q)
    assert ee == pytest.approx([(2 * MAX_MODULES + 1) * 1e150, 64e150, -64e150], rel=1e-12)
    assert np.isfinite(robot.frame_poses(q)).all()
    assert np.isfinite(robot.jacobian(q)).all()
    assert rc.characteristic_length(robot) == pytest.approx((64 * 3**0.5 + 1) * 1e150)
    lo, hi = robot.joint_limits()[0]
    assert np.isfinite([lo, hi]).all() and hi > 0
    # Revolute rows with the largest angles: θ + q stays finite for any finite q.
    arm = rc.Robot.from_dh([(MAX_PARAMETER, 0, 1, 0, "R")])
    assert np.isfinite(arm.end_effector([1.7e308])).all()


# -- robots: run-time coordinates ------------------------------------------------------


def two_slides() -> rc.Robot:
    return rc.Robot([rc.Module("Tx"), rc.Module("Tx")], end_effector=(1, 0, 0))


@pytest.mark.parametrize(
    "method", ["frame_poses", "frame_origins", "end_effector", "end_effector_pose"]
)
def test_prismatic_coordinates_that_overflow_are_named(method):
    q = np.zeros((5000, 2))
    q[4321] = (1e308, 1e308)  # the second slide pushes x past 1.8e308
    with pytest.raises(rc.InvalidInputError) as caught:
        getattr(two_slides(), method)(q)
    assert caught.value.field == "q[1]"
    assert caught.value.value == 1e308
    assert "sample 4321" in str(caught.value)


def test_overflow_in_a_later_link_after_a_turn_names_that_link():
    robot = rc.Robot([rc.Module("Ty"), rc.Module("Rz"), rc.Module("Ty"), rc.Module("Rz")])
    with pytest.raises(rc.InvalidInputError) as caught:
        robot.frame_origins([1.2e308, 0.0, 1.2e308, 0.0])
    assert caught.value.field == "q[2]"
    # Turned half way round, the second slide comes back: finite and right.
    origins = robot.frame_origins([1.2e308, np.pi, 1.2e308, 0.0])
    assert np.isfinite(origins).all()
    assert abs(origins[-1, 1]) < 1e293  # 1.2e308 − 1.2e308 up to cos(π) rounding


def test_a_single_link_of_robotconf_cannot_overflow():
    # |a| ≤ 1e150 is below the float spacing near 1e308: a + q never rounds past the top.
    slide = rc.Module("Tx", a=(MAX_PARAMETER, 0, 0))
    assert slide.matrix(1.7976931348623157e308)[0, 3] == 1.7976931348623157e308
    matrices = rc.Robot([slide]).transfer_matrices([[1.7e308], [-1.7e308]])
    assert np.isfinite(matrices).all()


def test_the_kernel_names_the_coordinate_of_hand_made_links():
    from robotconf.kinematics import LinkGeometry, chain_point, link_matrices

    far = LinkGeometry(pre_translation=np.array([1e308, 0.0, 0.0]), axis=0, joint="P")
    with pytest.raises(rc.InvalidInputError) as caught:
        link_matrices([far], np.array([[0.0], [1e308]]))
    assert caught.value.field == "q[0]" and "sample 1" in str(caught.value)
    fixed = LinkGeometry(pre_translation=np.array([1e308, 0.0, 0.0]))
    with pytest.raises(rc.InvalidInputError) as caught:
        chain_point([fixed], np.zeros((1, 1)), np.array([1e308, 0.0, 0.0]))
    assert caught.value.field == "point"
    with pytest.raises(rc.InvalidInputError) as caught:
        chain_point([fixed, fixed], np.zeros((1, 2)), np.zeros(3), fields=["a", "b"])
    assert caught.value.field == "links[1]"


def test_the_jacobian_refuses_lever_arms_that_overflow():
    robot = rc.Robot([rc.Module("Tx"), rc.Module("Rz"), rc.Module("Tx"), rc.Module("Tx")])
    # Frames at x = 1e308, 0, −1e308 are finite, but the lever p_EE − o_1 = −2e308 is not.
    with pytest.raises(rc.InvalidInputError, match="Jacobian") as caught:
        robot.jacobian([1e308, np.pi, 1e308, 1e308])
    assert caught.value.field == "q"
    jac = robot.jacobian([1e308, np.pi, 1e308, 0.0])
    assert jac[1, 1] == pytest.approx(-1e308)  # z × (−1e308, 0, 0) = (0, −1e308, 0)


def test_huge_but_harmless_coordinates_give_the_right_numbers():
    paper = rc.preset("paper")
    ee = paper.end_effector([1e300, 0, 0])
    assert np.hypot(ee[0], ee[1]) == pytest.approx(70.0) and ee[2] == pytest.approx(20.0)
    slide = rc.Robot([rc.Module("Tx", a=(1, 0, 0))], end_effector=(0, 2, 0))
    np.testing.assert_array_equal(slide.end_effector([1e308]), [1e308, 2.0, 0.0])


def test_no_numpy_warning_comes_before_the_error(recwarn):
    with pytest.raises(rc.InvalidInputError):
        two_slides().end_effector([1e308, 1e308])
    assert not [w for w in recwarn if issubclass(w.category, RuntimeWarning)]


# -- URDF ------------------------------------------------------------------------------


def test_urdf_never_writes_inf_or_nan():
    robot = rc.Robot(
        [rc.Module("Tx", a=(MAX_PARAMETER, 0, 0)), rc.Module("Tz", limits=(-1e150, 1e150))],
        end_effector=(1e150, 0, 0),
    )
    text = rc.to_urdf(robot, scale=1e150)
    assert "inf" not in text.lower() and "nan" not in text.lower()
    assert f'xyz="{1e150 * 1e150!r} 0 0"' in text
    with pytest.raises(rc.InvalidInputError, match="scaled lengths") as caught:
        rc.to_urdf(robot, scale=1e200)
    assert caught.value.field == "scale"


# -- signals ---------------------------------------------------------------------------


@pytest.mark.parametrize("cls", [sg.Cubic, sg.Quintic, sg.Trapezoidal])
@pytest.mark.parametrize("duration", [5e-324, 1e-300, 9.9e-10])
def test_durations_below_the_minimum_are_refused(cls, duration):
    with pytest.raises(rc.InvalidInputError, match="too short") as caught:
        cls(duration=duration)
    assert caught.value.field == "duration"


@pytest.mark.parametrize(
    ("cls", "duration", "peak"),
    [
        (sg.Cubic, sg.MIN_DURATION, 1.5),
        (sg.Quintic, sg.MIN_DURATION, 1.875),
        # The trapezoid's blend (a quarter of the duration by default) is a duration too.
        (sg.Trapezoidal, 4 * sg.MIN_DURATION, 4 / 3),
    ],
)
def test_the_shortest_duration_gives_finite_exact_derivatives(cls, duration, peak):
    move = cls(start=0.0, end=1.0, duration=duration)
    t = np.linspace(-duration, 2 * duration, 301)
    for values in (move.value(t), move.velocity(t), move.acceleration(t)):
        assert np.isfinite(values).all()
    assert move.value(duration) == 1.0
    assert move.velocity(duration / 2) == pytest.approx(peak / duration)
    if cls is sg.Trapezoidal:
        with pytest.raises(rc.InvalidInputError, match="blend") as caught:
            cls(duration=sg.MIN_DURATION)
        assert caught.value.field == "accel_fraction"


def test_a_distance_too_far_for_the_duration_is_refused():
    with pytest.raises(rc.InvalidInputError, match="too short for the distance") as caught:
        sg.Quintic(end=1e300, duration=1e-9)
    assert caught.value.field == "duration"
    with pytest.raises(rc.InvalidInputError, match="overflows") as caught:
        sg.Cubic(start=-1e308, end=1e308)
    assert caught.value.field == "end"
    with pytest.raises(rc.InvalidInputError, match="blend") as caught:
        sg.Trapezoidal(duration=1.0, accel_fraction=1e-300)
    assert caught.value.field == "accel_fraction"


def test_a_sine_whose_derivatives_overflow_is_refused_with_the_highest_frequency():
    with pytest.raises(rc.InvalidInputError, match="159 Hz") as caught:
        sg.Sine(amplitude=1e300, frequency=1e10)
    assert caught.value.field == "frequency"
    fast = sg.Sine(amplitude=1.0, frequency=1.5e152)  # just inside: A·ω² < 1e306
    assert np.isfinite(fast.acceleration([0.1, 0.2])).all()
    with pytest.raises(rc.InvalidInputError) as caught:
        sg.Sine(amplitude=1e308, bias=1e308, frequency=0.0)
    assert caught.value.field == "bias"


@pytest.mark.parametrize(
    ("call", "field", "words"),
    [
        (lambda: sg.Ramp(slope=1e308).value([0.0, 1e10]), "slope", "t = 10000000000.0 s"),
        (lambda: sg.Ramp(slope=2.0).value(1e308), "t", "values of Ramp"),
        (lambda: sg.Sine(frequency=1e150).value([1e300]), "frequency", "values of Sine"),
        (lambda: (sg.Ramp(slope=1e308) * 10).velocity([1.0]), "scale", "velocities"),
        (lambda: (sg.Ramp(slope=1e308) + sg.Ramp(slope=1e308)).value([1.0]), "terms", "Sum"),
        (lambda: (sg.Ramp(slope=1e300) * 2 + 1).value([1e10]), "slope", "values of Affine"),
    ],
)
def test_overflow_at_evaluation_names_the_parameter(call, field, words):
    with pytest.raises(rc.InvalidInputError, match="overflow") as caught:
        call()
    assert caught.value.field == field
    assert words in str(caught.value)


def test_the_reported_overflow_example_is_refused():
    with pytest.raises(rc.InvalidInputError) as caught:
        sg.Sine(amplitude=1e300, frequency=1e10).acceleration([0.1])
    assert caught.value.field == "frequency"
    with pytest.raises(rc.InvalidInputError) as caught:
        sg.Ramp(slope=1e308).value([1e10])
    assert caught.value.field == "slope"


@pytest.mark.parametrize(
    ("times", "values", "field", "words"),
    [
        ([0, 1e-10], [0, 1], "times", "too short"),
        ([0, 5e-324], [0, 1], "times", "too short"),
        ([0, 1e-9, 1], [-1e308, 1e308, 0], "values", "slope from values[0] to values[1]"),
        ([0, 1e-300, 1], [0, 1e10, 0], "values", "overflows"),
        (np.arange(10_001.0), np.zeros(10_001), "times", "too long"),
    ],
)
def test_repeating_tables_that_would_misbehave_are_refused(times, values, field, words):
    with pytest.raises(
        rc.InvalidInputError, match=words.replace("[", r"\[").replace("]", r"\]")
    ) as caught:
        sg.RepeatingSequence(times=times, values=values)
    assert caught.value.field == field


def test_repeating_tables_at_the_limits_work():
    saw = sg.RepeatingSequence(times=[0, 1e-9], values=[0, 1])
    assert saw.value(0.5e-9) == pytest.approx(0.5)
    assert saw.velocity(0.25e-9) == pytest.approx(1e9)
    long = sg.RepeatingSequence(times=np.arange(10_000.0), values=np.arange(10_000.0) % 2)
    assert long.value(2.5) == 0.5 and long.period == 9999.0


# -- kinks: counted cheaply, listed within the budget ----------------------------------


def test_kink_count_is_cheap_and_matches_kinks_up_to_rounding_at_the_ends():
    saw = sg.RepeatingSequence(times=[0, 2], values=[0, 2])
    triangle = sg.RepeatingSequence(times=[0, 1, 2], values=[0, 1, 0])
    signals = [
        saw,
        triangle,
        saw * 0.5 + 1,
        saw * 0.0,
        sg.Step(step_time=1.5),
        sg.Ramp(start_time=-3.0),
        sg.Sine(),
        sg.Cubic(duration=3.0),
        saw + sg.Step(step_time=3.0),
    ]
    rng = np.random.default_rng(7)
    for signal in signals:
        # Kink times k·2 + 1 are exact in binary: the count is exact too.
        for _ in range(20):
            t0, t1 = np.sort(rng.uniform(-20, 20, 2))
            assert signal.kink_count(t0, t1) == len(signal.kinks(t0, t1)), (signal, t0, t1)
        assert signal.kink_count(0.0, 10.0) == len(signal.kinks(0.0, 10.0))
        assert signal.kink_count(5.0, 1.0) == 0
    # With a period such as 0.001 (not exact in binary) rounding decides each end.
    milli = sg.RepeatingSequence(times=[0, 1e-3], values=[0, 1])
    for t0, t1 in [(0.0, 10.0), (0.0005, 3.0), (-1.0, 1.0)]:
        assert abs(milli.kink_count(t0, t1) - len(milli.kinks(t0, t1))) <= 2
    assert saw.kink_count(0.0, 10.0) == 6
    assert triangle.kink_count(0.0, 10.0) == 11
    fine = sg.RepeatingSequence(times=[0, 1e-9], values=[0, 1])
    assert fine.kink_count(0.0, 10.0) == 10**10  # the float 1e-9 is a hair above 1e-9 s
    assert fine.kink_count(-1e308, 1e308) > 10**316


def test_kinks_too_far_from_zero_for_the_period_are_refused():
    fine = sg.RepeatingSequence(times=[0, 1e-9], values=[0, 1])
    with pytest.raises(rc.InvalidInputError, match="t / period overflows") as caught:
        fine.kinks(1e300, 1e301)
    assert caught.value.field == "period"


def test_kinks_of_a_nanosecond_period_are_refused_before_allocating():
    outcome = in_child(
        "sg.RepeatingSequence(times=[0, 1e-9], values=[0, 1]).kinks(0.0, 10.0)",
        seconds=20,
        extra_mb=512,
    )
    assert_refused(outcome, "period", "of memory")
    assert outcome["seconds"] < 1.0


def test_kinks_within_the_budget_are_listed():
    saw = sg.RepeatingSequence(times=[0, 1e-3], values=[0, 1])
    kinks = saw.kinks(0.0, 10.0)
    assert kinks.size == 10_001
    np.testing.assert_allclose(kinks, np.arange(10_001) * 1e-3, rtol=0, atol=1e-12)
    rc.set_memory_budget(1)
    try:
        saw.kinks(0.0, 10.0)  # 400 kB: below what is always allowed
        with pytest.raises(rc.InvalidInputError, match="of memory") as caught:
            saw.kinks(0.0, 1e4)  # 10⁷ kinks, 400 MB
        assert caught.value.field == "period"
    finally:
        rc.set_memory_budget(None)


# -- the spec parser takes linear time -------------------------------------------------


@pytest.mark.parametrize(
    "spec",
    [
        "q3=sine:amplitude=" + "1" * 9_980,
        "q3=sine:amplitude=" + "1" * 9_900 + "x",
        "q3=sine:phase=" + "2" * 5_000 + "*pi",
        "q3=sine:phase=" + "2" * 4_000 + "e" + "1" * 4_000 + "pi/" + "3" * 1_000,
        "q3=sine:amplitude=" + "1." * 500_000,
        "q3=repeating:times=" + ",".join(["1" * 30] * 300),
    ],
    ids=["10^4 digits", "10^4 digits then x", "pi factor", "exponent and divisor", "10^6", "items"],
)
def test_long_specs_are_refused_in_linear_time(spec):
    outcome = in_child(f"sg.parse_signal_spec({spec!r})", seconds=10, extra_mb=256)
    assert_refused(outcome, "signal")
    assert outcome["seconds"] < 0.5
    assert len(outcome["message"]) < 600


def test_parse_signal_alone_refuses_text_of_a_million_characters():
    outcome = in_child("sg.parse_signal('sine:amplitude=' + '1' * 1_000_000)", seconds=10)
    assert_refused(outcome, "signal", "longer than 10000 characters")
    assert outcome["seconds"] < 0.5


def test_a_long_valid_spec_parses_fast_and_right():
    times = ",".join(str(k) for k in range(1500))
    values = ",".join(str(k % 2) for k in range(1500))
    spec = f"q2=repeating:times={times};values={values}"
    assert len(spec) <= sg.MAX_SPEC_LENGTH
    name, signal = sg.parse_signal_spec(spec)
    assert name == "q2" and signal.period == 1499.0
    assert signal.value([0.5, 1.25]) == pytest.approx([0.5, 0.75])


@pytest.mark.parametrize("number", ["١٢", "1_000", "0x10", "1e", "pi" * 3, "infinity", "1e999"])
def test_numbers_outside_the_ascii_grammar_are_refused(number):
    with pytest.raises(rc.InvalidInputError) as caught:
        sg.parse_signal_spec(f"q1=constant:{number}")
    assert caught.value.field == "signal"


def test_numbers_within_the_grammar_still_parse():
    for text, value in [("-2*pi", -2 * np.pi), ("0.5pi", 0.5 * np.pi), ("pi / 4", np.pi / 4)]:
        assert sg.parse_signal(f"constant:{text}").level == pytest.approx(value)
    assert sg.parse_signal("constant:-1.5e-3").level == -1.5e-3
    assert sg.parse_signal("constant:." + "5" * 38).level == pytest.approx(5 / 9)


# -- memory budgets --------------------------------------------------------------------


def test_frame_poses_over_the_budget_are_refused_before_allocating():
    outcome = in_child(
        "rc.preset('paper').frame_poses(np.zeros((10_000_000, 3)))",
        setup="rc.set_memory_budget('256M')",
        extra_mb=768,  # the input takes 240 MB; the 3.8 GB result could never be mapped
    )
    assert_refused(outcome, "q", "of memory")
    assert "shape (10000000, 3)" in outcome["message"]


def test_workspace_over_the_budget_is_refused_before_allocating():
    outcome = in_child(
        "rc.workspace(rc.preset('paper'), samples=50_000_000)",
        setup="rc.set_memory_budget('256M')",
        extra_mb=256,
    )
    assert_refused(outcome, "samples", "of memory")


def test_the_jacobian_over_the_budget_is_refused():
    rc.set_memory_budget("64M")
    try:
        with pytest.raises(rc.InvalidInputError, match="of memory") as caught:
            rc.preset("paper").jacobian(np.zeros((1_000_000, 3)))
        assert caught.value.field == "q"
    finally:
        rc.set_memory_budget(None)


def _peak(call) -> int:
    tracemalloc.start()
    try:
        call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("samples", [1, 1_000, 50_000])
def test_kernel_estimates_are_never_below_the_measured_peak(samples):
    robot = rc.Robot(
        [rc.Module("Rz", a=(0, 0, 1)), rc.Module("Ty", a=(1, 0, 0)), rc.Module("Rx")]
        + [rc.Module("Ry", a=(0.5, 0, 0))] * 3,
        end_effector=(0.1, 0, 0),
    )
    n = robot.n
    q = np.random.default_rng(1).uniform(-1, 1, (samples, n))
    for method, floats in [
        ("frame_poses", 16 * n),
        ("transfer_matrices", 16 * n),
        ("frame_origins", 3 * n),
        ("end_effector", 3),
        ("end_effector_pose", 16),
    ]:
        peak = _peak(lambda method=method: getattr(robot, method)(q))
        assert kernel_bytes(samples, n, floats) >= peak, method
    assert kernel_bytes(samples, n, 40 * n + 30) >= _peak(lambda: robot.jacobian(q))
    for method in ("random", "grid"):
        run = lambda method=method: rc.workspace(robot, max(samples, 64), method=method, seed=2)  # noqa: E731
        assert workspace_bytes(max(samples, 64), n) >= _peak(run)


def test_estimates_follow_the_result_size():
    # All poses of 10⁶ samples of 6 links: 768 MB of result, under 1 % on top.
    assert 768e6 <= kernel_bytes(1_000_000, 6, 96) <= 768e6 * 1.02
    assert workspace_bytes(10**6, 6) == pytest.approx(72e6, rel=0.11)
