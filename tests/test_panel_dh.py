"""DH-table mode: rows θ, d, a, α, joint type, the standard/modified selector, and the
questions the panel asks before it converts (never a silent swap of the robot)."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc

from .test_panel_support import make_panel, paper_robot, shown, ui

ROWS = [(0.0, 20.0, 0.0, np.pi / 2, "R"), (0.0, 0.0, 30.0, 0.0, "R"), (0.0, 0.0, 40.0, 0.0, "R")]


def dh_panel(convention: str = "standard"):
    return make_panel(rc.Robot.from_dh(ROWS, convention=convention))


def dh_value(panel, i: int, name: str) -> float:
    return shown(panel, f"dh[{i}].{name}")["value"]


def test_an_all_dh_robot_opens_in_the_dh_table():
    panel = dh_panel()
    assert panel.state.mode == "dh" and shown(panel, "mode")["value"] == "dh"
    assert shown(panel, "dh.convention")["value"] == "standard"
    assert [dh_value(panel, i, "a") for i in range(3)] == [0.0, 30.0, 40.0]
    np.testing.assert_allclose(panel.robot.end_effector(), [70, 0, 20], atol=1e-12)


def test_editing_a_row_changes_the_robot():
    panel = dh_panel()
    ui(panel, "dh[1].a").type("50")
    assert panel.robot.modules[1].a == 50.0
    np.testing.assert_allclose(panel.robot.end_effector(), [90, 0, 20], atol=1e-12)


def test_angles_in_the_table_are_shown_in_degrees():
    panel = dh_panel()
    assert dh_value(panel, 0, "alpha") == pytest.approx(90.0)
    ui(panel, "dh[0].alpha").type("0")
    assert panel.robot.modules[0].alpha == 0.0
    ui(panel, "angle_unit").choose(False)
    assert shown(panel, "dh[1].theta")["unit"] == "rad"


def test_q_of_a_dh_row_draws_one_snapshot():
    panel = dh_panel()
    panel.scene.calls.clear()
    ui(panel, "dh[0].q").type("90")
    np.testing.assert_allclose(panel.robot.end_effector(), [0, 70, 20], atol=1e-12)
    assert panel.scene.names() == ["show"]


def test_the_convention_selector_asks_then_reinterprets_every_row():
    panel = dh_panel()
    ui(panel, "dh.convention").choose("modified")
    assert panel.state.prompt.kind == "convention"  # asks first: the robot is unchanged
    assert shown(panel, "dh.convention")["value"] == "standard"
    assert panel.robot == rc.Robot.from_dh(ROWS)
    ui(panel, "dh.prompt.reinterpret").click()
    assert panel.state.prompt is None and shown(panel, "dh.convention")["value"] == "modified"
    assert panel.robot == rc.Robot.from_dh(ROWS, convention="modified")
    assert any("Craig" in c.get("value", "") for c in panel.editor.form.spec["rows"][0]["lines"][1])
    assert "modified DH" in panel.matrices.text(panel.state)


def test_prismatic_joint_makes_q_a_length():
    panel = dh_panel()
    ui(panel, "dh[2].joint").choose("P")
    assert panel.robot.modules[2].joint == "P"
    assert shown(panel, "dh[2].q")["unit"] == "units"
    ui(panel, "dh[2].q").type("5")
    assert panel.robot.q[2] == 5.0


def test_an_impossible_value_shows_the_message_and_keeps_the_robot():
    panel = dh_panel()
    good = panel.robot
    ui(panel, "dh[1].alpha").type("nan")
    assert panel.robot is good and set(panel.errors) == {"dh[1].alpha"}
    ui(panel, "dh[1].alpha").type("0")
    assert panel.errors == {}


def test_add_remove_move_rows():
    panel = dh_panel()
    ui(panel, "dh.add").click()
    assert panel.robot.n == 4 and panel.robot.modules[3].joint == "R"
    ui(panel, "dh[3].up").click()
    assert panel.robot.modules[2].a != 40.0 and panel.robot.modules[3].a == 40.0
    ui(panel, "dh[2].delete").click()
    assert panel.robot == rc.Robot.from_dh(ROWS)


def test_opening_the_dh_table_asks_and_says_why_the_paper_robot_cannot_convert():
    panel = make_panel()
    ui(panel, "mode").choose("dh")
    assert panel.state.mode == "modules" and panel.state.prompt.kind == "to_dh"
    assert shown(panel, "mode")["value"] == "modules"  # the robot is still the modules'
    ui(panel, "mode.dh.convert").click()  # the paper's Ry joints: no DH chain
    message = panel.errors["mode.dh"]
    # One sentence a student can act on: which module, why, what to do; no object dump.
    assert message.startswith("M2 turns about the y axis, but a DH table has no y")
    assert "start a new one" in message and "Module(" not in message
    assert "modules[" not in message
    assert panel.robot == paper_robot() and panel.state.prompt is not None
    ui(panel, "mode.dh.new").click()  # said explicitly: a new one-row table
    assert panel.state.mode == "dh" and panel.state.prompt is None
    assert panel.robot.n == 1 and isinstance(panel.robot.modules[0], rc.DHLink)
    assert "mode.dh" not in panel.errors
    panel.undo()
    assert panel.robot == paper_robot() and panel.state.mode == "modules"


def test_a_modules_robot_converts_to_dh_rows_and_back_to_the_same_robot():
    arm = rc.Robot(
        [rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))], end_effector=(40, 0, 0)
    )
    panel = make_panel(arm.with_q([0.3, -0.2]))
    ui(panel, "mode").choose("dh")
    assert shown(panel, "mode.dh.convention")["value"] == "modified"  # preselected
    ui(panel, "mode.dh.convert").click()
    assert panel.state.mode == "dh" and shown(panel, "dh.convention")["value"] == "modified"
    assert [dh_value(panel, i, "a") for i in range(2)] == [0.0, 30.0]
    assert [dh_value(panel, i, "d") for i in range(2)] == [20.0, 0.0]
    expected = [40 * np.cos(0.1) + 30 * np.cos(0.3), 40 * np.sin(0.1) + 30 * np.sin(0.3), 20]
    np.testing.assert_allclose(panel.robot.end_effector(), expected, atol=1e-12)
    assert panel.robot.q.tolist() == [0.3, -0.2]
    ui(panel, "mode").choose("modules")  # DH rows → modules: the same robot, no question
    np.testing.assert_allclose(panel.robot.end_effector(), arm.end_effector([0.3, -0.2]))
    panel.undo()
    panel.undo()
    assert panel.robot == arm.with_q([0.3, -0.2])


def test_a_dh_robot_to_modules_and_back_gives_the_same_rows():
    panel = dh_panel()
    ui(panel, "mode").choose("modules")
    assert panel.state.mode == "modules" and panel.robot.n > 3
    assert all(isinstance(link, rc.Module) for link in panel.robot.modules)
    ui(panel, "mode").choose("dh")
    ui(panel, "mode.dh.convert").click()  # the held constants stay constants
    assert panel.robot == rc.Robot.from_dh(ROWS)


def test_a_mixed_robot_shows_dh_links_read_only_in_the_module_list():
    robot = rc.Robot([rc.Module("Rz"), rc.DHLink(a=10.0)], end_effector=(5, 0, 0))
    panel = make_panel(robot)
    assert panel.state.mode == "modules"
    keys = panel.editor.form.control_keys()
    assert "modules[1].kind" not in keys and "modules[1].ax" not in keys
    ui(panel, "modules[1].q").type("90")
    assert panel.robot.modules[1] == rc.DHLink(a=10.0, q=np.pi / 2)


def test_converting_the_puma_to_modified_dh_keeps_the_robot(rng):
    puma = rc.preset("puma560")
    panel = make_panel(puma)
    ui(panel, "dh.convention").choose("modified")
    assert panel.state.prompt is not None and panel.robot == puma
    ui(panel, "dh.prompt.convert").click()
    converted = panel.robot
    assert shown(panel, "dh.convention")["value"] == "modified" and panel.state.prompt is None
    assert {link.convention for link in converted.modules} == {"modified"}
    assert converted.n == 6 and len(panel.state.document.motion.signals) == 6
    for q in rng.uniform(-np.pi, np.pi, size=(10, 6)):
        np.testing.assert_allclose(
            converted.end_effector_pose(q), puma.end_effector_pose(q), atol=1e-12
        )
    # The numbers moved (a and α one row down), and the boxes show them clean.
    assert [dh_value(panel, i, "alpha") for i in range(6)] == [0, 90, 0, -90, 90, -90]
    assert shown(panel, "preset")["value"] == ""  # the same motion, not the preset's table
    ui(panel, "dh.convention").choose("standard")
    ui(panel, "dh.prompt.convert").click()
    assert panel.robot == puma and shown(panel, "preset")["value"] == "puma560"
    panel.undo()
    panel.undo()
    assert panel.robot == puma and shown(panel, "dh.convention")["value"] == "standard"


def test_a_refused_conversion_shows_the_core_message_beside_the_question():
    robot = rc.Robot.from_dh(ROWS).with_active(2)  # the core converts whole tables only
    panel = make_panel(robot)
    ui(panel, "dh.convention").choose("modified")
    ui(panel, "dh.prompt.convert").click()
    assert "inactive rows" in panel.errors["dh.prompt"]
    assert panel.robot == robot and panel.state.prompt is not None
    ui(panel, "dh.prompt.cancel").click()
    assert panel.errors == {} and shown(panel, "dh.convention")["value"] == "standard"


def paper_style_arm() -> rc.Robot:
    """The paper's modules and offsets with every joint about z: a chain DH can hold,
    though only in modified DH (the offsets sit before each joint)."""
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def test_the_question_preselects_the_convention_the_robot_converts_in(rng):
    arm = paper_style_arm()
    panel = make_panel(arm)
    ui(panel, "mode").choose("dh")
    assert shown(panel, "mode.dh.convention")["value"] == "modified"
    note = _entry_note(panel)
    assert note.startswith("Modified DH is chosen: in standard DH, M3 is offset along x")
    ui(panel, "mode.dh.convert").click()  # no convention to pick by hand
    assert panel.errors == {} and panel.state.mode == "dh"
    assert all(isinstance(link, rc.DHLink) for link in panel.robot.modules)
    np.testing.assert_allclose(panel.robot.end_effector(), [70, 0, 20], atol=1e-12)
    for q in rng.uniform(-np.pi, np.pi, size=(10, 3)):
        np.testing.assert_allclose(panel.robot.end_effector(q), arm.end_effector(q), atol=1e-12)


def _entry_note(panel) -> str:
    row = next(r for r in panel.header.form.spec["rows"] if r["key"] == "mode.dh")
    return row["lines"][1][0]["value"]


def test_the_note_says_when_neither_convention_holds_the_robot():
    panel = make_panel()  # the paper's Ry joints: no DH table at all
    ui(panel, "mode").choose("dh")
    assert _entry_note(panel).startswith("M2 turns about the y axis")


def test_module_names_reach_the_question_as_text():
    arm = paper_style_arm()
    links = list(arm.modules)
    links[2] = links[2].with_name("<b>elbow</b>")
    panel = make_panel(rc.Robot(links, end_effector=(40, 0, 0)))
    ui(panel, "mode").choose("dh")
    # The page writes text controls as text, never markup: the name arrives as typed.
    assert "<b>elbow</b> is offset" in _entry_note(panel)
