"""Numbers as the panel shows and reads them: no float noise on screen, the exact value
kept in the state (a shown number never comes back as an edit), one step rule per kind,
typed text read without evaluating it."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.panel.form import display_number, parse_number, snap_to_step

from .test_panel_support import make_panel, shown, ui

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
    assert [shown(panel, f"modules[{i}].q")["value"] for i in range(6)] == NOISY_DEGREES


def test_dh_twists_show_whole_degrees():
    panel = make_panel(rc.preset("puma560"))
    assert [shown(panel, f"dh[{i}].alpha")["value"] for i in range(6)] == [
        90.0,
        0.0,
        -90.0,
        90.0,
        -90.0,
        0.0,
    ]
    assert [shown(panel, f"dh[{i}].a")["value"] for i in range(1, 3)] == [0.4318, 0.0203]


def test_editing_one_box_keeps_every_other_number_exact():
    robot = angles_robot()
    panel = make_panel(robot)
    ui(panel, "end_effector.Py").type("5")
    assert panel.robot.q.tolist() == robot.q.tolist()  # bit for bit, not via the boxes


def test_steps_are_one_degree_or_a_length_step():
    panel = make_panel()
    assert shown(panel, "modules[0].q")["step"] == 1.0
    assert shown(panel, "modules[1].az")["step"] == 1.0  # the paper's robot: size 90
    ui(panel, "angle_unit").choose(False)
    assert shown(panel, "modules[0].q")["step"] == 0.01
    ur5 = make_panel(rc.preset("ur5"))
    assert shown(ur5, "dh[0].d")["step"] == 0.01  # a UR5 in metres


def test_a_browser_notch_with_noise_is_the_notch():
    panel = make_panel()
    ui(panel, "modules[0].q").drag(29.999999999999996)
    assert panel.robot.q[0] == np.deg2rad(30.0)


@pytest.mark.parametrize(
    ("text", "value"),
    [("12", 12.0), (" -0.5 ", -0.5), ("1e-3", 0.001), ("+3", 3.0), ("2,5", 2.5), ("1 000", 1000.0)],
)
def test_typed_numbers_are_read_as_a_calculator_shows_them(text, value):
    assert parse_number(text, "q1") == value


@pytest.mark.parametrize(
    "text", ["", "abc", "pi", "1/2", "nan", "inf", "1e999", "__import__", "1" * 70]
)
def test_anything_else_is_refused_with_a_message_and_never_evaluated(text):
    with pytest.raises(rc.InvalidInputError, match="q1"):
        parse_number(text, "q1")
