"""A second blind set of answers to lessons 9–12 (families ``L9-second`` …), held-out
when measured, in-sample since (the checks were fixed against it; see the end).

Written on 2026-12-02 by a helper session that had not seen how the checker computes its
diagnoses (it opened neither ``robotconf/teaching/``, ``course/solutions/``, this corpus's
other data modules nor the course's diagnosis tests), only what a student and a teacher
see: the notebooks of lessons 9–12, ``course/INSTRUCTOR.md``, ``course/kit/``, ``robotconf
course rubric 9`` … ``12`` (the slip codes) and ``rc.Assignment(lesson, student)``.

Students ``s2041``, ``s2042`` and ``s2043``. Every right answer was worked by hand from
the lessons' formulas and confirmed with robotconf's kinematics, IK, simulation and
profile functions (never with the checker); it is typed in another form than the obvious
one where the course allows it: another valid DH frame choice, text expressions, 3 or 4
significant digits, a reordered solution set. Every wrong answer is one slip a student
makes (labelled with the code a teacher would name, from the rubric's list), or two
slips or an unexplained number (labelled ``None``). The cases and their labels were
written and committed before the checker was run on them once.

Measured once, after the commit of the cases (``python -m tests.diagnosis_corpus
--failures``, held-out line of this module), 192 answers (39 right, 153 wrong): the right
primary diagnosis for 141 of the 153 wrong ones (92.2 %; lesson 9: 32/34, 10: 34/38,
11: 40/43, 12: 35/38), 3 vague, 8 another diagnosis, 1 false accept, 3 false rejects.
Two of the false rejects are not verdicts: the checker refuses the text of
``L11.ex1-text`` (``atan2``) and ``L12.ex6-text`` (``acos``) with an InvalidInputError
(only sin, cos, tan and sqrt may be called), which stops ``python -m
tests.diagnosis_corpus`` and ``tests/test_diagnosis_corpus.py``; the figures above count
them as false rejects.

One fix after the measurement, of a case that was itself mistaken:
``s2041-L9.ex1-planar-z1-down`` was written as a right answer (z1 pointing down, ``-q2``
in row 2), but lesson 9's rules make z point along the joint's arrow and add the joint
variable to theta (rule 1 and 6): the table is the ``-q`` slip, now a wrong answer
labelled ``joint_direction``. With it: 192 answers (38 right, 154 wrong), 142/154 right
primary diagnoses (92.2 %), 1 false accept, 2 false rejects (the two refused texts).

**In-sample since.** The checks were then changed while looking at these cases, each
change with its own unit test: student text may call ``asin``, ``acos``, ``atan`` and
``atan2`` (the two refused texts); an IK answer that reaches the target but has an angle
rounded past 3 significant digits is ``too_rounded`` (the false accept
``L11.ex1-two-digits``); the measure counts a code that names no slip (the rubric's own
list: ``extra``, ``missing``, …) as right for a case labelled ``None``. The DH-table
changes that name ``cumulative-a2`` and ``a3-cumulative`` were made on the first blind
set, before this one was merged. After these changes the figure is an in-sample one
(``python -m tests.diagnosis_corpus``), not a measure of unseen answers.
"""

from __future__ import annotations

import dataclasses
from typing import Any

from .case import Case, right, wrong

S1, S2, S3 = "s2041", "s2042", "s2043"


def _family(reference: str) -> str:
    return reference.split(".")[0] + "-second"


def _r(student: str, name: str, reference: str, answer: Any) -> Case:
    case = right(_family(reference), f"{student}-{reference}-{name}", reference, answer)
    return dataclasses.replace(case, student=student)


def _w(student: str, name: str, reference: str, answer: Any, diagnosis: str | None) -> Case:
    case = wrong(_family(reference), f"{student}-{reference}-{name}", reference, answer, diagnosis)
    return dataclasses.replace(case, student=student)


