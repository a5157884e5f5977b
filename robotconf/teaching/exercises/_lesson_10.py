"""Lesson 10's exercises: the paper's §3 lab with the student's lengths and sawtooth.

The expected numbers come from the library (forward kinematics, the Jacobian, the
simulation the paper's scope shows); the lesson's typical slips are named by the
checks: the mean as (max + min)/2, the rate dq3/dt left out, q3 not restarted after a
drop, one term of the acceleration, q3 = A just before the drop, the central difference
for Simulink's backward one. The drop's sample time is drawn coarse enough (0.05 … 0.2
s) that "q3 = A" and the right last sample differ by more than the rounding rule.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...kinematics import jacobian
from ...motion import simulate
from ...signals import RepeatingSequence, Sine
from ._exercise import register
from ._kinds import EXERCISE_SLIPS, matrix_exercise, value_exercise
from ._lessons_02_08 import paper_robot

__all__: list[str] = []

LESSON = "10_paper_lab"

EXERCISE_SLIPS.update(
    {
        "mean_as_midrange": "the mean as (max + min)/2 where it is a time average",
        "min_at_amplitude": "the minimum where the ramp ends (q3 = A), not where sin q3 = 1",
        "mean_angle": "the displacement at the mean angle A/2, not the mean displacement",
        "rate_left_out": "dp/dq3 without the chain rule's factor dq3/dt",
        "no_restart": "q3 = A·t/T, not restarted at 0 after the drops",
        "centripetal_only": "the centripetal term of the acceleration alone",
        "tangential_only": "the tangential term of the acceleration alone",
        "q3_at_amplitude": "q3 = A just before the drop, where it is A·(T − dt)/T",
        "rate_inverted": "dq3/dt taken as T/A, the ramp's rate upside down",
        "omega_as_f": "the sine's angular frequency taken as f, where it is 2πf",
        "degrees_in_sin": "q3 in degrees fed to sin and cos",
    }
)


#: The hint of a calculator left in degree mode (the lesson's angles are radians).
_DEGREE_MODE = (
    "Your calculator is in degree mode: the angles here are radians, so sin and cos take "
    "radians — switch the calculator to RAD."
)


def _cos_deg(angle: Any) -> Any:
    """cos as a calculator in degree mode computes it for a number meant as radians."""
    return np.cos(np.radians(angle))


def _sin_deg(angle: Any) -> Any:
    """sin as a calculator in degree mode computes it for a number meant as radians."""
    return np.sin(np.radians(angle))


def _lab(variant: Any, _: Any) -> dict[str, Any]:
    l1 = variant.length("l1", 15, 30, step=5)
    l2 = variant.length("l2", 20, 40, step=5)
    l3 = variant.length("l3", 30, 50, step=5)
    amplitude = variant.length("A", 1.7, 2.5, step=0.1)  # rad, above π/2
    period = variant.length("T", 1.0, 3.0, step=0.5)  # s
    q_star = [
        variant.angle(f"q{i}*", choices)
        for i, choices in (
            (1, [30, 45, 60, 90, 120]),
            (2, [-45, -30, 30, 45, 60]),
            (3, [30, 45, 60, 90]),
        )
    ]
    return {
        "l1": l1,
        "l2": l2,
        "l3": l3,
        "A": amplitude,
        "T": period,
        "q_star": q_star,
        "robot": paper_robot(l1, l2, l3, name="lab arm"),
        "saw": RepeatingSequence(times=(0.0, period), values=(0.0, amplitude)),
    }


def _statistics(n: Any) -> np.ndarray:
    """max, min, mean of the end-effector's z displacement over three periods (the scope)."""
    # One period shows what three do (the scope repeats): a third of the samples.
    lab = simulate(n["robot"], {"q3": n["saw"]}, t_end=n["T"], dt=1e-3)
    z = lab.stats().loc[("EE", "displacement", "z")]
    return np.array([z["max"], z["min"], z["mean"]], dtype=float)


def _statistics_named(n: Any) -> dict[str, tuple[Any, str]]:
    l3, amplitude = n["l3"], n["A"]
    right = _statistics(n)
    mean = right[2]
    return {
        "mean_as_midrange": (
            [right[0], right[1], (right[0] + right[1]) / 2],
            "The mean is a time average over whole ramps, q3 = A·s with s running evenly "
            "from 0 to 1, not (max + min)/2.",
        ),
        "min_at_amplitude": (
            [right[0], -l3 * np.sin(amplitude), mean],
            "The minimum is where sin q3 is largest: q3 passes π/2 on the way to A > π/2.",
        ),
        "sign_flipped": (
            # the statistics of +l3·sin(q3): the max is minus the min, and back
            [-right[1], -right[0], -mean],
            "You measured the displacement upward: the tip goes down, so its z minus its "
            "z at t = 0 is -l3·sin(q3) ≤ 0 (the max is 0, the min and the mean negative).",
        ),
        "radians_as_degrees": (
            # the mean -l3·(1 − cos A)/A; max and min take no sine or cosine
            [right[0], right[1], -l3 * (1 - _cos_deg(amplitude)) / amplitude],
            _DEGREE_MODE,
        ),
        "mean_angle": (
            [right[0], right[1], -l3 * np.sin(amplitude / 2)],
            "That is the displacement at the mean angle A/2: average the displacement "
            "-l3·sin(q3) over the ramp, not the angle.",
        ),
    }


