"""The Reach tab: a typed target moves the robot through the panel's usual path.

The panel runs with the real scene on a recording channel, so the ghosts and the target
marker it draws can be read back. Targets are the forward kinematics of known
coordinates, so "reached" is checked against the core's own end-effector pose.
"""

from __future__ import annotations

import math
from itertools import product
from typing import Any

import ipywidgets as widgets
import numpy as np
import pytest

import robotconf as rc
from robotconf.inverse_kinematics import ik_all
from robotconf.kinematics import matrix_from_rpy as rotation_from_rpy
from robotconf.panel import Configurator
from robotconf.panel._reach_pose import pose_from_xyz_rpy, xyz_rpy_from_pose
from robotconf.scene import RecordingChannel, Scene
from robotconf.scene._ghosts import GHOSTS
from robotconf.scene._target import TARGET, TARGET_COLORS

REACH_TAB = 2
PUMA_Q = np.array([0.3, 0.2, -0.4, 0.5, 0.6, 0.7])


class RecordedScene(Scene):
    """The real scene, its ops recorded instead of sent; a stand-in widget for the panel."""

    widget: Any = None

    def __init__(self, robot: rc.Robot) -> None:
        super().__init__(robot, channel=RecordingChannel())
        self.widget = widgets.HTML("scene")


def reach_panel(robot: rc.Robot, **options: Any) -> Configurator:
    panel = Configurator(robot, scene_factory=RecordedScene, **options)
    panel.results.selected_index = REACH_TAB
    return panel


def set_target(panel: Configurator, pose: np.ndarray, degrees: bool = True) -> None:
    """Type a pose's x, y, z (and roll, pitch, yaw in pose mode) into the boxes."""
    point, rpy = xyz_rpy_from_pose(pose)
    controls = panel.reach.target.controls
    for name, value in zip("xyz", point, strict=True):
        controls[name].box.value = float(value)
    if panel.reach.target.is_pose:
        shown = np.degrees(rpy) if degrees else np.array(rpy)
        for name, value in zip(("roll", "pitch", "yaw"), shown, strict=True):
            controls[name].box.value = float(value)


def last_command(scene: Scene, kind: str, path: str) -> dict[str, Any]:
    return [c for c in scene.channel.commands(kind) if c["path"] == path][-1]


def test_the_reach_tab_sits_after_matrices() -> None:
    panel = reach_panel(rc.preset("planar_2r"))
    assert panel.results.titles == ("Motion", "Matrices", "Reach", "Program", "Save / Load")
    assert panel.results.children[REACH_TAB] is panel.reach.widget


def test_rpy_is_fixed_axes_xyz_by_hand() -> None:
    # Rz(90°)·Rx(90°): x → y, y → z, z → x, multiplied out by hand.
    turn = rotation_from_rpy(math.pi / 2, 0.0, math.pi / 2)
    np.testing.assert_allclose(turn, [[0, 0, 1], [1, 0, 0], [0, 1, 0]], atol=1e-15)
    # Pitch alone turns about y: x goes to −z.
    np.testing.assert_allclose(
        rotation_from_rpy(0, math.pi / 2, 0) @ [1, 0, 0], [0, 0, -1], atol=1e-15
    )
    # Gimbal lock: the turn is given to yaw and the pose survives the round trip.
    pose = pose_from_xyz_rpy((1, 2, 3), (0.4, math.pi / 2, -0.3))
    point, rpy = xyz_rpy_from_pose(pose)
    np.testing.assert_allclose(pose_from_xyz_rpy(point, rpy), pose, atol=1e-12)


def test_planar_2r_reaches_the_point_of_known_coordinates() -> None:
    arm = rc.preset("planar_2r")  # l1 = 40, l2 = 30
    panel = reach_panel(arm)
    q = np.array([0.4, 0.9])
    target = arm.end_effector_pose(q)
    # By hand: (40 cos 0.4 + 30 cos 1.3, 40 sin 0.4 + 30 sin 1.3, 0).
    expected = [40 * math.cos(0.4) + 30 * math.cos(1.3), 40 * math.sin(0.4) + 30 * math.sin(1.3)]
    np.testing.assert_allclose(target[:2, 3], expected, rtol=1e-14)
    set_target(panel, target)
    assert panel.reach.result is not None and panel.reach.result.reason == "converged"
    np.testing.assert_allclose(panel.robot.end_effector(), target[:3, 3], atol=1e-6)
    assert "reached" in panel.reach.status.value
    # The editors show the new q; the end-effector line and the scene follow.
    assert [row.q.core_value for row in panel.dh.rows] == list(panel.robot.q)
    assert f"{panel.robot.end_effector()[0]:.4g}"[:4] in panel.ee_label.value
    np.testing.assert_array_equal(panel.scene.q, panel.robot.q)
    # Both elbows, and the robot stands on one of them.
    assert [b.description for b in panel.reach.solutions.buttons] == ["elbow down", "elbow up"]
    assert [b.button_style for b in panel.reach.solutions.buttons].count("info") == 1


