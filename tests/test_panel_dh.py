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


def test_convention_selector_switches_every_row():
    panel = dh_panel()
    panel.dh.convention.value = "modified"
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


def test_switching_modes_keeps_each_editor_content():
    panel = make_panel()
    panel.mode.value = "dh"  # empty table: seeded with one revolute row
    assert len(panel.dh.rows) == 1
    assert isinstance(panel.robot.modules[0], rc.DHLink)
    panel.mode.value = "modules"
    assert panel.robot == paper_robot()
    panel.mode.value = "dh"
    assert panel.robot.n == 1


def test_mixed_robot_shows_dh_links_read_only_in_the_module_list():
    robot = rc.Robot([rc.Module("Rz"), rc.DHLink(a=10.0)], end_effector=(5, 0, 0))
    panel = make_panel(robot)
    assert panel.mode.value == "modules"
    assert not panel.modules.rows[1].is_module
    panel.modules.rows[1].q.box.value = 90.0
    assert panel.robot.modules[1] == rc.DHLink(a=10.0, q=np.pi / 2)
