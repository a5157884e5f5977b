"""SimulationSettings: one set of rules and limits for simulate, files, the CLI and the panel."""

from __future__ import annotations

import dataclasses
import json
import re

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.cli import main
from robotconf.motion import (
    MAX_SAMPLE_POINTS,
    MAX_TIME_SAMPLES,
    SimulationSettings,
    simulate,
)
from robotconf.signals import Ramp, RepeatingSequence

#: Too many samples for everyone: 10⁵ s at 1 ms is 10⁸ + 1 samples, ten times the limit.
OVER = {"t_end": 1e5, "dt": 1e-3}
#: What every front end says about OVER (the field name differs only by its file prefix).
OVER_MESSAGE = "dt: too many samples at 0.001; allowed: at most 10,000,000 time samples"


def test_limits_are_the_documented_numbers():
    assert MAX_TIME_SAMPLES == 10_000_000
    assert MAX_SAMPLE_POINTS == 50_000_000


def test_round_off_keeps_the_last_sample():
    settings = SimulationSettings(0.3, dt=0.1)  # 0.3 / 0.1 = 2.9999999999999996
    assert settings.samples == 4
    np.testing.assert_allclose(settings.time_grid(), [0.0, 0.1, 0.2, 0.3])
    assert SimulationSettings(1.0, dt=0.3).samples == 4  # 0, 0.3, 0.6, 0.9: 1.0 is not hit


def test_the_papers_run_has_10001_samples():
    settings = SimulationSettings(t_end=10.0)  # Simulink's stop time, the default 1 ms
    assert (settings.dt, settings.t0, settings.method) == (0.001, 0.0, "analytic")
    assert settings.samples == 10_001
    t = settings.time_grid(points=4)
    assert t.shape == (10_001,) and t[0] == 0.0 and t[-1] == pytest.approx(10.0)
    assert t[5000] == pytest.approx(5.0)


def test_t0_shifts_the_grid():
    t = SimulationSettings(1.0, dt=0.25, t0=0.5).time_grid()
    np.testing.assert_array_equal(t, [0.5, 0.75, 1.0])


def test_values_are_normalized_to_python_floats_and_lower_case():
    settings = SimulationSettings(np.float32(2.0), dt=1, t0=np.int64(0), method=" Numeric ")
    assert settings == SimulationSettings(2.0, 1.0, 0.0, "numeric")
    assert type(settings.t_end) is float and type(settings.dt) is float
    assert type(settings.t0) is float and settings.method == "numeric"


def test_the_sample_limit_is_exact():
    assert SimulationSettings(t_end=9_999_999, dt=1).samples == MAX_TIME_SAMPLES
    with pytest.raises(InvalidInputError) as caught:
        SimulationSettings(t_end=10_000_000, dt=1)
    assert caught.value.field == "dt"
    assert "((t_end − t0)/dt + 1 = 1e+07 here)" in str(caught.value)


@pytest.mark.parametrize(
    ("kwargs", "field", "match"),
    [
        ({"t_end": float("nan")}, "t_end", r"t_end: must be finite, got nan"),
        ({"t_end": "10"}, "t_end", r"t_end: text is not a number"),
        ({"t_end": True}, "t_end", r"t_end: a boolean is not a number"),
        ({"dt": 0.0}, "dt", r"dt: must be positive, got 0.0; allowed: a time step > 0 \(s\)"),
        ({"dt": -1e-3}, "dt", r"dt: must be positive, got -0.001"),
        ({"dt": float("inf")}, "dt", r"dt: must be finite, got inf"),
        ({"t0": [0.0]}, "t0", r"t0: expected one number, got shape \(1,\)"),
        ({"t0": 2.0}, "t_end", r"t_end: must be later than t0, got 1.0; .* t0 = 2.0 s"),
        ({"t_end": 0.0}, "t_end", r"t_end: must be later than t0, got 0.0"),
        ({"method": "euler"}, "method", r"method: unknown method 'euler'; allowed: 'analytic'"),
        ({"method": None}, "method", r"method: expected text, got None"),
        ({"t_end": 1e6, "dt": 1e-4}, "dt", r"dt: too many samples at 0.0001; .* = 1e\+10 here"),
        # times whose arithmetic could overflow are refused by their bounds first
        ({"t_end": 1e308, "dt": 1e-308}, "t_end", r"t_end: out of range: 1e\+308"),
        ({"t_end": 1e308, "t0": -1e308}, "t_end", r"t_end: out of range: 1e\+308"),
        ({"t0": -1e308}, "t0", r"t0: out of range: -1e\+308; allowed: a time from -1e\+09"),
        ({"dt": 1e-308}, "dt", r"dt: below the smallest time step: 1e-308"),
    ],
)
def test_each_error_names_its_field(kwargs, field, match):
    arguments = {"t_end": 1.0, **kwargs}
    with pytest.raises(InvalidInputError, match=match) as caught:
        SimulationSettings(**arguments)
    assert caught.value.field == field


