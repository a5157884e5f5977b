"""Signals: exact values, derivatives against finite differences, arithmetic, validation."""

from __future__ import annotations

import numpy as np
import pytest

from robotconf.signals import (
    Affine,
    Constant,
    Cubic,
    Quintic,
    Ramp,
    RepeatingSequence,
    Signal,
    Sine,
    Step,
    Sum,
    Trapezoidal,
)

SIGNALS = [
    Constant(0.7),
    Step(step_time=0.5, initial=1.0, final=-2.0),
    Ramp(slope=-1.5, start_time=0.3, initial_output=0.2),
    Sine(amplitude=2.0, bias=0.5, frequency=0.7, phase=0.3),
    RepeatingSequence(),
    RepeatingSequence(times=[0, 0.4, 1.0, 1.3], values=[0, 1, -0.5, 0.2]),
    Cubic(start=1.0, end=-2.0, duration=1.5, start_time=0.2),
    Quintic(start=0.0, end=3.0, duration=2.0, start_time=-0.5),
    Trapezoidal(start=0.5, end=2.5, duration=1.2, start_time=0.1, accel_fraction=0.3),
    Trapezoidal(start=1.0, end=-1.0, duration=2.0, accel_fraction=0.5),
    RepeatingSequence() * 0.5 + 1,
    Sine(frequency=0.3) + Ramp(slope=0.5) - Cubic(end=2.0, duration=3.0),
]


def _kink_free_times(signal: Signal, h: float) -> np.ndarray:
    """Times in [-1, 4] at least 3h away from any instant where a derivative jumps."""
    t = np.linspace(-1.0, 4.0, 2001)
    corners = [signal.kinks(-2.0, 5.0)]
    for part in signal.terms if isinstance(signal, Sum) else (signal,):
        base = part.base if isinstance(part, Affine) else part
        if isinstance(base, Cubic | Quintic | Trapezoidal):
            tb = getattr(base, "accel_fraction", 0.0) * base.duration
            corners.append(
                np.array([base.start_time, base.start_time + tb, base.end_time - tb, base.end_time])
            )
    corners_all = np.concatenate(corners)
    if corners_all.size == 0:
        return t
    distance = np.min(np.abs(t[:, None] - corners_all[None, :]), axis=1)
    return t[distance > 3 * h]


@pytest.mark.parametrize("signal", SIGNALS, ids=repr)
def test_derivatives_match_finite_differences(signal: Signal) -> None:
    h = 1e-5
    t = _kink_free_times(signal, h)
    assert t.size > 1500
    fd_v = (signal.value(t + h) - signal.value(t - h)) / (2 * h)
    fd_a = (signal.velocity(t + h) - signal.velocity(t - h)) / (2 * h)
    np.testing.assert_allclose(signal.velocity(t), fd_v, rtol=0, atol=1e-6)
    np.testing.assert_allclose(signal.acceleration(t), fd_a, rtol=0, atol=1e-5)


@pytest.mark.parametrize("signal", SIGNALS, ids=repr)
def test_shapes_scalars_and_repr_round_trip(signal: Signal) -> None:
    t = np.linspace(0, 3, 7)
    for method in (signal.value, signal.velocity, signal.acceleration):
        assert method(t).shape == (7,)
        assert isinstance(method(1.0), float)
        assert method(1.0) == method(t)[2]  # t[2] == 1.0
    namespace = {c.__name__: c for c in (Constant, Cubic, Quintic, Ramp, RepeatingSequence)}
    namespace.update({c.__name__: c for c in (Sine, Step, Trapezoidal)})
    rebuilt = eval(repr(signal), namespace)  # repr is readable Python
    np.testing.assert_allclose(rebuilt.value(t), signal.value(t))
    assert signal(1.0) == signal.value(1.0)


def test_sawtooth_is_simulinks_default() -> None:
    saw = RepeatingSequence()
    assert saw.times == (0.0, 2.0) and saw.values == (0.0, 2.0) and saw.period == 2.0
    t = np.array([0.0, 0.5, 1.999, 2.0, 2.5, 5.0, -0.5])
    np.testing.assert_allclose(saw.value(t), [0, 0.5, 1.999, 0, 0.5, 1.0, 1.5])
    np.testing.assert_array_equal(saw.velocity(t), np.ones(7))
    np.testing.assert_array_equal(saw.acceleration(t), np.zeros(7))
    np.testing.assert_array_equal(saw.kinks(0.0, 7.0), [0.0, 2.0, 4.0, 6.0])


