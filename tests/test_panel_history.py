"""Undo and redo in the panel, the preset dropdown that follows the robot, stale messages."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.panel._history import HISTORY_LIMIT, History

from .test_panel_support import make_panel, paper_robot


class Clock:
    """A clock a test moves by hand."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now


def timed_panel(robot=None):
    panel = make_panel(robot)
    clock = Clock()
    panel.history.history._clock = clock
    return panel, clock


# -- undo and redo ------------------------------------------------------------------------


def test_undo_brings_back_a_deleted_module_with_its_values():
    panel = make_panel()
    panel.modules.rows[1].remove_button.click()  # module 2: Ry with az = 20
    np.testing.assert_allclose(panel.robot.end_effector(), [70, 0, 0], atol=1e-12)
    assert panel.robot.n == 2
    panel.undo()
    assert panel.robot == paper_robot()
    np.testing.assert_array_equal(panel.robot.end_effector(), [70, 0, 20])
    assert [row.kind.value for row in panel.modules.rows] == ["Rz", "Ry", "Ry"]
    assert panel.modules.rows[1].offsets[2].box.value == 20.0
    assert len(panel.motion_section.editors) == 3
    assert panel.scene.calls[-1] == ("set_robot", paper_robot())
    panel.redo()
    assert panel.robot.n == 2 and panel.robot.modules[1] == rc.Module("Ry", a=(30, 0, 0))


def test_the_buttons_undo_and_redo_and_are_disabled_when_there_is_nothing():
    panel = make_panel()
    undo, redo = panel.history.undo_button, panel.history.redo_button
    assert undo.disabled and redo.disabled
    assert "undo" in undo.tooltip and "redo" in redo.tooltip
    panel.modules.add_button.click()
    assert not undo.disabled and redo.disabled
    undo.click()
    assert panel.robot == paper_robot() and undo.disabled and not redo.disabled
    redo.click()
    assert panel.robot.n == 4 and redo.disabled


def test_a_slider_drag_is_one_undo_step_and_separate_edits_are_separate():
    panel, clock = timed_panel()
    for degrees in range(0, 46, 5):  # the slider fires at every notch
        panel.modules.rows[1].q.slider.value = float(degrees)
        clock.now += 0.05
    assert panel.robot.q[1] == pytest.approx(np.deg2rad(45))
    clock.now += 5.0
    panel.modules.rows[2].offsets[0].box.value = 50.0  # l2: 30 → 50
    clock.now += 0.2
    panel.modules.rows[2].offsets[0].box.value = 55.0  # a second commit, same box: merged
    assert len(panel.history.history) == 3
    panel.undo()
    assert panel.robot.modules[2].a == (30.0, 0.0, 0.0)
    assert panel.robot.q[1] == pytest.approx(np.deg2rad(45))
    panel.undo()
    assert panel.robot == paper_robot()


def test_the_same_control_after_a_pause_is_a_new_step():
    panel, clock = timed_panel()
    panel.modules.rows[0].q.box.value = 10.0
    clock.now += 10.0
    panel.modules.rows[0].q.box.value = 20.0
    panel.undo()
    assert panel.robot.q[0] == pytest.approx(np.deg2rad(10.0))


def test_typing_back_the_old_value_leaves_no_step():
    panel = make_panel()
    panel.modules.rows[0].q.box.value = 10.0
    panel.modules.rows[0].q.box.value = 0.0
    assert panel.robot == paper_robot()
    assert panel.history.undo_button.disabled


def test_an_edit_after_undo_forgets_the_redo():
    panel = make_panel()
    panel.modules.add_button.click()
    panel.undo()
    panel.extras.point[0].box.value = 10.0
    assert panel.history.redo_button.disabled
    np.testing.assert_array_equal(panel.robot.end_effector(), [40, 0, 20])


