"""Clean numbers in the boxes, no drift when they are read back, one step rule per kind."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.panel._clean_numbers import display_number, snap_to_step
from robotconf.panel._number_control import NumberControl
from robotconf.panel._ranges import length_scale, length_step

from .test_panel_support import make_panel, paper_robot

#: Angles whose degree conversion leaves float noise (rad2deg gives 29.999999999999996 …).
NOISY_DEGREES = [3.0, 15.0, 30.0, 48.0, -22.0, 90.0]


def angles_robot() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz", q=np.deg2rad(d)) for d in NOISY_DEGREES], end_effector=(10, 0, 0)
    )


def test_display_number_drops_float_noise_only():
    assert display_number(21.99999999999997) == 22.0
    assert display_number(89.99999999999999) == 90.0
    assert display_number(-7.105427357601002e-15) == 0.0
    assert display_number(0.15005, 0.01) == 0.15005  # real digits stay
    assert display_number(123.456789, 1.0) == 123.456789
    assert np.isnan(display_number(float("nan")))
    assert snap_to_step(7.105427357601002e-15, 1.0) == 0.0
    assert snap_to_step(-44.99999999999999, 1.0) == -45.0
    assert snap_to_step(12.5, 1.0) == 12.5  # a value between notches is typed, not noise


def test_the_box_for_90_degrees_shows_90():
    panel = make_panel(angles_robot())
    shown = [row.q.box.value for row in panel.modules.rows]
    assert shown == NOISY_DEGREES  # not 29.999999999999996, 89.99999999999999
    assert f"{panel.modules.rows[5].q.box.value:g}" == "90"


@pytest.mark.skipif("puma560" not in rc.preset_names(), reason="no PUMA preset")
def test_dh_twists_show_whole_degrees():
    panel = make_panel(rc.preset("puma560"))
    alphas = [row.cells["alpha"].box.value for row in panel.dh.rows]
    assert alphas == [90.0, 0.0, -90.0, 90.0, -90.0, 0.0]
    assert [row.cells["a"].box.value for row in panel.dh.rows][1:3] == [0.4318, 0.0203]


def test_boxes_read_back_give_exactly_the_loaded_robot():
    robot = angles_robot()
    panel = make_panel(robot)
    panel.extras.point[1].box.value = 5.0  # rebuilds from every box
    assert panel.robot.q.tolist() == robot.q.tolist()  # exact: no degree round trip
    assert panel.robot == robot.with_end_effector((10, 5, 0))
    panel.angle_unit.value = False  # radians and back: display only
    panel.angle_unit.value = True
    panel.extras.point[1].box.value = 0.0
    assert panel.robot == robot
    assert [row.q.box.value for row in panel.modules.rows] == NOISY_DEGREES


def test_a_typed_value_is_the_value_typed():
    panel = make_panel(angles_robot())
    panel.modules.rows[2].q.box.value = 31.0
    assert panel.robot.q[2] == np.deg2rad(31.0)
    panel.modules.rows[2].q.box.value = 30.0  # the shown number again: the exact one
    assert panel.robot.q[2] == np.deg2rad(30.0)


@pytest.mark.skipif("puma560" not in rc.preset_names(), reason="no PUMA preset")
def test_slider_noise_from_the_browser_is_no_edit():
    panel = make_panel()
    panel.preset.value = "puma560"
    panel.scene.calls.clear()
    q2 = panel.dh.rows[1].q
    assert (q2.slider.min, q2.slider.max) == (-45.0, 225.0)
    # A browser slider over −45°…225° at the 0 notch sends this (percentages round-trip).
    q2.slider.value = -7.105427357601002e-15
    assert q2.box.value == 0.0
    assert panel.robot == rc.preset("puma560") and panel.robot.q[1] == 0.0
    assert panel.scene.calls == [] and panel.preset.value == "puma560"
    q2.slider.value = 29.999999999999996  # the 30° notch
    assert q2.box.value == 30.0
    assert panel.robot.q[1] == np.deg2rad(30.0)


def test_one_step_for_every_angle_and_one_for_every_length():
    panel = make_panel()
    q_steps = {(row.q.slider.step, row.q.box.step) for row in panel.modules.rows}
    assert q_steps == {(1.0, 1.0)}  # q2's limits (±90°) no longer give it 0.1°
    offset_steps = {c.slider.step for row in panel.modules.rows for c in row.offsets}
    assert offset_steps == {1.0} == {length_step(length_scale(paper_robot()))}
    assert {c.slider.step for c in panel.extras.point} == {1.0}
    panel.modules.rows[1].offsets[2].widen_button.click()  # a wider slider, the same step
    assert panel.modules.rows[1].offsets[2].slider.step == 1.0
    panel.angle_unit.value = False
    assert {row.q.slider.step for row in panel.modules.rows} == {0.01}
    panel.modules.rows[2].kind.value = "Tx"  # a length coordinate: the length step
    assert panel.modules.rows[2].q.slider.step == 1.0


@pytest.mark.skipif("ur5" not in rc.preset_names(), reason="no UR5 preset")
def test_a_robot_in_metres_steps_by_centimetres():
    panel = make_panel(rc.preset("ur5"))
    assert length_scale(panel.robot) == 2.0
    steps = {row.cells[name].box.step for row in panel.dh.rows for name in ("d", "a")}
    assert steps == {0.01}
    assert {row.cells["alpha"].box.step for row in panel.dh.rows} == {1.0}
    assert {c.box.step for c in panel.extras.point} == {0.01}


def test_slider_ends_fall_on_the_step():
    control = NumberControl("q", 0.0, -57.29577951308232, 114.59155902616465, angle=True)
    assert (control.slider.min, control.slider.max) == (-58.0, 115.0)
    control.set_range(-0.123, 0.456)
    assert (control.slider.min, control.slider.max) == (-1.0, 1.0)
