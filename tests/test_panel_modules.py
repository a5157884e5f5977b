"""The module list editor: every control changes panel.robot, the matrices and the scene
as it should, through one action each; refused input keeps the robot."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.panel import actions as act

from .test_panel_support import FakeScene, make_panel, note, paper_robot, shown, ui


def test_initial_state_is_the_given_robot():
    panel = make_panel()
    assert panel.robot == paper_robot() and panel.state.robot is panel.robot
    np.testing.assert_array_equal(panel.robot.end_effector(), [70, 0, 20])
    assert panel.motion is None and panel.errors == {}
    assert "p_EE = (70, 0, 20)" in panel.ee_label.value
    assert [shown(panel, f"modules[{i}].kind")["value"] for i in range(3)] == ["Rz", "Ry", "Ry"]
    assert panel.scene.names() == ["show"] and panel.scene.robot == panel.robot


def test_type_dropdown_uses_the_papers_codes():
    options = shown(make_panel(), "modules[0].kind")["options"]
    labels = [label for label, _ in options]
    assert labels == ["0 none", "1 Rx", "2 Ry", "3 Rz", "4 Tx", "5 Ty", "6 Tz", "fixed"]


def test_changing_the_type_of_module_2_changes_the_robot_and_redraws_it():
    panel = make_panel()
    panel.scene.calls.clear()
    ui(panel, "modules[1].kind").choose("Tz")
    assert panel.robot.modules[1] == rc.Module("Tz", a=(0, 0, 20))
    assert "A2: Tz(q2)" in panel.matrices.text(panel.state)
    shown = panel.matrices.text(panel.state)  # the core's printout, q in the panel's units
    assert "at q = (0°, 0 units, 0°)" in shown
    assert shown.replace("(0°, 0 units, 0°)", "(0, 0, 0)") == str(rc.derivation(panel.robot))
    assert panel.scene.names() == ["show"] and panel.scene.robot == panel.robot


def test_a_q_drag_moves_the_robot_and_draws_one_snapshot():
    panel = make_panel()
    panel.scene.calls.clear()
    ui(panel, "modules[1].q").drag(-90.0)  # degrees by default: the arm points up
    assert panel.robot.q[1] == pytest.approx(-np.pi / 2)
    np.testing.assert_allclose(panel.robot.end_effector(), [0, 0, 90], atol=1e-12)
    assert panel.scene.names() == ["show"]
    snapshot = panel.scene.calls[0][1]
    assert snapshot.robot is panel.robot  # the snapshot of the very robot on screen
    np.testing.assert_array_equal(snapshot.end_effector, panel.robot.end_effector())
    assert "p_EE = (0, 0, 90)" in panel.ee_label.value
    assert FakeScene.created >= 1


@pytest.mark.parametrize("tab", ["motion", "program"])
def test_a_q_step_checks_q_once_and_runs_the_kernel_once(monkeypatch, tab):
    import robotconf.kinematics.kernel._kernel as kernel
    import robotconf.kinematics.robot._chain as chain_module
    import robotconf.kinematics.robot._robot as robot_module
    import robotconf.kinematics.robot._snapshot as snapshot

    panel = make_panel()
    panel.apply(act.SelectTab(tab))
    ui(panel, "modules[1].q").drag(-80.0)
    counts = {"checks": 0, "passes": 0}

    def counted(name, function):  # type: ignore[no-untyped-def]
        def call(*args, **kwargs):  # type: ignore[no-untyped-def]
            counts[name] += 1
            return function(*args, **kwargs)

        return call

    check = robot_module.check_configuration
    monkeypatch.setattr(robot_module, "check_configuration", counted("checks", check))
    chain_check = chain_module.check_configuration
    monkeypatch.setattr(chain_module, "check_configuration", counted("checks", chain_check))
    monkeypatch.setattr(kernel, "_run", counted("passes", kernel._run))
    monkeypatch.setattr(snapshot, "run_chain", counted("passes", snapshot.run_chain))
    ui(panel, "modules[1].q").drag(-90.0)
    # The header's p_EE, the editor, the 3D view (and the Program tab's points) share one
    # snapshot of the robot at its new q.
    assert counts == {"checks": 1, "passes": 1}
    np.testing.assert_allclose(panel.scene.snapshot.end_effector, [0, 0, 90], atol=1e-12)


def test_the_box_and_the_slider_show_one_number():
    panel = make_panel()
    ui(panel, "modules[2].q").type("-45")
    control = shown(panel, "modules[2].q")
    assert control["value"] == -45.0 and control["slider"]
    assert panel.robot.q[2] == pytest.approx(-np.pi / 4)


def test_a_value_beyond_the_range_widens_it_and_the_widen_button_doubles_it():
    panel = make_panel()
    control = shown(panel, "modules[1].az")  # az, ±100 for the paper's robot
    assert (control["min"], control["max"], control["step"]) == (-100.0, 100.0, 1.0)
    ui(panel, "modules[1].az").type("250")
    control = shown(panel, "modules[1].az")
    assert control["max"] >= 250.0 and control["value"] == 250.0
    assert panel.robot.modules[1].a == (0.0, 0.0, 250.0)
    before = shown(panel, "modules[0].ax")  # the robot grew: ±500 now
    ui(panel, "modules[0].ax").widen()
    control = shown(panel, "modules[0].ax")
    assert (control["min"], control["max"]) == (2 * before["min"], 2 * before["max"])
    assert panel.robot == panel.robot.with_q(panel.robot.q)  # widening changes no number


def test_slider_ranges_follow_the_core_joint_limits():
    panel = make_panel(rc.Robot([rc.Module("Rz", limits=(-1.0, 2.0)), rc.Module("Tz")]))
    q1 = shown(panel, "modules[0].q")
    # The limits (-57.3°, 114.6°) rounded outwards onto the 1° step: notches on whole degrees.
    assert (q1["min"], q1["max"], q1["step"]) == (-58.0, 115.0, 1.0)


def test_a_q_beyond_its_joint_range_says_so_and_is_kept():
    panel = make_panel(rc.Robot([rc.Module("Rz", limits=(-1.0, 1.0))], end_effector=(1, 0, 0)))
    ui(panel, "modules[0].q").type("120")
    assert panel.robot.q[0] == pytest.approx(np.radians(120))
    warning = shown(panel, "modules[0].q")["message"]
    assert (
        warning["tone"] == "warning"
        and "beyond its range −57.2958 … 57.2958 deg" in (warning["text"])
    )
    assert panel.errors == {}  # allowed, but never silently
    ui(panel, "modules[0].q").type("10")
    assert "message" not in shown(panel, "modules[0].q")


def test_offsets_change_the_robot():
    panel = make_panel()
    panel.scene.calls.clear()
    ui(panel, "modules[2].ax").type("50")  # l2: 30 → 50
    np.testing.assert_array_equal(panel.robot.end_effector(), [90, 0, 20])
    assert panel.scene.names() == ["show"]


def test_add_remove_and_reorder_modules():
    panel = make_panel()
    ui(panel, "modules.add").click()
    assert panel.robot.n == 4 and panel.robot.modules[3] == rc.Module("Rz")
    assert panel.robot.active == 4 and shown(panel, "active")["value"] == 4.0
    ui(panel, "modules[3].delete").click()
    assert panel.robot == paper_robot()
    ui(panel, "modules[2].up").click()  # module 3 becomes module 2
    assert panel.robot.modules[1] == rc.Module("Ry", a=(30, 0, 0))
    assert panel.robot.modules[2] == rc.Module("Ry", a=(0, 0, 20))
    ui(panel, "modules[1].down").click()
    assert panel.robot == paper_robot()
    assert shown(panel, "modules[0].up").get("disabled")
    assert shown(panel, "modules[2].down").get("disabled")


def test_the_last_module_cannot_be_removed():
    panel = make_panel(rc.Robot([rc.Module("Rz")]))
    ui(panel, "modules[0].delete").click()
    assert panel.robot.n == 1
    assert "cannot remove the last module" in panel.errors["modules[0]"]
    ui(panel, "modules[0].delete").click()  # the same control again: still refused
    ui(panel, "modules[0].q").type("10")  # another control works; its own message stays
    assert panel.robot.q[0] == pytest.approx(np.radians(10))


def test_the_active_count_makes_later_modules_identity():
    panel = make_panel()
    ui(panel, "active").type("2")
    assert panel.robot.active == 2
    np.testing.assert_array_equal(panel.robot.end_effector(), [40, 0, 20])  # M3 = M2
    assert "inactive" in panel.matrices.text(panel.state)
    ui(panel, "active").type("2.5")
    assert "whole number" in panel.errors["active"] and panel.robot.active == 2
    ui(panel, "active").type("3")
    assert panel.robot.active == 3 and panel.errors == {}


def test_end_effector_point():
    panel = make_panel()
    ui(panel, "end_effector.Px").type("10")
    np.testing.assert_array_equal(panel.robot.end_effector(), [40, 0, 20])


def test_deg_rad_switch_changes_the_display_not_the_robot():
    panel = make_panel()
    ui(panel, "modules[0].q").type("90")
    robot = panel.robot
    ui(panel, "angle_unit").choose(False)  # radians
    control = shown(panel, "modules[0].q")
    assert control["value"] == pytest.approx(np.pi / 2) and control["unit"] == "rad"
    assert panel.robot is robot  # not a copy: nothing changed
    ui(panel, "modules[0].q").type("1")
    assert panel.robot.q[0] == 1.0
    ui(panel, "angle_unit").choose(True)
    assert shown(panel, "modules[0].q")["value"] == pytest.approx(np.rad2deg(1.0))


def test_a_drag_made_before_a_unit_switch_is_stale_and_changes_nothing():
    panel = make_panel()
    form = panel.editor.form
    rev = form.control("modules[1].q")["rev"]
    ui(panel, "angle_unit").choose(False)  # the slider's numbers mean radians now
    form.receive({"key": "modules[1].q", "event": "drag", "value": 30.0, "rev": rev, "seq": 1})
    assert panel.robot == paper_robot()  # 30 (degrees, sent late) is not read as 30 rad


def test_translation_coordinates_are_lengths():
    panel = make_panel()
    ui(panel, "modules[2].kind").choose("Tx")
    control = shown(panel, "modules[2].q")
    assert control["unit"] == "units"
    ui(panel, "modules[2].q").type("5")
    assert panel.robot.q[2] == 5.0  # no degree conversion for a length


def test_none_and_fixed_grey_out_what_they_ignore():
    panel = make_panel()
    ui(panel, "modules[2].kind").choose("fixed")
    assert shown(panel, "modules[2].q").get("disabled")
    assert not shown(panel, "modules[2].ax").get("disabled")
    ui(panel, "modules[2].kind").choose("none")
    assert shown(panel, "modules[2].ax").get("disabled")
    assert panel.robot.modules[2].kind == "none"


@pytest.mark.parametrize(
    ("typed", "message"),
    [
        ("nan", "not a number: 'nan'"),
        ("abc", "not a number: 'abc'"),
        ("1e999", "too large for a number: '1e999'"),
        ("1e200", "too large"),
    ],
)
def test_bad_text_shows_a_message_beside_the_box_and_keeps_the_robot(typed, message):
    panel = make_panel()
    ui(panel, "modules[0].q").type("30")
    good = panel.robot
    panel.scene.calls.clear()
    ui(panel, "modules[1].az").type(typed)
    assert panel.robot is good and panel.scene.calls == []
    assert message in panel.errors["modules[1].az"]
    control = shown(panel, "modules[1].az")
    assert control["text"] == typed and control["message"]["tone"] == "error"  # no revert
    assert shown(panel, "modules[0].q")["value"] == 30.0
    ui(panel, "modules[1].az").type("25")
    assert panel.errors == {} and panel.robot.modules[1].a == (0.0, 0.0, 25.0)
    assert panel.robot.q[0] == pytest.approx(np.pi / 6)


def test_nan_in_the_end_effector_is_refused_beside_it():
    panel = make_panel()
    ui(panel, "end_effector.Pz").type("inf")
    assert set(panel.errors) == {"end_effector.Pz"} and panel.robot == paper_robot()


def test_presets_load_into_the_editors():
    panel = make_panel()
    assert "paper" in [value for _, value in shown(panel, "preset")["options"]]
    ui(panel, "preset").choose("cartesian")
    assert panel.robot == rc.preset("cartesian") and panel.scene.names()[-1] == "show"
    ui(panel, "preset").choose("paper")
    assert panel.robot == rc.preset("paper") and shown(panel, "preset")["value"] == "paper"
    ui(panel, "modules[0].q").type("10")  # an edit: no longer the preset
    assert shown(panel, "preset")["value"] == ""
    assert panel.robot.modules[0].limits == rc.preset("paper").modules[0].limits
    ui(panel, "preset").choose("")  # "— preset —" is a reading, not a choice
    assert panel.robot.q[0] == pytest.approx(np.radians(10))


def test_a_dh_preset_opens_the_dh_table():
    panel = make_panel()
    ui(panel, "preset").choose("puma560")
    assert panel.state.mode == "dh" and panel.robot == rc.preset("puma560")
    assert [key for key in panel.editor.form.control_keys() if key.endswith(".alpha")] == [
        f"dh[{i}].alpha" for i in range(6)
    ]


def test_set_robot_refuses_non_robots():
    with pytest.raises(rc.InvalidInputError, match="robot"):
        make_panel().set_robot("paper")  # type: ignore[arg-type]


def test_the_delete_button_removes_and_undo_brings_the_row_back_with_its_signal():
    panel = make_panel()
    ui(panel, "modules[1].q").type("-30")
    ui(panel, "signals.q3").choose("Sine")
    edited = panel.robot
    ui(panel, "modules[1].delete").click()  # module 2 goes; q3 becomes q2
    assert panel.robot.n == 2 and panel.state.document.motion.signals == (None, rc.signals.Sine())
    panel.undo()
    assert panel.robot == edited and shown(panel, "modules[1].q")["value"] == -30.0
    assert panel.state.document.motion.signals[2] == rc.signals.Sine()  # with q3 again
    panel.redo()
    assert panel.robot.n == 2 and panel.state.document.motion.signals[1] == rc.signals.Sine()


def test_moves_are_undone_one_by_one():
    panel = make_panel()
    ui(panel, "modules[2].up").click()
    ui(panel, "modules[1].up").click()  # M3 is now first
    assert panel.robot.modules[0] == rc.Module("Ry", a=(30, 0, 0))
    panel.undo()
    assert panel.robot.modules[1] == rc.Module("Ry", a=(30, 0, 0))
    panel.undo()
    assert panel.robot == paper_robot()


def test_apply_is_the_same_path_as_a_click():
    clicked, applied = make_panel(), make_panel()
    ui(clicked, "modules[1].kind").choose("Rx")
    applied.apply(act.SetModuleKind(1, "Rx"))
    assert clicked.state.document == applied.state.document
    with pytest.raises(rc.InvalidInputError, match="kind"):
        applied.apply(act.SetModuleKind(1, "Rw"))
    assert applied.state.document == clicked.state.document  # refused: nothing changed


def test_messages_name_the_field_and_the_value():
    panel = make_panel()
    ui(panel, "modules[1].az").type("x")
    assert note(panel, "modules[1].az").startswith("az: not a number: 'x'; allowed: ")
