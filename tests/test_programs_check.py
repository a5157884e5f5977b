"""``Program.check``: every violation named with its move, its time and its joint.

The times are derived by hand from the trapezoid (path length, speed, acceleration) and
the geometry: where the line reaches the singular axis, enters the workspace's hole or
drives a joint past its range.
"""

from __future__ import annotations

import numpy as np
import pytest

from robotconf.presets import preset
from robotconf.programs import LIN, PTP, Program, Wait

DT = 1e-3


@pytest.fixture(scope="module")
def paper():
    return preset("paper")


def _only(report, kind, move=None):
    found = [v for v in report if v.kind == kind and (move is None or v.move == move)]
    assert found, f"no {kind!r} in:\n{report}"
    return found


def test_a_clean_program_has_no_violations(paper):
    prog = Program(paper, [PTP(q=[0, 0.3, -0.5]), Wait(0.2), PTP(q=[0.5, 0, 0])])
    report = prog.check(dt=DT)
    assert report.ok and len(report) == 0 and str(report) == "no violations"


def test_lin_through_the_shoulder_axis_is_reported_as_a_singularity(paper):
    # The line from (10, −10, 50) to (−10, 10, 50) crosses joint 1's axis (x = y = 0) at
    # its midpoint; the paper arm's Jacobian loses rank there (q1 no longer moves the EE).
    # L = 20√2, v = 10, a = 22.5 (default 0.25·90): T = L/v + v/a, symmetric, so the
    # crossing is at T/2.
    prog = Program(paper, [PTP(position=[10, -10, 50]), LIN(position=[-10, 10, 50], speed=10)])
    lin = prog.segments[1]
    T = 20 * np.sqrt(2) / 10 + 10 / 22.5
    assert lin.duration == pytest.approx(T, rel=1e-12)
    report = prog.check(dt=DT)
    (singular,) = _only(report, "singularity")
    assert singular.move == 1 and singular.joint is None
    assert abs(singular.worst_time - (lin.start + T / 2)) <= DT
    assert lin.start < singular.time < singular.worst_time
    assert singular.value < 1e-3 and "singular" in singular.message
    assert singular.message.startswith("move 2 (LIN):")
    with pytest.warns(UserWarning, match="near a singularity"):
        prog.simulate(dt=DT)


def test_lin_to_the_stretched_planar_arm_is_reported(paper):
    arm = preset("planar_2r")  # l1 = 40, l2 = 30: stretched at 70 from the base
    prog = Program(arm, [PTP(q=[0.3, 1.0]), LIN(position=[70, 0, 0], speed=10)])
    lin = prog.segments[1]
    report = prog.check(dt=DT)
    (singular,) = _only(report, "singularity", move=1)
    # σ → 0 as the arm straightens: lowest at the move's end, where it is stretched.
    assert singular.worst_time == pytest.approx(lin.end)
    assert singular.value < 1e-4
    assert lin.start < singular.time < lin.end
    assert report.kinds[0] in ("ik failure", "singularity")


def test_lin_through_the_hole_reports_where_inverse_kinematics_fails(paper):
    # From (30, 0, 20) to (−30, 0, 20) through the shoulder (0, 0, 20): no point closer
    # than |40 − 30| = 10 is reachable. With v = 10, a = 100 the ramp covers ½·v²/a = 0.5
    # in t_b = 0.1 s; the hole starts 20 along, at 0.1 + 19.5/10 = 2.05 s into the move.
    prog = Program(
        paper, [PTP(position=[30, 0, 20]), LIN(position=[-30, 0, 20], speed=10, accel=100)]
    )
    lin = prog.segments[1]
    report = prog.check(dt=DT)
    (failure,) = _only(report, "ik failure")
    assert failure.move == 1
    assert lin.start + 2.05 <= failure.time <= lin.start + 2.05 + DT
    assert "unreachable" in failure.message
    assert _only(report, "joint limit", move=1)  # q3 passes 135° before the hole


def test_ptp_past_a_joint_range_is_reported_when_it_leaves_the_range(paper):
    # q3 from 0 to 3 rad (range ±3π/4): v = 1, a = 2 → t_b = 0.5, q3 = 0.25 + (t − 0.5)
    # while cruising, so it passes 2.35619 at t = 2.60619 s.
    prog = Program(paper, [PTP(q=[0, 0, 3.0])])
    (limit,) = _only(prog.check(dt=DT), "joint limit")
    assert limit.move == 0 and limit.joint == "q3"
    assert 2.60619 <= limit.time <= 2.60619 + DT
    assert limit.value == pytest.approx(3.0 - 3 * np.pi / 4)
    assert limit.worst_time == pytest.approx(3.5)


def test_a_fast_lin_breaks_joint_speed_limits(paper):
    prog = Program(
        paper, [PTP(q=[0, 0.3, -0.5]), LIN(position=[40, 20, 40], speed=200, accel=2000)]
    )
    report = prog.check(dt=DT)
    speed = _only(report, "joint speed", move=1)
    assert {v.joint for v in speed} <= {"q1", "q2", "q3"}
    worst = max(speed, key=lambda v: v.value)
    assert worst.limit == 1.0 and worst.value > 1.0
    # The reported peak is the motion's own.
    with pytest.warns(UserWarning, match="moves faster"):
        motion = prog.simulate(dt=DT)
    j = int(worst.joint[1:]) - 1
    inside = motion.t >= prog.segments[1].start
    assert worst.value == pytest.approx(np.abs(motion.qd[inside, j]).max(), rel=1e-6)
    assert motion.report.kinds == report.kinds


def test_a_branch_change_between_samples_is_a_jump(paper):
    prog = Program(paper, [PTP(q=[0, 0.3, -0.5])])
    samples = prog._sample(DT)
    # Plant a flip of q1 by π in the middle, as a change of IK branch would do.
    samples.q[400:, 0] += np.pi
    report = prog._report(samples, 1e-3)
    (jump,) = _only(report, "jump")
    assert jump.joint == "q1" and jump.time == pytest.approx(0.399)
    assert jump.value == pytest.approx(np.pi, rel=1e-3)
    prog._cache = None


def test_report_lists_and_indexes_its_violations(paper):
    report = Program(paper, [PTP(q=[0, 0, 3.0]), PTP(q=[0, 0, 0])]).check(dt=0.01)
    assert report.kinds == ("joint limit",)
    assert [v.move for v in report] == [0, 1]
    assert report[0].kind == "joint limit" and len(report.of_kind("joint speed")) == 0
    assert repr(report) == "ProgramReport(2 violations: joint limit)"
    assert str(report).count("\n") == 1
