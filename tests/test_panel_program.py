"""The Program tab: moves taught and typed in the panel become the core's Program.

Durations are derived by hand from the trapezoidal law (docs/programs.md): a PTP step Δ at
joint speed v and acceleration a takes Δ/v + v/a when Δ ≥ v²/a; a LIN of length L at path
speed v and acceleration a, L/v + v/a. Violations are compared with the core's own check
of the same program.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest

import robotconf as rc
from robotconf.panel import Configurator
from robotconf.panel import actions as act
from robotconf.programs import CIRC, LIN, PTP, Program, ProgramMotion, Wait

from .test_panel_support import FakeScene, make_panel, shown, ui

#: The paper's robot: l1 = 20 (z), l2 = 30, l3 = 40; EE (70, 0, 20) at q = 0; size 90, so
#: the default path speed and acceleration are 0.25·90 = 22.5.
PATH_DEFAULT = 22.5


def program_panel(robot: Any = None, **options: Any) -> Configurator:
    panel = make_panel(rc.preset("paper") if robot is None else robot, **options)
    panel.apply(act.SelectTab("program"))
    return panel


def set_q(panel: Configurator, degrees: list[float]) -> None:
    """Move the robot with the editor's q boxes (degrees, the panel's default unit)."""
    for i, value in enumerate(degrees):
        ui(panel, f"modules[{i}].q").type(str(value))


def taught_line(panel: Configurator) -> None:
    """P1: PTP to q3 = −90° (EE (30, 0, 60)); P2: LIN 30 along y at 10 per second."""
    set_q(panel, [0, 0, -90])
    ui(panel, "program.add").click()
    ui(panel, "program.add").click()
    ui(panel, "program.moves[1].kind").choose("LIN")  # the PTP's point becomes its end…
    assert "goes nowhere" in panel.errors["program.moves[1]"]  # …kept, and said, until…
    ui(panel, "program.moves[1].point1").type("30")  # …it goes somewhere
    ui(panel, "program.moves[1].speed").type("10")
    assert "program.moves[1]" not in panel.errors
    set_q(panel, [0, 0, 0])  # the program starts where the robot is: EE (70, 0, 20)


def moves(panel) -> tuple:  # type: ignore[no-untyped-def]
    return panel.state.document.program.moves


def status(panel) -> str:  # type: ignore[no-untyped-def]
    return next(
        c["value"]
        for r in panel.program_tab.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-program-status"
    )


def violations(panel, i: int) -> list[str]:  # type: ignore[no-untyped-def]
    row = next(r for r in panel.program_tab.form.spec["rows"] if r["key"] == f"program.moves[{i}]")
    return [c["value"][2:] for line in row["lines"][1:] for c in line]


def test_the_program_tab_sits_after_reach() -> None:
    panel = program_panel()
    assert panel.results.titles == ("Motion", "Matrices", "Reach", "Program", "Save / Load")
    assert panel.results.children[3] is panel.program_tab.widget
    assert panel.program is None and moves(panel) == ()


def test_taught_moves_build_the_program_and_run_with_hand_derived_times() -> None:
    panel = program_panel(length_unit="mm")
    taught_line(panel)
    program = panel.program
    assert program is not None
    ptp, lin = program.moves
    assert ptp == PTP(q=(0.0, 0.0, -math.pi / 2))  # the editor's −90°, exactly
    assert isinstance(lin, LIN) and lin.speed == 10.0
    np.testing.assert_allclose(lin.position, [30, 30, 60], atol=1e-12)
    ui(panel, "program.run").click()
    motion = panel.motion
    assert isinstance(motion, ProgramMotion) and motion is panel.state.program_run.motion
    # PTP: Δ = π/2 at 1 rad/s, 2 rad/s² (π/2 ≥ 1/2): π/2 + 1/2. LIN: 30/10 + 10/22.5.
    durations = [segment.duration for segment in motion.segments]
    np.testing.assert_allclose(durations, [math.pi / 2 + 0.5, 3 + 10 / PATH_DEFAULT], rtol=1e-12)
    np.testing.assert_allclose(motion.trace[0], [70, 0, 20], atol=1e-12)
    np.testing.assert_allclose(motion.trace[-1], [30, 30, 60], atol=1e-9)
    assert panel.state.program_run.report.ok and "no violations" in status(panel)
    assert violations(panel, 0) == violations(panel, 1) == []


def test_run_shows_the_motion_in_the_motion_tab_and_animates_it_with_the_trace() -> None:
    panel = program_panel(length_unit="mm")
    taught_line(panel)
    ui(panel, "program.run").click()
    motion = panel.state.program_run.motion
    assert panel.scene.calls[-1] == ("animate", motion)
    assert panel.state.view.trace and panel.scene.trace_shown
    assert panel.state.playback.source == "program" and panel.state.playback.playing
    ui(panel, "program.motion").click()
    assert panel.results.selected_index == 0
    assert "position [mm]" in panel.motion_tab.results.table.value
    assert panel.motion_tab.results.motion is motion


def test_violations_show_under_the_move_that_causes_them() -> None:
    robot = rc.preset("paper")
    program = Program(robot, [PTP(position=[10, -10, 50]), LIN(position=[-10, 10, 50], speed=10)])
    panel = program_panel(robot)
    panel.apply(act.LoadSetup(robot, {}, None, program))
    ui(panel, "program.dt").type("0.01")
    ui(panel, "program.run").click()
    expected = program.check(dt=0.01)  # the core, independently
    assert expected.kinds == ("singularity",) and {v.move for v in expected} == {1}
    assert violations(panel, 0) == []
    assert violations(panel, 1) == [violation.message for violation in expected]
    assert f"{len(expected)} violation(s), at P2" in status(panel)
    # An edit makes the run stale: its marks go, the status says so.
    ui(panel, "program.moves[1].speed").type("5")
    assert violations(panel, 1) == [] and "changed since this run" in status(panel)


#: P1 ends at (30, 0, 60) and starts from (70, 0, 20); each case first makes a valid move
#: (``ready``: box, value), then types one bad value.
BAD_INPUT = [
    ("LIN", [], ("speed", "-5"), "speed", "must be > 0, got -5.0"),
    ("LIN", [("point2", "20")], ("point0", "200"), "point0", "unreachable"),
    ("LIN", [("point2", "20")], ("point0", "70"), "point0", "goes nowhere"),
    # start (70, 0, 20), via (50, 0, 20), end (30, 0, 20): one line, no circle.
    (
        "CIRC",
        [("via0", "50"), ("via1", "20"), ("via2", "20"), ("point2", "20")],
        ("via1", "0"),
        "via1",
        "lie on one line",
    ),
]


@pytest.mark.parametrize(("kind", "ready", "bad", "box", "words"), BAD_INPUT)
def test_a_program_the_core_refuses_is_kept_named_and_not_saved(
    kind: str, ready: list[tuple[str, str]], bad: tuple[str, str], box: str, words: str
) -> None:
    panel = program_panel()
    set_q(panel, [0, 0, -90])
    ui(panel, "program.add").click()
    set_q(panel, [0, 0, 0])
    ui(panel, "program.moves[0].kind").choose(kind)
    for name, value in ready:
        ui(panel, f"program.moves[0].{name}").type(value)
    valid, robot = panel.to_json(), panel.robot
    assert panel.program is not None and panel.program.moves[0].kind == kind
    assert panel.errors == {}
    name, value = bad
    ui(panel, f"program.moves[0].{name}").type(value)
    message = panel.errors["program.moves[0]"]  # beside the move, in the core's words
    assert message.startswith("program.moves[0]") and words in message
    assert panel.program is None and panel.robot is robot
    ui(panel, "program.run").click()
    assert panel.motion is None and panel.errors["program.run"] == message  # Run says so too
    with pytest.raises(rc.InvalidInputError, match=r"program\.moves\[0\]"):
        panel.to_json()  # and the setup is not saved while it is wrong
    panel.undo()  # the last valid program is one undo away
    assert panel.to_json() == valid and panel.errors == {}


def test_undo_brings_back_a_deleted_move_and_redo_deletes_it_again() -> None:
    panel = program_panel()
    for q3 in (-30, -60, -90):
        set_q(panel, [0, 0, q3])
        ui(panel, "program.add").click()
    before = moves(panel)
    assert [move.q[2] for move in before] == [math.radians(a) for a in (-30, -60, -90)]
    ui(panel, "program.moves[1].delete").click()
    assert moves(panel) == (before[0], before[2]) and panel.program.moves == moves(panel)
    ui(panel, "program.undo").click()  # the tab's ↶ is the panel's one undo
    assert moves(panel) == before
    assert [shown(panel, f"program.moves[{i}].q2")["value"] for i in range(3)] == [-30, -60, -90]
    ui(panel, "program.redo").click()
    assert moves(panel) == (before[0], before[2])
    ui(panel, "program.moves[1].up").click()  # reordering is a step of its own too
    assert moves(panel) == (before[2], before[0])
    panel.undo()
    assert moves(panel) == (before[0], before[2])
    ui(panel, "program.clear").click()
    assert moves(panel) == () and panel.program is None
    panel.undo()
    assert moves(panel) == (before[0], before[2])
    assert panel.robot.q.tolist() == [0.0, 0.0, math.radians(-90)]  # the robot never moved


def test_teach_records_the_current_pose() -> None:
    panel = program_panel()
    ui(panel, "program.add").click()
    set_q(panel, [90, 0, 0])
    ui(panel, "program.moves[0].teach").click()
    assert moves(panel)[0] == PTP(q=(math.pi / 2, 0.0, 0.0))
    set_q(panel, [0, 0, -90])
    ui(panel, "program.add").click()
    ui(panel, "program.moves[1].kind").choose("CIRC")  # from P1: an arc to here
    set_q(panel, [0, 0, 0])
    ui(panel, "program.moves[1].teach").click()  # end: here
    circ = moves(panel)[1]
    assert isinstance(circ, CIRC)
    np.testing.assert_allclose(circ.end, [70, 0, 20], atol=1e-12)
    ui(panel, "program.moves[1].via").click()  # via at the end: the core refuses that arc
    assert "program.moves[1]" in panel.errors and moves(panel)[1].via == circ.end


def test_save_and_load_round_trip_the_program(tmp_path: Any) -> None:
    panel = program_panel()
    taught_line(panel)
    ui(panel, "program.cartesian_accel").type("15")
    original = panel.program
    assert original is not None and original.limits.cartesian_accel == 15.0
    path = tmp_path / "setup.json"
    panel.save(path)
    data = json.loads(path.read_text("utf-8"))
    assert [move["type"] for move in data["program"]["moves"]] == ["PTP", "LIN"]
    other = program_panel(rc.preset("planar_2r"))
    other.load(path)
    assert other.robot == panel.robot and other.program == original
    assert shown(other, "program.moves[1].speed")["value"] == 10.0
    # A file without a program empties the table, as one undoable step.
    plain = tmp_path / "plain.json"
    plain.write_text(rc.preset("paper").to_json(), "utf-8")
    other.load(plain)
    assert moves(other) == ()
    other.undo()
    assert other.state.document.program == panel.state.document.program


def test_a_bound_file_keeps_the_program_across_a_restart(tmp_path: Any) -> None:
    path = tmp_path / "work.json"
    panel = Configurator(str(path), scene_factory=FakeScene)
    panel.apply(act.SelectTab("program"))
    taught_line(panel)
    saved = json.loads(path.read_text("utf-8"))
    assert saved["program"]["moves"][1]["speed"] == 10.0
    again = Configurator(str(path), scene_factory=FakeScene)  # the kernel restarted
    assert again.program == panel.program and again.program is not None
    assert again.errors == {} and not again.can_undo  # the file's program comes first


def test_units_convert_angles_and_name_lengths() -> None:
    panel = program_panel(length_unit="mm")
    ui(panel, "program.add").click()
    ui(panel, "program.moves[0].q2").type("90")
    assert moves(panel)[0].q[2] == math.pi / 2  # degrees typed, radians kept
    assert shown(panel, "program.joint_speed")["value"] == 57.2958  # 1 rad/s
    ui(panel, "angle_unit").choose(False)  # radians
    assert shown(panel, "program.moves[0].q2")["value"] == 1.5708
    ui(panel, "program.moves[0].q1").type("0.25")
    assert moves(panel)[0].q == (0.0, 0.25, math.pi / 2)  # the untouched q3 stays exact
    assert shown(panel, "program.joint_speed")["value"] == 1.0
    set_q(panel, [0.1, 0, 0])
    ui(panel, "program.add").click()
    ui(panel, "program.moves[1].kind").choose("LIN")
    assert shown(panel, "program.moves[1].speed")["value"] == PATH_DEFAULT  # the default
    assert moves(panel)[1].speed is None  # untouched: still the default
    assert shown(panel, "program.cartesian_speed")["label"] == "path speed [mm/s]"


def test_typed_limits_reach_the_program() -> None:
    panel = program_panel()
    set_q(panel, [0, 0, 90])
    ui(panel, "program.add").click()
    set_q(panel, [0, 0, 0])
    ui(panel, "program.joint_speed").type("90")  # deg/s
    program = panel.program
    assert panel.state.document.program.settings["joint_speed"] == math.pi / 2
    np.testing.assert_array_equal(program.limits.joint_speed, [math.pi / 2] * 3)
    # Δ = π/2 at v = π/2 rad/s, a = 2 rad/s² (Δ ≥ v²/a): 1 + (π/2)/2.
    assert program.duration == pytest.approx(1 + math.pi / 4, rel=1e-12)
    ui(panel, "program.joint_accel").type("-1")
    assert "joint_accel: must be > 0" in panel.errors["program.joint_accel"]
    assert panel.program is None
    ui(panel, "program.joint_accel").type("180")  # deg/s²
    assert panel.program is not None and panel.errors == {}


def test_a_sliding_joint_has_its_own_limit_box() -> None:
    scara = rc.preset("scara")
    panel = program_panel(scara)
    default = Program(scara, [Wait(0.0)]).limits.joint_speed[2]
    assert shown(panel, "program.slide_speed")["value"] == float(f"{default:.6g}")
    ui(panel, "program.add").click()
    ui(panel, "program.joint_speed").type("90")
    expected = (math.pi / 2, math.pi / 2, float(default), math.pi / 2)
    assert panel.state.document.program.settings["joint_speed"] == expected
    assert "program.slide_speed" not in program_panel().program_tab.form.control_keys()


def test_ptp_coordinates_follow_an_added_and_a_removed_module() -> None:
    panel = program_panel()
    set_q(panel, [10, 20, 30])
    ui(panel, "program.add").click()
    taught_q = moves(panel)[0].q
    ui(panel, "modules.add").click()  # a fourth module at q = 0
    assert moves(panel)[0].q == (*taught_q, 0.0) and panel.errors == {}
    panel.undo()
    assert moves(panel)[0].q == taught_q
    ui(panel, "modules[0].delete").click()  # q1 goes
    assert moves(panel)[0].q == taught_q[1:]
    assert panel.program is not None and panel.program.robot == panel.robot


def test_a_joint_set_to_none_keeps_its_own_value_in_every_ptp(tmp_path: Any) -> None:
    # A taught PTP holds q2 = 20°; module 2, moved on to 40°, then becomes "none": the
    # program cannot move it, so the PTP takes the robot's own q2 (40°), and the bound file
    # goes on saving.
    path = tmp_path / "work.json"
    panel = Configurator(str(path), scene_factory=FakeScene)
    panel.apply(act.LoadPreset("paper"))
    panel.apply(act.SelectTab("program"))
    set_q(panel, [10, 20, 30])
    ui(panel, "program.add").click()
    taught = moves(panel)[0].q
    set_q(panel, [0, 40, 0])  # the arm moved on: module 2 now stands at 40°
    ui(panel, "modules[1].kind").choose("none")
    own = panel.robot.q[1]
    assert own == pytest.approx(math.radians(40)) and taught[1] == pytest.approx(math.radians(20))
    assert moves(panel)[0].q == (taught[0], own, taught[2])
    assert panel.errors == {} and panel.program is not None
    assert json.loads(path.read_text("utf-8"))["program"]["moves"][0]["q"][1] == own
    box = panel.program_tab.form.control("program.moves[0].q1")  # no number in degrees
    assert box["disabled"] and box["text"] == "—"
    panel.undo()  # the taught value comes back with the joint
    assert moves(panel)[0].q == taught and panel.robot.modules[1].kind == "Ry"


def test_the_taught_points_are_marked_while_the_tab_shows() -> None:
    panel = program_panel()
    taught_line(panel)
    ui(panel, "program.add").click()
    ui(panel, "program.moves[2].kind").choose("Wait")  # no point of its own
    name, (points, labels, _) = panel.scene.calls[-1]
    assert name == "show_taught_points" and labels == ["P1", "P2"]
    np.testing.assert_allclose(points, [[30, 0, 60], [30, 30, 60]], atol=1e-9)
    panel.apply(act.SelectTab("motion"))
    assert ("clear_taught_points", None) in panel.scene.calls[-3:]
    panel.apply(act.SelectTab("program"))
    assert panel.scene.calls[-1][0] == "show_taught_points"


def test_an_empty_program_and_a_bad_dt_are_refused() -> None:
    panel = program_panel()
    ui(panel, "program.run").click()
    assert panel.errors["program.run"].startswith("moves: empty program")
    ui(panel, "program.add").click()
    ui(panel, "program.moves[0].q0").type("30")
    ui(panel, "program.dt").type("0")
    assert panel.errors["program.dt"].startswith("dt:") and panel.state.program_dt == 0.01
    ui(panel, "program.dt").type("0.05")
    ui(panel, "program.run").click()
    assert "program.dt" not in panel.errors and panel.motion is not None
