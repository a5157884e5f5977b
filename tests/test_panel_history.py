"""Undo and redo of the panel's document (robot, signals, time settings, program), the
preset dropdown that follows the robot, and messages that go when they are stale."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals
from robotconf.panel import actions as act
from robotconf.panel.state import HISTORY_LIMIT, History

from .test_panel_support import make_panel, paper_robot, shown, ui


class Clock:
    """A clock a test moves by hand."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now


def timed_panel(robot=None):
    panel = make_panel(robot)
    clock = Clock()
    panel._history._clock = clock
    return panel, clock


# -- undo and redo ------------------------------------------------------------------------


def test_undo_brings_back_a_deleted_module_with_its_values():
    panel = make_panel()
    ui(panel, "modules[1].delete").click()  # module 2: Ry with az = 20
    np.testing.assert_allclose(panel.robot.end_effector(), [70, 0, 0], atol=1e-12)
    panel.undo()
    assert panel.robot == paper_robot()
    np.testing.assert_array_equal(panel.robot.end_effector(), [70, 0, 20])
    assert [shown(panel, f"modules[{i}].kind")["value"] for i in range(3)] == ["Rz", "Ry", "Ry"]
    assert shown(panel, "modules[1].az")["value"] == 20.0
    assert len(panel.state.document.motion.signals) == 3
    assert panel.scene.robot == paper_robot()
    panel.redo()
    assert panel.robot.n == 2 and panel.robot.modules[1] == rc.Module("Ry", a=(30, 0, 0))


def test_the_buttons_undo_and_redo_and_are_disabled_when_there_is_nothing():
    panel = make_panel()
    assert shown(panel, "undo").get("disabled") and shown(panel, "redo").get("disabled")
    assert "undo" in shown(panel, "undo")["title"] and "redo" in shown(panel, "redo")["title"]
    ui(panel, "modules.add").click()
    assert not shown(panel, "undo").get("disabled") and shown(panel, "redo").get("disabled")
    ui(panel, "undo").click()
    assert panel.robot == paper_robot() and shown(panel, "undo").get("disabled")
    ui(panel, "redo").click()
    assert panel.robot.n == 4 and shown(panel, "redo").get("disabled")


def test_a_slider_drag_is_one_undo_step_and_separate_edits_are_separate():
    panel, clock = timed_panel()
    for degrees in range(0, 46, 5):  # the slider sends every notch
        ui(panel, "modules[1].q").drag(float(degrees))
        clock.now += 0.05
    assert panel.robot.q[1] == pytest.approx(np.deg2rad(45))
    clock.now += 5.0
    ui(panel, "modules[2].ax").type("50")  # l2: 30 → 50
    clock.now += 0.2
    ui(panel, "modules[2].ax").type("55")  # a second entry, same box: merged
    assert len(panel._history) == 3
    panel.undo()
    assert panel.robot.modules[2].a == (30.0, 0.0, 0.0)
    assert panel.robot.q[1] == pytest.approx(np.deg2rad(45))
    panel.undo()
    assert panel.robot == paper_robot()


def test_the_same_control_after_a_pause_is_a_new_step():
    panel, clock = timed_panel()
    ui(panel, "modules[0].q").type("10")
    clock.now += 10.0
    ui(panel, "modules[0].q").type("20")
    panel.undo()
    assert panel.robot.q[0] == pytest.approx(np.deg2rad(10.0))


def test_typing_back_the_old_value_leaves_no_step():
    panel = make_panel()
    ui(panel, "modules[0].q").type("10")
    ui(panel, "modules[0].q").type("0")
    assert panel.robot == paper_robot() and not panel.can_undo


def test_an_edit_after_undo_forgets_the_redo():
    panel = make_panel()
    ui(panel, "modules.add").click()
    panel.undo()
    ui(panel, "end_effector.Px").type("10")
    assert not panel.can_redo
    np.testing.assert_array_equal(panel.robot.end_effector(), [40, 0, 20])


def test_signals_settings_and_program_edits_are_undone_too():
    panel, clock = timed_panel()
    ui(panel, "signals.q1").choose("Sine")
    clock.now += 5
    ui(panel, "dt").type("0.02")
    clock.now += 5
    panel.apply(act.AddMove())
    assert panel.state.document.program.moves
    panel.undo()
    assert panel.state.document.program.moves == ()
    panel.undo()
    assert panel.state.document.motion.settings.dt == 0.01
    panel.undo()
    assert panel.state.document.motion.signals == (None, None, None)
    for _ in range(3):
        panel.redo()
    assert panel.state.document.motion.signals[0] == signals.Sine()
    assert panel.state.document.motion.settings.dt == 0.02 and panel.program is not None


