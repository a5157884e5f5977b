"""Lessons 9–12: answers to the exercises with the demo student's numbers, each wrong one
made by one slip by hand, labelled with what a teacher would name (in-sample: written
while the checks' diagnoses were built).

A reference ``"L12.ex4"`` is exercise 4 of lesson 12, checked as the notebook checks it
(``rc.Assignment("12_trajectories", "demo").check(4, answer)``). The answers are worked
out from the demo numbers here, with the slip made in the working.
"""

from __future__ import annotations

import math

import numpy as np

import robotconf as rc

from .case import right, wrong

F9, F10, F11, F12 = "dh_tables", "lab", "inverse_kinematics", "trajectories"

L9 = rc.Assignment("09_dh_frame_assignment", "demo").numbers
L10 = rc.Assignment("10_paper_lab", "demo").numbers
L11 = rc.Assignment("11_inverse_kinematics", "demo").numbers
L12 = rc.Assignment("12_trajectories", "demo").numbers


def _lesson_9() -> list:
    l1, l2, h, u, f, h3, e = (L9[k] for k in ("l1", "l2", "h", "u", "f", "h3", "e"))
    return [
        right(F9, "L9.ex1-text", "L9.ex1", f"[[q1, 0, {l1}, 0], [q2, 0, {l2}, 0]]"),
        right(  # x1 pointing back at the base: θ1 + π with a negative a, and θ2 + π to turn back
            F9, "L9.ex1-other-x", "L9.ex1", [("q1 + pi", 0, -l1, 0), ("q2 + pi", 0, l2, 0)]
        ),
        wrong(  # the same x1, but frame 2 not turned back: link 2 points at the base at q2 = 0
            F9,
            "L9.ex1-other-x-not-undone",
            "L9.ex1",
            [("q1 + pi", 0, -l1, 0), ("q2", 0, l2, 0)],
            "theta_offset",
        ),
        wrong(
            F9, "L9.ex1-a-d-swapped", "L9.ex1", [("q1", l1, 0, 0), ("q2", 0, l2, 0)], "swapped_a_d"
        ),
        wrong(  # a and d mixed up in every row: the columns read in the wrong order
            F9, "L9.ex1-columns", "L9.ex1", [("q1", l1, 0, 0), ("q2", l2, 0, 0)], "swapped_a_d"
        ),
        wrong(
            F9,
            "L9.ex2-alpha-sign",
            "L9.ex2",
            [("q1 + pi/2", h, 0, "-pi/2"), ("q2", 0, u, 0), ("q3", 0, f, 0)],
            "alpha_sign",
        ),
        right(  # written as text, the constants as the student reads them off the drawing
            F9,
            "L9.ex2-text",
            "L9.ex2",
            f"[[q1 + pi/2, {h:g}, 0, pi/2], [q2, 0, {u:g}, 0], [q3, 0, {f:g}, 0]]",
        ),
        wrong(
            F9,
            "L9.ex2-theta-offset",
            "L9.ex2",
            [("q1", h, 0, "pi/2"), ("q2", 0, u, 0), ("q3", 0, f, 0)],
            "theta_offset",
        ),
        wrong(
            F9,
            "L9.ex2-degrees",
            "L9.ex2",
            [("q1 + 90", h, 0, 90), ("q2", 0, u, 0), ("q3", 0, f, 0)],
            "degrees",
        ),
        right(
            F9,
            "L9.ex3-rows",
            "L9.ex3",
            [("q1", 0, 0, 0), ("pi/2", f"q2 + {h3}", 0, "pi/2"), (0, f"q3 + {e}", 0, 0)],
        ),
        wrong(  # the slide's start h left out of row 2
            F9,
            "L9.ex3-height-forgotten",
            "L9.ex3",
            [("q1", 0, 0, 0), ("pi/2", "q2", 0, "pi/2"), (0, f"q3 + {e}", 0, 0)],
            "d_value",
        ),
        wrong(  # the tool's e as a row of its own
            F9,
            "L9.ex3-tool-as-a-row",
            "L9.ex3",
            [("q1", 0, 0, 0), ("pi/2", f"q2 + {h3}", 0, "pi/2"), (0, "q3", 0, 0), (0, e, 0, 0)],
            "row_count",
        ),
        right(
            F9,
            "L9.ex4-modified-rows",
            "L9.ex4",
            [("q1 + pi/2", h, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, u, 0)],
        ),
        wrong(
            F9,
            "L9.ex4-standard-rows",
            "L9.ex4",
            [("q1 + pi/2", h, 0, "pi/2"), ("q2", 0, u, 0), ("q3", 0, 0, 0)],
            "convention",
        ),
    ]