def _t3(variant: Any, earlier: Any) -> dict[str, Any]:
    fraction = variant.choice("t3 fraction", [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8])
    return {"t3": earlier["T"] * (1 + fraction)}


def _velocity(n: Any, q3: float, rate: float) -> np.ndarray:
    return np.asarray(jacobian(n["robot"], [0, 0, q3])[:3] @ [0, 0, rate], dtype=float)


def _velocity_named(n: Any) -> dict[str, tuple[Any, str]]:
    amplitude, period, t3 = n["A"], n["T"], n["t3"]
    rate = amplitude / period
    q3 = float(n["saw"].value(t3))
    return {
        "rate_left_out": (
            _velocity(n, q3, 1.0).tolist(),
            "You left out dq3/dt: on a ramp q3 grows at A/T rad/s, so multiply dp/dq3 by A/T.",
        ),
        "no_restart": (
            _velocity(n, amplitude * t3 / period, rate).tolist(),
            "q3 restarts at 0 after every drop: at t3 it is A·(t3 mod T)/T, not A·t3/T.",
        ),
        "rate_inverted": (
            _velocity(n, q3, period / amplitude).tolist(),
            "On a ramp q3 rises by A in T seconds: dq3/dt = A/T, not T/A.",
        ),
        "degrees_in_sin": (
            _velocity(n, float(np.degrees(q3)), rate).tolist(),
            "q3 is in radians: sin(q3) and cos(q3) of the radians, not of degrees.",
        ),
        # the same slip the other way round: radians typed into a degree-mode calculator
        "degrees_in_sin[degree mode]": (
            _velocity(n, float(np.radians(q3)), rate).tolist(),
            "q3 is in radians, but your sin and cos took it as degrees (a calculator in "
            "degree mode): switch it to radians.",
        ),
    }


def _wave(variant: Any, _: Any) -> dict[str, Any]:
    amplitude = variant.length("B", 0.4, 1.2, step=0.1)
    frequency = variant.choice("f", [0.1, 0.2, 0.25])
    t4 = variant.choice("t4", [0.4, 0.8, 1.2, 1.6])
    return {
        "B": amplitude,
        "f4": frequency,
        "t4": t4,
        "wave": Sine(amplitude=amplitude, frequency=frequency),
    }


def _terms(n: Any) -> tuple[np.ndarray, np.ndarray]:
    wave, t4, l3 = n["wave"], n["t4"], n["l3"]
    q, qd, qdd = wave.value(t4), wave.velocity(t4), wave.acceleration(t4)
    centripetal = l3 * np.array([-np.cos(q), 0, np.sin(q)]) * qd**2
    tangential = l3 * np.array([-np.sin(q), 0, -np.cos(q)]) * qdd
    return centripetal, tangential


def _omega_as_f(n: Any) -> np.ndarray:
    """The acceleration with ω = f in q3 = B sin(ωt) (2π left out)."""
    b, f, t, l3 = n["B"], n["f4"], n["t4"], n["l3"]
    q, qd, qdd = b * np.sin(f * t), b * f * np.cos(f * t), -b * f**2 * np.sin(f * t)
    return np.asarray(
        l3
        * (
            np.array([-np.cos(q), 0, np.sin(q)]) * qd**2
            + np.array([-np.sin(q), 0, -np.cos(q)]) * qdd
        )
    )


def _degree_mode_acceleration(n: Any) -> np.ndarray:
    """The acceleration by hand with every sine and cosine taken in degree mode."""
    b, omega, t, l3 = n["B"], 2 * np.pi * n["f4"], n["t4"], n["l3"]
    q = b * _sin_deg(omega * t)
    qd, qdd = b * omega * _cos_deg(omega * t), -b * omega**2 * _sin_deg(omega * t)
    centripetal = np.array([-_cos_deg(q), 0, _sin_deg(q)]) * qd**2
    return np.asarray(l3 * (centripetal + np.array([-_sin_deg(q), 0, -_cos_deg(q)]) * qdd))


def _acceleration(n: Any) -> np.ndarray:
    run = simulate(n["robot"], {"q3": n["wave"]}, t_end=2.0, dt=1e-3)
    return np.asarray(run.acceleration[int(round(n["t4"] / 1e-3)), run.points.index("EE")])


