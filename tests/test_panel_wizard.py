"""Guided mode: the paper's Figure 12 questionnaire ends in the same robot as the list."""

from __future__ import annotations

import numpy as np

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