def test_preset_file_load_wizard_and_mode_switch_are_undoable(tmp_path):
    panel = make_panel()
    ui(panel, "preset").choose("puma560")
    assert panel.state.mode == "dh"
    path = tmp_path / "two.json"
    make_panel(rc.Robot([rc.Module("Tz")], end_effector=(1, 0, 0))).save(path)
    panel.load(path)
    assert panel.robot.modules == (rc.Module("Tz"),)
    ui(panel, "mode").choose("wizard")
    ui(panel, "wizard.count").type("1")
    for _ in range(6):
        ui(panel, "wizard.next").click()
    assert panel.robot.modules == (rc.Module("Rz"),)
    ui(panel, "mode").choose("dh")
    ui(panel, "mode.dh.new").click()
    assert isinstance(panel.robot.modules[0], rc.DHLink)
    panel.undo()  # the new table
    assert panel.robot.modules == (rc.Module("Rz"),) and panel.state.mode == "modules"
    panel.undo()  # the wizard's robot
    assert panel.robot.modules == (rc.Module("Tz"),)
    panel.undo()  # the file
    assert panel.robot == rc.preset("puma560") and panel.state.mode == "dh"
    assert shown(panel, "preset")["value"] == "puma560"
    panel.undo()  # the preset
    assert panel.robot == paper_robot() and panel.state.mode == "modules"


def test_the_history_keeps_at_most_its_limit():
    history = History(0)
    for k in range(HISTORY_LIMIT + 50):
        history.record(k + 1)
    assert len(history) == HISTORY_LIMIT == 200
    while history.can_undo:
        oldest = history.undo()
    assert oldest == 51


def test_a_gesture_that_comes_back_to_its_start_leaves_no_step():
    history = History("a", clock=lambda: 0.0)
    history.record("b", gesture="box")
    history.record("a", gesture="box")
    assert len(history) == 1 and not history.can_undo


def test_undo_clears_a_pending_bad_value():
    panel = make_panel()
    ui(panel, "modules[0].q").type("30")
    ui(panel, "modules[1].az").type("nan")
    assert "modules[1].az" in panel.errors
    panel.undo()
    assert panel.robot == paper_robot() and panel.errors == {}
    assert shown(panel, "modules[1].az")["value"] == 20.0 and "text" not in shown(
        panel, "modules[1].az"
    )


def test_undo_then_redo_is_the_identity():
    panel, clock = timed_panel()
    ui(panel, "modules[0].q").type("10")
    clock.now += 5
    ui(panel, "signals.q2").choose("Ramp")
    document = panel.state.document
    panel.undo()
    panel.redo()
    assert panel.state.document == document


# -- the preset dropdown ---------------------------------------------------------------------


def test_the_preset_dropdown_names_the_preset_the_robot_is():
    panel = make_panel(rc.preset("paper"))
    assert shown(panel, "preset")["value"] == "paper"  # not "— preset —"
    ui(panel, "preset").choose("cartesian")
    assert shown(panel, "preset")["value"] == "cartesian"
    ui(panel, "modules[0].q").type("5")  # edited away from it
    assert shown(panel, "preset")["value"] == ""
    panel.undo()
    assert shown(panel, "preset")["value"] == "cartesian"
    panel.set_robot(rc.preset("paper"))  # from elsewhere, but the same robot
    assert shown(panel, "preset")["value"] == "paper"


def test_choosing_no_preset_changes_nothing():
    panel = make_panel(rc.preset("paper"))
    ui(panel, "preset").choose("")
    assert shown(panel, "preset")["value"] == "paper" and panel.robot == rc.preset("paper")
    assert not panel.can_undo


# -- stale messages ------------------------------------------------------------------------


def _status(panel) -> str:
    return next(
        c["value"]
        for r in panel.motion_tab.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-run-status"
    )


def test_press_run_goes_when_the_robot_is_the_simulated_one_again(tmp_path):
    panel = make_panel(t_end=1.0, dt=0.5)
    ui(panel, "run").click()
    assert "3 samples" in _status(panel)
    ui(panel, "modules[0].q").type("10")
    assert "press Run" in _status(panel)
    panel.undo()
    assert "press Run" not in _status(panel) and "3 samples" in _status(panel)
    path = tmp_path / "same.json"
    panel.save(path)
    panel.load(path)  # an identical robot
    assert "press Run" not in _status(panel)


def test_a_dt_message_goes_when_dt_is_fixed():
    panel = make_panel()
    ui(panel, "dt").type("0")
    assert panel.errors["dt"].startswith("dt: must be positive")
    ui(panel, "t_end").type("2")  # another setting: dt's message stays
    assert "dt" in panel.errors
    ui(panel, "dt").type("0.05")
    assert panel.errors == {}