def _lesson_10() -> list:
    robot, q, l3, amplitude, period = (L10[k] for k in ("robot", "q_star", "l3", "A", "T"))
    point = robot.end_effector(q)
    degrees = robot.end_effector(np.degrees(q))
    absolute = robot.end_effector([q[0], q[1], q[2] - q[1]])
    t3 = L10["t3"]
    q3 = amplitude * (t3 % period) / period
    rate = amplitude / period

    def velocity(angle: float, speed: float) -> list:
        return (l3 * speed * np.array([-np.sin(angle), 0, -np.cos(angle)])).tolist()

    b, freq, t4 = L10["B"], L10["f4"], L10["t4"]
    w = 2 * math.pi * freq
    qa, qd, qdd = b * math.sin(w * t4), b * w * math.cos(w * t4), -b * w**2 * math.sin(w * t4)
    centripetal = l3 * np.array([-math.cos(qa), 0, math.sin(qa)]) * qd**2
    tangential = l3 * np.array([-math.sin(qa), 0, -math.cos(qa)]) * qdd
    dt = L10["dt5"]
    backward = l3 * (1 - math.cos(amplitude * (period - dt) / period)) / dt
    mean = -l3 * (1 - math.cos(amplitude)) / amplitude
    return [
        right(F10, "L10.ex1-rounded", "L10.ex1", [float(f"{x:.3g}") for x in point]),
        wrong(F10, "L10.ex1-degrees", "L10.ex1", degrees.tolist(), "degrees_as_radians"),
        wrong(F10, "L10.ex1-q3-absolute", "L10.ex1", absolute.tolist(), "absolute_angle"),
        right(F10, "L10.ex2-text", "L10.ex2", f"[0, {-l3}, {mean:.4g}]"),
        wrong(F10, "L10.ex2-midrange", "L10.ex2", [0, -l3, -l3 / 2], "mean_as_midrange"),
        wrong(
            F10,
            "L10.ex2-min-at-A",
            "L10.ex2",
            [0, -l3 * math.sin(amplitude), mean],
            "min_at_amplitude",
        ),
        right(F10, "L10.ex3-formula", "L10.ex3", velocity(q3, rate)),
        wrong(F10, "L10.ex3-rate-left-out", "L10.ex3", velocity(q3, 1.0), "rate_left_out"),
        wrong(F10, "L10.ex3-per-A", "L10.ex3", velocity(q3, period / amplitude), "rate_inverted"),
        wrong(
            F10,
            "L10.ex3-no-restart",
            "L10.ex3",
            velocity(amplitude * t3 / period, rate),
            "no_restart",
        ),
        wrong(
            F10,
            "L10.ex3-degrees",
            "L10.ex3",
            velocity(math.degrees(q3), rate),
            "degrees_in_sin",
        ),
        right(
            F10, "L10.ex4-rounded", "L10.ex4", [float(f"{x:.3g}") for x in centripetal + tangential]
        ),
        wrong(F10, "L10.ex4-centripetal", "L10.ex4", centripetal.tolist(), "centripetal_only"),
        wrong(F10, "L10.ex4-tangential", "L10.ex4", tangential.tolist(), "tangential_only"),
        wrong(
            F10,
            "L10.ex4-omega-f",
            "L10.ex4",
            (
                l3
                * (
                    np.array(
                        [-math.cos(b * math.sin(freq * t4)), 0, math.sin(b * math.sin(freq * t4))]
                    )
                    * (b * freq * math.cos(freq * t4)) ** 2
                    + np.array(
                        [-math.sin(b * math.sin(freq * t4)), 0, -math.cos(b * math.sin(freq * t4))]
                    )
                    * (-b * freq**2 * math.sin(freq * t4))
                )
            ).tolist(),
            "omega_as_f",
        ),
        right(
            F10,
            "L10.ex5-text",
            "L10.ex5",
            f"{l3}*(1 - cos({amplitude}*({period} - {dt})/{period}))/{dt}",
        ),
        wrong(
            F10,
            "L10.ex5-q3-at-A",
            "L10.ex5",
            l3 * (1 - math.cos(amplitude)) / dt,
            "q3_at_amplitude",
        ),
        wrong(F10, "L10.ex5-not-divided", "L10.ex5", backward * dt, "not_divided_by_dt"),
    ]


def _ik() -> tuple:
    l1, l2 = L11["l1"], L11["l2"]
    x, y = (float(v) for v in L11["target"][:2])
    q2 = math.acos((x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2))
    beta = math.atan2(l2 * math.sin(q2), l1 + l2 * math.cos(q2))
    return l1, l2, x, y, q2, beta