def test_puma560_reaches_a_pose_and_lists_eight_branches() -> None:
    puma = rc.preset("puma560")
    panel = reach_panel(puma, length_unit="m")
    panel.reach.target.mode.value = "pose"
    target = puma.end_effector_pose(PUMA_Q)
    set_target(panel, target)
    np.testing.assert_allclose(panel.robot.end_effector_pose(), target, atol=1e-6)
    buttons = panel.reach.solutions.buttons
    assert len(buttons) == 8
    words = product(("left", "right"), ("up", "down"), ("no flip", "flip"))
    assert {b.description for b in buttons} == {
        f"shoulder {s}, elbow {e}, wrist {w}" for s, e, w in words
    }
    # Flagged exactly where a branch leaves the joint ranges (some turn of each angle).
    solutions = ik_all(puma, target)
    limits = puma.joint_limits()
    for button, row in zip(buttons, solutions.q, strict=True):
        turns = row[:, None] + 2 * np.pi * np.arange(-2, 3)
        inside = ((turns >= limits[:, :1] - 1e-12) & (turns <= limits[:, 1:] + 1e-12)).any(axis=1)
        assert ("robotconf-reach-outside" in button._dom_classes) == (not inside.all())
        assert (button.icon == "exclamation-triangle") == (not inside.all())
    assert panel.scene.ghost_count == 8 and panel.scene.target_shown


def test_clicking_a_branch_moves_the_robot_to_that_row() -> None:
    puma = rc.preset("puma560")
    panel = reach_panel(puma)
    panel.reach.target.mode.value = "pose"
    target = puma.end_effector_pose(PUMA_Q)
    set_target(panel, target)
    solutions = ik_all(puma, target)
    before = len(panel.history.history)
    panel.reach.solutions.buttons[5].click()
    np.testing.assert_array_equal(panel.robot.q, solutions.q[5])
    np.testing.assert_allclose(panel.robot.end_effector_pose(), target, atol=1e-9)
    assert [b.button_style for b in panel.reach.solutions.buttons].index("info") == 5
    assert solutions.labels[5] in panel.reach.status.value
    assert len(panel.history.history) == before + 1  # its own undo step
    panel.undo()
    np.testing.assert_allclose(panel.robot.end_effector_pose(), target, atol=1e-6)
    assert not np.allclose(panel.robot.q, solutions.q[5])


def test_an_unreachable_target_shows_the_distance_and_keeps_the_robot() -> None:
    arm = rc.preset("planar_2r").with_q([0.2, 0.3])
    panel = reach_panel(arm)
    panel.reach.target.controls["y"].box.value = 0.0
    panel.reach.target.controls["x"].box.value = 100.0  # 30 beyond 40 + 30
    result = panel.reach.result
    assert result is not None and result.reason == "unreachable"
    assert result.distance_to_reach == pytest.approx(100.0 - 70.0, abs=1e-9)
    assert "30 beyond the reach" in panel.reach.status.value
    assert "the robot stays where it was" in panel.reach.status.value
    # The robot is the last one that worked (y = 0 was reachable: it moved there).
    assert panel.robot.end_effector()[1] == pytest.approx(0.0, abs=1e-6)
    # The marker turns orange-red; the closed forms agree and say why.
    sphere = last_command(panel.scene, "set_object", f"{TARGET}/sphere")
    assert sphere["object"]["materials"][0]["color"] == TARGET_COLORS[False]
    assert panel.reach.solutions.buttons == []
    assert "30 beyond the reach" in panel.reach.solutions.note.value


def test_one_drag_of_a_target_slider_is_one_undo_step() -> None:
    arm = rc.preset("planar_2r").with_q([0.3, 0.6])
    panel = reach_panel(arm)
    now = [0.0]
    panel.reach.moves.clock = lambda: now[0]
    start = panel.robot
    x = panel.reach.target.controls["x"]
    for value in (50.0, 48.0, 46.0, 44.0):  # one drag: steps 0.1 s apart
        x.slider.value = value
        now[0] += 0.1
    assert panel.robot.end_effector()[0] == pytest.approx(44.0, abs=1e-6)
    panel.undo()
    assert panel.robot == start
    panel.redo()
    assert panel.robot.end_effector()[0] == pytest.approx(44.0, abs=1e-6)
    now[0] += 10.0  # a new drag, later: its own step
    x.slider.value = 40.0
    panel.undo()
    assert panel.robot.end_effector()[0] == pytest.approx(44.0, abs=1e-6)


