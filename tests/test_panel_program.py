"""The Program tab: moves taught and typed in the panel become the core's Program.

The panel runs with the real scene on a recording channel, so the taught points, the
trace and the animation it draws can be read back. Durations are derived by hand from
the trapezoidal law (docs/programs.md): a PTP step Δ at joint speed v and acceleration a
takes Δ/v + v/a when Δ ≥ v²/a; a LIN of length L at path speed v and acceleration a,
L/v + v/a. Violations are compared with the core's own check of the same program.
"""

from __future__ import annotations

import html
import json
import math
from typing import Any

import ipywidgets as widgets
import numpy as np
import pytest

import robotconf as rc
from robotconf.panel import Configurator
from robotconf.programs import CIRC, LIN, PTP, Program, ProgramMotion, Wait
from robotconf.scene import RecordingChannel, Scene
from robotconf.scene._playback import TRACE

PROGRAM_TAB, MOTION_TAB = 3, 0
#: The paper's robot: l1 = 20 (z), l2 = 30, l3 = 40; EE (70, 0, 20) at q = 0; size 90, so
#: the default path speed and acceleration are 0.25·90 = 22.5.
PATH_DEFAULT = 22.5


class RecordedScene(Scene):
    """The real scene, its ops recorded instead of sent; a stand-in widget for the panel."""

    widget: Any = None

    def __init__(self, robot: rc.Robot) -> None:
        super().__init__(robot, channel=RecordingChannel())
        self.widget = widgets.HTML("scene")


def program_panel(robot: Any = None, **options: Any) -> Configurator:
    panel = Configurator(
        rc.preset("paper") if robot is None else robot, scene_factory=RecordedScene, **options
    )
    panel.results.selected_index = PROGRAM_TAB
    return panel


def set_q(panel: Configurator, degrees: list[float]) -> None:
    """Move the robot with the editor's q boxes (degrees, the panel's default unit)."""
    for row, value in zip(panel.modules.rows, degrees, strict=True):
        row.q.box.value = float(value)


def taught_line(panel: Configurator) -> None:
    """P1: PTP to q3 = −90° (EE (30, 0, 60)); P2: LIN 30 along y at 10 per second."""
    tab = panel.program_tab
    set_q(panel, [0, 0, -90])
    tab.add_button.click()
    tab.add_button.click()
    tab.rows[1].kind.value = "LIN"  # the PTP's point becomes the line's end
    tab.rows[1].boxes["point"][1].value = 30.0
    tab.rows[1].boxes["speed"][0].value = 10.0
    set_q(panel, [0, 0, 0])  # the program starts where the robot is: EE (70, 0, 20)


def test_the_program_tab_sits_after_reach() -> None:
    panel = program_panel()
    assert panel.results.titles == ("Motion", "Matrices", "Reach", "Program", "Save / Load")
    assert panel.results.children[PROGRAM_TAB] is panel.program_tab.widget
    assert panel.program is None and panel.program_tab.rows == []


def test_taught_moves_build_the_program_and_run_with_hand_derived_times() -> None:
    panel = program_panel(length_unit="mm")
    taught_line(panel)
    program = panel.program
    assert program is not None and panel.errors == {}
    ptp, lin = program.moves
    assert ptp == PTP(q=(0.0, 0.0, -math.pi / 2))  # the editor's −90°, exactly
    assert isinstance(lin, LIN) and lin.speed == 10.0 and lin.position[1] == 30.0
    np.testing.assert_allclose(lin.position, [30, 30, 60], atol=1e-12)
    panel.program_tab.run_button.click()
    motion = panel.motion
    assert isinstance(motion, ProgramMotion) and motion is panel.program_tab.motion
    # PTP: Δ = π/2 at 1 rad/s, 2 rad/s² (π/2 ≥ 1/2): π/2 + 1/2. LIN: 30/10 + 10/22.5.
    durations = [segment.duration for segment in motion.segments]
    np.testing.assert_allclose(durations, [math.pi / 2 + 0.5, 3 + 10 / PATH_DEFAULT], rtol=1e-12)
    np.testing.assert_allclose(motion.trace[0], [70, 0, 20], atol=1e-12)
    np.testing.assert_allclose(motion.trace[-1], [30, 30, 60], atol=1e-9)
    assert panel.program_tab.report is not None and panel.program_tab.report.ok
    assert "no violations" in panel.program_tab.status.value
    assert all(row.violations.value == "" for row in panel.program_tab.rows)


