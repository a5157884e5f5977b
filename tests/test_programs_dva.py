"""A program's analytic DVA agrees with numerical derivatives of its own positions.

Central differences of the sampled positions converge to the derivative at rate dt²,
so halving dt must cut the gap by about 4; a wrong analytic term would leave an O(1)
gap instead. Samples within 2 steps of a profile corner (where the trapezoid's
acceleration jumps) or of a move boundary are left out: differences straddle the jump.
"""

from __future__ import annotations

import numpy as np
import pytest

from robotconf.presets import preset
from robotconf.programs import CIRC, LIN, PTP, Program, Wait
from robotconf.programs._chain import bias, kinematics, make_chain

pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")


def _smooth(motion, prog, dt):
    times = [t for s in prog.segments for t in (s.start, s.end, *s.corners)]
    distance = np.min(np.abs(motion.t[:, None] - np.array(times)[None, :]), axis=1)
    keep = distance > 2.5 * dt
    keep[[0, -1]] = False
    return keep


def _gaps(prog, dt):
    motion = prog.simulate(dt=dt)
    keep = _smooth(motion, prog, dt)
    position = motion.position  # (T, n + 1, 3): every frame and the EE
    velocity = np.gradient(position, dt, axis=0)
    accel = np.gradient(motion.velocity, dt, axis=0)
    joint_rate = np.gradient(motion.q, dt, axis=0)
    joint_accel = np.gradient(motion.qd, dt, axis=0)
    pairs = [
        (velocity, motion.velocity),
        (accel, motion.acceleration),
        (joint_rate, motion.qd),
        (joint_accel, motion.qdd),
    ]
    # Each gap relative to the largest value of its quantity.
    return np.array([np.abs(d - a)[keep].max() / np.abs(a).max() for d, a in pairs])


@pytest.mark.parametrize("robot_name", ["paper", "puma560"])
def test_analytic_dva_converges_to_the_differenced_positions(robot_name):
    robot = preset(robot_name)
    if robot_name == "paper":
        q0 = np.array([0.0, 0.3, -0.5])
        moves = [
            PTP(q=q0, profile="quintic"),
            LIN(position=[60, 10, 30], speed=20),
            CIRC(via=[50, 20, 30], end=[40, 10, 30], speed=20),
            Wait(0.2),
        ]
    else:
        q0 = np.array([0.2, 0.7, -2.6, 0.1, 0.8, 0.3])
        pose = robot.end_effector_pose(q0)
        goal = pose.copy()
        goal[:3, 3] += [-0.08, 0.05, 0.03]
        p = pose[:3, 3]
        moves = [
            PTP(q=q0),
            LIN(pose=goal),
            CIRC(via=p + [-0.05, 0.08, 0.0], end=p + [0.0, 0.05, -0.03]),
        ]
    prog = Program(robot, moves)
    coarse, fine = _gaps(prog, 4e-3), _gaps(prog, 2e-3)
    ratios = coarse / fine
    assert np.all(ratios > 3.0) and np.all(ratios < 5.5), (coarse, fine)
    assert np.all(fine < 1e-3), fine


@pytest.mark.parametrize("robot_name", ["paper", "puma560", "scara", "stanford"])
def test_bias_acceleration_is_the_derivative_of_the_jacobian_along_qd(robot_name):
    robot = preset(robot_name)
    chain = make_chain(robot, robot.q)
    rng = np.random.default_rng(7)
    limits = robot.joint_limits()
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.random((5, robot.n))
    qd = rng.normal(size=(5, robot.n))
    _, jac = kinematics(chain, q)
    h = 1e-6
    _, ahead = kinematics(chain, q + h * qd)
    _, behind = kinematics(chain, q - h * qd)
    expected = np.einsum("tmn,tn->tm", (ahead - behind) / (2 * h), qd)
    got = bias(chain, q, qd, jac)
    scale = np.abs(expected).max()
    np.testing.assert_allclose(got, expected, atol=1e-6 * scale)


def test_combined_pass_matches_the_public_jacobian_and_pose():
    robot = preset("stanford")
    chain = make_chain(robot, robot.q)
    q = np.random.default_rng(1).uniform(-1, 1, (4, robot.n))
    pose, jac = kinematics(chain, q)
    np.testing.assert_allclose(jac, robot.jacobian(q), atol=1e-12)
    np.testing.assert_allclose(pose, robot.end_effector_pose(q), atol=1e-12)


def test_motion_of_a_program_is_a_motion():
    prog = Program(preset("paper"), [PTP(q=[0, 0.3, -0.5]), Wait(0.1)])
    motion = prog.simulate(dt=0.05)
    assert motion.method == "analytic" and motion.signals == {}
    assert motion.t[-1] == pytest.approx(prog.duration)
    table = motion.table
    assert ("EE", "velocity", "x") in table.columns
    stats = motion.stats()
    assert stats.shape[0] == table.shape[1]
    csv = motion.to_csv()
    assert csv is not None and len(csv.splitlines()) == motion.t.size + 4  # 4 header rows
    np.testing.assert_allclose(motion.taught_points[0], [70, 0, 20])
    np.testing.assert_allclose(
        motion.taught_points[-1], preset("paper").end_effector([0, 0.3, -0.5])
    )
    assert motion.boundaries.tolist() == [0.0, 1.0, 1.1]
    assert motion.move_at(0.5) == 0 and motion.move_at(1.05) == 1


def test_the_last_sample_is_the_end_of_the_program():
    prog = Program(preset("paper"), [PTP(q=[0, 0.3, -0.5]), Wait(0.013)])
    motion = prog.simulate(dt=0.01)  # 1.013 s is off the grid: 0 … 1.01, then 1.013
    assert motion.t[-2] == pytest.approx(1.01) and motion.t[-1] == pytest.approx(1.013)
    np.testing.assert_allclose(motion.q[-1], [0, 0.3, -0.5])
