"""Signals ⇄ dicts: lossless for every class, strict on reading."""

import json

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from robotconf import InvalidInputError
from robotconf import signals as sg
from robotconf.signals import signal_from_dict

EXAMPLES = [
    sg.Constant(0.5),
    sg.Step(step_time=0.3, initial=-1.0, final=2.0),
    sg.Ramp(slope=-0.7, start_time=1.5, initial_output=0.25),
    sg.Sine(amplitude=2.0, bias=0.1, frequency=0.25, phase=1.0),
    sg.RepeatingSequence(times=[0, 0.5, 2], values=[0, 1.5, -1]),
    sg.Cubic(start=0.1, end=1.2, duration=2.0, start_time=0.5),
    sg.Quintic(start=-1.0, end=1.0, duration=0.5),
    sg.Trapezoidal(start=0.0, end=3.0, duration=4.0, accel_fraction=0.5),
    sg.Ramp() * 0.5 + 1,
    sg.Sine() + sg.Step() - sg.RepeatingSequence() * 2,
    -(sg.Constant(1.0) + sg.Ramp()),
]


@pytest.mark.parametrize("signal", EXAMPLES, ids=repr)
def test_round_trip_through_json_is_exact(signal):
    data = json.loads(json.dumps(signal.to_dict()))
    back = signal_from_dict(data)
    assert back == signal
    t = np.linspace(-1, 5, 61)
    np.testing.assert_array_equal(back.value(t), signal.value(t))
    np.testing.assert_array_equal(back.acceleration(t), signal.acceleration(t))


def test_dict_forms_are_plain_and_complete():
    assert sg.Trapezoidal(end=2.0).to_dict() == {
        "type": "Trapezoidal",
        "start": 0.0,
        "end": 2.0,
        "duration": 1.0,
        "start_time": 0.0,
        "accel_fraction": 0.25,
    }
    assert (sg.Constant(1.0) + sg.Ramp()).to_dict() == {
        "type": "Sum",
        "terms": [
            {"type": "Constant", "level": 1.0},
            {"type": "Ramp", "slope": 1.0, "start_time": 0.0, "initial_output": 0.0},
        ],
    }


def test_missing_parameters_take_the_defaults():
    assert signal_from_dict({"type": "RepeatingSequence"}) == sg.RepeatingSequence()
    assert signal_from_dict({"type": "Sine", "frequency": 2}) == sg.Sine(frequency=2.0)


@given(
    amplitude=st.floats(-1e6, 1e6),
    bias=st.floats(-1e6, 1e6),
    frequency=st.floats(0, 1e6),
    phase=st.floats(-10, 10),
    scale=st.floats(-1e3, 1e3),
)
def test_round_trip_property(amplitude, bias, frequency, phase, scale):
    signal = sg.Sine(amplitude, bias, frequency, phase) * scale + sg.Ramp(slope=bias)
    assert signal_from_dict(json.loads(json.dumps(signal.to_dict()))) == signal


def _nested(depth):
    data = {"type": "Constant", "level": 1.0}
    for _ in range(depth):
        data = {"type": "Affine", "base": data, "scale": 2.0}
    return data


@pytest.mark.parametrize(
    ("data", "match"),
    [
        ([1, 2], r"sig: not a dict: \[1, 2\]"),
        ({"level": 1}, r"sig\.type: unknown signal type None; allowed: Constant, Step"),
        ({"type": "eval"}, r"sig\.type: unknown signal type 'eval'"),
        ({"type": "Sine", "amp": 1}, r"sig\.amp: unknown key, value 1; allowed: the keys of Sine"),
        ({"type": "Sine", "amplitude": True}, r"sig\.amplitude: expected a number, got bool True"),
        ({"type": "Sine", "amplitude": "2"}, r"sig\.amplitude: expected a number, got str '2'"),
        ({"type": "Sine", "amplitude": None}, r"sig\.amplitude: expected a number, got NoneType"),
        ({"type": "Sine", "frequency": -1}, r"sig\.frequency: must be ≥ 0, got -1.0"),
        ({"type": "Constant", "level": float("nan")}, r"sig\.level: must be finite, got nan"),
        ({"type": "RepeatingSequence", "times": 2}, r"sig\.times: not a list: 2"),
        ({"type": "RepeatingSequence", "times": [0, True]}, r"sig\.times\[1\]: expected a number"),
        (
            {"type": "RepeatingSequence", "times": list(range(10_001)), "values": [0] * 10_001},
            r"sig\.times: table too long: '<10001 entries>'; allowed: a list of at most 10000",
        ),
        (
            {"type": "RepeatingSequence", "times": [0, 2, 1], "values": [0, 1, 0]},
            r"sig\.times: times must strictly increase",
        ),
        ({"type": "Affine", "scale": 2}, r"sig\.base: missing: None; allowed: Affine needs 'base'"),
        ({"type": "Affine", "base": 3}, r"sig\.base: not a dict: 3"),
        ({"type": "Sum", "terms": []}, r"sig\.terms: not a non-empty list"),
        ({"type": "Sum", "terms": [{"type": "Ramp"}] * 65}, r"sig\.terms: too many terms"),
        ({"type": "Sum", "terms": [{"type": "Ramp"}, {"type": "X"}]}, r"sig\.terms\[1\]\.type"),
        ({"type": "Sine", "phase": 10**400}, r"sig\.phase: too large"),
        (_nested(17), r"sig(\.base){17}: nested too deeply"),
    ],
)
def test_reading_errors_name_the_path(data, match):
    with pytest.raises(InvalidInputError, match=match):
        signal_from_dict(data, "sig")


def test_sixteen_levels_are_fine():
    assert signal_from_dict(_nested(16)).value(0.0) == 2.0**16
