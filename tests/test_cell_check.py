"""``cell.check``: contact intervals found to within one sample, and no false contacts.

Expected times come from outside the cell's code: the trapezoidal time law of a LIN
(docs/programs.md: ``s = ½at²``, then ``v`` per second, then braking) where the first
contact is a capsule's end cap meeting a face, and a brute-force distance (1000 points
along each segment) on a ten times finer time grid where it is not.
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.programs import LIN, PTP, Program, Wait

pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")

R = 0.04 * 90.0  # the paper arm's default link radius: 4 % of its size


def _trapezoid_time(s, length, v, a):
    """When a rest-to-rest trapezoidal (or triangular) profile has covered ``s``."""
    if v * v / a > length:  # a triangle
        v = np.sqrt(length * a)
    blend = v / a
    covered = 0.5 * a * blend**2
    if s <= covered:
        return np.sqrt(2 * s / a)
    if s <= length - covered:
        return blend + (s - covered) / v
    total = length / v + blend
    return total - np.sqrt(2 * (length - s) / a)


def _start_at(robot, point):
    solutions = rc.ik_all(robot, point)
    return solutions.q[np.flatnonzero(solutions.within_limits)[0]]


def _paper_cell():
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", rc.preset("paper"))
    return cell


def test_a_lin_into_a_box_enters_within_one_sample():
    cell = _paper_cell()
    cell.add(rc.Box([10, 30, 40], pose=rc.pose([60, 0, 30]), name="fixture"))  # face at x = 55
    robot = cell.robot("arm")
    start = _start_at(robot, [40, 0, 30])
    prog = Program(robot, [LIN(position=[62, 0, 30], speed=10, accel=20)], start=start)
    dt = 0.01
    result = cell.check(prog, dt=dt)
    assert len(result) == 1
    contact = result.contacts[0]
    assert (contact.link, contact.other, contact.kind, contact.move) == (
        "link 3",
        "fixture",
        "object",
        1,
    )
    # The tip's end cap meets the face when the tip is at x = 55 − r.
    expected = _trapezoid_time(55 - R - 40, 22, 10, 20)
    assert expected - 1e-9 <= contact.start <= expected + dt + 1e-9  # within one sample
    assert contact.end == pytest.approx(prog.duration)
    assert contact.depth == pytest.approx(62 + R - 55, abs=1e-9)  # pushed back along −x
    assert "move 1 (LIN): link 3 enters 'fixture' at t = " in contact.message
    assert "10.6 mm deep" in contact.message
    assert result.min_clearance == pytest.approx(-(62 + R - 55), abs=1e-9)
    table = result.table
    assert list(table["other"]) == ["fixture"] and table["depth"][0] == contact.depth


def _dense_distance(first, second, count=1000):
    """Brute force: the least distance of 1000 points along each segment, shape (T,)."""
    u = np.linspace(0.0, 1.0, count)
    p = first[:, None, 0] + u[None, :, None] * (first[:, None, 1] - first[:, None, 0])
    q = second[:, None, 0] + u[None, :, None] * (second[:, None, 1] - second[:, None, 0])
    out = np.empty(len(first))
    for k in range(len(first)):
        gaps = p[k][:, None, :] - q[k][None, :, :]
        out[k] = np.sqrt(np.min(np.einsum("ijk,ijk->ij", gaps, gaps)))
    return out


def test_self_collision_interval_within_one_sample():
    robot = rc.preset("paper").with_limits("q3", (-3.1, 3.1))
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", robot)
    assert cell.robot_entry("arm").links.self_pairs == ((0, 2),)
    prog = Program(robot, [PTP(q=[0, 0, 2.9])])
    dt = 0.01
    result = cell.check(prog, dt=dt)
    contact = result.contacts[0]
    assert (contact.link, contact.other, contact.kind) == ("link 1", "link 3", "self")
    assert "touches its own link 3" in contact.message
    fine = prog.simulate(dt=dt / 10)
    near = np.flatnonzero(np.abs(fine.t - contact.start) <= 2 * dt)  # brute force is slow
    segments, _ = cell.link_capsules("arm", fine.q[near])
    gap = _dense_distance(segments[:, 0], segments[:, 2]) - 2 * R
    assert gap[0] > 0 > gap[-1]
    first = fine.t[near][np.argmax(gap < 0)]
    assert first - dt / 10 <= contact.start <= first + dt + dt / 10


def test_two_robots_meet_within_one_sample():
    cell = rc.Cell(unit="mm")
    cell.add_robot("a", rc.preset("paper"))
    cell.add_robot("b", rc.preset("paper"), base=rc.pose([125, 0, 0], [0, 0, np.pi]))
    start = _start_at(cell.robot("a"), [40, 0, 20])
    # b faces a, stretched: its tip at x = 55; a's tip starts at 40, 15 away.
    assert cell.clearance("a", start).distance == pytest.approx(15 - 2 * R, abs=1e-9)
    move = Program(cell.robot("a"), [LIN(position=[52, 0, 20], speed=4, accel=8)], start=start)
    still = Program(cell.robot("b"), [Wait(5.0)])
    dt = 0.01
    result = cell.check({"a": move, "b": still}, dt=dt)
    contact = result.contacts[0]
    assert (contact.robot, contact.link, contact.other, contact.kind) == (
        "a",
        "link 3",
        "b/link 3",
        "robot",
    )
    expected = _trapezoid_time(55 - 2 * R - 40, 12, 4, 8)
    assert expected - 1e-9 <= contact.start <= expected + dt + 1e-9  # within one sample
    assert contact.message.startswith("a: move 1 (LIN): link 3 meets robot 'b' link 3 at t = ")
    assert result.t[-1] == pytest.approx(5.0)  # b's program is longer: the grid runs on


def test_a_clear_path_has_no_false_contact_with_a_1_mm_margin():
    cell = _paper_cell()
    # The tip runs along y at z = 20; the box's top is 1.5 below its end cap.
    top = 20 - R - 1.5
    cell.add(rc.Box([20, 60, 10], pose=rc.pose([60, 0, top - 5]), name="plate"))
    robot = cell.robot("arm")
    prog = Program(
        robot, [LIN(position=[60, 10, 20], speed=5)], start=_start_at(robot, [60, -10, 20])
    )
    clear = cell.check(prog, margin=1.0, dt=0.005)
    assert clear.ok and str(clear).startswith("no contact")
    assert clear.min_clearance == pytest.approx(1.5, abs=1e-9)
    assert clear.min_pair == ("arm", "link 3", "plate")
    close = cell.check(prog, margin=2.0, dt=0.005)
    assert len(close) == 1 and close.contacts[0].depth == pytest.approx(-1.5, abs=1e-9)
    assert "away (margin 2 mm)" in close.contacts[0].message


def test_a_motion_of_another_robot_is_refused():
    cell = _paper_cell()
    motion = Program(rc.preset("planar_2r"), [PTP(q=[0.1, 0.2])]).simulate(0.1)
    with pytest.raises(rc.InvalidInputError) as caught:
        cell.check(motion)
    assert caught.value.field == "motion['arm']"


def test_clearance_over_time_equals_one_at_a_time():
    cell = _paper_cell()
    cell.add(rc.Cylinder(5, 30, pose=rc.pose([40, 30, 15]), name="post"))
    cell.add(rc.Sphere(4, pose=rc.pose([20, -30, 50]), name="ball"))
    rng = np.random.default_rng(0)
    q = rng.uniform(-1.5, 1.5, (50, 3))
    many = cell.clearance("arm", q)
    for k in range(0, 50, 7):
        one = cell.clearance("arm", q[k])
        assert one.distance == many.distance[k] and one.other == many.other[k]
