"""Time laws of programs: trapezoid and quintic formulas, synchronized PTP moves.

Expected durations and peaks are derived by hand in the comments from the limits; the
sampled joint values are compared with those closed forms, not with the profile code.
"""

from __future__ import annotations

import numpy as np
import pytest

from robotconf.presets import preset
from robotconf.programs import PTP, Program, Wait, quintic, trapezoidal


def test_trapezoid_reaches_the_cruise_speed_when_long_enough():
    # L = 1, v = 0.5, a = 1: v²/a = 0.25 ≤ L, so T = L/v + v/a = 2 + 0.5.
    p = trapezoidal(0.5, 1.0)
    assert (p.duration, p.blend, p.speed, p.accel) == (2.5, 0.5, 0.5, 1.0)
    t = np.array([0.0, 0.25, 0.5, 1.25, 2.0, 2.25, 2.5, 3.0])
    u, ud, udd = p.evaluate(t)
    # ½at² on the ramp; ½a·t_b² + v(t − t_b) cruising; 1 − ½a(T − t)² braking; then rest.
    np.testing.assert_allclose(u, [0, 0.03125, 0.125, 0.5, 0.875, 0.96875, 1, 1], atol=1e-15)
    np.testing.assert_allclose(ud, [0, 0.25, 0.5, 0.5, 0.5, 0.25, 0, 0], atol=1e-15)
    assert udd.tolist() == [1.0, 1.0, 0.0, 0.0, -1.0, -1.0, 0.0, 0.0]  # right-sided at corners
    assert p.corners == (0.5, 2.0)


def test_short_trapezoid_degenerates_to_a_triangle():
    # L = 1 < v²/a = 4: t_b = √(L/a) = 1, T = 2, peak speed √(L·a) = 1 < v.
    p = trapezoidal(2.0, 1.0)
    assert (p.duration, p.blend, p.speed) == (2.0, 1.0, 1.0)
    u, ud, _ = p.evaluate(np.array([0.5, 1.0, 1.5]))
    np.testing.assert_allclose(u, [0.125, 0.5, 0.875])
    np.testing.assert_allclose(ud, [0.5, 1.0, 0.5])
    assert p.corners == (1.0,)


def test_quintic_peaks_match_the_formulas():
    # T = max(15/(8V), √(10/(√3·A))): V = 1, A = 100 → the speed sets T = 15/8.
    p = quintic(1.0, 100.0)
    assert p.duration == pytest.approx(15 / 8)
    t = np.linspace(0, p.duration, 200_001)
    u, ud, udd = p.evaluate(t)
    assert u[0] == 0.0 and u[-1] == pytest.approx(1.0, abs=1e-15)
    assert ud.max() == pytest.approx(15 / (8 * p.duration), rel=1e-9)  # = V
    assert np.abs(udd).max() == pytest.approx(10 / (np.sqrt(3) * p.duration**2), rel=1e-9)
    # At τ = (3 − √3)/6 the acceleration peaks.
    assert t[np.argmax(udd)] / p.duration == pytest.approx((3 - np.sqrt(3)) / 6, abs=1e-5)
    # V = 100, A = 1: the acceleration sets T = √(10/√3).
    assert quintic(100.0, 1.0).duration == pytest.approx(np.sqrt(10 / np.sqrt(3)))


@pytest.fixture(scope="module")
def paper():
    return preset("paper")


def _ptp_motion(robot, target, profile, **limits):
    prog = Program(robot, [PTP(q=target, profile=profile), Wait(0.1)], **limits)
    return prog, prog.simulate(dt=1e-3)


def test_ptp_joints_start_and_stop_together_within_their_limits(paper):
    speed, accel = np.array([1.0, 0.5, 2.0]), np.array([4.0, 1.0, 3.0])
    delta = np.array([0.8, -0.3, 0.6])
    prog, motion = _ptp_motion(paper, delta, "trapezoidal", joint_speed=speed, joint_accel=accel)
    # In u: V = min(v/|Δ|) = min(1.25, 1.667, 3.333) = 1.25 (joint 1),
    #       A = min(a/|Δ|) = min(5, 3.333, 5) = 3.333 (joint 2); V²/A = 0.469 ≤ 1:
    # T = 1/V + V/A = 0.8 + 0.375 = 1.175 s.
    assert prog.segments[0].duration == pytest.approx(1.175, rel=1e-12)
    moving = motion.t < 1.175 - 1e-9
    assert np.all(np.abs(motion.qd[moving][1:]) > 0)  # every joint moves the whole time
    at_end = np.searchsorted(motion.t, 1.175 - 1e-12)
    np.testing.assert_allclose(motion.q[at_end:], np.tile(delta, (motion.t.size - at_end, 1)))
    assert np.all(motion.qd[[0, at_end]] == 0)  # rest at the start and at the end
    # Each joint is Δ_j·u(t): the ratios q_j/Δ_j agree at every sample.
    ratios = motion.q / delta
    np.testing.assert_allclose(ratios, ratios[:, [0, 0, 0]], atol=1e-15)
    # Limits hold, and are tight for the joints that set V and A.
    peak_speed = np.abs(motion.qd).max(axis=0)
    peak_accel = np.abs(motion.qdd).max(axis=0)
    assert np.all(peak_speed <= speed * (1 + 1e-12)) and np.all(peak_accel <= accel * (1 + 1e-12))
    assert peak_speed[0] == pytest.approx(1.0, rel=1e-12)
    assert peak_accel[1] == pytest.approx(1.0, rel=1e-12)
    assert prog.check(dt=1e-3).ok


def test_ptp_quintic_peaks_follow_15_8_and_10_sqrt3(paper):
    delta = np.array([0.0, 0.4, -1.0])
    prog, motion = _ptp_motion(paper, delta, "quintic", joint_speed=1.0, joint_accel=2.0)
    # Joint 3 leads (|Δ| = 1): T = max(15/8 · 1/1, √(10/√3 · 1/2)) = max(1.875, 1.699).
    duration = prog.segments[0].duration
    assert duration == pytest.approx(1.875, rel=1e-12)
    assert np.abs(motion.qd[:, 2]).max() == pytest.approx(15 / 8 / duration, rel=1e-6)
    peak_accel = 10 / np.sqrt(3) / duration**2
    assert np.abs(motion.qdd[:, 2]).max() == pytest.approx(peak_accel, rel=1e-5)
    # Zero acceleration at both ends (unlike the trapezoid).
    assert motion.qdd[0].tolist() == [0.0, 0.0, 0.0]
    end = np.searchsorted(motion.t, duration)
    assert np.abs(motion.qdd[end - 1]).max() < 1e-2


def test_ptp_to_where_it_is_takes_no_time(paper):
    prog = Program(paper, [PTP(q=[0, 0, 0]), Wait(0.25)])
    assert [s.duration for s in prog.segments] == [0.0, 0.25]
    assert prog.duration == 0.25
