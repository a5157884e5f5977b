"""The command-line signal language: every kind, numbers with pi, and every error branch."""

from __future__ import annotations

import math

import numpy as np
import pytest

from robotconf import InvalidInputError
from robotconf.signals import (
    MAX_SPEC_LENGTH,
    Constant,
    Cubic,
    Quintic,
    Ramp,
    RepeatingSequence,
    Sine,
    Step,
    Trapezoidal,
    parse_signal,
    parse_signal_spec,
)


@pytest.mark.parametrize(
    ("spec", "expected"),
    [
        ("q3=repeating:times=0,2;values=0,2", RepeatingSequence(times=(0, 2), values=(0, 2))),
        ("q3=repeating", RepeatingSequence()),
        ("q3=repeating:times=0,1,2;values=0,1,0", RepeatingSequence((0, 1, 2), (0, 1, 0))),
        ("q1=sine:amplitude=1,frequency=0.5", Sine(amplitude=1.0, frequency=0.5)),
        ("q1=sin:amplitude=2;bias=0.5;phase=pi/2", Sine(amplitude=2, bias=0.5, phase=math.pi / 2)),
        ("q2=step:time=1,final=0.5", Step(step_time=1.0, final=0.5)),
        ("q2=step:step_time=2,initial=-1,final=1", Step(step_time=2, initial=-1, final=1)),
        ("q2=ramp:slope=0.1", Ramp(slope=0.1)),
        ("q2=ramp:slope=2,start_time=1,initial=3", Ramp(slope=2, start_time=1, initial_output=3)),
        ("q1=constant:0.3", Constant(0.3)),
        ("q1=const:level=-2*pi", Constant(-2 * math.pi)),
        ("q1=constant", Constant(0.0)),
        ("q2=cubic:end=1,duration=2", Cubic(end=1, duration=2)),
        ("q2=quintic:start=1,end=0,duration=0.5,start_time=1", Quintic(1, 0, 0.5, 1)),
        (
            "q4=trapezoidal:end=1,duration=2,accel_fraction=0.3",
            Trapezoidal(end=1, duration=2, accel_fraction=0.3),
        ),
        (" Q12 = Sine : amplitude = 1e-3 ", Sine(amplitude=1e-3)),
    ],
)
def test_specs_build_the_right_signal(spec, expected):
    name, signal = parse_signal_spec(spec)
    assert name == spec.split("=")[0].strip().lower()
    assert signal == expected
    t = np.linspace(0, 5, 11)
    np.testing.assert_allclose(signal.value(t), expected.value(t), rtol=0, atol=0)


def test_pi_forms():
    values = [parse_signal(f"constant:{text}").level for text in ("pi", "-pi", "0.5pi", "3*pi/4")]
    np.testing.assert_allclose(values, [math.pi, -math.pi, math.pi / 2, 3 * math.pi / 4])


def test_paper_sawtooth_values():
    _, saw = parse_signal_spec("q3=repeating:times=0,2;values=0,2")
    np.testing.assert_allclose(saw.value([0.0, 1.0, 1.999, 2.0, 3.5]), [0, 1, 1.999, 0, 1.5])


@pytest.mark.parametrize(
    ("spec", "match"),
    [
        (3, "signal: not text"),
        ("q1=" + "1" * MAX_SPEC_LENGTH, "longer than 10000 characters"),
        ("q1", "expected NAME=KIND"),
        ("q1=", "expected NAME=KIND"),
        ("x1=sine", "'x1' is not a coordinate name"),
        ("q0=sine", "'q0' is not a coordinate name"),
        ("q1=wave", "unknown kind 'wave'"),
        ("q1=sine:amp=1", "unknown parameter 'amp'"),
        ("q1=sine:amplitude=1,amplitude=2", "'amplitude' given twice"),
        ("q1=sine:amplitude=1,2", "'amplitude' takes one number, got 2"),
        ("q1=step:0.5", "step needs key=value items"),
        ("q1=sine:amplitude=1,,frequency=2", "empty item"),
        ("q1=sine:amplitude=nan", "'nan' is not a number"),
        ("q1=sine:amplitude=inf", "'inf' is not a number"),
        ("q1=constant:1e999", "'1e999' is not finite"),
        ("q1=constant:pi/0", "division by zero"),
        ("q1=constant:__import__('os')", "is not a number"),
        ("q1=constant:2**8", "is not a number"),
        ("q1=repeating:times=0,2,1;values=0,1,0", "times must strictly increase"),
        ("q1=repeating:times=0,2;values=0", "values"),
        ("q1=sine:frequency=-1", "frequency: must be ≥ 0"),
        ("q1=cubic:duration=0", "duration: must be positive"),
    ],
)
def test_bad_specs(spec, match):
    with pytest.raises(InvalidInputError, match=match):
        parse_signal_spec(spec)