def test_repeating_table_interpolates_and_reports_right_sided_slopes() -> None:
    seq = RepeatingSequence(times=[0, 1, 3, 4], values=[0, 2, 2, 0])
    np.testing.assert_allclose(seq.value([0.5, 2.0, 3.5, 4.5, 9.0]), [1, 2, 1, 1, 2])
    # Right-sided at the corners: at t=1 the flat segment starts, at t=3 the descent.
    np.testing.assert_array_equal(seq.velocity([0.5, 1.0, 3.0, 4.0]), [2.0, 0.0, -2.0, 2.0])
    np.testing.assert_array_equal(seq.kinks(0.0, 5.0), [0.0, 1.0, 3.0, 4.0, 5.0])
    # A triangle that closes on itself still has its corners listed, a constant none.
    assert RepeatingSequence(times=[0, 1], values=[3, 3]).kinks(0, 10).size == 0


def test_step_ramp_one_sided_choices() -> None:
    step = Step(step_time=1.0, initial=2.0, final=5.0)
    np.testing.assert_array_equal(step.value([0.999, 1.0]), [2.0, 5.0])
    np.testing.assert_array_equal(step.velocity([1.0]), [0.0])
    np.testing.assert_array_equal(step.kinks(0, 2), [1.0])
    assert step.kinks(1.5, 2).size == 0
    ramp = Ramp(slope=3.0, start_time=1.0, initial_output=1.0)
    np.testing.assert_array_equal(ramp.velocity([0.999, 1.0]), [0.0, 3.0])
    np.testing.assert_allclose(ramp.value([0.0, 2.0]), [1.0, 4.0])


def test_profiles_hit_their_end_points_with_zero_velocity() -> None:
    for cls in (Cubic, Quintic, Trapezoidal):
        move = cls(start=-1.0, end=2.0, duration=2.0, start_time=1.0)
        np.testing.assert_allclose(move.value([0.0, 1.0, 3.0, 9.0]), [-1, -1, 2, 2], atol=1e-15)
        np.testing.assert_allclose(move.velocity([0.0, 1.0, 3.0, 9.0]), 0.0, atol=1e-15)
        assert move.value(2.0) == pytest.approx(0.5)  # symmetric profiles pass the midpoint
        t = np.linspace(1.0, 3.0, 20001)
        # Integral of velocity over the move is the distance travelled.
        assert np.trapezoid(move.velocity(t), t) == pytest.approx(3.0, abs=1e-7)
    quintic = Quintic(start=0, end=1, duration=1)
    np.testing.assert_allclose(quintic.acceleration([0.0, 1.0]), 0.0, atol=1e-15)
    cubic = Cubic(start=0, end=1, duration=1)
    np.testing.assert_array_equal(cubic.acceleration([0.0, 1.0]), [6.0, 0.0])  # right-sided
    trap = Trapezoidal(start=0, end=1, duration=1, accel_fraction=0.5)  # triangle
    assert trap.velocity(0.5) == pytest.approx(2.0)


def test_sine_frequency_is_in_hertz() -> None:
    wave = Sine(amplitude=3.0, bias=1.0, frequency=2.0, phase=np.pi / 2)
    np.testing.assert_allclose(wave.value([0.0, 0.25, 0.5]), [4.0, -2.0, 4.0], atol=1e-12)
    assert wave.acceleration(0.0) == pytest.approx(-3.0 * (4 * np.pi) ** 2)
    assert Sine(frequency=0.0, bias=2.0).value(7.0) == pytest.approx(2.0)


