"""The Reach tab: a typed target moves the robot through the panel's one flow.

Targets are the forward kinematics of known coordinates, so "reached" is checked against
the core's own end-effector pose; what the 3D view is asked to draw (ghosts, the marker)
is read from the recording fake scene.
"""

from __future__ import annotations

import math
from itertools import product

import numpy as np
import pytest

import robotconf as rc
from robotconf.inverse_kinematics import ik_all
from robotconf.kinematics import matrix_from_rpy, rpy_from_matrix
from robotconf.panel import actions as act
from robotconf.panel.state import target_of

from .test_panel_support import make_panel, shown, ui

PUMA_Q = np.array([0.3, 0.2, -0.4, 0.5, 0.6, 0.7])


def reach_panel(robot: rc.Robot, **options):  # type: ignore[no-untyped-def]
    panel = make_panel(robot, **options)
    panel.apply(act.SelectTab("reach"))
    return panel


def set_target(panel, pose: np.ndarray, degrees: bool = True) -> None:  # type: ignore[no-untyped-def]
    """Type a pose's x, y, z (and roll, pitch, yaw in pose mode) into the boxes."""
    for name, value in zip("xyz", pose[:3, 3], strict=True):
        ui(panel, f"reach.{name}").type(repr(float(value)))
    if panel.state.reach.mode == "pose":
        rpy = np.array(rpy_from_matrix(pose[:3, :3]))
        values = np.degrees(rpy) if degrees else rpy
        for name, value in zip(("roll", "pitch", "yaw"), values, strict=True):
            ui(panel, f"reach.{name}").type(repr(float(value)))


def status(panel) -> str:  # type: ignore[no-untyped-def]
    return next(
        c["value"]
        for r in panel.reach.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-reach-status"
    )


def solution_buttons(panel) -> list[dict]:  # type: ignore[no-untyped-def]
    return [shown(panel, k) for k in panel.reach.form.control_keys() if ".solution." in k]


def last(panel, name: str):  # type: ignore[no-untyped-def]
    return [args for called, args in panel.scene.calls if called == name][-1]


def test_the_reach_tab_sits_after_matrices() -> None:
    panel = reach_panel(rc.preset("planar_2r"))
    assert panel.results.titles == ("Motion", "Matrices", "Reach", "Program", "Save / Load")
    assert panel.results.children[2] is panel.reach.widget and panel.results.selected_index == 2


def test_rpy_is_fixed_axes_xyz_by_hand() -> None:
    # Rz(90°)·Rx(90°): x → y, y → z, z → x, multiplied out by hand.
    turn = matrix_from_rpy(math.pi / 2, 0.0, math.pi / 2)
    np.testing.assert_allclose(turn, [[0, 0, 1], [1, 0, 0], [0, 1, 0]], atol=1e-15)
    # Pitch alone turns about y: x goes to −z.
    np.testing.assert_allclose(
        matrix_from_rpy(0, math.pi / 2, 0) @ [1, 0, 0], [0, 0, -1], atol=1e-15
    )
    numbers = (1.0, 2.0, 3.0, 0.4, math.pi / 2, -0.3)  # gimbal lock: the pose survives
    pose = target_of(numbers, "pose")
    again = target_of((1.0, 2.0, 3.0, *rpy_from_matrix(pose[:3, :3])), "pose")
    np.testing.assert_allclose(again, pose, atol=1e-12)


def test_a_planar_2r_reaches_the_point_of_known_coordinates() -> None:
    arm = rc.preset("planar_2r")  # l1 = 40, l2 = 30
    panel = reach_panel(arm)
    q = np.array([0.4, 0.9])
    target = arm.end_effector_pose(q)
    # By hand: (40 cos 0.4 + 30 cos 1.3, 40 sin 0.4 + 30 sin 1.3, 0).
    expected = [40 * math.cos(0.4) + 30 * math.cos(1.3), 40 * math.sin(0.4) + 30 * math.sin(1.3)]
    np.testing.assert_allclose(target[:2, 3], expected, rtol=1e-14)
    set_target(panel, target)
    assert panel.state.reach.outcome.reason == "converged" and "reached" in status(panel)
    np.testing.assert_allclose(panel.robot.end_effector(), target[:3, 3], atol=1e-6)
    # The editors show the new q; the end-effector line and the scene follow.
    assert [shown(panel, f"dh[{i}].q")["value"] for i in range(2)] == pytest.approx(
        list(np.degrees(panel.robot.q)), abs=1e-9
    )
    np.testing.assert_array_equal(panel.scene.q, panel.robot.q)
    # Both elbows, and the robot stands on one of them.
    buttons = solution_buttons(panel)
    assert [b["label"] for b in buttons] == ["elbow down", "elbow up"]
    assert [b.get("style") for b in buttons].count("current") == 1


