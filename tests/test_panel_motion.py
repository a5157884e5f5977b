"""The Motion tab: signal editors, repeating table, time settings, Run and its results."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals

from .test_panel_support import make_panel, paper_robot


def test_one_signal_editor_per_coordinate_with_units():
    panel = make_panel()
    editors = panel.motion_section.editors
    assert [e.name for e in editors] == ["q1", "q2", "q3"]
    assert "[deg]" in editors[0].label.value  # the panel's angle unit
    panel.modules.rows[2].kind.value = "Tz"
    assert "[units]" in panel.motion_section.editors[2].label.value  # its length unit


def test_signal_parameters_come_from_the_core_classes():
    editor = make_panel().motion_section.editors[0]
    editor.kind.value = "Sine"
    assert list(editor.parameters) == ["amplitude", "bias", "frequency", "phase"]
    editor.kind.value = "Trapezoidal"
    assert "accel_fraction" in editor.parameters
    editor.parameters["duration"].value = 3.0
    assert editor.build() == (True, signals.Trapezoidal(duration=3.0))


def test_run_produces_the_table_with_the_papers_numbers():
    panel = make_panel(dt=0.01, t_end=2.0)
    editor = panel.motion_section.editors[2]
    editor.kind.value = "RepeatingSequence"  # Simulink's default sawtooth on q3
    panel.motion_section.run_button.click()
    motion = panel.motion
    assert motion is not None and panel.errors == {}
    table = motion.table
    assert table.shape[0] == 201
    np.testing.assert_array_equal(
        [table[("EE", "position", axis)].iloc[0] for axis in "xyz"], [70, 0, 20]
    )
    np.testing.assert_allclose(motion.velocity[0, -1], [0, 0, -40], atol=1e-12)
    expected = rc.simulate(paper_robot(), {"q3": signals.RepeatingSequence()}, 2.0, 0.01)
    np.testing.assert_array_equal(motion.columns(), expected.columns())
    results = panel.motion_section.results
    assert "<table" in results.table.value and "70" in results.table.value
    assert "rms" in results.stats.value


def test_point_choice_filters_table_and_plots_on_demand():
    panel = make_panel(t_end=1.0, dt=0.1)
    panel.motion_section.editors[0].kind.value = "Ramp"
    panel.motion_section.run_button.click()
    results = panel.motion_section.results
    assert results.point.options[0] == "EE"
    results.point.value = "M2"
    assert "M2" in results.table.value and "EE" not in results.table.value
    assert results.plot.value == b""  # drawn only when its tab shows
    results.tabs.selected_index = 2
    assert results.plot.value[:4] == b"\x89PNG"


def test_csv_download_link_is_a_data_uri_of_the_whole_table():
    import base64

    panel = make_panel(t_end=1.0, dt=0.5)
    panel.motion_section.run_button.click()
    link = panel.motion_section.results.make_csv_link()
    href = link.split('href="')[1].split('"')[0]
    assert href.startswith("data:text/csv;base64,")
    text = base64.b64decode(href.split(",", 1)[1]).decode()
    assert text == panel.motion.table.to_csv()


def test_dt_zero_is_shown_next_to_dt_and_keeps_robot_and_motion():
    panel = make_panel(t_end=1.0, dt=0.5)
    panel.motion_section.run_button.click()
    motion, robot = panel.motion, panel.robot
    panel.motion_section.dt.value = 0.0
    panel.motion_section.run_button.click()
    assert panel.motion is motion and panel.robot == robot
    assert set(panel.errors) == {"dt"}
    assert panel.errors["dt"].startswith("dt: must be positive, got 0.0")
    assert "must be positive" in panel.motion_section.setting_errors["dt"].widget.value
    assert panel.motion_section.t_end.value == 1.0  # nothing else lost
    panel.motion_section.dt.value = 0.25
    panel.motion_section.run_button.click()
    assert panel.errors == {} and panel.motion is not motion


def test_t_end_before_t0_is_shown_next_to_t_end():
    panel = make_panel()
    panel.motion_section.t_end.value = -1.0
    panel.motion_section.run_button.click()
    assert set(panel.errors) == {"t_end"} and panel.motion is None


def test_numeric_method():
    panel = make_panel(t_end=1.0, dt=0.01)
    panel.motion_section.editors[0].kind.value = "Sine"
    panel.motion_section.method.value = "numeric"
    panel.motion_section.run_button.click()
    assert panel.motion.method == "numeric"


def test_repeating_table_is_editable_and_validated():
    panel = make_panel(t_end=4.0, dt=0.5)
    editor = panel.motion_section.editors[1]
    editor.kind.value = "RepeatingSequence"
    table = editor.table
    assert table.preview.value[:4] == b"\x89PNG"
    table.add_button.click()
    assert [b.value for b in table.times] == [0.0, 2.0, 4.0]
    table.values[2].value = 0.0  # a triangle 0 → 2 → 0
    panel.motion_section.run_button.click()
    assert panel.motion.signals["q2"] == signals.RepeatingSequence((0, 2, 4), (0, 2, 0))
    motion = panel.motion
    table.times[2].value = 1.0  # not increasing
    key = "signals.q2.table"
    assert panel.errors[key].startswith("times: times must strictly increase")
    panel.motion_section.run_button.click()
    assert panel.motion is motion
    table.times[2].value = 4.0
    assert key not in panel.errors
    table.remove_button.click()
    assert editor.build() == (True, signals.RepeatingSequence())


def test_invalid_signal_parameter_is_shown_next_to_it():
    panel = make_panel()
    editor = panel.motion_section.editors[0]
    editor.kind.value = "Sine"
    editor.parameters["frequency"].value = -1.0
    assert set(panel.errors) == {"signals.q1.frequency"}
    assert panel.errors["signals.q1.frequency"].startswith("frequency: must be ≥ 0")
    panel.motion_section.run_button.click()
    assert panel.motion is None


def test_signals_move_with_their_module_when_reordered():
    panel = make_panel()
    panel.motion_section.editors[2].kind.value = "Ramp"
    panel.modules.rows[2].up_button.click()
    assert panel.motion_section.editors[1].kind.value == "Ramp"
    assert panel.motion_section.editors[1].name == "q2"
    assert panel.motion_section.editors[2].kind.value == "hold"


def test_animation_goes_to_the_scene_and_a_changed_robot_is_noted():
    panel = make_panel(t_end=1.0, dt=0.5)
    panel.motion_section.run_button.click()
    panel.motion_section.results.animate_button.click()
    assert panel.scene.calls[-1] == ("animate", panel.motion)
    panel.modules.rows[0].q.box.value = 10.0
    assert "robot changed" in panel.motion_section.status.value
    assert panel.motion.robot == paper_robot()


@pytest.mark.parametrize("kind", ["Constant", "Step", "Ramp", "Sine", "Cubic", "Quintic"])
def test_every_signal_type_runs(kind):
    panel = make_panel(t_end=1.0, dt=0.25)
    panel.motion_section.editors[0].kind.value = kind
    panel.motion_section.run_button.click()
    assert type(panel.motion.signals["q1"]).__name__ == kind
