"""DH-table mode: rows θ, d, a, α, joint type, and the standard/modified selector."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc

from .test_panel_support import make_panel, paper_robot

ROWS = [(0.0, 20.0, 0.0, np.pi / 2, "R"), (0.0, 0.0, 30.0, 0.0, "R"), (0.0, 0.0, 40.0, 0.0, "R")]


def dh_panel(convention: str = "standard"):
    return make_panel(rc.Robot.from_dh(ROWS, convention=convention))


def test_an_all_dh_robot_opens_in_dh_mode():
    panel = dh_panel()
    assert panel.mode.value == "dh"
    assert len(panel.dh.rows) == 3
    assert panel.dh.convention.value == "standard"
    np.testing.assert_allclose(panel.robot.end_effector(), [70, 0, 20], atol=1e-12)


def test_editing_a_row_changes_the_robot():
    panel = dh_panel()
    panel.dh.rows[1].cells["a"].box.value = 50.0
    assert panel.robot.modules[1].a == 50.0
    np.testing.assert_allclose(panel.robot.end_effector(), [90, 0, 20], atol=1e-12)


def test_angles_in_the_table_are_shown_in_degrees():
    panel = dh_panel()
    assert panel.dh.rows[0].cells["alpha"].box.value == pytest.approx(90.0)
    panel.dh.rows[0].cells["alpha"].box.value = 0.0
    assert panel.robot.modules[0].alpha == 0.0
    panel.angle_unit.value = False
    assert panel.dh.rows[1].cells["theta"].unit_label.value == "rad"


def test_q_of_a_dh_row_updates_the_scene_without_rebuild():
    panel = dh_panel()
    panel.dh.rows[0].q.box.value = 90.0
    np.testing.assert_allclose(panel.robot.end_effector(), [0, 70, 20], atol=1e-12)
    assert panel.scene.names() == ["update"]


def test_convention_selector_reinterprets_every_row_when_asked_to():
    panel = dh_panel()
    panel.dh.convention.value = "modified"
    assert panel.dh.convention_prompt.visible  # asks first: the robot is unchanged
    assert panel.dh.convention.value == "standard" and panel.robot == rc.Robot.from_dh(ROWS)
    panel.dh.convention_prompt.buttons["reinterpret"].click()
    assert not panel.dh.convention_prompt.visible and panel.dh.convention.value == "modified"
    assert {link.convention for link in panel.robot.modules} == {"modified"}
    assert panel.robot == rc.Robot.from_dh(ROWS, convention="modified")
    assert "Craig" in panel.dh.convention_note.value
    assert "modified DH" in panel.matrices.text


def test_joint_type_prismatic_makes_q_a_length():
    panel = dh_panel()
    row = panel.dh.rows[2]
    row.joint.value = "P"
    assert panel.robot.modules[2].joint == "P"
    assert not row.q.angle
    row.q.box.value = 5.0
    assert panel.robot.q[2] == 5.0


def test_impossible_dh_row_shows_the_message_and_keeps_the_robot():
    panel = dh_panel()
    good = panel.robot
    panel.dh.rows[1].cells["alpha"].box.value = float("nan")
    assert panel.robot == good
    assert panel.errors == {
        "dh[1].alpha": "alpha: must be finite, got nan; allowed: a finite real number"
    }
    panel.dh.rows[1].cells["alpha"].box.value = 0.0
    assert panel.errors == {}


def test_add_remove_move_rows():
    panel = dh_panel()
    panel.dh.add_button.click()
    assert panel.robot.n == 4 and panel.robot.modules[3].joint == "R"
    panel.dh.rows[3].up_button.click()
    assert panel.robot.modules[2].a != 40.0 and panel.robot.modules[3].a == 40.0
    panel.dh.rows[2].remove_button.click()
    assert panel.robot == rc.Robot.from_dh(ROWS)


def test_opening_the_dh_table_asks_and_the_core_says_why_a_robot_cannot_convert():
    panel = make_panel()
    panel.mode.value = "dh"
    assert panel.mode.value == "modules" and panel.dh_entry.prompt.visible
    panel.dh_entry.prompt.buttons["convert"].click()  # the paper's Ry joints: no DH chain
    assert "turns about the y axis" in panel.errors["mode.dh"]
    assert panel.robot == paper_robot() and panel.dh_entry.prompt.visible
    panel.dh_entry.prompt.buttons["new"].click()  # said explicitly: a new one-row table
    assert panel.mode.value == "dh" and not panel.dh_entry.prompt.visible
    assert len(panel.dh.rows) == 1 and isinstance(panel.robot.modules[0], rc.DHLink)
    assert "mode.dh" not in panel.errors
    panel.undo()
    assert panel.robot == paper_robot() and panel.mode.value == "modules"


def test_a_modules_robot_converts_to_dh_rows_and_back_to_the_same_robot():
    arm = rc.Robot(
        [rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))], end_effector=(40, 0, 0)
    )
    panel = make_panel(arm.with_q([0.3, -0.2]))
    panel.mode.value = "dh"
    panel.dh_entry.convention.value = "modified"  # offsets before each joint: Craig's rows
    panel.dh_entry.prompt.buttons["convert"].click()
    assert panel.mode.value == "dh" and panel.dh.convention.value == "modified"
    assert [row.cells["a"].box.value for row in panel.dh.rows] == [0.0, 30.0]
    assert [row.cells["d"].box.value for row in panel.dh.rows] == [20.0, 0.0]
    expected = [40 * np.cos(0.1) + 30 * np.cos(0.3), 40 * np.sin(0.1) + 30 * np.sin(0.3), 20]
    np.testing.assert_allclose(panel.robot.end_effector(), expected, atol=1e-12)
    assert panel.robot.q.tolist() == [0.3, -0.2]
    panel.mode.value = "modules"  # DH rows → modules: the same robot, nothing to ask
    np.testing.assert_allclose(panel.robot.end_effector(), arm.end_effector([0.3, -0.2]))
    panel.undo()
    panel.undo()
    assert panel.robot == arm.with_q([0.3, -0.2])


def test_dh_robot_to_modules_and_back_gives_the_same_rows():
    panel = dh_panel()
    panel.mode.value = "modules"
    assert panel.mode.value == "modules" and panel.robot.n > 3
    assert all(isinstance(link, rc.Module) for link in panel.robot.modules)
    panel.mode.value = "dh"
    panel.dh_entry.prompt.buttons["convert"].click()  # the held constants stay constants
    assert panel.robot == rc.Robot.from_dh(ROWS)


def test_mixed_robot_shows_dh_links_read_only_in_the_module_list():
    robot = rc.Robot([rc.Module("Rz"), rc.DHLink(a=10.0)], end_effector=(5, 0, 0))
    panel = make_panel(robot)
    assert panel.mode.value == "modules"
    assert not panel.modules.rows[1].is_module
    panel.modules.rows[1].q.box.value = 90.0
    assert panel.robot.modules[1] == rc.DHLink(a=10.0, q=np.pi / 2)


@pytest.mark.skipif("puma560" not in rc.preset_names(), reason="no PUMA preset")
def test_converting_the_puma_to_modified_dh_keeps_the_robot(rng):
    puma = rc.preset("puma560")
    panel = make_panel(puma)
    panel.dh.convention.value = "modified"
    assert panel.dh.convention_prompt.visible and panel.robot == puma
    panel.dh.convention_prompt.buttons["convert"].click()
    converted = panel.robot
    assert panel.dh.convention.value == "modified" and not panel.dh.convention_prompt.visible
    assert {link.convention for link in converted.modules} == {"modified"}
    assert converted.n == 6 and len(panel.motion_section.editors) == 6
    for q in rng.uniform(-np.pi, np.pi, size=(10, 6)):
        np.testing.assert_allclose(
            converted.end_effector_pose(q), puma.end_effector_pose(q), atol=1e-12
        )
    # The numbers moved (a and α one row down), and the boxes show them clean.
    assert [row.cells["alpha"].box.value for row in panel.dh.rows] == [0, 90, 0, -90, 90, -90]
    assert panel.preset.value == ""  # the same motion, but not the preset's table
    panel.dh.convention.value = "standard"
    panel.dh.convention_prompt.buttons["convert"].click()
    assert panel.robot == puma and panel.preset.value == "puma560"
    panel.undo()
    panel.undo()
    assert panel.robot == puma and panel.dh.convention.value == "standard"


def test_a_refused_conversion_shows_the_core_message_beside_the_switch():
    robot = rc.Robot.from_dh(ROWS).with_active(2)  # the core converts whole tables only
    panel = make_panel(robot)
    panel.dh.convention.value = "modified"
    panel.dh.convention_prompt.buttons["convert"].click()
    assert "inactive rows" in panel.errors["dh.convention.convert"]
    assert panel.robot == robot and panel.dh.convention_prompt.visible
    panel.dh.convention_prompt.cancel_button.click()
    assert panel.errors == {} and panel.dh.convention.value == "standard"


def paper_style_arm() -> rc.Robot:
    """The paper's modules and offsets with every joint about z: a chain DH can hold,
    though only in modified DH (the offsets sit before each joint)."""
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def test_opening_the_dh_table_preselects_the_convention_the_robot_converts_in(rng):
    arm = paper_style_arm()
    panel = make_panel(arm)
    assert panel.dh.convention.value == "standard"  # the table's own convention
    panel.mode.value = "dh"
    entry = panel.dh_entry
    assert entry.prompt.visible and entry.convention.value == "modified"
    note = entry.note.value
    assert "modified DH preselected" in note and "standard DH cannot hold it" in note
    assert "module M3 is offset along x before its row" in note
    entry.prompt.buttons["convert"].click()  # no convention to pick by hand
    assert panel.errors == {} and panel.mode.value == "dh"
    assert panel.dh.convention.value == "modified"
    assert all(isinstance(link, rc.DHLink) for link in panel.robot.modules)
    np.testing.assert_allclose(panel.robot.end_effector(), [70, 0, 20], atol=1e-12)
    for q in rng.uniform(-np.pi, np.pi, size=(10, 3)):
        np.testing.assert_allclose(panel.robot.end_effector(q), arm.end_effector(q), atol=1e-12)


def test_the_tables_convention_stays_when_it_holds_the_robot_or_when_neither_does():
    panel = dh_panel()
    panel.mode.value = "modules"  # standard DH rows as modules: standard holds them
    panel.mode.value = "dh"
    assert panel.dh_entry.convention.value == "standard"
    assert "the table's convention, standard DH, holds this robot" in panel.dh_entry.note.value
    paper = make_panel()  # the paper's Ry joints: no DH table at all
    paper.mode.value = "dh"
    assert paper.dh_entry.convention.value == "standard"
    assert "neither DH convention holds this robot" in paper.dh_entry.note.value
    paper.dh_entry.prompt.buttons["convert"].click()
    assert "turns about the y axis" in paper.errors["mode.dh"]


def test_the_preselection_note_shows_module_names_as_text():
    arm = paper_style_arm()
    links = list(arm.modules)
    links[2] = links[2].with_name("<b>elbow</b>")
    panel = make_panel(rc.Robot(links, end_effector=(40, 0, 0)))
    panel.mode.value = "dh"
    assert "module &lt;b&gt;elbow&lt;/b&gt; is offset" in panel.dh_entry.note.value