def test_run_shows_the_motion_in_the_motion_tab_and_animates_it_with_the_trace() -> None:
    panel = program_panel(length_unit="mm")
    taught_line(panel)
    panel.program_tab.run_button.click()
    motion = panel.program_tab.motion
    assert motion is not None
    results = panel.motion_section.results
    assert results.motion is motion and "position [mm]" in results.table.value
    scene = panel.scene
    assert scene.playback_state.loaded
    assert scene.playback_state.duration == pytest.approx(motion.program.duration, rel=1e-12)
    assert scene.trace_shown
    assert [c for c in scene.channel.commands("set_object") if c["path"] == TRACE]
    panel.program_tab.motion_button.click()
    assert panel.results.selected_index == MOTION_TAB


def test_violations_show_under_the_move_that_causes_them() -> None:
    robot = rc.preset("paper")
    moves = [PTP(position=[10, -10, 50]), LIN(position=[-10, 10, 50], speed=10)]
    panel = program_panel(robot)
    panel.program_tab.load(Program(robot, moves))
    panel.program_tab.dt.value = 0.01
    panel.program_tab.run_button.click()
    expected = Program(robot, moves).check(dt=0.01)  # the core, independently
    assert expected.kinds == ("singularity",) and {v.move for v in expected} == {1}
    rows = panel.program_tab.rows
    assert rows[0].messages == [] and rows[0].violations.value == ""
    assert rows[1].messages == [violation.message for violation in expected]
    assert html.escape(expected.violations[0].message) in rows[1].violations.value
    assert f"{len(expected)} violation(s), at P2" in panel.program_tab.status.value
    # An edit makes the run stale: its marks go, the status says so.
    rows[1].boxes["speed"][0].value = 5.0
    assert rows[1].messages == [] and rows[1].violations.value == ""
    assert "changed since this run" in panel.program_tab.status.value


#: P1 ends at (30, 0, 60) and starts from (70, 0, 20); each case first makes a valid move
#: (``ready``: box, component, value), then types one bad value.
BAD_INPUT = [
    ("LIN", [], ("speed", 0, -5.0), "moves[0].speed", "must be > 0, got -5.0"),
    ("LIN", [("point", 2, 20.0)], ("point", 0, 200.0), "moves[0].position", "unreachable"),
    ("LIN", [("point", 2, 20.0)], ("point", 0, 70.0), "moves[0].position", "goes nowhere"),
    # start (70, 0, 20), via (50, 0, 20), end (30, 0, 20): one line, no circle.
    (
        "CIRC",
        [("via", 0, 50.0), ("via", 1, 20.0), ("via", 2, 20.0), ("point", 2, 20.0)],
        ("via", 1, 0.0),
        "moves[0].via",
        "lie on one line",
    ),
]


@pytest.mark.parametrize(("kind", "ready", "bad", "field", "words"), BAD_INPUT)
def test_bad_input_shows_the_core_message_beside_the_move_and_keeps_the_last_program(
    kind: str,
    ready: list[tuple[str, int, float]],
    bad: tuple[str, int, float],
    field: str,
    words: str,
) -> None:
    panel = program_panel()
    tab = panel.program_tab
    set_q(panel, [0, 0, -90])
    tab.add_button.click()
    set_q(panel, [0, 0, 0])
    tab.rows[0].kind.value = kind
    for name, component, value in ready:
        tab.rows[0].boxes[name][component].value = value
    last, robot = panel.program, panel.robot
    assert last is not None and last.moves[0].kind == kind and panel.errors == {}
    name, component, value = bad
    tab.rows[0].boxes[name][component].value = value
    message = panel.errors["program.moves[0]"]
    assert message.startswith(field) and words in message
    assert panel.program is last and panel.robot == robot  # the last valid ones stay
    panel.program_tab.run_button.click()
    assert panel.motion is None  # Run refuses too, with the same message
    assert panel.errors["program.moves[0]"] == message
    with pytest.raises(rc.InvalidInputError, match=r"program\.moves\[0\]"):
        panel.to_json()  # and the setup is not saved while it is wrong
    tab.rows[0].boxes[name][component].value = {"speed": 5.0, "point": 40.0}.get(name, 10.0)
    assert "program.moves[0]" not in panel.errors and panel.program is not last


