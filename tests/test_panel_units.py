"""Units chosen once: the length unit names the robot's unit everywhere, the angle unit
converts at the boundary (typed and shown in degrees, the core gets radians), and a
switch changes no number of the state."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals
from robotconf.panel.actions import EDITABLE_SIGNALS
from robotconf.panel.motion import PARAMETER_KINDS
from robotconf.panel.state import LENGTH_UNITS, Units

from .test_panel_support import make_panel, paper_robot, shown, ui


def _run(panel):  # type: ignore[no-untyped-def]
    ui(panel, "run").click()
    assert panel.errors == {}, panel.errors
    return panel.motion


def _signal(panel, i: int):
    return panel.state.document.motion.signals[i]


def _label(panel, key: str) -> str:
    return shown(panel, key)["label"]


def test_every_parameter_of_every_signal_has_a_unit():
    for name, kind in EDITABLE_SIGNALS.items():
        if kind is signals.RepeatingSequence:
            continue  # a table: values in the coordinate's unit, times in seconds
        fields = [f.name for f in dataclasses.fields(kind) if f.init and not f.name.startswith("_")]
        assert set(fields) <= set(PARAMETER_KINDS), (name, set(fields) - set(PARAMETER_KINDS))


def test_units_label_every_quantity():
    units = Units("mm", degrees=True)
    assert [units.quantity(q) for q in rc.motion.QUANTITIES] == [
        "mm",
        "mm",
        "mm/s",
        "mm/s²",
        "deg/s",
    ]
    assert Units("m", degrees=False).quantity("angular_velocity") == "rad/s"
    assert [units.coordinate("rad", k) for k in range(3)] == ["deg", "deg/s", "deg/s²"]
    assert units.coordinate("", 0) == ""  # a link without a joint has no unit


def test_a_sine_amplitude_typed_in_degrees_reaches_the_core_in_radians():
    panel = make_panel(t_end=1.0, dt=0.5)
    ui(panel, "signals.q3").choose("Sine")
    assert _label(panel, "signals.q3.amplitude") == "amplitude [deg]"
    ui(panel, "signals.q3.amplitude").type("30")
    motion = _run(panel)
    assert motion.signals["q3"].amplitude == 0.5235987755982988
    core = [
        c["value"]
        for r in panel.motion_tab.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-core-signal"
    ]
    assert core == ["core signal: Sine(amplitude=0.5235987755982988)"]  # what a cell passes
    expected = rc.simulate(paper_robot(), {"q3": signals.Sine(amplitude=np.deg2rad(30))}, 1.0, 0.5)
    np.testing.assert_array_equal(motion.columns(), expected.columns())


def test_every_angle_parameter_converts_and_times_do_not():
    panel = make_panel()
    ui(panel, "signals.q1").choose("Sine")
    for name, value in (("bias", "90"), ("phase", "180"), ("frequency", "2")):
        ui(panel, f"signals.q1.{name}").type(value)
    assert _label(panel, "signals.q1.frequency") == "frequency [Hz]"
    assert _signal(panel, 0) == signals.Sine(bias=np.pi / 2, phase=np.pi, frequency=2.0)
    ui(panel, "signals.q1").choose("Ramp")
    ui(panel, "signals.q1.slope").type("45")  # deg/s
    ui(panel, "signals.q1.start_time").type("2")  # s
    assert _label(panel, "signals.q1.slope") == "slope [deg/s]"
    assert _signal(panel, 0) == signals.Ramp(slope=np.pi / 4, start_time=2.0)


def test_untouched_defaults_are_the_core_defaults_exactly():
    panel = make_panel()
    for name in ("Sine", "Step", "Ramp", "Cubic", "Quintic", "Trapezoidal", "Constant"):
        ui(panel, "signals.q2").choose(name)
        assert _signal(panel, 1) == EDITABLE_SIGNALS[name]()
    ui(panel, "signals.q2").choose("Sine")
    assert shown(panel, "signals.q2.amplitude")["value"] == 57.2958  # 1 rad, shown short


def test_switching_to_radians_shows_the_same_signal_and_saves_nothing():
    panel = make_panel()
    ui(panel, "signals.q1").choose("Sine")
    ui(panel, "signals.q1.amplitude").type("30")
    document = panel.state.document
    depth = len(panel._history)
    ui(panel, "angle_unit").choose(False)
    assert panel.state.document is document and len(panel._history) == depth
    assert shown(panel, "signals.q1.amplitude")["value"] == pytest.approx(0.523599)
    assert _label(panel, "signals.q1.amplitude") == "amplitude [rad]"
    assert _signal(panel, 0) == signals.Sine(amplitude=0.5235987755982988)
    ui(panel, "signals.q1.amplitude").type("1")  # now typed in radians
    ui(panel, "angle_unit").choose(True)
    assert shown(panel, "signals.q1.amplitude")["value"] == 57.2958
    assert _signal(panel, 0) == signals.Sine(amplitude=1.0)


def test_a_repeating_table_shows_its_values_in_the_panels_units():
    panel = make_panel()
    ui(panel, "signals.q3").choose("RepeatingSequence")
    assert [shown(panel, f"signals.q3.table.v{k}")["value"] for k in (0, 1)] == [0.0, 114.592]
    ui(panel, "signals.q3.table.v1").type("90")
    ui(panel, "angle_unit").choose(False)
    assert shown(panel, "signals.q3.table.v1")["value"] == pytest.approx(np.pi / 2, abs=1e-6)
    assert _signal(panel, 2) == signals.RepeatingSequence((0, 2), (0, np.pi / 2))
    ui(panel, "signals.q3.table.add").click()
    assert _signal(panel, 2) == signals.RepeatingSequence((0, 2, 4), (0, np.pi / 2, np.pi / 2))
    ui(panel, "signals.q3.table.t2").type("1")  # times must increase: refused, kept
    assert "signals.q3.table.t2" in panel.errors and len(_signal(panel, 2).times) == 3
    ui(panel, "signals.q3.table.remove").click()
    assert _signal(panel, 2) == signals.RepeatingSequence((0, 2), (0, np.pi / 2))


def test_prismatic_coordinates_are_in_the_length_unit_unconverted():
    panel = make_panel(length_unit="mm")
    ui(panel, "modules[2].kind").choose("Tz")
    ui(panel, "signals.q3").choose("Sine")
    assert _label(panel, "signals.q3.amplitude") == "amplitude [mm]"
    assert _label(panel, "signals.q3.phase") == "phase [deg]"  # an angle still
    ui(panel, "signals.q3.amplitude").type("5")
    ui(panel, "signals.q3.phase").type("90")
    assert _signal(panel, 2) == signals.Sine(amplitude=5.0, phase=np.pi / 2)


def test_a_coordinate_changing_type_keeps_the_core_signal():
    panel = make_panel(length_unit="cm")
    ui(panel, "signals.q1").choose("Step")
    ui(panel, "signals.q1.final").type("90")  # degrees
    ui(panel, "modules[0].kind").choose("Tz")  # Rz → Tz
    assert _label(panel, "signals.q1.final") == "final [cm]"
    assert shown(panel, "signals.q1.final")["value"] == pytest.approx(np.pi / 2, abs=1e-6)
    assert _signal(panel, 0) == signals.Step(final=np.pi / 2)


def test_loaded_signals_show_in_the_panels_units():
    panel = make_panel()
    panel.apply(rc.panel.actions.LoadSetup(paper_robot(), {"q1": signals.Sine(amplitude=0.5)}))
    assert shown(panel, "signals.q1.amplitude")["value"] == 28.6479
    assert panel.state.document.motion.driven(panel.robot.coordinate_names) == {
        "q1": signals.Sine(amplitude=0.5)
    }


def test_the_length_unit_is_chosen_in_the_header_and_named_everywhere():
    panel = make_panel()
    options = [value for _, value in shown(panel, "length_unit")["options"]]
    assert shown(panel, "length_unit")["value"] == "units" and tuple(options) == LENGTH_UNITS
    assert "[units]" in panel.ee_label.value
    ui(panel, "length_unit").choose("mm")
    assert panel.units == Units("mm", degrees=True)
    assert "p_EE = (70, 0, 20)</code> <small>[mm]" in panel.ee_label.value
    assert shown(panel, "modules[1].az")["unit"] == "mm"
    assert panel.robot == paper_robot() and panel.errors == {}  # a name only


@pytest.mark.parametrize("bad", ["", "$x$", "<b>", "a" * 13, 3])
def test_a_length_unit_that_could_become_markup_is_refused(bad):
    with pytest.raises(rc.InvalidInputError, match="length_unit"):
        make_panel(length_unit=bad)


def test_an_unlisted_length_unit_is_offered_too():
    panel = make_panel(length_unit="ft")
    options = [value for _, value in shown(panel, "length_unit")["options"]]
    assert shown(panel, "length_unit")["value"] == "ft" and "ft" in options


def test_ten_unit_switches_change_no_number():
    panel = make_panel()
    ui(panel, "modules[1].q").type("34.4")  # between two notches
    ui(panel, "signals.q2").choose("Sine")
    document = panel.state.document
    for degrees in (False, True) * 5:
        ui(panel, "angle_unit").choose(degrees)
        assert panel.state.document is document
    assert panel.robot.q[1] == np.radians(34.4)


def test_messages_speak_the_panels_units():
    from robotconf.panel import actions as act

    panel = make_panel(length_unit="mm")
    panel.apply(act.SelectTab("program"))
    ui(panel, "modules[1].q").type("200")  # beyond q2's range of ±180°
    ui(panel, "program.add").click()
    ui(panel, "modules[1].q").type("0")
    ui(panel, "program.add").click()
    ui(panel, "program.run").click()
    texts = [
        c["value"]
        for r in panel.program_tab.form.spec["rows"]
        for line in r.get("lines", [])
        for c in line
        if c.get("type") == "text" and "move 1 (PTP)" in c.get("value", "")
    ]
    # The core says [-3.14159, 3.14159] rad and 0.3491 rad: 20° = 0.349 rad beyond π.
    assert texts == [
        "⚠ move 1 (PTP): q2 leaves its range [-180, 180] deg at t = 3.4 s "
        "(by up to 20 deg, at t = 3.99 s)"
    ]
    ui(panel, "angle_unit").choose("rad")
    texts = [
        c["value"]
        for r in panel.program_tab.form.spec["rows"]
        for line in r.get("lines", [])
        for c in line
        if c.get("type") == "text" and "move 1 (PTP)" in c.get("value", "")
    ]
    assert "[-3.14159, 3.14159] rad" in texts[0] and "0.3491 rad" in texts[0]
