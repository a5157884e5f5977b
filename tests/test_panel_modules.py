"""The module list editor: every control changes panel.robot, matrices and scene as it should."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc

from .test_panel_support import FakeScene, make_panel, paper_robot


def test_initial_state_is_the_given_robot():
    panel = make_panel()
    assert panel.robot == paper_robot()
    np.testing.assert_array_equal(panel.robot.end_effector(), [70, 0, 20])
    assert panel.motion is None
    assert panel.errors == {}
    assert "p_EE = (70, 0, 20)" in panel.ee_label.value
    assert [row.kind.value for row in panel.modules.rows] == ["Rz", "Ry", "Ry"]


def test_type_dropdown_uses_the_papers_codes():
    row = make_panel().modules.rows[0]
    labels = [label for label, _ in row.kind.options]
    assert labels == ["0 none", "1 Rx", "2 Ry", "3 Rz", "4 Tx", "5 Ty", "6 Tz", "fixed"]


def test_changing_type_of_module_2_changes_robot_matrices_and_rebuilds_scene():
    panel = make_panel()
    before = panel.matrices.text
    panel.modules.rows[1].kind.value = "Tz"
    assert panel.robot.modules[1] == rc.Module("Tz", a=(0, 0, 20))
    assert panel.matrices.text != before
    assert "A2: Tz(q2)" in panel.matrices.text
    assert panel.matrices.text == str(rc.derivation(panel.robot))
    assert panel.scene.names() == ["set_robot"]
    assert panel.scene.calls[-1][1] == panel.robot


def test_q_slider_moves_the_robot_and_only_updates_the_scene():
    panel = make_panel()
    panel.modules.rows[1].q.slider.value = -90.0  # degrees by default: the arm points up
    assert panel.robot.q[1] == pytest.approx(-np.pi / 2)
    np.testing.assert_allclose(panel.robot.end_effector(), [0, 0, 90], atol=1e-12)
    assert panel.scene.names() == ["update"]
    np.testing.assert_allclose(panel.scene.calls[0][1], panel.robot.q)
    assert "p_EE = (0, 0, 90)" in panel.ee_label.value
    assert FakeScene.created >= 1


def test_number_box_and_slider_stay_in_step():
    panel = make_panel()
    control = panel.modules.rows[2].q
    control.box.value = -45.0
    assert control.slider.value == -45.0
    assert panel.robot.q[2] == pytest.approx(-np.pi / 4)


def test_typing_beyond_the_range_widens_it_and_the_widen_button_doubles_it():
    panel = make_panel()
    control = panel.modules.rows[1].offsets[2]  # az, ±100 for the paper's robot
    assert (control.slider.min, control.slider.max) == (-100.0, 100.0)
    control.box.value = 250.0
    assert control.slider.max >= 250.0 and control.slider.value == 250.0
    assert panel.robot.modules[1].a == (0.0, 0.0, 250.0)
    span = control.slider.max - control.slider.min
    control.widen_button.click()
    assert control.slider.max - control.slider.min == pytest.approx(2 * span)


def test_slider_ranges_follow_the_core_joint_limits():
    panel = make_panel(rc.Robot([rc.Module("Rz", limits=(-1.0, 2.0)), rc.Module("Tz")]))
    q1 = panel.modules.rows[0].q.slider
    # The limits (-57.3°, 114.6°) rounded outwards onto the 1° step: notches on whole degrees.
    assert (q1.min, q1.max, q1.step) == (-58.0, 115.0, 1.0)


def test_offsets_change_the_robot():
    panel = make_panel()
    panel.modules.rows[2].offsets[0].box.value = 50.0  # l2: 30 → 50
    np.testing.assert_array_equal(panel.robot.end_effector(), [90, 0, 20])
    assert panel.scene.names() == ["set_robot"]


def test_add_remove_and_reorder_modules():
    panel = make_panel()
    panel.modules.add_button.click()
    assert panel.robot.n == 4 and panel.robot.modules[3] == rc.Module("Rz")
    assert panel.extras.active.max == 4 and panel.robot.active == 4
    panel.modules.rows[3].remove_button.click()
    assert panel.robot == paper_robot()
    panel.modules.rows[2].up_button.click()  # module 3 becomes module 2
    assert panel.robot.modules[1] == rc.Module("Ry", a=(30, 0, 0))
    assert panel.robot.modules[2] == rc.Module("Ry", a=(0, 0, 20))
    assert [row.title.value for row in panel.modules.rows] == [
        "<b>M1</b>",
        "<b>M2</b>",
        "<b>M3</b>",
    ]
    panel.modules.rows[1].down_button.click()
    assert panel.robot == paper_robot()
    assert panel.modules.rows[0].up_button.disabled and panel.modules.rows[2].down_button.disabled


def test_the_last_module_cannot_be_removed():
    panel = make_panel(rc.Robot([rc.Module("Rz")]))
    panel.modules.rows[0].remove_button.click()
    assert panel.robot.n == 1
    assert "cannot remove the last module" in panel.errors["modules"]
    panel.modules.rows[0].q.box.value = 10.0  # the next valid edit: the message is old news
    assert panel.errors == {}


def test_active_count_makes_later_modules_identity():
    panel = make_panel()
    panel.extras.active.value = 2
    assert panel.robot.active == 2
    np.testing.assert_array_equal(panel.robot.end_effector(), [40, 0, 20])  # M3 = M2
    assert "inactive" in panel.matrices.text
    panel.extras.active.value = 3
    assert panel.robot.active == 3


def test_end_effector_point():
    panel = make_panel()
    panel.extras.point[0].box.value = 10.0
    np.testing.assert_array_equal(panel.robot.end_effector(), [40, 0, 20])


def test_deg_rad_toggle_changes_display_not_robot():
    panel = make_panel()
    panel.modules.rows[0].q.box.value = 90.0
    robot = panel.robot
    panel.angle_unit.value = False  # radians
    control = panel.modules.rows[0].q
    assert control.box.value == pytest.approx(np.pi / 2)
    assert control.unit_label.value == "rad"
    assert panel.robot == robot
    control.box.value = 1.0
    assert panel.robot.q[0] == 1.0
    panel.angle_unit.value = True
    assert control.box.value == pytest.approx(np.rad2deg(1.0))


def test_translation_coordinates_are_lengths():
    panel = make_panel()
    panel.modules.rows[2].kind.value = "Tx"
    control = panel.modules.rows[2].q
    assert not control.angle and control.unit_label.value == "length"
    control.box.value = 5.0
    assert panel.robot.q[2] == 5.0  # no degree conversion for a length


def test_none_and_fixed_grey_out_what_they_ignore():
    panel = make_panel()
    row = panel.modules.rows[2]
    row.kind.value = "fixed"
    assert row.q.box.disabled and not row.offsets[0].box.disabled
    row.kind.value = "none"
    assert row.offsets[0].box.disabled
    assert panel.robot.modules[2].kind == "none"


def test_typed_nan_shows_the_core_message_and_keeps_the_last_robot():
    panel = make_panel()
    panel.modules.rows[0].q.box.value = 30.0
    good = panel.robot
    panel.scene.calls.clear()
    panel.modules.rows[1].offsets[2].box.value = float("nan")
    assert panel.robot == good
    assert panel.errors == {
        "modules[1].az": "az: must be finite, got nan; allowed: a finite real number"
    }
    assert "must be finite" in panel.modules.rows[1].offsets[2].error.widget.value
    assert panel.scene.calls == []
    # Other controls keep their values, and the robot follows again once fixed.
    assert panel.modules.rows[0].q.box.value == 30.0
    panel.modules.rows[1].offsets[2].box.value = 25.0
    assert panel.errors == {}
    assert panel.robot.modules[1].a == (0.0, 0.0, 25.0)
    assert panel.robot.q[0] == pytest.approx(np.pi / 6)


def test_nan_in_end_effector_is_refused_next_to_it():
    panel = make_panel()
    panel.extras.point[2].box.value = float("inf")
    assert set(panel.errors) == {"end_effector.Pz"}
    assert panel.robot == paper_robot()


def test_presets_load_into_the_editors():
    if not hasattr(rc, "preset_names"):
        pytest.skip("presets not available in this robotconf")
    panel = make_panel()
    assert "paper" in [value for _, value in panel.preset.options]
    panel.preset.value = "cartesian"
    assert panel.robot == rc.preset("cartesian")
    assert panel.scene.names()[-1] == "set_robot"
    panel.preset.value = "paper"
    assert panel.robot == rc.preset("paper")
    np.testing.assert_array_equal(panel.robot.end_effector(), [70, 0, 20])
    panel.modules.rows[0].q.box.value = 10.0  # an edit: no longer the preset
    assert panel.preset.value == ""
    assert panel.robot.modules[0].limits == rc.preset("paper").modules[0].limits


def test_dh_preset_opens_the_dh_table():
    if not hasattr(rc, "preset_names") or "puma560" not in rc.preset_names():
        pytest.skip("the puma560 preset is not available")
    panel = make_panel()
    panel.preset.value = "puma560"
    assert panel.mode.value == "dh"
    assert panel.robot == rc.preset("puma560")
    assert len(panel.dh.rows) == 6


def test_set_robot_rejects_non_robots():
    with pytest.raises(rc.InvalidInputError, match="robot"):
        make_panel().set_robot("paper")  # type: ignore[arg-type]


def test_the_trash_button_deletes_and_undo_brings_the_row_back_with_its_signal():
    panel = make_panel()
    panel.modules.rows[1].q.box.value = -30.0
    panel.motion_section.editors[2].kind.value = "Sine"  # q3's signal
    edited = panel.robot
    panel.modules.rows[1].remove_button.click()  # module 2 goes; q3 becomes q2
    assert panel.robot.n == 2 and panel.motion_section.editors[1].kind.value == "Sine"
    panel.undo()
    assert panel.robot == edited
    np.testing.assert_allclose(panel.robot.end_effector(), edited.end_effector())
    assert panel.modules.rows[1].q.box.value == -30.0
    assert [e.kind.value for e in panel.motion_section.editors][2] == "Sine"  # with q3 again
    panel.redo()
    assert panel.robot.n == 2 and panel.motion_section.editors[1].kind.value == "Sine"


def test_moves_are_undone_one_by_one():
    panel = make_panel()
    panel.modules.rows[2].up_button.click()
    panel.modules.rows[1].up_button.click()  # M3 is now first
    assert panel.robot.modules[0] == rc.Module("Ry", a=(30, 0, 0))
    panel.undo()
    assert panel.robot.modules[1] == rc.Module("Ry", a=(30, 0, 0))
    panel.undo()
    assert panel.robot == paper_robot()