def test_arithmetic_builds_affine_and_sum() -> None:
    saw = RepeatingSequence()
    scaled = saw * 0.5 + 1
    assert isinstance(scaled, Affine) and scaled.base is saw
    assert (scaled.scale, scaled.offset) == (0.5, 1.0)
    assert repr(scaled) == "RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0)) * 0.5 + 1.0"
    assert repr(-saw) == "-RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0))"
    assert repr(saw - 1) == "RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0)) - 1.0"
    t = np.linspace(0, 3, 13)
    np.testing.assert_allclose((2 * saw).value(t), 2 * saw.value(t))
    np.testing.assert_allclose((saw / 4).velocity(t), saw.velocity(t) / 4)
    np.testing.assert_allclose((1 - saw).value(t), 1 - saw.value(t))
    np.testing.assert_allclose((-saw).velocity(t), -saw.velocity(t))
    total = saw + Sine() + Ramp()
    assert repr(Sine() - Ramp()) == "Sine() - Ramp()"
    assert isinstance(total, Sum) and len(total.terms) == 3
    np.testing.assert_allclose(total.value(t), saw.value(t) + Sine().value(t) + t)
    np.testing.assert_allclose((saw - Ramp()).velocity(t), 0.0)
    assert +saw is saw
    assert (saw * 0).kinks(0, 5).size == 0
    with pytest.raises(TypeError):
        saw * saw  # noqa: B018
    with pytest.raises(TypeError):
        saw + "1"  # noqa: B018


def test_signals_are_immutable_hashable_and_equal_by_value() -> None:
    saw = RepeatingSequence(times=[0, 2], values=[0, 2])
    assert saw == RepeatingSequence() and hash(saw) == hash(RepeatingSequence())
    assert saw * 2 == saw * 2.0
    with pytest.raises(AttributeError):
        saw.times = (0.0, 1.0)  # type: ignore[misc]
    with pytest.raises(AttributeError):
        Sine().frequency = 3.0  # type: ignore[misc]


@pytest.mark.parametrize(
    ("build", "match"),
    [
        (lambda: RepeatingSequence(times=[], values=[]), r"times: empty table"),
        (lambda: RepeatingSequence(times=[0, 1, 2], values=[0, 1]), r"unequal lengths: 3 times"),
        (lambda: RepeatingSequence(times=[0, 2, 1], values=[0, 1, 0]), r"strictly increase"),
        (lambda: RepeatingSequence(times=[0, 1, 1], values=[0, 1, 0]), r"times\[2\] = 1.0"),
        (lambda: RepeatingSequence(times=[0, np.nan], values=[0, 1]), r"times: entry 1 is nan"),
        (lambda: RepeatingSequence(times=[0, 1], values=[0, np.inf]), r"values: entry 1 is inf"),
        (lambda: RepeatingSequence(times=[0], values=[1]), r"at least two points"),
        (lambda: RepeatingSequence(times=[1, 2], values=[0, 1]), r"first time must be 0"),
        (lambda: RepeatingSequence(times="0 2", values=[0, 1]), r"times: text is not a table"),
        (lambda: RepeatingSequence(times=[[0, 1]], values=[0, 1]), r"expected a flat list"),
        (lambda: RepeatingSequence(times=[0, "a"], values=[0, 1]), r"times: not numeric"),
        (lambda: Sine(frequency=-1.0), r"frequency: must be ≥ 0, got -1.0; allowed: .*Hz"),
        (lambda: Sine(amplitude=np.nan), r"amplitude: must be finite"),
        (lambda: Step(step_time="1"), r"step_time: text is not a number"),
        (lambda: Ramp(slope=True), r"slope: a boolean is not a number"),
        (lambda: Constant(np.inf), r"level: must be finite"),
        (lambda: Cubic(duration=0.0), r"duration: must be positive, got 0.0"),
        (lambda: Quintic(duration=-1.0), r"duration: must be positive"),
        (lambda: Trapezoidal(accel_fraction=0.6), r"accel_fraction: out of range: 0.6"),
        (lambda: Trapezoidal(accel_fraction=0.0), r"accel_fraction: out of range"),
        (lambda: RepeatingSequence() * np.nan, r"scale: must be finite"),
        (lambda: RepeatingSequence() + np.inf, r"offset: must be finite"),
        (lambda: RepeatingSequence() / 0, r"divisor: zero"),
        (lambda: Sine().value([0.0, np.nan]), r"t: must be finite, got nan"),
        (lambda: Sine().velocity("now"), r"t: not a time"),
        (lambda: Sine().acceleration([object()]), r"t: not numeric"),
        (lambda: Affine(3.0), r"base: invalid value 3.0; allowed: a signal"),
        (lambda: Sum(()), r"terms: invalid value"),
    ],
)
def test_bad_parameters_raise_clear_errors(build, match) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        build()