def test_units_mm_and_degrees_name_and_convert() -> None:
    arm = rc.preset("planar_2r")
    panel = reach_panel(arm, length_unit="mm", degrees=True)
    controls = panel.reach.target.controls
    assert controls["x"].unit_label.value == "mm" and controls["yaw"].unit_label.value == "deg"
    panel.reach.target.mode.value = "pose"
    # q = (30°, 60°): the tool points along y (yaw 90°) at (40 cos 30°, 40 sin 30° + 30).
    controls["x"].box.value = 40 * math.cos(math.radians(30))
    controls["y"].box.value = 40 * math.sin(math.radians(30)) + 30
    controls["yaw"].box.value = 90.0
    pose = panel.robot.end_effector_pose()
    np.testing.assert_allclose(pose[:3, 3], [40 * math.cos(math.pi / 6), 50.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(pose[:3, :3], rotation_from_rpy(0, 0, math.pi / 2), atol=1e-9)
    np.testing.assert_allclose(np.degrees(panel.robot.q), [30.0, 60.0], atol=1e-6)
    # Switching units shows the same target: radians for angles, the length unit renamed.
    robot = panel.robot
    panel.angle_unit.value = False
    panel.length_unit.value = "in"
    assert controls["yaw"].box.value == pytest.approx(math.pi / 2, abs=1e-6)
    assert controls["x"].unit_label.value == "in" and controls["x"].box.value == pytest.approx(
        40 * math.cos(math.pi / 6), abs=1e-9
    )
    assert panel.robot == robot


def test_from_current_pose_and_an_edit_elsewhere() -> None:
    arm = rc.preset("planar_2r")
    panel = reach_panel(arm)
    panel.reach.target.controls["x"].box.value = 50.0
    moved = panel.robot.with_q([0.1, 0.2])
    panel.set_robot(moved)  # an edit elsewhere: the target stays, the tab says how far
    assert "from the target" in panel.reach.status.value
    assert panel.reach.target.controls["x"].box.value == 50.0
    panel.reach.from_current.click()
    point = panel.robot.end_effector()
    assert panel.reach.target.controls["x"].core_value == pytest.approx(point[0], abs=1e-9)
    assert panel.reach.target.controls["y"].core_value == pytest.approx(point[1], abs=1e-9)
    assert panel.robot == moved  # the target moved, not the robot


def test_the_page_sliders_snapped_copy_of_a_target_is_no_edit() -> None:
    # A browser slider snaps 0.50338 to its notch 0.50 and sends that back (with noise)
    # as if dragged: the target and the robot stay; a real move is taken.
    panel = reach_panel(rc.preset("puma560"), length_unit="m")
    x = panel.reach.target.controls["x"]
    x.box.value = 0.4018
    robot, history = panel.robot, len(panel.history.history)
    x.slider.value = 0.39999999999999997
    assert x.core_value == 0.4018 and panel.robot == robot
    assert len(panel.history.history) == history
    x.slider.value = 0.41
    assert panel.robot.end_effector()[0] == pytest.approx(0.41, abs=1e-6)


def test_a_nan_target_is_refused_beside_its_box() -> None:
    panel = reach_panel(rc.preset("planar_2r"))
    robot = panel.robot
    panel.reach.target.controls["x"].box.value = float("nan")
    assert panel.errors["reach.target.x"].startswith("target.x: not a number")
    assert panel.robot == robot


def test_a_geometry_without_closed_form_says_so_and_leaving_the_tab_clears_the_pane() -> None:
    panel = reach_panel(rc.preset("paper").with_q([0.1, 0.2, 0.3]))
    panel.reach.target.controls["z"].box.value = 25.0
    assert panel.reach.result is not None and panel.reach.result.success
    assert panel.robot.end_effector()[2] == pytest.approx(25.0, abs=1e-6)
    skew = rc.Robot(
        [rc.Module("Rz"), rc.Module("Rx", a=(0, 0, 20)), rc.Module("Ry", a=(30, 5, 0))],
        end_effector=(40, 0, 0),
    )
    panel.set_robot(skew)
    assert "no closed form" in panel.reach.solutions.note.value
    assert panel.scene.ghost_count == 0
    panel.results.selected_index = 0
    assert not panel.scene.target_shown
    kinds = [op.content.get("command", {}).get("path") for op in panel.scene._replay()]
    assert GHOSTS not in kinds and not any(str(k).startswith(TARGET) for k in kinds)
