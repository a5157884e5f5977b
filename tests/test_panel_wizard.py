"""Guided mode: the paper's Figure 12 questionnaire ends in the same robot as the list; its
draft is not the panel's robot until Finish, and the scene and header show the draft."""

from __future__ import annotations

import numpy as np

import robotconf as rc

from .test_panel_support import make_panel, paper_robot, shown, ui


def part(panel) -> str:
    return panel.state.wizard.part


def answer(panel, kinds, offsets, q, point):
    ui(panel, "mode").choose("wizard")
    ui(panel, "wizard.count").type(str(len(kinds)))
    ui(panel, "wizard.next").click()
    for i, kind in enumerate(kinds):
        assert part(panel) == "type"
        ui(panel, f"wizard.modules[{i}].kind").choose(kind)
        ui(panel, "wizard.next").click()
        assert part(panel) == "a"
        for name, value in zip(("ax", "ay", "az"), offsets[i], strict=True):
            ui(panel, f"wizard.modules[{i}].{name}").type(str(value))
        ui(panel, "wizard.next").click()
        assert part(panel) == "q"
        ui(panel, f"wizard.modules[{i}].q").type(str(q[i]))
        ui(panel, "wizard.next").click()
    assert part(panel) == "end_effector"
    for name, value in zip(("Px", "Py", "Pz"), point, strict=True):
        ui(panel, f"wizard.end_effector.{name}").type(str(value))
    ui(panel, "wizard.next").click()
    assert part(panel) == "summary"


def test_the_wizard_reproduces_the_papers_robot_and_its_end_effector():
    panel = make_panel()
    ui(panel, "modules[0].kind").choose("Tx")  # start from something else
    answer(panel, ["Rz", "Ry", "Ry"], [(0, 0, 0), (0, 0, 20), (30, 0, 0)], [0, 0, 0], (40, 0, 0))
    assert "p_EE = (70, 0, 20)" in panel.wizard.preview.value
    assert shown(panel, "wizard.next")["label"] == "Finish"
    ui(panel, "wizard.next").click()
    assert panel.robot == paper_robot() and panel.state.wizard is None
    # It lands in the list editor: the same robot as built there.
    assert panel.state.mode == "modules" and shown(panel, "mode")["value"] == "modules"
    assert [shown(panel, f"modules[{i}].kind")["value"] for i in range(3)] == ["Rz", "Ry", "Ry"]
    assert panel.scene.robot == panel.robot
    panel.undo()  # Finish is one undo step
    assert panel.robot.modules[0].kind == "Tx"


def test_each_step_explains_and_shows_the_formula_of_the_type():
    panel = make_panel()
    ui(panel, "mode").choose("wizard")
    assert "How many modules" in panel.wizard.explanation.value
    ui(panel, "wizard.next").click()
    ui(panel, "wizard.modules[0].kind").choose("Ry")
    assert "about the module's own y axis" in panel.wizard.explanation.value
    assert r"\sin{\left(q_{1} \right)}" in panel.wizard.formula.value
    assert "a_{x}" in panel.wizard.formula.value
    ui(panel, "wizard.next").click()
    ui(panel, "wizard.modules[0].az").type("20")
    ui(panel, "wizard.back").click()
    ui(panel, "wizard.next").click()
    assert "20" in panel.wizard.formula.value


def test_an_invalid_answer_shows_the_message_and_the_draft_keeps_the_last_valid_one():
    panel = make_panel()
    ui(panel, "mode").choose("wizard")
    ui(panel, "wizard.next").click()
    ui(panel, "wizard.next").click()  # → offsets of module 1
    ui(panel, "wizard.modules[0].ax").type("nan")
    assert panel.errors["wizard.modules[0].ax"].startswith("ax: not a number")
    assert panel.state.wizard.answers(0).a == (0.0, 0.0, 0.0)
    assert panel.robot == paper_robot()  # the wizard never touches the robot until Finish
    ui(panel, "wizard.modules[0].ax").type("5")
    assert panel.errors == {} and panel.state.wizard.answers(0).a == (5.0, 0.0, 0.0)


def test_angles_in_the_wizard_follow_the_degree_switch():
    panel = make_panel()
    answer(panel, ["Rz"], [(0, 0, 0)], [90.0], (1, 0, 0))
    ui(panel, "wizard.next").click()
    assert panel.robot.q[0] == np.pi / 2