def test_undo_brings_back_a_deleted_move_and_redo_deletes_it_again() -> None:
    panel = program_panel()
    tab = panel.program_tab
    for q3 in (-30, -60, -90):
        set_q(panel, [0, 0, q3])
        tab.add_button.click()
    before = tab.draft.moves
    assert [move.q[2] for move in before] == [math.radians(a) for a in (-30, -60, -90)]
    tab.rows[1].delete_button.click()
    assert tab.draft.moves == (before[0], before[2]) and len(tab.rows) == 2
    assert panel.program.moves == (before[0], before[2])
    tab.history.undo_button.click()
    assert tab.draft.moves == before and panel.program.moves == before
    assert [row.boxes["q"][2].value for row in tab.rows] == [-30.0, -60.0, -90.0]
    tab.history.redo_button.click()
    assert tab.draft.moves == (before[0], before[2])
    # Reordering is a step of its own too.
    tab.rows[1].up_button.click()
    assert tab.draft.moves == (before[2], before[0])
    tab.history.undo_button.click()
    assert tab.draft.moves == (before[0], before[2])
    tab.clear_button.click()
    assert tab.draft.moves == () and tab.rows == [] and panel.program is None
    tab.history.undo_button.click()
    assert tab.draft.moves == (before[0], before[2])
    assert panel.robot.q.tolist() == [0.0, 0.0, math.radians(-90)]  # the robot never moved


def test_teach_records_the_current_pose() -> None:
    panel = program_panel()
    tab = panel.program_tab
    tab.add_button.click()
    tab.add_button.click()
    tab.rows[1].kind.value = "CIRC"
    set_q(panel, [90, 0, 0])
    tab.rows[0].teach_button.click()
    assert tab.draft.moves[0] == PTP(q=(math.pi / 2, 0.0, 0.0))
    set_q(panel, [0, 0, -90])
    tab.rows[1].teach_button.click()
    tab.rows[1].via_button.click()
    circ = tab.draft.moves[1]
    assert isinstance(circ, CIRC)
    np.testing.assert_allclose(circ.end, [30, 0, 60], atol=1e-12)
    assert circ.via == circ.end  # taught at the same place: the core refuses that arc
    assert "moves[1]" in panel.errors["program.moves[1]"]


def test_save_and_load_round_trip_the_program(tmp_path: Any) -> None:
    panel = program_panel()
    taught_line(panel)
    panel.program_tab.limits.boxes["cartesian_accel"].value = 15.0
    original = panel.program
    assert original is not None and original.limits.cartesian_accel == 15.0
    path = tmp_path / "setup.json"
    panel.save(path)
    data = json.loads(path.read_text("utf-8"))
    assert [move["type"] for move in data["program"]["moves"]] == ["PTP", "LIN"]
    other = program_panel(rc.preset("planar_2r"))
    other.load(path)
    assert other.robot == panel.robot
    assert other.program == original and other.program_tab.draft == panel.program_tab.draft
    assert other.program_tab.rows[1].boxes["speed"][0].value == 10.0
    # A file without a program empties the table, as one undoable step.
    plain = tmp_path / "plain.json"
    plain.write_text(rc.preset("paper").to_json(), "utf-8")
    other.load(plain)
    assert other.program_tab.draft.moves == ()
    other.program_tab.history.undo_button.click()
    assert other.program_tab.draft == panel.program_tab.draft


def test_a_bound_file_keeps_the_program_across_a_restart(tmp_path: Any) -> None:
    path = tmp_path / "work.json"
    panel = Configurator(str(path), scene_factory=RecordedScene)
    taught_line(panel)
    saved = json.loads(path.read_text("utf-8"))
    assert saved["program"]["moves"][1]["speed"] == 10.0
    again = Configurator(str(path), scene_factory=RecordedScene)  # the kernel restarted
    assert again.program == panel.program and again.program is not None
    assert again.program_tab.draft == panel.program_tab.draft
    assert again.errors == {}
    assert again.program_tab.history.undo_button.disabled  # the file's program comes first


