"""The drag relay: a slider value forwarded by the page moves the robot like the slider does."""

from __future__ import annotations

import numpy as np
import pytest

from robotconf.panel._drag_relay import DragRelay

from .test_panel_support import make_panel


def _relay(panel):
    relay = panel.modules.drag_relay
    sent: list[dict] = []
    relay.send = lambda content, buffers=None: sent.append(content)
    return relay, sent


def test_the_relay_watches_every_q_slider_and_follows_added_and_removed_rows():
    panel = make_panel()
    relay = panel.modules.drag_relay
    assert relay.sliders == [row.q.slider for row in panel.modules.rows]
    panel.modules.add_button.click()
    assert len(relay.sliders) == 4
    assert relay.sliders[-1] is panel.modules.rows[-1].q.slider
    panel.modules.rows[0].remove_button.click()
    assert relay.sliders == [row.q.slider for row in panel.modules.rows]


def test_a_relayed_value_moves_the_robot_and_is_answered():
    panel = make_panel()
    relay, sent = _relay(panel)
    slider = panel.modules.rows[1].q.slider
    relay.receive({"slider": slider.model_id, "value": 90.0, "seq": 7})
    # q2 = 90°: the paper arm's upper arm points down, the tip is at (0, 0, 20 - 70).
    np.testing.assert_allclose(panel.robot.q, [0, np.pi / 2, 0], atol=1e-15)
    np.testing.assert_allclose(panel.robot.end_effector(), [0, 0, -50], atol=1e-12)
    assert "p_EE = (0, 0, -50)" in panel.ee_label.value
    assert panel.modules.rows[1].q.box.value == 90.0
    assert sent == [{"ack": 7}]
    assert relay.received == 1


def test_the_sliders_own_later_update_of_the_same_value_changes_nothing():
    panel = make_panel()
    relay, _ = _relay(panel)
    slider = panel.modules.rows[2].q.slider
    relay.receive({"slider": slider.model_id, "value": -30.0, "seq": 1})
    robot, undo_steps = panel.robot, len(panel.history.history)
    slider.value = -30.0  # ipywidgets' own (throttled) copy arrives afterwards
    assert panel.robot is robot
    assert len(panel.history.history) == undo_steps


@pytest.mark.parametrize(
    "content",
    [
        {"slider": "no-such-model", "value": 10.0, "seq": 1},
        {"value": 10.0, "seq": 1},
        {"slider": None, "value": 10.0, "seq": 1},
    ],
)
def test_a_message_for_no_tracked_slider_is_answered_and_ignored(content):
    panel = make_panel()
    relay, sent = _relay(panel)
    robot = panel.robot
    relay.receive(content)
    assert panel.robot is robot
    assert sent == [{"ack": 1}]


@pytest.mark.parametrize("value", [True, "45", None, float("nan"), float("inf"), [45.0], 1e6])
def test_a_value_that_is_not_a_slider_position_is_ignored(value):
    panel = make_panel()
    relay, sent = _relay(panel)
    robot = panel.robot
    slider = panel.modules.rows[0].q.slider
    relay.receive({"slider": slider.model_id, "value": value, "seq": 3})
    assert panel.robot is robot  # 1e6 is beyond the slider's range: a stale copy
    assert panel.errors == {}
    assert sent == [{"ack": 3}]


def test_content_that_is_not_a_dict_is_ignored():
    relay = DragRelay()
    sent: list = []
    relay.send = lambda content, buffers=None: sent.append(content)
    relay.receive(["not", "a", "dict"])  # type: ignore[arg-type]
    assert sent == [] and relay.received == 0


def test_a_relayed_value_after_a_unit_switch_is_read_in_the_new_unit():
    panel = make_panel()
    relay, _ = _relay(panel)
    panel.angle_unit.value = False  # radians
    slider = panel.modules.rows[0].q.slider
    relay.receive({"slider": slider.model_id, "value": 45.0, "seq": 1})  # stale, in degrees
    np.testing.assert_array_equal(panel.robot.q, [0, 0, 0])
    relay.receive({"slider": slider.model_id, "value": 1.5, "seq": 2})
    np.testing.assert_allclose(panel.robot.q, [1.5, 0, 0])
