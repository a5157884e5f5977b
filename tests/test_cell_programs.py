"""Programs in the cell: moves that name cell frames, and every robot's program run at once."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.io import program_from_dict, program_to_dict
from robotconf.programs import CIRC, LIN, PTP, Program, Wait

pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")


def _cell():
    cell = rc.Cell(unit="mm")
    cell.add(rc.Box([80, 80, 4], pose=rc.pose([100, 0, -2]), name="table"))
    cell.add_robot(
        "arm", rc.preset("paper"), base=rc.pose([60, 0, 0], [0, 0, np.pi / 2]), parent=None
    )
    cell.add_frame("pick", rc.pose([-20, 20, 30]), parent="table")  # in the table's frame
    return cell


def test_a_lin_to_a_frame_ends_on_the_frame():
    cell = _cell()
    prog = cell.program("arm", [PTP(q=[0, 0.3, -0.5]), LIN(frame="table/pick", speed=10)])
    motion = prog.simulate(0.01)
    world = cell.pose_of("arm") @ np.append(motion.trace[-1], 1.0)
    assert np.allclose(world[:3], cell.pose_of("table/pick")[:3, 3], atol=1e-9)
    assert prog.moves[1].frame is None and prog.moves[1].pose is not None  # resolved


def test_ptp_and_circ_take_frames_too():
    cell = _cell()
    cell.add_frame("start", rc.pose([-20, 30, 30]), parent="table")
    # In the robot's base frame (turned 90°): start (30, −20, 28), pick (20, −20, 28).
    prog = cell.program(
        "arm", [PTP(frame="table/start"), CIRC(via=[25, -25, 28], frame="table/pick")]
    )
    end = cell.pose_of("arm") @ np.append(prog.simulate(0.01).trace[-1], 1.0)
    assert np.allclose(end[:3], cell.pose_of("table/pick")[:3, 3], atol=1e-9)


def test_a_frame_outside_a_cell_is_refused_naming_the_move():
    with pytest.raises(rc.InvalidInputError) as caught:
        Program(rc.preset("paper"), [Wait(1), LIN(frame="table/pick")])
    assert caught.value.field == "moves[1].frame"
    assert "cell.program" in str(caught.value)
    with pytest.raises(rc.InvalidInputError) as caught:
        _cell().program("arm", [LIN(frame="table/nothing")])
    assert caught.value.field == "moves[0].frame"


def test_a_move_with_a_frame_writes_it_and_a_move_without_does_not():
    assert LIN(frame="table/pick").to_dict()["frame"] == "table/pick"
    assert "frame" not in LIN(position=[1, 2, 3]).to_dict()
    prog = Program(rc.preset("paper"), [PTP(q=[0, 0.3, -0.5])])
    assert program_from_dict(program_to_dict(prog), prog.robot) == prog


def test_a_tool_program_puts_the_tcp_on_the_frame():
    cell = rc.Cell()
    tool = rc.Tool(tcp=rc.pose([6, 0, 0]))
    cell.add_robot("arm", rc.preset("paper"), tool=tool)
    cell.add_frame("pick", rc.pose([50, 10, 25]))
    prog = cell.program("arm", [PTP(q=[0, 0.3, -0.5]), LIN(frame="pick", speed=10)])
    q = prog.simulate(0.01).q[-1]
    flange = cell.robot("arm").end_effector_pose(q)
    assert np.allclose((flange @ tool.tcp)[:3, 3], [50, 10, 25], atol=1e-9)


def test_run_plans_checks_and_reports_the_cycle_time():
    cell = rc.Cell(unit="mm")
    cell.add_robot("a", rc.preset("paper"))
    cell.add_robot("b", rc.preset("paper"), base=rc.pose([125, 0, 0], [0, 0, np.pi]))
    start = rc.ik_all(cell.robot("a"), [40, 0, 20])
    q0 = start.q[np.flatnonzero(start.within_limits)[0]]
    programs = {
        "a": Program(cell.robot("a"), [LIN(position=[52, 0, 20], speed=4, accel=8)], start=q0),
        "b": [Wait(3.0), PTP(q=[0.6, 0, 0])],
    }
    result = cell.run(programs, dt=0.01)
    assert result.cycle_time == pytest.approx(max(p.duration for p in result.programs.values()))
    assert not result.check.ok and result.check.contacts[0].kind == "robot"
    assert str(result).startswith("cycle time")
    assert set(result.motions) == {"a", "b"}


def test_a_robot_that_turns_away_in_time_is_not_hit():
    cell = rc.Cell(unit="mm")
    cell.add_robot("a", rc.preset("paper"))
    cell.add_robot("b", rc.preset("paper"), base=rc.pose([125, 0, 0], [0, 0, np.pi]))
    start = rc.ik_all(cell.robot("a"), [40, 0, 20])
    q0 = start.q[np.flatnonzero(start.within_limits)[0]]
    lin = Program(cell.robot("a"), [LIN(position=[52, 0, 20], speed=4, accel=8)], start=q0)
    # a's tip would meet b's at t = 2.2 s; b turns away from t = 2 s.
    result = cell.run({"a": lin, "b": [Wait(2.0), PTP(q=[0.6, 0, 0])]}, dt=0.01)
    assert result.check.ok and 0 < result.check.min_clearance < 1