def test_units_convert_angles_and_name_lengths() -> None:
    panel = program_panel(length_unit="mm")
    tab = panel.program_tab
    tab.add_button.click()
    row = tab.rows[0]
    row.boxes["q"][2].value = 90.0
    assert tab.draft.moves[0].q[2] == math.pi / 2  # degrees typed, radians kept
    assert "q [deg]" in row.fields.children[0].value
    assert tab.limits.boxes["joint_speed"].value == 57.2958  # 1 rad/s
    panel.angle_unit.value = False  # radians
    assert row.boxes["q"][2].value == 1.5708 and "q [rad]" in row.fields.children[0].value
    row.boxes["q"][1].value = 0.25
    assert tab.draft.moves[0].q == (0.0, 0.25, math.pi / 2)  # the untouched q3 stays exact
    assert tab.limits.boxes["joint_speed"].value == 1.0
    tab.add_button.click()
    tab.rows[1].kind.value = "LIN"
    captions = [child.value for child in tab.rows[1].fields.children[::4]]
    assert "x, y, z [mm]" in captions[0] and "speed [mm/s]" in captions[1]
    assert tab.rows[1].boxes["speed"][0].value == PATH_DEFAULT  # the program's default
    assert tab.draft.moves[1].speed is None  # untouched: still the default
    assert "path speed [mm/s]" in tab.limits.captions["cartesian_speed"].value


def test_typed_limits_reach_the_program() -> None:
    panel = program_panel()
    tab = panel.program_tab
    set_q(panel, [0, 0, 90])
    tab.add_button.click()
    set_q(panel, [0, 0, 0])
    tab.limits.boxes["joint_speed"].value = 90.0  # deg/s
    program = panel.program
    assert program is not None
    assert tab.draft.settings["joint_speed"] == math.pi / 2
    np.testing.assert_array_equal(program.limits.joint_speed, [math.pi / 2] * 3)
    # Δ = π/2 at v = π/2 rad/s, a = 2 rad/s² (Δ ≥ v²/a): 1 + (π/2)/2.
    assert program.duration == pytest.approx(1 + math.pi / 4, rel=1e-12)
    tab.limits.boxes["joint_accel"].value = -1.0
    assert panel.errors["program.joint_accel"].startswith("joint_accel: must be > 0")
    assert panel.program is program


def test_a_sliding_joint_has_its_own_limit_box() -> None:
    scara = rc.preset("scara")
    panel = program_panel(scara)
    tab = panel.program_tab
    assert tab.limits.cells["slide_speed"].layout.display is None
    default = Program(scara, [Wait(0.0)]).limits.joint_speed[2]
    assert tab.limits.boxes["slide_speed"].value == float(f"{default:.6g}")
    tab.add_button.click()
    tab.limits.boxes["joint_speed"].value = 90.0
    expected = (math.pi / 2, math.pi / 2, float(default), math.pi / 2)
    assert tab.draft.settings["joint_speed"] == expected
    assert program_panel().program_tab.limits.cells["slide_speed"].layout.display == "none"


def test_ptp_coordinates_follow_an_added_and_a_removed_module() -> None:
    panel = program_panel()
    tab = panel.program_tab
    set_q(panel, [10, 20, 30])
    tab.add_button.click()
    taught_q = tab.draft.moves[0].q
    panel.modules.add_button.click()  # a fourth module at q = 0
    assert tab.draft.moves[0].q == (*taught_q, 0.0) and panel.errors == {}
    panel.undo()
    assert tab.draft.moves[0].q == taught_q
    panel.modules.rows[0].remove_button.click()  # q1 goes
    assert tab.draft.moves[0].q == taught_q[1:]
    assert panel.program is not None and panel.program.robot == panel.robot


def test_the_taught_points_are_marked_while_the_tab_shows() -> None:
    panel = program_panel()
    tab = panel.program_tab
    taught_line(panel)
    tab.add_button.click()
    tab.rows[2].kind.value = "Wait"  # no point of its own
    assert panel.scene.taught_labels == ["P1", "P2"]
    tab.rows[1].boxes["point"][1].value = 0.0  # P2 onto P1: one label
    assert panel.scene.taught_labels == ["P1, P2", ""]
    panel.results.selected_index = MOTION_TAB
    assert panel.scene.taught_labels == []
    panel.results.selected_index = PROGRAM_TAB
    assert panel.scene.taught_labels == ["P1, P2", ""]


def test_an_empty_program_and_a_bad_dt_are_refused_on_run() -> None:
    panel = program_panel()
    panel.program_tab.run_button.click()
    assert panel.errors["program.run"].startswith("moves: empty program")
    panel.program_tab.add_button.click()
    panel.program_tab.rows[0].boxes["q"][0].value = 30.0
    panel.program_tab.dt.value = 0.0
    panel.program_tab.run_button.click()
    assert panel.errors["program.dt"].startswith("dt:") and panel.motion is None
    panel.program_tab.dt.value = 0.05
    panel.program_tab.run_button.click()
    assert "program.dt" not in panel.errors and panel.motion is not None
