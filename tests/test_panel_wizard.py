"""Guided mode: the paper's Figure 12 questionnaire ends in the same robot as the list."""

from __future__ import annotations

import numpy as np

import robotconf as rc

from .test_panel_support import make_panel, paper_robot


def answer(panel, kinds, offsets, q, point):
    wizard = panel.wizard
    panel.mode.value = "wizard"
    wizard.count.value = len(kinds)
    wizard.next_button.click()
    for i, kind in enumerate(kinds):
        assert wizard.step_name == "type"
        wizard.answers[i].kind.value = kind
        wizard.next_button.click()
        assert wizard.step_name == "a"
        for control, value in zip(wizard.answers[i].offsets, offsets[i], strict=True):
            control.box.value = value
        wizard.next_button.click()
        assert wizard.step_name == "q"
        wizard.answers[i].q.box.value = q[i]
        wizard.next_button.click()
    assert wizard.step_name == "end_effector"
    for control, value in zip(wizard.end_effector, point, strict=True):
        control.box.value = value
    wizard.next_button.click()
    assert wizard.step_name == "summary"
    return wizard


def test_wizard_reproduces_the_papers_robot_and_its_end_effector():
    panel = make_panel(robot=None)
    panel.modules.rows[0].kind.value = "Tx"  # start from something else
    wizard = answer(
        panel,
        ["Rz", "Ry", "Ry"],
        [(0, 0, 0), (0, 0, 20), (30, 0, 0)],
        [0, 0, 0],
        (40, 0, 0),
    )
    assert "p_EE = (70, 0, 20)" in wizard.body.children[0].value
    assert wizard.next_button.description == "Finish"
    wizard.next_button.click()
    assert panel.robot == paper_robot()
    np.testing.assert_array_equal(panel.robot.end_effector(), [70, 0, 20])
    # It lands in the list editor: the same robot as built there.
    assert panel.mode.value == "modules"
    assert [row.kind.value for row in panel.modules.rows] == ["Rz", "Ry", "Ry"]
    assert panel.scene.names()[-1] == "set_robot"


def test_each_step_explains_and_shows_the_formula_of_the_type():
    panel = make_panel()
    wizard = panel.wizard
    panel.mode.value = "wizard"
    assert "How many modules" in wizard.explanation.value
    wizard.next_button.click()
    wizard.answers[0].kind.value = "Ry"
    assert "about the module's own y axis" in wizard.explanation.value
    assert r"\sin{\left(q_{1} \right)}" in wizard.formula.value
    assert "a_{x}" in wizard.formula.value
    wizard.next_button.click()
    wizard.answers[0].offsets[2].box.value = 20.0
    wizard.back_button.click()
    wizard.next_button.click()
    assert "20" in wizard.formula.value


def test_invalid_answer_stays_on_its_step_with_the_core_message():
    panel = make_panel()
    wizard = panel.wizard
    panel.mode.value = "wizard"
    wizard.next_button.click()
    wizard.next_button.click()  # → geometry of module 1
    wizard.answers[0].offsets[0].box.value = float("nan")
    wizard.next_button.click()
    assert wizard.step_name == "a"
    assert panel.errors["wizard.modules[0].ax"].startswith("ax: must be finite")
    assert panel.robot == paper_robot()  # the wizard never touches the robot until Finish


def test_angles_in_the_wizard_follow_the_degree_toggle():
    panel = make_panel()
    answer(panel, ["Rz"], [(0, 0, 0)], [90.0], (1, 0, 0))
    panel.wizard.next_button.click()
    assert panel.robot.q[0] == np.pi / 2


def test_the_formula_and_the_numbers_follow_every_field_as_it_is_typed():
    panel = make_panel()
    wizard = panel.wizard
    panel.mode.value = "wizard"
    wizard.next_button.click()
    wizard.answers[0].kind.value = "Ry"
    wizard.next_button.click()  # offsets of module 1
    offsets = wizard.answers[0].offsets
    offsets[0].box.value = 30.0  # no Back/Next needed: A_1 shows it at once
    assert "30" in wizard.formula.value and r"\sin{\left(q_{1} \right)}" in wizard.formula.value
    offsets[2].box.value = 20.0
    assert "20" in wizard.formula.value
    at_zero = "A_1 at q1 = 0°:\n[ 1  0  0  30 ]\n[ 0  1  0   0 ]\n[ 0  0  1  20 ]"
    assert at_zero in wizard.preview.value
    wizard.next_button.click()  # its coordinate
    wizard.answers[0].q.box.value = 90.0
    # Ry(90°): the new x axis is the old -z, the new z the old x.
    assert "A_1 at q1 = 90°:\n[  0  0  1  30 ]\n[  0  1  0   0 ]\n[ -1  0  0  20 ]" in (
        wizard.preview.value
    )
    assert "30" in wizard.formula.value  # the typed offsets, not symbols


def test_the_scene_previews_the_robot_being_built_and_cancel_restores_it():
    panel = make_panel()
    wizard = panel.wizard
    panel.scene.calls.clear()
    panel.mode.value = "wizard"
    assert panel.scene.calls == []  # the first question: nothing built yet
    wizard.count.value = 2
    wizard.next_button.click()
    assert panel.scene.robot.modules == (rc.Module("Rz"),)  # module 1 so far
    wizard.next_button.click()
    wizard.answers[0].offsets[2].box.value = 20.0
    assert panel.scene.robot.modules == (rc.Module("Rz", a=(0, 0, 20)),)
    for _ in range(3):  # q1, type 2, offsets 2
        wizard.next_button.click()
    wizard.answers[1].offsets[0].box.value = 30.0
    assert panel.scene.robot.n == 2 and panel.scene.robot.modules[1].a == (30.0, 0.0, 0.0)
    assert panel.robot == paper_robot()  # only the scene shows it
    wizard.answers[1].offsets[0].box.value = float("nan")  # refused: the last preview stays
    assert panel.scene.robot.modules[1].a == (30.0, 0.0, 0.0)
    wizard.cancel_button.click()
    assert panel.mode.value == "modules" and panel.robot == paper_robot()
    assert panel.scene.calls[-1] == ("set_robot", paper_robot())


def test_leaving_the_wizard_by_the_mode_selector_also_restores_the_scene():
    panel = make_panel()
    panel.mode.value = "wizard"
    panel.wizard.count.value = 1
    panel.wizard.next_button.click()
    panel.wizard.answers[0].kind.value = "Tx"
    assert panel.scene.robot.modules == (rc.Module("Tx"),)
    panel.mode.value = "modules"
    assert panel.scene.robot == paper_robot()


def test_a_refused_answer_loses_its_message_once_fixed():
    panel = make_panel()
    wizard = panel.wizard
    panel.mode.value = "wizard"
    wizard.next_button.click()
    wizard.next_button.click()  # → geometry of module 1
    wizard.answers[0].offsets[1].box.value = float("inf")
    wizard.next_button.click()
    assert "wizard.modules[0].ay" in panel.errors
    wizard.answers[0].offsets[1].box.value = 5.0
    assert panel.errors == {}
