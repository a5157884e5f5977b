"""Units chosen once: the length unit names the robot's unit everywhere, the angle unit
converts at the boundary (typed and shown in degrees, the core gets radians)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals
from robotconf.panel._motion_section import MotionSection
from robotconf.panel._signal_editor import PARAMETER_KINDS, SIGNAL_TYPES, SignalEditor
from robotconf.panel._units import LENGTH_UNITS, Units

from .test_panel_support import make_panel, paper_robot


def _run(panel):  # type: ignore[no-untyped-def]
    panel.motion_section.run_button.click()
    assert panel.errors == {}, panel.errors
    return panel.motion


def test_every_parameter_of_every_signal_has_a_unit():
    for name, kind in SIGNAL_TYPES.items():
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


def test_sine_amplitude_typed_in_degrees_reaches_the_core_in_radians():
    panel = make_panel(t_end=1.0, dt=0.5)
    editor = panel.motion_section.editors[2]
    editor.kind.value = "Sine"
    assert editor.parameters["amplitude"].description == "amplitude [deg]"
    editor.parameters["amplitude"].value = 30.0
    motion = _run(panel)
    assert motion.signals["q3"].amplitude == 0.5235987755982988
    assert "0.5235987755982988" in editor.core_call.value  # the core signal, shown
    expected = rc.simulate(paper_robot(), {"q3": signals.Sine(amplitude=np.deg2rad(30))}, 1.0, 0.5)
    np.testing.assert_array_equal(motion.columns(), expected.columns())


def test_every_angle_parameter_converts_and_times_do_not():
    panel = make_panel()
    editor = panel.motion_section.editors[0]
    editor.kind.value = "Sine"
    boxes = editor.parameters
    boxes["bias"].value, boxes["phase"].value, boxes["frequency"].value = 90.0, 180.0, 2.0
    assert boxes["frequency"].description == "frequency [Hz]"
    ok, signal = editor.build()
    assert ok and signal == signals.Sine(bias=np.pi / 2, phase=np.pi, frequency=2.0)
    editor.kind.value = "Ramp"
    editor.parameters["slope"].value = 45.0  # deg/s
    editor.parameters["start_time"].value = 2.0  # s
    assert editor.parameters["slope"].description == "slope [deg/s]"
    assert editor.build() == (True, signals.Ramp(slope=np.pi / 4, start_time=2.0))


def test_untouched_defaults_are_the_core_defaults_exactly():
    editor = make_panel().motion_section.editors[1]
    for name in ("Sine", "Step", "Ramp", "Cubic", "Quintic", "Trapezoidal", "Constant"):
        editor.kind.value = name
        assert editor.build() == (True, SIGNAL_TYPES[name]())
    editor.kind.value = "Sine"
    assert editor.parameters["amplitude"].value == 57.2958  # 1 rad, shown short


def test_switching_to_radians_shows_the_same_signal_and_saves_nothing():
    changes: list[int] = []
    robot = paper_robot()
    section = MotionSection(
        lambda: robot, lambda m: None, units=Units(), on_change=lambda: changes.append(1)
    )
    section.sync(robot)
    editor = section.editors[0]
    editor.kind.value = "Sine"
    editor.parameters["amplitude"].value = 30.0
    changes.clear()
    section.set_units(Units(degrees=False))
    assert changes == []  # the signal did not change: nothing to save
    assert editor.parameters["amplitude"].value == pytest.approx(0.523599)
    assert editor.parameters["amplitude"].description == "amplitude [rad]"
    assert editor.build() == (True, signals.Sine(amplitude=0.5235987755982988))
    editor.parameters["amplitude"].value = 1.0  # now typed in radians
    section.set_units(Units(degrees=True))
    assert editor.parameters["amplitude"].value == 57.2958
    assert editor.build() == (True, signals.Sine(amplitude=1.0))


def test_the_panels_toggle_converts_the_signal_editors():
    panel = make_panel()
    editor = panel.motion_section.editors[2]
    editor.kind.value = "RepeatingSequence"
    table = editor.table
    assert table.header() == ("time [s]", "value [deg]")
    assert [b.value for b in table.values] == [0.0, 114.592]  # the core's 0 → 2 rad
    table.values[1].value = 90.0
    panel.angle_unit.value = False
    assert table.header() == ("time [s]", "value [rad]")
    assert table.values[1].value == pytest.approx(np.pi / 2, abs=1e-6)
    assert editor.build() == (True, signals.RepeatingSequence((0, 2), (0, np.pi / 2)))
    assert "[rad]" in editor.label.value


def test_prismatic_coordinates_are_in_the_length_unit_unconverted():
    panel = make_panel(length_unit="mm")
    panel.modules.rows[2].kind.value = "Tz"
    editor = panel.motion_section.editors[2]
    assert "[mm]" in editor.label.value
    editor.kind.value = "Sine"
    assert editor.parameters["amplitude"].description == "amplitude [mm]"
    assert editor.parameters["phase"].description == "phase [deg]"  # an angle still
    editor.parameters["amplitude"].value = 5.0
    editor.parameters["phase"].value = 90.0
    assert editor.build() == (True, signals.Sine(amplitude=5.0, phase=np.pi / 2))


def test_a_coordinate_changing_type_keeps_the_core_signal():
    editor = SignalEditor("q1", "rad", units=Units("cm"))
    editor.kind.value = "Step"
    editor.parameters["final"].value = 90.0  # degrees
    editor.rename("q1", "length")  # Rz → Tz
    assert editor.parameters["final"].description == "final [cm]"
    assert editor.parameters["final"].value == pytest.approx(np.pi / 2, abs=1e-6)
    assert editor.build() == (True, signals.Step(final=np.pi / 2))


def test_loaded_signals_show_in_the_panels_units():
    panel = make_panel()
    panel.motion_section.load({"q1": signals.Sine(amplitude=0.5)}, None)
    editor = panel.motion_section.editors[0]
    assert editor.parameters["amplitude"].value == 28.6479
    assert panel.motion_section.signals() == {"q1": signals.Sine(amplitude=0.5)}


def test_the_length_unit_is_chosen_in_the_header_and_named_everywhere():
    panel = make_panel()
    assert panel.length_unit.value == "units" and tuple(panel.length_unit.options) == LENGTH_UNITS
    header = panel.widget.children[3]
    assert panel.length_unit in header.children  # beside deg/rad
    assert "[units]" in panel.ee_label.value
    panel.length_unit.value = "mm"
    assert panel.units == Units("mm", degrees=True)
    assert "p_EE = (70, 0, 20)</code> <small>[mm]" in panel.ee_label.value
    assert "mm and s" in panel.motion_section.signals_note.value
    assert panel.robot == paper_robot()  # a name only: no length changed
    assert panel.errors == {}


@pytest.mark.parametrize("bad", ["", "$x$", "<b>", "a" * 13, 3])
def test_a_length_unit_that_could_become_markup_is_refused(bad):
    with pytest.raises(rc.InvalidInputError, match="length_unit"):
        make_panel(length_unit=bad)


def test_an_unlisted_length_unit_is_offered_too():
    panel = make_panel(length_unit="ft")
    assert panel.length_unit.value == "ft" and "ft" in panel.length_unit.options