def test_time_grid_refuses_too_many_samples_times_points():
    settings = SimulationSettings(t_end=9_999_999, dt=1)  # exactly MAX_TIME_SAMPLES
    with pytest.raises(
        InvalidInputError,
        match=r"dt: 10000000 samples × 6 points = 6e\+07 is too many at 1.0; "
        r"allowed: at most 5e\+07 samples × points",
    ):
        settings.time_grid(points=6)
    with pytest.raises(InvalidInputError, match=r"dt: 101 samples × 2 points = 202 is too many"):
        SimulationSettings(1.0, dt=0.01).time_grid(points=2, limit=200)
    with pytest.raises(InvalidInputError, match=r"points: out of range: 0"):
        SimulationSettings(1.0).time_grid(points=0)


def test_with_changes_validates_the_whole():
    settings = SimulationSettings(10.0, t0=5.0)
    assert settings.with_changes(dt=0.5).samples == 11
    assert settings.with_changes(method="numeric").method == "numeric"
    with pytest.raises(
        InvalidInputError, match=r"t_end: must be later than t0, got 4.0; .* t0 = 5.0 s"
    ):
        settings.with_changes(t_end=4.0)
    with pytest.raises(InvalidInputError, match=r"solver: unknown field 'ode45'"):
        settings.with_changes(solver="ode45")
    with pytest.raises(dataclasses.FrozenInstanceError):
        settings.dt = 0.1  # type: ignore[misc]


def test_dict_round_trip():
    settings = SimulationSettings(2.5, dt=0.01, t0=0.5, method="numeric")
    data = settings.to_dict()
    assert data == {"t_end": 2.5, "dt": 0.01, "t0": 0.5, "method": "numeric"}
    assert SimulationSettings.from_dict(data) == settings
    assert SimulationSettings.from_dict(json.loads(json.dumps(data))) == settings
    assert SimulationSettings.from_dict({"t_end": 3}) == SimulationSettings(3.0)


@pytest.mark.parametrize(
    ("data", "match"),
    [
        ([1.0], r"run: expected an object, got \[1.0\]"),
        ({"dt": 0.1}, r"run\.t_end: missing"),
        ({"t_end": 1, "solver": "ode45"}, r"run\.solver: unknown key, value 'ode45'"),
        ({"t_end": 1, "dt": True}, r"run\.dt: expected a number, got a boolean"),
        ({"t_end": "1"}, r"run\.t_end: expected a number, got '1'"),
        ({"t_end": 10**400}, r"run\.t_end: too large"),
        ({"t_end": 1, "method": 2}, r"run\.method: expected text, got 2"),
        ({"t_end": 1, "dt": 0}, r"run\.dt: must be positive, got 0.0"),
        ({"t_end": 1, "t0": 1}, r"run\.t_end: must be later than t0, got 1.0"),
        ({"t_end": 1, "method": "euler"}, r"run\.method: unknown method 'euler'"),
        ({"t_end": 1e4, "dt": 1e-4}, r"run\.dt: too many samples at 0.0001"),
    ],
)
def test_from_dict_names_the_path(data, match):
    with pytest.raises(InvalidInputError, match=match):
        SimulationSettings.from_dict(data, path="run")


# -- every front end refuses the same settings with the same limit ----------------------


def test_simulate_refuses_over_limit_settings():
    with pytest.raises(InvalidInputError, match=OVER_MESSAGE) as caught:
        simulate(rc.preset("paper"), {}, **OVER)
    assert caught.value.field == "dt"


def test_simulate_refuses_too_many_samples_times_points_before_allocating():
    # 7 modules + EE = 8 points; 7 000 001 samples are under MAX_TIME_SAMPLES, but
    # 5.6·10⁷ sample-points are over MAX_SAMPLE_POINTS.
    robot = rc.Robot([rc.Module("Rz", a=(1, 0, 0)) for _ in range(7)])
    with pytest.raises(
        InvalidInputError, match=r"dt: 7000001 samples × 8 points = 5\.6e\+07 is too many"
    ):
        simulate(robot, {}, t_end=7000.0)