@pytest.mark.skipif("puma560" not in rc.preset_names(), reason="no PUMA preset")
def test_preset_load_file_load_wizard_and_mode_switch_are_undoable(tmp_path):
    panel = make_panel()
    panel.preset.value = "puma560"
    assert panel.mode.value == "dh"
    path = tmp_path / "two.json"
    make_panel(rc.Robot([rc.Module("Tz")], end_effector=(1, 0, 0))).save(path)
    panel.load(path)
    assert panel.robot.modules == (rc.Module("Tz"),)
    panel.mode.value = "wizard"
    panel.wizard.count.value = 1
    for _ in range(6):
        panel.wizard.next_button.click()
    assert panel.robot.modules == (rc.Module("Rz"),)
    panel.mode.value = "dh"
    panel.dh_entry.prompt.buttons["new"].click()
    assert isinstance(panel.robot.modules[0], rc.DHLink)
    panel.undo()  # the new table
    assert panel.robot.modules == (rc.Module("Rz"),) and panel.mode.value == "modules"
    panel.undo()  # the wizard's robot
    assert panel.robot.modules == (rc.Module("Tz"),)
    panel.undo()  # the file
    assert panel.robot == rc.preset("puma560") and panel.mode.value == "dh"
    assert panel.preset.value == "puma560"
    panel.undo()  # the preset
    assert panel.robot == paper_robot() and panel.mode.value == "modules"


def test_the_history_keeps_at_most_its_limit():
    arm = rc.Robot([rc.Module("Tz")])
    history = History(arm)
    for k in range(HISTORY_LIMIT + 50):
        history.record(arm.with_end_effector((k + 1, 0, 0)), coalesce=False)
    assert len(history) == HISTORY_LIMIT == 200
    while history.can_undo:
        oldest = history.undo()
    assert oldest.end_effector_point[0] == 51.0


def test_undo_clears_a_pending_bad_value():
    panel = make_panel()
    panel.modules.rows[0].q.box.value = 30.0
    panel.modules.rows[1].offsets[2].box.value = float("nan")
    assert "modules[1].az" in panel.errors
    panel.undo()
    assert panel.robot == paper_robot() and panel.errors == {}
    assert panel.modules.rows[1].offsets[2].box.value == 20.0


# -- the preset dropdown ---------------------------------------------------------------------


def test_the_preset_dropdown_names_the_preset_the_robot_is():
    panel = make_panel(rc.preset("paper"))
    assert panel.preset.value == "paper"  # not "— preset —"
    panel.preset.value = "cartesian"
    assert panel.preset.value == "cartesian" and panel.robot == rc.preset("cartesian")
    panel.modules.rows[0].q.box.value = 5.0  # edited away from it
    assert panel.preset.value == ""
    panel.undo()
    assert panel.preset.value == "cartesian"
    panel.set_robot(rc.preset("paper"))  # from elsewhere, but the same robot
    assert panel.preset.value == "paper"


def test_choosing_no_preset_changes_nothing():
    panel = make_panel(rc.preset("paper"))
    panel.preset.value = ""
    assert panel.preset.value == "paper" and panel.robot == rc.preset("paper")
    assert panel.history.undo_button.disabled


# -- stale messages ------------------------------------------------------------------------


def test_press_run_goes_when_the_robot_is_the_simulated_one_again(tmp_path):
    panel = make_panel(t_end=1.0, dt=0.5)
    panel.motion_section.run_button.click()
    status = panel.motion_section.status
    assert "3 samples" in status.value
    panel.modules.rows[0].q.box.value = 10.0
    assert "press Run" in status.value
    panel.undo()
    assert "press Run" not in status.value and "3 samples" in status.value
    path = tmp_path / "same.json"
    panel.save(path)
    panel.load(path)  # an identical robot
    assert "press Run" not in status.value


def test_a_dt_message_goes_when_dt_is_fixed():
    panel = make_panel()
    section = panel.motion_section
    section.dt.value = 0.0
    section.run_button.click()
    assert panel.errors["dt"].startswith("dt: must be positive")
    section.t_end.value = 2.0  # another setting: dt is still wrong
    assert "dt" in panel.errors
    section.dt.value = 0.05
    assert "dt" not in panel.errors and panel.errors == {}