def _lesson_11() -> list:
    l1, l2, x, y, q2, beta = _ik()
    # each q1 wrapped into the joint range (−π, π] the exercises ask for
    down = [math.remainder(math.atan2(y, x) - beta, math.tau), q2]
    up = [math.remainder(math.atan2(y, x) + beta, math.tau), -q2]
    q_k, jac, err, lam = L11["q_k"], L11["J_k"], L11["e_k"], L11["lam"]
    step = np.linalg.solve(jac, err)
    damped = np.linalg.solve(jac.T @ jac + lam * np.eye(2), jac.T @ err)
    far = L11["far"]
    return [
        right(F11, "L11.ex1-elbow-up-text", "L11.ex1", f"[{up[0]:.4f}, {up[1]:.4f}]"),
        wrong(F11, "L11.ex1-atan", "L11.ex1", [math.atan(y / x) - beta, q2], "atan_quadrant"),
        wrong(
            F11, "L11.ex1-degrees", "L11.ex1", [math.degrees(v) for v in down], "degrees_as_radians"
        ),
        wrong(F11, "L11.ex1-branches-mixed", "L11.ex1", [down[0], -q2], "cosine_law_sign"),
        right(F11, "L11.ex2-any-order", "L11.ex2", [up, down]),
        wrong(F11, "L11.ex2-one-missing", "L11.ex2", [down], "missing"),
        right(F11, "L11.ex3-text", "L11.ex3", f"[{abs(l1 - l2)}, {l1} + {l2}]"),
        wrong(F11, "L11.ex3-inner-zero", "L11.ex3", [0, l1 + l2], "inner_radius_zero"),
        wrong(F11, "L11.ex3-ends-swapped", "L11.ex3", [l1 + l2, abs(l1 - l2)], "swapped_ends"),
        right(F11, "L11.ex4-rounded", "L11.ex4", [float(f"{v:.3g}") for v in q_k + step]),
        wrong(F11, "L11.ex4-step-only", "L11.ex4", step.tolist(), "step_without_q"),
        wrong(F11, "L11.ex4-e-reversed", "L11.ex4", (q_k - step).tolist(), "error_reversed"),
        wrong(
            F11, "L11.ex4-Jt-e", "L11.ex4", (q_k + jac.T @ err).tolist(), "transpose_for_inverse"
        ),
        wrong(
            F11,
            "L11.ex4-J-transposed",
            "L11.ex4",
            (q_k + np.linalg.solve(jac.T, err)).tolist(),
            "inverse_transposed",
        ),
        right(
            F11, "L11.ex5-text", "L11.ex5", "[" + ", ".join(f"{x:.3g}" for x in q_k + damped) + "]"
        ),
        wrong(F11, "L11.ex5-step-only", "L11.ex5", damped.tolist(), "step_without_q"),
        wrong(F11, "L11.ex5-e-reversed", "L11.ex5", (q_k - damped).tolist(), "error_reversed"),
        wrong(
            F11,
            "L11.ex5-lambda-squared",
            "L11.ex5",
            (q_k + np.linalg.solve(jac.T @ jac + lam**2 * np.eye(2), jac.T @ err)).tolist(),
            "lambda_squared",
        ),
        wrong(F11, "L11.ex5-no-damping", "L11.ex5", (q_k + step).tolist(), "no_damping"),
        wrong(
            F11,
            "L11.ex5-Jt-left-out",
            "L11.ex5",
            (q_k + np.linalg.solve(jac.T @ jac + lam * np.eye(2), err)).tolist(),
            "transpose_left_out",
        ),
        wrong(
            F11, "L11.ex5-Jt-e", "L11.ex5", (q_k + jac.T @ err).tolist(), "transpose_for_inverse"
        ),
        right(
            F11,
            "L11.ex6-text",
            "L11.ex6",
            f"sqrt({far[0]}**2 + {far[1]}**2 + ({far[2]} - 20)**2) - 70",
        ),
        wrong(
            F11, "L11.ex6-from-base", "L11.ex6", float(np.linalg.norm(far) - 70), "from_the_base"
        ),
        wrong(
            F11,
            "L11.ex6-radius-90",
            "L11.ex6",
            float(np.linalg.norm(far - [0, 0, 20]) - 90),
            "radius_with_l1",
        ),
        right(F11, "L11.ex7-order", "L11.ex7", [6, 4]),
        wrong(F11, "L11.ex7-from-0", "L11.ex7", [3, 5], "counted_from_0"),
        wrong(F11, "L11.ex7-the-cause", "L11.ex7", [5], "cause_for_joints"),
    ]