CASES = [
    # ---- lesson 9
    _r(S2, "planar-standard", "L9.ex1", [("q1", 0, 35, 0), ("q2", 0, 45, 0)]),
    # z1 against joint 2's arrow, -q2 (a right answer until the fix after the measurement)
    _w(
        S1,
        "planar-z1-down",
        "L9.ex1",
        [("q1", 0, 50, "pi"), ("-q2", 0, 45, "-pi")],
        "joint_direction",
    ),
    _w(S1, "lengths-in-d", "L9.ex1", [("q1", 50, 0, 0), ("q2", 45, 0, 0)], "swapped_a_d"),
    _w(S2, "negative-a1", "L9.ex1", [("q1", 0, -35, 0), ("q2", 0, 45, 0)], "a_sign"),
    _w(S3, "cumulative-a2", "L9.ex1", [("q1", 0, 35, 0), ("q2", 0, 50, 0)], "a_value"),
    _w(
        S2, "needless-offset", "L9.ex1", [("q1 + pi/2", 0, 35, 0), ("q2", 0, 45, 0)], "theta_offset"
    ),
    _w(S1, "modified-table", "L9.ex1", [("q1", 0, 0, 0), ("q2", 0, 50, 0)], "convention"),
    _w(S3, "joint2-backwards", "L9.ex1", [("q1", 0, 35, 0), ("-q2", 0, 15, 0)], "joint_direction"),
    _w(S3, "one-row", "L9.ex1", [("q1", 0, 35, 0)], "row_count"),  # stopped after the first joint
    # two slips: lengths in d and a theta offset
    _w(S2, "d-and-offset", "L9.ex1", [("q1 + pi/2", 35, 0, 0), ("q2", 45, 0, 0)], None),
    _r(
        S3, "decimals", "L9.ex2", [("q1 + 1.571", 40, 0, 1.571), ("q2", 0, 30, 0), ("q3", 0, 20, 0)]
    ),
    # x1 = -y: twist -pi/2, theta2 offset pi
    _r(
        S2,
        "x1-along-minus-y",
        "L9.ex2",
        [("q1 - pi/2", 40, 0, "-pi/2"), ("q2 + pi", 0, 25, 0), ("q3", 0, 30, 0)],
    ),
    _w(
        S1,
        "twist-sign",
        "L9.ex2",
        [("q1 + pi/2", 40, 0, "-pi/2"), ("q2", 0, 20, 0), ("q3", 0, 25, 0)],
        "alpha_sign",
    ),
    _w(
        S2,
        "no-theta-offset",
        "L9.ex2",
        [("q1", 40, 0, "pi/2"), ("q2", 0, 25, 0), ("q3", 0, 30, 0)],
        "theta_offset",
    ),
    _w(
        S3,
        "height-in-a",
        "L9.ex2",
        [("q1 + pi/2", 0, 40, "pi/2"), ("q2", 0, 30, 0), ("q3", 0, 20, 0)],
        "swapped_a_d",
    ),
    _w(
        S1,
        "height-down",
        "L9.ex2",
        [("q1 + pi/2", -40, 0, "pi/2"), ("q2", 0, 20, 0), ("q3", 0, 25, 0)],
        "d_sign",
    ),
    _w(
        S2,
        "height-forgotten",
        "L9.ex2",
        [("q1 + pi/2", 0, 0, "pi/2"), ("q2", 0, 25, 0), ("q3", 0, 30, 0)],
        "d_value",
    ),
    _w(
        S3,
        "a2-negative",
        "L9.ex2",
        [("q1 + pi/2", 40, 0, "pi/2"), ("q2", 0, -30, 0), ("q3", 0, 20, 0)],
        "a_sign",
    ),
    _w(
        S1,
        "a3-cumulative",
        "L9.ex2",
        [("q1 + pi/2", 40, 0, "pi/2"), ("q2", 0, 20, 0), ("q3", 0, 45, 0)],
        "a_value",
    ),
    _w(
        S3,
        "degrees",
        "L9.ex2",
        [("q1 + 90", 40, 0, 90), ("q2", 0, 30, 0), ("q3", 0, 20, 0)],
        "degrees",
    ),
    _w(
        S1,
        "twist-forgotten",
        "L9.ex2",
        [("q1 + pi/2", 40, 0, 0), ("q2", 0, 20, 0), ("q3", 0, 25, 0)],
        "twist",
    ),
    # x2 = y: theta2 = pi/2, alpha2 = pi/2
    _r(
        S1,
        "standard",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2 + 25", 0, "pi/2"), (0, "q3 + 10", 0, 0)],
    ),
    # frame 1 at height h, x2 = -y
    _r(
        S3,
        "offset-in-d1",
        "L9.ex3",
        [("q1", 15, 0, 0), ("-pi/2", "q2", 0, "-pi/2"), (0, "q3 + 5", 0, 0)],
    ),
    _w(
        S1,
        "theta2-zero",
        "L9.ex3",
        [("q1", 0, 0, 0), (0, "q2 + 25", 0, "pi/2"), (0, "q3 + 10", 0, 0)],
        "theta_offset",
    ),
    _w(
        S2,
        "alpha2-sign",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2 + 15", 0, "-pi/2"), (0, "q3 + 15", 0, 0)],
        "alpha_sign",
    ),
    _w(
        S3,
        "h-forgotten",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2", 0, "pi/2"), (0, "q3 + 5", 0, 0)],
        "d_value",
    ),
    _w(
        S1,
        "e-forgotten",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2 + 25", 0, "pi/2"), (0, "q3", 0, 0)],
        "d_value",
    ),
    _w(
        S2,
        "h-negative",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2 - 15", 0, "pi/2"), (0, "q3 + 15", 0, 0)],
        "d_sign",
    ),
    _w(
        S3,
        "h-in-a",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2", 15, "pi/2"), (0, "q3 + 5", 0, 0)],
        "swapped_a_d",
    ),
    _w(
        S1,
        "slide-as-revolute",
        "L9.ex3",
        [("q1", 0, 0, 0), ("pi/2", "q2 + 25", 0, "pi/2"), ("q3", 10, 0, 0)],
        "joint_type",
    ),
    _w(
        S2,
        "degrees",
        "L9.ex3",
        [("q1", 0, 0, 0), (90, "q2 + 15", 0, 90), (0, "q3 + 15", 0, 0)],
        "degrees",
    ),
    _r(S2, "craig", "L9.ex4", [("q1 + pi/2", 40, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 25, 0)]),
    # x1 = -y
    _r(
        S1,
        "craig-x1-minus-y",
        "L9.ex4",
        [("q1 - pi/2", 40, 0, 0), ("q2 + pi", 0, 0, "-pi/2"), ("q3", 0, 20, 0)],
    ),
    _w(
        S1,
        "standard-table",
        "L9.ex4",
        [("q1 + pi/2", 40, 0, "pi/2"), ("q2", 0, 20, 0), ("q3", 0, 25, 0)],
        "convention",
    ),
    _w(
        S2,
        "twist-sign",
        "L9.ex4",
        [("q1 + pi/2", 40, 0, 0), ("q2", 0, 0, "-pi/2"), ("q3", 0, 25, 0)],
        "alpha_sign",
    ),
    _w(
        S3,
        "no-theta-offset",
        "L9.ex4",
        [("q1", 40, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 30, 0)],
        "theta_offset",
    ),
    _w(
        S1,
        "height-in-a",
        "L9.ex4",
        [("q1 + pi/2", 0, 40, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 20, 0)],
        "swapped_a_d",
    ),
    _w(
        S2,
        "height-down",
        "L9.ex4",
        [("q1 + pi/2", -40, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 25, 0)],
        "d_sign",
    ),
    _w(
        S3,
        "a2-negative",
        "L9.ex4",
        [("q1 + pi/2", 40, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, -30, 0)],
        "a_sign",
    ),
    _w(
        S1,
        "height-forgotten",
        "L9.ex4",
        [("q1 + pi/2", 0, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 20, 0)],
        "d_value",
    ),
    _w(
        S2,
        "tool-row",
        "L9.ex4",
        [("q1 + pi/2", 40, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 25, 0), (0, 0, 30, 0)],
        "row_count",
    ),
    _w(
        S3,
        "twist-forgotten",
        "L9.ex4",
        [("q1 + pi/2", 40, 0, 0), ("q2", 0, 0, 0), ("q3", 0, 30, 0)],
        "twist",
    ),
    # ---- lesson 10
    _r(S1, "four-digits", "L10.ex1", [0.0, 17.32, -15.0]),
    # the formula typed in
    _r(
        S3,
        "text",
        "L10.ex1",
        [
            "cos(2*pi/3)*(20*cos(pi/3) + 45*cos(pi/2))",
            "sin(2*pi/3)*(20*cos(pi/3) + 45*cos(pi/2))",
            "25 - 20*sin(pi/3) - 45*sin(pi/2)",
        ],
    ),
    _w(S2, "parking", "L10.ex1", [80.0, 0.0, 30.0], "parking_pose"),  # p at q = 0
    _w(S3, "q3-left-out", "L10.ex1", [-16.25, 28.15, -31.29], "joint_left_out"),  # q3 not applied
    # Ry turning z toward x the other way
    _w(S2, "ry-sign", "L10.ex1", [-7.321, 12.68, 84.64], "rotation_direction"),
    # every joint turned the other way
    _w(S1, "all-signs", "L10.ex1", [0.0, -17.32, 75.0], "rotation_direction_all"),
    # q3 used as the last link's absolute angle
    _w(S3, "absolute-q3", "L10.ex1", [-24.49, 42.41, -14.82], "absolute_angle"),
    # 90, 30, 60 fed to cos/sin in radians
    _w(S1, "degrees-in-trig", "L10.ex1", [5.645, -11.26, 18.47], "degrees_as_radians"),
    _w(S2, "l1-left-out", "L10.ex1", [-7.321, 12.68, -54.64], "missing_offset"),  # z without l1
    _w(S3, "metres", "L10.ex1", [-0.005, 0.00866, -0.03732], "unit_slip"),  # in m
    # q2 and q3 values swapped
    _w(S1, "q2-q3-swapped", "L10.ex1", [0.0, 10.0, -22.32], "swapped_joints"),
    _w(S2, "two-digits", "L10.ex1", [-7.3, 13.0, -25.0], "coarse_rounding"),  # 2 significant digits
    _w(S3, "x-y-swapped", "L10.ex1", [8.66, -5.0, -37.32], "row_swap"),  # x and y rows swapped
    _r(S3, "three-digits", "L10.ex2", [0, -45, -31.3]),
    _w(S1, "midrange", "L10.ex2", [0, -35.0, -17.5], "mean_as_midrange"),  # (max + min)/2
    _w(S2, "min-at-A", "L10.ex2", [0, -37.85, -27.86], "min_at_amplitude"),  # min where q3 = A
    _w(S3, "z-up", "L10.ex2", [45.0, 0, 31.34], "sign_flipped"),  # displacement +l3 sin q3
    _w(S1, "metres", "L10.ex2", [0, -0.035, -0.02478], "unit_factor"),  # in m
    _w(S2, "sin-of-mean", "L10.ex2", [0, -40.0, -32.54], "mean_angle"),  # z at the mean angle A/2
    _w(S3, "min-max-swapped", "L10.ex2", [-45.0, 0, -31.34], "swapped_ends"),  # [min, max, mean]
    _w(
        S1, "not-divided-by-A", "L10.ex2", [0, -35.0, -49.57], None
    ),  # the integral not divided by A
    _r(S2, "three-digits", "L10.ex3", [-73.8, 0.0, -18.1]),
    # q3 = A t/T without the restart
    _w(S1, "no-restart", "L10.ex3", [-12.03, 0.0, 19.99], "no_restart"),
    _w(S2, "no-rate", "L10.ex3", [-38.85, 0.0, -9.539], "rate_left_out"),  # dq3/dt left out
    _w(S3, "T-over-A", "L10.ex3", [-70.96, 0.0, -3.608], "rate_inverted"),  # dq3/dt = T/A
    # calculator in degree mode for sin and cos
    _w(S1, "sin-in-degrees", "L10.ex3", [-0.2443, 0.0, -23.33], "degrees_in_sin"),
    _w(S2, "all-signs", "L10.ex3", [73.81, -0.0, 18.12], "sign_flipped"),  # every sign flipped
    _w(S3, "metres", "L10.ex3", [-0.02846, 0.0, -0.001447], "unit_factor"),  # in m/s
    _w(S1, "vz-sign", "L10.ex3", [-13.17, 0, 19.26], "sign_error"),  # vz's sign lost
    _r(S1, "three-digits", "L10.ex4", [-18.9, 0.0, 73.6]),
    _r(S3, "four-digits", "L10.ex4", [-32.5, 0.0, 55.62]),
    # the dq3^2 term only
    _w(S1, "centripetal", "L10.ex4", [-47.04, 0.0, 31.34], "centripetal_only"),
    _w(S2, "tangential", "L10.ex4", [0.7845, 0.0, 3.446], "tangential_only"),  # the ddq3 term only
    _w(S3, "omega-f", "L10.ex4", [-1.771, 0.0, 0.2862], "omega_as_f"),  # omega = f, no 2 pi
    _w(S1, "all-signs", "L10.ex4", [18.89, -0.0, -73.58], "sign_flipped"),  # every sign flipped
    # calculator in degree mode
    _w(S3, "degree-mode", "L10.ex4", [-71.06, 0.0, 0.6343], "radians_as_degrees"),
    _w(S2, "metres", "L10.ex4", [-0.01092, 0.0, 0.00611], "unit_factor"),  # in m/s^2
    # two slips: one term, omega = f
    _w(S3, "centripetal-omega-f", "L10.ex4", [-1.783, 0.0, 0.1428], None),
    _r(S3, "text", "L10.ex5", "45*(1 - cos(1.9*(3 - 0.1)/3))/0.1"),  # the formula typed in
    _w(S1, "central", "L10.ex5", 236.7, "central_for_backward"),  # the central difference
    _w(S2, "q3-at-A", "L10.ex5", 529.3, "q3_at_amplitude"),  # q3 = A before the drop
    _w(S3, "jump-only", "L10.ex5", 56.82, "not_divided_by_dt"),  # the jump, not divided by dt
    _w(S1, "negative", "L10.ex5", -474.1, "sign_error"),  # x(T - dt) - x(T)
    _w(S2, "metres", "L10.ex5", 0.4555, "unit_factor"),  # in m/s
    _w(S3, "degree-mode", "L10.ex5", 0.2312, "radians_as_degrees"),  # cos in degree mode
    # ---- lesson 11
    _r(S1, "elbow-down", "L11.ex1", [2.922, -1.254]),  # the other branch
    # atan2 typed in
    _r(
        S3, "text", "L11.ex1", ["atan2(-0.65, -1.79) + atan2(sin(1.921), 2 + cos(1.921))", "-1.921"]
    ),
    _w(S1, "atan", "L11.ex1", [-0.999, 1.254], "atan_quadrant"),  # atan(y/x) for atan2(y, x)
    # cos q2 = (l1^2 + l2^2 - r^2)/(2 l1 l2)
    _w(S2, "cosine-law", "L11.ex1", [1.267, 1.649], "cosine_law_sign"),
    _w(S3, "degrees", "L11.ex1", [170.4, 110.1], "degrees_as_radians"),  # in degrees
    _w(S1, "x-y-swapped", "L11.ex1", [-1.352, 1.254], "wrong_target"),  # target read as (y, x)
    _w(S3, "not-wrapped", "L11.ex1", [-3.309, 1.921], "outside_limits"),  # q1 = -3.309 not wrapped
    _w(S2, "two-digits", "L11.ex1", [1.3, 1.5], "too_rounded"),  # 2 significant digits
    _w(S2, "q1-sign", "L11.ex1", [-1.298, 1.492], "sign_error"),  # q1's sign lost
    _r(S2, "reordered", "L11.ex2", [[2.192, -1.492], [1.298, 1.492]]),  # elbow-down first
    _r(S1, "three-digits", "L11.ex2", [[2.14, 1.25], [2.92, -1.25]]),
    _w(S1, "one-branch", "L11.ex2", [[2.143, 1.254]], "missing"),  # one solution only
    # atan for atan2, wrapped
    _w(S2, "atan", "L11.ex2", [[-1.844, 1.492], [-0.9491, -1.492]], "atan_quadrant"),
    # the law of cosines with the wrong sign
    _w(S3, "cosine-law", "L11.ex2", [[3.109, 1.22], [-2.412, -1.22]], "cosine_law_sign"),
    # q1 of one branch with q2 of the other
    _w(S1, "mixed-pairs", "L11.ex2", [[2.143, -1.254], [2.922, 1.254]], None),
    # in degrees
    _w(S1, "degrees", "L11.ex2", [[122.8, 71.83], [167.4, -71.83]], "degrees_as_radians"),
    # the same solution twice
    _w(S3, "twice", "L11.ex2", [[2.974, 1.921], [2.974, 1.921]], "duplicate"),
    # q1 = -3.309 not wrapped
    _w(S3, "not-wrapped", "L11.ex2", [[-3.309, 1.921], [-2.278, -1.921]], "outside_limits"),
    _r(S3, "text", "L11.ex3", ["2 - 1", "2 + 1"]),  # l1 - l2, l1 + l2
    _w(S1, "zero-inner", "L11.ex3", [0, 3], "inner_radius_zero"),  # r_min = 0
    _w(S2, "reversed", "L11.ex3", [3, 1], "swapped_ends"),  # [max, min]
    _w(S3, "l1-inner", "L11.ex3", [2, 3], None),  # r_min = l1
    _w(S3, "zero-inner", "L11.ex3", ["0", "3.0"], "inner_radius_zero"),  # r_min = 0
    _r(S2, "four-digits", "L11.ex4", [1.086, 1.925]),
    _r(S3, "three-digits", "L11.ex4", [-0.0427, 6.42]),
    _w(S1, "dq-only", "L11.ex4", [-0.1321, 3.629], "step_without_q"),  # Delta q without q_k
    _w(S2, "minus", "L11.ex4", [1.314, -0.3254], "error_reversed"),  # e = p - p*
    _w(S3, "jt", "L11.ex4", [4.361, 4.962], "transpose_for_inverse"),  # J^T for J^-1
    _w(S1, "inv-t", "L11.ex4", [1.912, 0.5394], "inverse_transposed"),  # J^-T e
    _w(S2, "all-signs", "L11.ex4", [-1.086, -1.925], "sign_flipped"),  # every sign flipped
    _w(S2, "two-digits", "L11.ex4", [1.1, 1.9], "too_rounded"),  # 2 significant digits
    _w(S1, "q1-sign", "L11.ex4", [-0.6679, 4.629], "sign_error"),  # q1's sign lost
    _r(S3, "four-digits", "L11.ex5", [0.4226, 4.731]),
    # lambda^2 on the diagonal
    _w(S1, "lambda-squared", "L11.ex5", [0.6943, 4.539], "lambda_squared"),
    _w(S2, "newton", "L11.ex5", [1.086, 1.925], "no_damping"),  # the Newton step
    _w(S3, "no-jt", "L11.ex5", [1.116, -1.631], "transpose_left_out"),  # J^T e written as e
    _w(S1, "dq-only", "L11.ex5", [0.07832, 2.901], "step_without_q"),  # Delta q without q_k
    _w(S2, "minus", "L11.ex5", [1.1, 0.3906], "error_reversed"),  # e = p - p*
    _w(S3, "jt", "L11.ex5", [4.361, 4.962], "transpose_for_inverse"),  # J^T e, the inverse dropped
    # two slips: lambda^2 and no q_k
    _w(S1, "lambda-squared-dq-only", "L11.ex5", [-0.1057, 3.539], None),
    _r(S1, "text", "L11.ex6", "sqrt(70**2 + 30**2 + 40**2) - 70"),  # the formula typed in
    _r(S2, "three-digits", "L11.ex6", 21.7),
    # distance from the base, not the shoulder
    _w(S1, "from-base", "L11.ex6", 26.95, "from_the_base"),
    _w(S2, "radius-90", "L11.ex6", 1.652, "radius_with_l1"),  # radius l1 + l2 + l3
    _w(S3, "negative", "L11.ex6", -21.65, "sign_error"),  # reach minus distance
    _w(S1, "metres", "L11.ex6", 0.01602, "unit_factor"),  # in m
    _w(S3, "from-base", "L11.ex6", 14.85, "from_the_base"),  # distance from the base
    # the distance to the shoulder, the radius not subtracted
    _w(S2, "distance-only", "L11.ex6", 91.65, None),
    _r(S3, "reordered", "L11.ex7", [6, 4]),
    _r(S1, "plain", "L11.ex7", [4, 6]),
    _w(S1, "from-0", "L11.ex7", [3, 5], "counted_from_0"),  # V^T's indices
    _w(S2, "q5", "L11.ex7", [5], "cause_for_joints"),  # the joint whose value causes it
    _w(S3, "one", "L11.ex7", [4], "missing"),  # one joint only
    _w(S1, "with-5", "L11.ex7", [4, 5, 6], "extra"),  # joint 5 too
    _w(S2, "example", "L11.ex7", [1, 2], None),  # the example copied
    # ---- lesson 12
    _r(S3, "text", "L12.ex1", ["1/1", "2.5/1 + 1/1", 1]),  # v/a, d/v + v/a, v
    _r(S2, "three-digits", "L12.ex1", [0.467, 3.47, 0.7]),
    _w(S1, "2v-over-a", "L12.ex1", [0.4, 5.2, 0.5], "accel_time_factor"),  # t_a = 2v/a
    _w(S2, "d-over-v", "L12.ex1", [0.4667, 3.0, 0.7], "ramps_forgotten"),  # T = d/v
    # accelerates, then cruises to the end
    _w(S3, "no-braking", "L12.ex1", [1.0, 3.0, 1.0], "not_at_rest_end"),
    # the speed limit ignored: a triangle
    _w(S1, "accel-only", "L12.ex1", [0.9798, 1.96, 2.449], "one_limit"),
    _w(S2, "average", "L12.ex1", [0.4667, 3.467, 0.6058], "average_speed"),  # v_peak = d/T
    _w(S2, "two-digits", "L12.ex1", [0.47, 3.5, 0.7], "too_rounded"),  # 2 significant digits
    # the triangle's formulas
    _r(S1, "text", "L12.ex2", ["sqrt(0.025/2.5)", "2*sqrt(0.025/2.5)", "sqrt(0.025*2.5)"]),
    _r(S3, "plain", "L12.ex2", [0.8, 1.6, 0.8]),
    # the trapezoid's formulas
    _w(S1, "trapezoid", "L12.ex2", [0.2, 0.25, 0.5], "triangle_as_trapezoid"),
    # the trapezoid's formulas
    _w(S3, "trapezoid", "L12.ex2", [1.0, 1.64, 1.0], "triangle_as_trapezoid"),
    _w(S2, "average", "L12.ex2", [0.2334, 0.4668, 0.175], "average_speed"),  # v_peak = d/T
    # accelerates the whole way
    _w(S1, "no-braking", "L12.ex2", [0.1414, 0.1414, 0.3536], "not_at_rest_end"),
    # d = a t_a^2 / 2 for the whole move on each ramp
    _w(S3, "half-forgotten", "L12.ex2", [1.131, 2.263, 1.131], None),
    _w(S2, "two-digits", "L12.ex2", [0.23, 0.47, 0.35], "too_rounded"),  # 2 significant digits
    _r(S2, "text", "L12.ex3", "15/8*1.1/3"),  # 15/8 d/T
    _r(S3, "three-digits", "L12.ex3", 1.27),
    _w(S1, "cubic", "L12.ex3", 0.3, "cubic_quintic_swapped"),  # the cubic's 3/2
    _w(S2, "average", "L12.ex3", 0.3667, "average_speed"),  # d/T
    _w(S3, "cubic", "L12.ex3", 1.02, "cubic_quintic_swapped"),  # the cubic's 3/2
    _w(S3, "peak-accel", "L12.ex3", 1.57, None),  # the peak acceleration
    _w(S1, "two-digits", "L12.ex3", 0.38, "too_rounded"),  # 2 significant digits
    _r(S1, "text", "L12.ex4", "1/(0.5/0.6) + (0.5/0.6)/(1.5/0.8)"),  # 1/V + V/A
    _r(S2, "four-digits", "L12.ex4", 2.033),
    _w(S1, "own", "L12.ex4", [1.45, 1.467, 1.3], "not_synchronized"),  # each joint's own duration
    _w(
        S3, "own", "L12.ex4", [1.265, 1.167, 1.233], "not_synchronized"
    ),  # each joint's own duration
    _w(S1, "slowest", "L12.ex4", 1.467, "mixed_limits"),  # the slowest joint alone
    _w(S2, "slowest", "L12.ex4", 2.0, "mixed_limits"),  # the slowest joint alone
    _w(S3, "slowest", "L12.ex4", 1.265, "mixed_limits"),  # the slowest joint alone
    _w(S1, "largest-move", "L12.ex4", 1.3, "largest_move"),  # the joint with the largest Delta
    _w(S3, "1-over-V", "L12.ex4", 0.8333, "ramps_forgotten"),  # T = 1/V
    _w(S2, "2V-over-A", "L12.ex4", 2.867, "accel_time_factor"),  # t_a = 2V/A
    _w(S2, "sum", "L12.ex4", 4.5, None),  # the joints one after the other
    _r(S3, "plain", "L12.ex5", [3]),
    _r(S2, "tuple", "L12.ex5", (3,)),
    _w(S1, "from-1", "L12.ex5", [4], "counted_from_1"),  # the message's move 4
    _w(S2, "ptp-too", "L12.ex5", [1, 3], "ptp_counted"),  # the PTP to the stretched point too
    _w(S3, "aside-too", "L12.ex5", [3, 5], "extra"),  # the LIN aside too
    _w(S1, "none", "L12.ex5", [], "missing"),  # no move reported
    _w(S3, "from-1-ptp", "L12.ex5", [2, 4], None),  # two slips: counted from 1, the PTP too
    _r(S2, "three-digits", "L12.ex6", 1.07),
    # the formula typed in
    _r(
        S3,
        "text",
        "L12.ex6",
        "0.32*1.504/(0.9*0.7*sin(acos((1.504**2 - 0.81 - 0.49)/(2*0.9*0.7))))",
    ),
    _w(S1, "joint-1", "L12.ex6", 0.5467, "joint_1_speed"),  # |dq1/dt|
    _w(S2, "no-x", "L12.ex6", 0.8336, "x_left_out"),  # x left out
    _w(S3, "L-for-x", "L12.ex6", 1.258, "length_for_x"),  # L for x*
    _w(S1, "cos", "L12.ex6", 1.201, "cos_for_sin"),  # cos q2 for sin q2
    _w(S2, "negative", "L12.ex6", -1.074, "sign_error"),  # the signed value, negative
    _w(S3, "two-digits", "L12.ex6", 1.2, "too_rounded"),  # 2 significant digits
    _w(S1, "v-over-l2", "L12.ex6", 0.35, None),  # v/l2, the tip speed over the last link
]