def test_the_formula_and_the_numbers_follow_every_field_as_it_is_typed():
    panel = make_panel()
    ui(panel, "mode").choose("wizard")
    ui(panel, "wizard.next").click()
    ui(panel, "wizard.modules[0].kind").choose("Ry")
    ui(panel, "wizard.next").click()  # offsets of module 1
    ui(panel, "wizard.modules[0].ax").typing("30")  # no Enter, no Next: A_1 shows it at once
    formula = panel.wizard.formula.value
    assert "30" in formula and r"\sin{\left(q_{1} \right)}" in formula
    ui(panel, "wizard.modules[0].az").typing("-")  # half typed: no message, nothing changes
    assert panel.errors == {} and panel.state.wizard.answers(0).a == (30.0, 0.0, 0.0)
    ui(panel, "wizard.modules[0].az").typing("20")
    assert "20" in panel.wizard.formula.value
    at_zero = "A_1 at q1 = 0°:\n[ 1  0  0  30 ]\n[ 0  1  0   0 ]\n[ 0  0  1  20 ]"
    assert at_zero in panel.wizard.preview.value
    ui(panel, "wizard.next").click()  # its coordinate
    ui(panel, "wizard.modules[0].q").typing("90")
    # Ry(90°): the new x axis is the old -z, the new z the old x.
    assert "A_1 at q1 = 90°:\n[  0  0  1  30 ]\n[  0  1  0   0 ]\n[ -1  0  0  20 ]" in (
        panel.wizard.preview.value
    )


def test_the_scene_and_the_header_show_the_draft_and_cancel_restores_the_robot():
    panel = make_panel()
    panel.scene.calls.clear()
    ui(panel, "mode").choose("wizard")
    assert panel.scene.calls == []  # the first question: nothing built yet
    ui(panel, "wizard.count").type("2")
    ui(panel, "wizard.next").click()
    assert panel.scene.robot.modules == (rc.Module("Rz"),)  # module 1 so far
    assert "p_EE = (0, 0, 0)" in panel.ee_label.value  # the header follows the draft
    assert ("fit_view", None) in panel.scene.calls  # a new draft is brought into view
    ui(panel, "wizard.next").click()
    ui(panel, "wizard.modules[0].az").typing("20")
    assert panel.scene.robot.modules == (rc.Module("Rz", a=(0, 0, 20)),)
    assert "p_EE = (0, 0, 20)" in panel.ee_label.value
    for _ in range(3):  # q1, type 2, offsets 2
        ui(panel, "wizard.next").click()
    ui(panel, "wizard.modules[1].ax").type("30")
    assert panel.scene.robot.n == 2 and panel.scene.robot.modules[1].a == (30.0, 0.0, 0.0)
    assert panel.robot == paper_robot()  # only the scene and the header show it
    ui(panel, "wizard.modules[1].ax").type("nan")  # refused: the draft stays
    assert panel.scene.robot.modules[1].a == (30.0, 0.0, 0.0)
    ui(panel, "wizard.cancel").click()
    assert panel.state.mode == "modules" and panel.robot == paper_robot()
    assert panel.scene.robot == paper_robot() and "p_EE = (70, 0, 20)" in panel.ee_label.value


def test_leaving_the_wizard_by_the_mode_selector_also_restores_the_scene():
    panel = make_panel()
    ui(panel, "mode").choose("wizard")
    ui(panel, "wizard.count").type("1")
    ui(panel, "wizard.next").click()
    ui(panel, "wizard.modules[0].kind").choose("Tx")
    assert panel.scene.robot.modules == (rc.Module("Tx"),)
    ui(panel, "mode").choose("modules")
    assert panel.scene.robot == paper_robot() and panel.state.wizard is None


def test_a_preset_after_the_wizard_is_the_preset_exactly():
    panel = make_panel()
    answer(panel, ["Rz", "Tz", "Tx"], [(0, 0, 0), (0, 0, 10), (5, 0, 0)], [0, 0, 0], (2, 0, 0))
    ui(panel, "wizard.next").click()
    ui(panel, "preset").choose("puma560")
    assert panel.robot == rc.preset("puma560") and panel.scene.robot == panel.robot
    np.testing.assert_allclose(
        panel.robot.end_effector(), rc.preset("puma560").end_effector(), atol=0
    )
    ui(panel, "preset").choose("paper")
    ui(panel, "angle_unit").choose(False)
    assert panel.scene.robot == panel.robot == rc.preset("paper")
    assert shown(panel, "preset")["value"] == "paper"