def _dt5(variant: Any, earlier: Any) -> dict[str, Any]:
    # The drop at t = T must fall on a sample (T = 2.5 s with dt = 0.2 s has none there).
    steps = [
        dt for dt in (0.05, 0.1, 0.2) if abs(earlier["T"] / dt - round(earlier["T"] / dt)) < 1e-9
    ]
    return {"dt5": variant.choice("dt5", steps)}


def _scope(n: Any, method: str) -> float:
    """v_x of the end-effector at the first drop, t = T, sampled every dt5."""
    dt = n["dt5"]
    run = simulate(n["robot"], {"q3": n["saw"]}, t_end=2 * n["T"], dt=dt, method=method)
    return float(run.velocity[int(round(n["T"] / dt)), n["robot"].n, 0])


def _scope_named(n: Any) -> dict[str, tuple[Any, str]]:
    l3, amplitude, dt = n["l3"], n["A"], n["dt5"]
    return {
        "central_for_backward": (
            _scope(n, "numeric"),
            "That is the central difference (x[k+1] - x[k-1]) / (2 dt); Simulink's "
            "Derivative block uses the backward difference (x[k] - x[k-1]) / dt.",
        ),
        "q3_at_amplitude": (
            l3 * (1 - np.cos(amplitude)) / dt,
            "Just before the drop the last sample is at t = T - dt, where q3 = A·(T - dt)/T, "
            "not A: the jump is a little smaller.",
        ),
        "radians_as_degrees": (
            l3 * (1 - _cos_deg(amplitude * (n["T"] - dt) / n["T"])) / dt,
            _DEGREE_MODE,
        ),
        "not_divided_by_dt": (
            _scope(n, "backward") * dt,
            "Divide the jump by dt: (x[k] - x[k-1]) / dt is a speed in mm/s.",
        ),
    }


register(
    matrix_exercise(
        LESSON,
        1,
        "the arm at a pose",
        _lab,
        lambda n: n["robot"],
        "p_EE",
        lambda n: n["q_star"],
        shows=lambda n: "$q^* = (" + ", ".join(f"{np.degrees(a):g}°" for a in n["q_star"]) + ")$",
        xyz=True,  # the notebook asks for [x, y, z]
    ),
    value_exercise(
        LESSON,
        2,
        "the scope's statistics",
        lambda v, earlier: {},
        _statistics,
        "check_vector",
        lambda n: {
            "name": "the z displacement statistics",
            "components": ["max", "min", "mean"],
            "unit": "mm",
            "hint": "The z displacement is -l3·sin(q3). Max and min: where is sin(q3) "
            "smallest and largest while q3 runs from 0 to A (A > pi/2)?",
        },
        named=_statistics_named,
    ),
    value_exercise(
        LESSON,
        3,
        "a velocity by the chain rule",
        _t3,
        lambda n: _velocity(n, float(n["saw"].value(n["t3"])), n["A"] / n["T"]),
        "check_vector",
        lambda n: {
            "name": "the velocity at t3",
            "unit": "mm/s",
            "hint": "Chain rule: v = dp/dq3 · dq3/dt, with dp/dq3 = l3·(-sin q3, 0, -cos q3).",
        },
        named=_velocity_named,
        shows=lambda n: f"$t_3 = {n['t3']:g}$ s",
    ),
    value_exercise(
        LESSON,
        4,
        "an acceleration by hand",
        _wave,
        _acceleration,
        "check_vector",
        lambda n: {
            "name": "the acceleration at t4",
            "unit": "mm/s²",
            "hint": "p'' = dp/dq3 · q3'' + d²p/dq3² · q3'², with q3' and q3'' of the sine at t4.",
        },
        named=lambda n: {
            "centripetal_only": (
                _terms(n)[0].tolist(),
                "Only the centripetal term: the sine's q3'' is not 0, so add the tangential "
                "term dp/dq3 · q3''.",
            ),
            "tangential_only": (
                _terms(n)[1].tolist(),
                "Only the tangential term: add the centripetal term d²p/dq3² · q3'², which "
                "does not vanish while q3 moves.",
            ),
            "omega_as_f": (
                _omega_as_f(n).tolist(),
                "The sine's angular frequency is ω = 2πf (rad/s), not f: q3 = B sin(2πf t).",
            ),
            "radians_as_degrees": (_degree_mode_acceleration(n).tolist(), _DEGREE_MODE),
        },
        shows=lambda n: f"$B = {n['B']:g}$ rad, $f = {n['f4']:g}$ Hz, $t_4 = {n['t4']:g}$ s",
    ),
    value_exercise(
        LESSON,
        5,
        "the spike on Simulink's scope",
        _dt5,
        lambda n: _scope(n, "backward"),
        "check_value",
        lambda n: {
            "name": "v_x at t = T (backward)",
            "unit": "mm/s",
            "hint": "Backward difference: (x(T) - x(T - dt)) / dt, with x = l2 + l3·cos(q3).",
        },
        named=_scope_named,
        shows=lambda n: f"$dt = {n['dt5']:g}$ s",
    ),
)