def test_puma560_reaches_a_pose_and_lists_eight_branches() -> None:
    puma = rc.preset("puma560")
    panel = reach_panel(puma, length_unit="m")
    ui(panel, "reach.mode").choose("pose")
    target = puma.end_effector_pose(PUMA_Q)
    set_target(panel, target)
    np.testing.assert_allclose(panel.robot.end_effector_pose(), target, atol=1e-6)
    buttons = solution_buttons(panel)
    assert len(buttons) == 8
    words = product(("left", "right"), ("up", "down"), ("no flip", "flip"))
    labels = {b["label"].removeprefix("⚠ ") for b in buttons}
    assert labels == {f"shoulder {s}, elbow {e}, wrist {w}" for s, e, w in words}
    # Flagged exactly where a branch leaves the joint ranges (some turn of each angle).
    solutions = ik_all(puma, target)
    limits = puma.joint_limits()
    for button, row in zip(buttons, solutions.q, strict=True):
        turns = row[:, None] + 2 * np.pi * np.arange(-2, 3)
        inside = ((turns >= limits[:, :1] - 1e-12) & (turns <= limits[:, 1:] + 1e-12)).any(axis=1)
        assert ("robotconf-reach-outside" in button["class"]) == (not inside.all())
        assert button["label"].startswith("⚠") == (not inside.all())
    ghosts = last(panel, "show_ghosts")
    assert ghosts[1].shape == (8, 6) and last(panel, "show_target")[1] is True


def test_clicking_a_branch_moves_the_robot_to_that_row() -> None:
    puma = rc.preset("puma560")
    panel = reach_panel(puma)
    ui(panel, "reach.mode").choose("pose")
    target = puma.end_effector_pose(PUMA_Q)
    set_target(panel, target)
    solutions = ik_all(puma, target)
    depth = len(panel._history)
    ui(panel, "reach.solution.5").click()
    # Exactly the branch the tab listed (its target went through roll, pitch and yaw, so it
    # may differ from ik_all of the original pose in the last bit).
    listed = act.solutions_for(panel.robot, panel.state.reach.target, "pose").solutions
    np.testing.assert_array_equal(panel.robot.q, listed.q[5])
    np.testing.assert_allclose(panel.robot.q, solutions.q[5], rtol=0, atol=1e-12)
    np.testing.assert_allclose(panel.robot.end_effector_pose(), target, atol=1e-9)
    assert [b.get("style") for b in solution_buttons(panel)].index("current") == 5
    assert solutions.labels[5] in status(panel)
    assert len(panel._history) == depth + 1  # its own undo step
    panel.undo()
    np.testing.assert_allclose(panel.robot.end_effector_pose(), target, atol=1e-6)
    assert not np.allclose(panel.robot.q, solutions.q[5])


def test_an_unreachable_target_shows_the_distance_and_keeps_the_robot() -> None:
    arm = rc.preset("planar_2r").with_q([0.2, 0.3])
    panel = reach_panel(arm)
    ui(panel, "reach.y").type("0")
    ui(panel, "reach.x").type("100")  # 30 beyond 40 + 30
    outcome = panel.state.reach.outcome
    assert outcome.reason == "unreachable" and "30 beyond the reach" in status(panel)
    assert "the robot stays where it was" in status(panel)
    # The robot is the last one that worked (y = 0 was reachable: it moved there).
    assert panel.robot.end_effector()[1] == pytest.approx(0.0, abs=1e-6)
    assert last(panel, "show_target")[1] is False  # the marker shows it unreachable
    assert solution_buttons(panel) == []
    notes = [
        c["value"]
        for r in panel.reach.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-reach-note"
    ]
    assert notes and "30 beyond the reach" in notes[0]


def test_one_drag_of_a_target_slider_is_one_undo_step() -> None:
    arm = rc.preset("planar_2r").with_q([0.3, 0.6])
    panel = reach_panel(arm)
    now = [0.0]
    panel._history._clock = lambda: now[0]
    start = panel.robot
    for value in (50.0, 48.0, 46.0, 44.0):  # one drag: steps 0.1 s apart
        ui(panel, "reach.x").drag(value)
        now[0] += 0.1
    assert panel.robot.end_effector()[0] == pytest.approx(44.0, abs=1e-6)
    panel.undo()
    assert panel.robot == start
    panel.redo()
    assert panel.robot.end_effector()[0] == pytest.approx(44.0, abs=1e-6)
    now[0] += 10.0  # a new drag, later: its own step
    ui(panel, "reach.x").drag(40.0)
    panel.undo()
    assert panel.robot.end_effector()[0] == pytest.approx(44.0, abs=1e-6)