def test_simulate_takes_settings_as_keywords():
    settings = SimulationSettings(1.0, dt=0.25)
    motion = simulate(rc.preset("paper"), {"q1": Ramp()}, **settings.to_dict())
    np.testing.assert_array_equal(motion.t, settings.time_grid())
    assert motion.t.size == 5


def test_file_refuses_over_limit_settings():
    text = rc.preset("paper").to_json(simulation={"t_end": 1.0})
    data = json.loads(text)
    data["simulation"] = OVER
    with pytest.raises(InvalidInputError, match="simulation." + OVER_MESSAGE) as caught:
        rc.load_setup(json.dumps(data))
    assert caught.value.field == "simulation.dt"
    with pytest.raises(InvalidInputError, match="simulation." + OVER_MESSAGE):
        rc.preset("paper").to_json(simulation=OVER)
    # The largest run allowed is read without complaint.
    data["simulation"] = {"t_end": 9_999_999, "dt": 1}
    assert rc.load_setup(json.dumps(data)).settings.samples == MAX_TIME_SAMPLES


def test_cli_refuses_over_limit_settings(tmp_path, capsys):
    out = tmp_path / "out"
    argv = ["report", "--preset", "paper", "--t-end", "1e5", "--out", str(out), "--quiet"]
    assert main(argv) == 2
    assert capsys.readouterr().err == f"robotconf: error: {OVER_MESSAGE} " + (
        "((t_end − t0)/dt + 1 = 1e+08 here): increase dt or shorten t_end − t0\n"
    )
    assert not out.exists()


def test_cli_combines_command_line_file_and_defaults(tmp_path, capsys):
    setup = rc.Setup(rc.preset("paper"), {"q3": RepeatingSequence()}, {"t_end": 1e4, "t0": 2.0})
    path = setup.save(tmp_path / "robot.json")
    # The file's t_end with the default dt is allowed; the command line's dt makes it
    # ten times too many samples, and the combination is what gets checked.
    argv = ["report", str(path), "--dt", "1e-4", "--out", str(tmp_path / "out"), "--quiet"]
    assert main(argv) == 2
    assert "dt: too many samples at 0.0001" in capsys.readouterr().err
    argv = ["report", str(path), "--t-end", "1", "--out", str(tmp_path / "out"), "--quiet"]
    assert main(argv) == 2
    assert "t_end: must be later than t0, got 1.0; allowed: a time after t0 = 2.0 s" in (
        capsys.readouterr().err
    )


def test_panel_refuses_over_limit_settings_and_keeps_the_last_valid_ones(tmp_path):
    pytest.importorskip("ipywidgets")
    from .test_panel_support import make_panel, note, ui

    panel = make_panel(t_end=2.0, dt=0.5)
    ui(panel, "t_end").type("1e5")  # 2·10⁵ samples at 0.5 s: fine
    ui(panel, "dt").type("0.001")  # 10⁸ + 1 samples: refused beside dt
    assert note(panel, "dt").startswith(OVER_MESSAGE)
    assert panel.state.document.motion.settings == SimulationSettings(1e5, dt=0.5)
    ui(panel, "run").click()  # runs with the last valid settings, not the refused ones
    assert panel.motion is not None and panel.motion.t.size == 200_001
    panel.save(tmp_path / "robot.json")
    assert rc.load_setup(tmp_path / "robot.json").simulation["dt"] == 0.5


def test_panel_made_with_over_limit_settings_says_which_field():
    pytest.importorskip("ipywidgets")
    from .test_panel_support import make_panel

    with pytest.raises(InvalidInputError, match=re.escape(OVER_MESSAGE)) as caught:
        make_panel(**OVER)
    assert caught.value.field == "dt"


def test_panel_keeps_a_files_t0(tmp_path):
    pytest.importorskip("ipywidgets")
    from .test_panel_support import make_panel, ui

    setup = rc.Setup(rc.preset("paper"), {"q1": Ramp()}, {"t_end": 2.0, "dt": 0.5, "t0": 1.0})
    panel = make_panel()
    panel.load(setup.save(tmp_path / "robot.json"))
    ui(panel, "run").click()
    np.testing.assert_array_equal(panel.motion.t, [1.0, 1.5, 2.0])
    assert panel.state.document.motion.settings == SimulationSettings(2.0, 0.5, 1.0)
    panel.save(tmp_path / "again.json")
    assert rc.load_setup(tmp_path / "again.json").simulation["t0"] == 1.0