def _lesson_12() -> list:
    d1, v, a, d2, d3, t3 = (L12[k] for k in ("d1", "v_max", "a_max", "d2", "d3", "T3"))
    delta, speed, accel = L12["delta_4"], L12["speed_4"], L12["accel_4"]
    own = [
        abs(d) / s + s / c if abs(d) >= s * s / c else 2 * math.sqrt(abs(d) / c)
        for d, s, c in zip(delta, speed, accel, strict=True)
    ]
    trapezoid_only = max(abs(d) / s + s / c for d, s, c in zip(delta, speed, accel, strict=True))
    largest = own[int(np.argmax(np.abs(delta)))]
    l1, l2, x_star, v6 = L12["l1"], L12["l2"], L12["x_star"], L12["v_6"]
    q2 = math.acos((x_star**2 - l1**2 - l2**2) / (2 * l1 * l2))
    det = l1 * l2 * math.sin(q2)
    # one time law for all joints: u from 0 to 1 with u' <= min v/|d|, u'' <= min a/|d|
    speed_u = min(s / abs(d) for d, s in zip(delta, speed, strict=True))
    accel_u = min(c / abs(d) for d, c in zip(delta, accel, strict=True))
    synchronized = (
        1 / speed_u + speed_u / accel_u if speed_u**2 / accel_u <= 1 else 2 * math.sqrt(1 / accel_u)
    )
    return [
        right(
            F12,
            "L12.ex1-dict",
            "L12.ex1",
            {"t_total": d1 / v + v / a, "t_accel": v / a, "v_peak": v},
        ),
        wrong(
            F12,
            "L12.ex1-2v-over-a",
            "L12.ex1",
            [2 * v / a, d1 / v + 2 * v / a, v],
            "accel_time_factor",
        ),
        wrong(
            F12,
            "L12.ex1-no-ramp-down",
            "L12.ex1",
            [v / a, d1 / v + v / (2 * a), v],
            "not_at_rest_end",
        ),
        wrong(F12, "L12.ex1-no-ramps", "L12.ex1", [0, d1 / v, v], "ramps_forgotten"),
        right(  # the triangle: no cruise, the peak speed sqrt(a·d) at half way
            F12,
            "L12.ex2-triangle",
            "L12.ex2",
            [math.sqrt(d2 / a), 2 * math.sqrt(d2 / a), math.sqrt(a * d2)],
        ),
        wrong(
            F12,
            "L12.ex2-trapezoid-formulas",
            "L12.ex2",
            [v / a, d2 / v + v / a, v],
            "triangle_as_trapezoid",
        ),
        right(F12, "L12.ex3-text", "L12.ex3", f"15/8*{d3}/{t3}"),
        wrong(F12, "L12.ex3-cubic", "L12.ex3", 1.5 * d3 / t3, "cubic_quintic_swapped"),
        wrong(F12, "L12.ex3-average", "L12.ex3", d3 / t3, "average_speed"),
        right(F12, "L12.ex4-rounded", "L12.ex4", float(f"{synchronized:.3g}")),
        wrong(F12, "L12.ex4-own-durations", "L12.ex4", own, "not_synchronized"),
        wrong(F12, "L12.ex4-slowest-alone", "L12.ex4", max(own), "mixed_limits"),
        wrong(F12, "L12.ex4-no-triangle-check", "L12.ex4", trapezoid_only, "triangle_as_trapezoid"),
        *(
            [wrong(F12, "L12.ex4-largest-move", "L12.ex4", largest, "largest_move")]
            if not math.isclose(largest, max(own))
            else []
        ),
        right(F12, "L12.ex5-text", "L12.ex5", "[3]"),
        wrong(F12, "L12.ex5-from-1", "L12.ex5", [4], "counted_from_1"),
        wrong(F12, "L12.ex5-ptp-too", "L12.ex5", [1, 3], "ptp_counted"),
        right(F12, "L12.ex6-rounded", "L12.ex6", float(f"{v6 * x_star / det:.3g}")),
        wrong(F12, "L12.ex6-x-left-out", "L12.ex6", v6 / det, "x_left_out"),
        wrong(F12, "L12.ex6-L-for-x", "L12.ex6", v6 * (l1 + l2) / det, "length_for_x"),
        wrong(F12, "L12.ex6-cos", "L12.ex6", v6 * x_star / (l1 * l2 * math.cos(q2)), "cos_for_sin"),
    ]


CASES = [*_lesson_9(), *_lesson_10(), *_lesson_11(), *_lesson_12()]