def test_units_mm_and_degrees_name_and_convert() -> None:
    arm = rc.preset("planar_2r")
    panel = reach_panel(arm, length_unit="mm", degrees=True)
    assert shown(panel, "reach.x")["unit"] == "mm"
    ui(panel, "reach.mode").choose("pose")
    assert shown(panel, "reach.yaw")["unit"] == "deg"
    # q = (30°, 60°): the tool points along y (yaw 90°) at (40 cos 30°, 40 sin 30° + 30).
    ui(panel, "reach.x").type(repr(40 * math.cos(math.radians(30))))
    ui(panel, "reach.y").type(repr(40 * math.sin(math.radians(30)) + 30))
    ui(panel, "reach.yaw").type("90")
    pose = panel.robot.end_effector_pose()
    np.testing.assert_allclose(pose[:3, 3], [40 * math.cos(math.pi / 6), 50.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(pose[:3, :3], matrix_from_rpy(0, 0, math.pi / 2), atol=1e-9)
    np.testing.assert_allclose(np.degrees(panel.robot.q), [30.0, 60.0], atol=1e-6)
    # Switching units shows the same target: radians for angles, the length unit renamed.
    robot = panel.robot
    ui(panel, "angle_unit").choose(False)
    ui(panel, "length_unit").choose("in")
    assert shown(panel, "reach.yaw")["value"] == pytest.approx(math.pi / 2, abs=1e-6)
    assert shown(panel, "reach.x")["unit"] == "in"
    assert shown(panel, "reach.x")["value"] == pytest.approx(40 * math.cos(math.pi / 6), abs=1e-9)
    assert panel.robot == robot and panel.robot is robot


def test_the_pose_switch_moves_nothing() -> None:
    puma = rc.preset("puma560").with_q(PUMA_Q)
    panel = reach_panel(puma)
    ui(panel, "reach.mode").choose("pose")
    np.testing.assert_allclose(panel.robot.end_effector_pose(), puma.end_effector_pose(), atol=1e-9)


def test_from_current_pose_and_an_edit_elsewhere() -> None:
    arm = rc.preset("planar_2r")
    panel = reach_panel(arm)
    ui(panel, "reach.x").type("50")
    moved = panel.robot.with_q([0.1, 0.2])
    panel.apply(act.SetQ(0, 0.1))
    panel.apply(act.SetQ(1, 0.2))  # an edit elsewhere: the target stays, the tab says how far
    assert "from the target" in status(panel) and shown(panel, "reach.x")["value"] == 50.0
    ui(panel, "reach.from_current").click()
    point = panel.robot.end_effector()
    assert shown(panel, "reach.x")["value"] == pytest.approx(point[0], abs=1e-9)
    assert shown(panel, "reach.y")["value"] == pytest.approx(point[1], abs=1e-9)
    assert panel.robot == moved  # the target moved, not the robot


def test_a_preset_change_starts_the_reach_tab_again() -> None:
    panel = reach_panel(rc.preset("planar_2r"))
    ui(panel, "reach.x").type("100")
    assert "unreachable" in status(panel)
    ui(panel, "preset").choose("paper")
    assert status(panel) == "target: the end effector's current pose"  # no stale outcome


def test_a_nan_target_is_refused_beside_its_box() -> None:
    panel = reach_panel(rc.preset("planar_2r"))
    robot = panel.robot
    ui(panel, "reach.x").type("nan")
    assert panel.errors["reach.x"].startswith("x: not a number")
    assert panel.robot is robot


def test_a_geometry_without_closed_form_says_so_and_leaving_the_tab_clears_the_pane() -> None:
    panel = reach_panel(rc.preset("paper").with_q([0.1, 0.2, 0.3]))
    ui(panel, "reach.z").type("25")
    assert panel.state.reach.outcome.success
    assert panel.robot.end_effector()[2] == pytest.approx(25.0, abs=1e-6)
    skew = rc.Robot(
        [rc.Module("Rz"), rc.Module("Rx", a=(0, 0, 20)), rc.Module("Ry", a=(30, 5, 0))],
        end_effector=(40, 0, 0),
    )
    panel.set_robot(skew)
    notes = [
        c["value"]
        for r in panel.reach.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-reach-note"
    ]
    assert "no closed form" in notes[0]
    assert panel.scene.calls[-1][0] in ("show_target", "clear_ghosts")
    panel.scene.calls.clear()
    panel.apply(act.SelectTab("motion"))
    assert {name for name, _ in panel.scene.calls} == {
        "clear_ghosts",
        "clear_target",
        "clear_taught_points",
    }
