"""Identifying robot parameters from measured end-effector points: the truth within the
reported uncertainty, honest standard errors, named unidentifiable groups, bad input."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.calibration import MAX_WORK, calibrate

NOISE = 0.05  # per measured coordinate, the paper robot's length units
CHOSEN = ["M2.az", "M3.ax", "EE.x", "q2.offset", "q3.offset"]
TRUTH = np.array([20.3, 29.8, 40.25, 0.004, -0.006])


def true_robot() -> rc.Robot:
    nominal = rc.preset("paper")
    robot = nominal.with_module(1, nominal.modules[1].with_parameters(az=TRUTH[0]))
    robot = robot.with_module(2, robot.modules[2].with_parameters(ax=TRUTH[1]))
    return robot.with_end_effector((TRUTH[2], 0.0, 0.0))


def samples(count: int, rng: np.random.Generator) -> np.ndarray:
    limits = rc.preset("paper").joint_limits()
    return limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.random((count, 3))


def measured(q: np.ndarray, rng: np.random.Generator, noise: float = NOISE) -> np.ndarray:
    # The robot's true coordinates are its readings plus the offsets.
    offsets = np.array([0.0, TRUTH[3], TRUTH[4]])
    exact = true_robot().end_effector(q + offsets)
    return exact + rng.normal(scale=noise, size=exact.shape)


def test_noise_free_measurements_give_the_parameters_to_round_off():
    rng = np.random.default_rng(0)
    q = samples(20, rng)
    found = calibrate(rc.preset("paper"), q, measured(q, rng, noise=0.0), CHOSEN)
    np.testing.assert_allclose(found.values, TRUTH, atol=1e-9)
    assert found.rms_after < 1e-9 and found.rank == 5 and found.unidentifiable == ()
    assert found.rms_before > 0.3


def test_offsets_from_50_noisy_samples_are_within_3_sigma_of_the_truth():
    rng = np.random.default_rng(4)
    q = samples(50, rng)
    points = measured(q, rng)
    found = rc.calibrate(rc.preset("paper"), q, points, CHOSEN)
    assert found.parameters == ("M2.az", "M3.ax", "EE.x", "M2.offset", "M3.offset")
    assert np.all(np.isfinite(found.standard_errors))
    assert np.all(np.abs(found.values - TRUTH) <= 3 * found.standard_errors)
    # σ from the residuals (150 coordinates, 5 parameters) is near the true noise, and the
    # standard errors are far below the changes, so the calibration tells.
    assert found.noise == pytest.approx(NOISE, rel=0.25)
    assert np.all(found.standard_errors < 0.2 * np.abs(TRUTH - found.nominal))
    # The calibrated model reproduces the measurements up to the residuals.
    np.testing.assert_allclose(found.end_effector(q) + found.residuals, points, atol=1e-9)
    np.testing.assert_allclose(found.covariance, found.covariance.T, atol=1e-15)
    assert "identified 5 parameter(s) from 50 samples" in found.message


def test_the_standard_errors_are_honest_over_many_campaigns():
    # Over 40 measurement campaigns the errors divided by their standard errors spread as
    # a unit normal: standard deviation 1 within sampling error (200 scores: ±0.05; the
    # bounds are 4 of it).
    rng = np.random.default_rng(7)
    scores = []
    for _ in range(40):
        q = samples(50, rng)
        found = calibrate(rc.preset("paper"), q, measured(q, rng), CHOSEN)
        scores.append((found.values - TRUTH) / found.standard_errors)
    spread = float(np.std(np.array(scores)))
    assert 0.8 < spread < 1.2


def test_two_offsets_along_one_axis_are_named_and_only_their_sum_is_found():
    # M1.az (the base module's height) and M2.az (the column) both slide along the base
    # z axis before anything turns off it: the data see only their sum.
    rng = np.random.default_rng(1)
    q = samples(30, rng)
    exact = true_robot().end_effector(q)
    found = calibrate(rc.preset("paper"), q, exact, ["M1.az", "M2.az", "M3.ax", "EE.x"])
    assert found.unidentifiable == (("M1.az", "M2.az"),)
    assert found.combinations == ("M1.az + M2.az",)
    assert np.isinf(found.standard_errors[:2]).all()
    assert found.rank == 3
    assert found.values[0] + found.values[1] == pytest.approx(TRUTH[0], abs=1e-9)
    # The undetermined direction keeps its nominal value: the change is shared equally.
    assert found.values[0] == pytest.approx(TRUTH[0] - found.values[1] + 0.0, abs=1e-9)
    assert found.change[0] == pytest.approx(found.change[1], abs=1e-9)
    np.testing.assert_allclose(found.values[2:], TRUTH[1:3], atol=1e-9)
    assert "cannot tell M1.az and M2.az apart (only M1.az + M2.az is determined" in found.message


def test_a_dh_robot_theta_and_its_joint_offset_are_the_same_parameter():
    puma = rc.preset("puma560")
    true = puma.with_module(2, puma.modules[2].with_parameters(a=0.4418, d=0.16))
    rng = np.random.default_rng(3)
    q = rng.uniform(-1.0, 1.0, (40, 6))
    found = calibrate(puma, q, true.end_effector(q), ["M3.a", "M3.d", "M2.theta", "q2.offset"])
    np.testing.assert_allclose(found.values[:2], [0.4418, 0.16], atol=1e-10)
    assert found.unidentifiable == (("M2.theta", "M2.offset"),)
    assert found.combinations == ("M2.theta + M2.offset",)
    assert found.robot.modules[2].a == pytest.approx(0.4418, abs=1e-10)


def test_the_default_names_every_link_number_and_the_end_effector():
    rng = np.random.default_rng(5)
    q = samples(40, rng)
    found = calibrate(rc.preset("paper"), q, true_robot().end_effector(q))
    assert len(found.parameters) == 12 and found.parameters[-3:] == ("EE.x", "EE.y", "EE.z")
    # Offsets along parallel lines: the base z pair, and the y offsets along the two
    # parallel y axes and the end effector's.
    assert ("M1.az", "M2.az") in found.unidentifiable
    assert ("M2.ay", "M3.ay", "EE.y") in found.unidentifiable
    assert found.rms_after < 1e-9


@pytest.mark.parametrize(
    ("change", "field", "words"),
    [
        ({"q_samples": np.zeros((5, 2))}, "q_samples", "shape"),
        ({"q_samples": np.full((5, 3), np.nan)}, "q_samples", "finite"),
        ({"measured_positions": np.zeros((4, 3))}, "measured_positions", "expected 5 rows"),
        ({"measured_positions": np.full((5, 3), np.inf)}, "measured_positions", "finite"),
        ({"measured_positions": np.full((5, 3), 1e151)}, "measured_positions", "too large"),
        ({"parameters": ["M9.az"]}, "parameters[0]", "unknown module"),
        ({"parameters": ["M2.theta"]}, "parameters[0]", "not a parameter of M2"),
        ({"parameters": ["M2"]}, "parameters[0]", "no '.key'"),
        ({"parameters": ["M2.az", "q2.az"]}, "parameters[1]", "named twice"),
        ({"parameters": ["EE.w"]}, "parameters[0]", "unknown key"),
        ({"parameters": []}, "parameters", "wrong number"),
        ({"parameters": 5}, "parameters", "not a list"),
        ({"max_iterations": 0}, "max_iterations", "out of range"),
        ({"robot": "paper"}, "robot", "not a robot"),
    ],
)
def test_bad_input_is_refused_naming_the_field(change, field, words):
    arguments = {
        "robot": rc.preset("paper"),
        "q_samples": np.zeros((5, 3)),
        "measured_positions": np.zeros((5, 3)),
        "parameters": ["M2.az"],
        "max_iterations": 50,
    }
    arguments.update(change)
    with pytest.raises(rc.InvalidInputError) as caught:
        calibrate(**arguments)
    assert caught.value.field == field
    assert words in str(caught.value)


def test_a_fixed_module_has_no_joint_offset():
    robot = rc.Robot(
        [rc.Module("Rz"), rc.Module("fixed", a=(0, 0, 1)), rc.Module("Ry", a=(1, 0, 0))],
        end_effector=(1, 0, 0),
    )
    with pytest.raises(rc.InvalidInputError, match="not a joint"):
        calibrate(robot, np.zeros((3, 3)), np.zeros((3, 3)), ["M2.offset"])


def test_too_much_work_is_refused_before_it_starts():
    count = int(MAX_WORK / 144) + 1  # 12 default parameters
    with pytest.raises(rc.InvalidInputError, match="too much work") as caught:
        calibrate(rc.preset("paper"), np.zeros((count, 3)), np.zeros((count, 3)))
    assert caught.value.field == "q_samples"


def test_measurements_no_robot_can_fit_end_without_overflow():
    # Points 1e12 away: the fit moves the parameters as far as it can, stays finite, and
    # says how badly it fits.
    rng = np.random.default_rng(2)
    q = samples(10, rng)
    found = calibrate(rc.preset("paper"), q, np.full((10, 3), 1e12), ["EE.x", "M3.ax"])
    assert np.all(np.isfinite(found.values)) and found.rms_after > 1e11
