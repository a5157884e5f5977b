"""Lesson 12 (trajectories): solutions pass, blanks fail kindly, slips are named, ids differ.

The exercises draw their numbers from the student id (``rc.Assignment``: drawn with
``rc.Variant`` and screened so that every typical slip gives a refused answer). The notebooks run
once per case: the solutions as committed (id ``"demo"``), the solutions under another id
with answers written another right way, the blank exercises, two runs of typical wrong
answers, and the exercises under another id with the demo student's numbers (which must
fail: the numbers follow the id). The demo student's numbers are also worked out here
and compared with what robotconf's programs plan and simulate.
"""

from __future__ import annotations

import ast
import math
import warnings

import nbformat
import numpy as np
import pytest

import robotconf as rc

from .course_support import COURSE, exercise_cells, read_notebook, run_with_answers, solutions_path

LESSON = "12_trajectories"
EXERCISES = COURSE / LESSON / "exercises.ipynb"
VARIABLES = [f"answer_{i}" for i in range(1, 7)]
OTHER_ID = "s1234567"


def _numbers(student: str) -> dict:
    """A student's drawn numbers and right answers, worked out by hand."""
    task = rc.Assignment(LESSON, student)
    d1, v_max, a_max, d2 = task["d1"], task["v_max"], task["a_max"], task["d2"]
    d3, T3 = task["d3"], task["T3"]
    delta, speed, accel = task["delta_4"], task["speed_4"], task["accel_4"]
    own = [
        abs(d) / s + s / a if abs(d) >= s**2 / a else 2 * math.sqrt(abs(d) / a)
        for d, s, a in zip(delta, speed, accel, strict=True)
    ]
    # one law for all joints: u̇ ≤ V = min v/|Δ|, |ü| ≤ A = min a/|Δ|, u from 0 to 1
    V = min(s / abs(d) for d, s in zip(delta, speed, strict=True))
    A = min(a / abs(d) for d, a in zip(delta, accel, strict=True))
    synchronized = 1 / V + V / A if V**2 / A <= 1 else 2 * math.sqrt(1 / A)
    l1, l2 = task["l1"], task["l2"]
    L = l1 + l2
    x_star = task["x_star"]
    cos_q2 = (x_star**2 - l1**2 - l2**2) / (2 * l1 * l2)
    sin_q2 = math.sqrt(1 - cos_q2**2)
    q1 = -math.atan2(l2 * sin_q2, l1 + l2 * cos_q2)  # elbow with q2 > 0
    speed_6 = 0.2 * L
    return {
        "d1": d1,
        "v_max": v_max,
        "a_max": a_max,
        "d2": d2,
        "d3": d3,
        "T3": T3,
        "delta": delta,
        "speed": speed,
        "accel": accel,
        "own": own,
        "l1": l1,
        "l2": l2,
        "x_star": x_star,
        "speed_6": speed_6,
        "answer_1": [v_max / a_max, d1 / v_max + v_max / a_max, v_max],
        "answer_2": [math.sqrt(d2 / a_max), 2 * math.sqrt(d2 / a_max), math.sqrt(d2 * a_max)],
        "answer_3": 15 / 8 * d3 / T3,
        "answer_4": synchronized,
        "answer_6": speed_6 * x_star / (l1 * l2 * sin_q2),
        "qd1_6": abs(speed_6 * math.cos(q1 + math.acos(cos_q2)) / (l1 * sin_q2)),
    }


def _cells_with(numbers: dict) -> dict[str, str]:
    """Answer cells holding a student's right answers as plain numbers."""
    return {
        name: f"{name} = {numbers[name]!r}"
        for name in ("answer_1", "answer_2", "answer_3", "answer_4", "answer_6")
    }


# variable -> (code of a wrong answer cell, words the failure must contain)
WRONG_A = {
    "answer_1": (  # t_a = 2v/a
        "answer_1 = [2 * v_max / a_max, d1 / v_max + 2 * v_max / a_max, v_max]",
        "twice too long",
    ),
    "answer_2": (  # the trapezoid formulas on a move too short to reach v
        "answer_2 = [v_max / a_max, d2 / v_max + v_max / a_max, v_max]",
        "too short to reach the speed limit",
    ),
    "answer_3": ("answer_3 = 3 / 2 * d3 / T3", "These are the cubic's numbers"),
    "answer_4": (  # each joint its own duration
        "answer_4 = [\n"
        "    abs(d) / v + v / a if abs(d) >= v**2 / a else 2 * np.sqrt(abs(d) / a)\n"
        "    for d, v, a in zip(delta_4, speed_4, accel_4)\n"
        "]",
        "Each joint got its own duration",
    ),
    "answer_5": ("answer_5 = [1, 3]", "moves_5[1] is a PTP"),
    "answer_6": (  # joint 1's speed
        "c2 = (x_star**2 - l1**2 - l2**2) / (2 * l1 * l2)\n"
        "q2 = np.arccos(c2)\n"
        "q1 = -np.arctan2(l2 * np.sin(q2), l1 + l2 * c2)\n"
        "answer_6 = abs(v_6 * np.cos(q1 + q2) / (l1 * np.sin(q2)))",
        "That is joint 1's speed",
    ),
}
WRONG_B = {
    "answer_1": (  # accelerates, then cruises to the end: no ramp down
        "answer_1 = [v_max / a_max, d1 / v_max + v_max / (2 * a_max), v_max]",
        "does not come to rest",
    ),
    "answer_2": (  # d = ½·a·t² over the whole distance
        "answer_2 = [np.sqrt(2 * d2 / a_max), 2 * np.sqrt(2 * d2 / a_max), "
        "np.sqrt(2 * d2 * a_max)]",
        "covers only half the distance",
    ),
    "answer_3": ("answer_3 = d3 / T3", "the average speed"),
    "answer_4": (  # the slowest joint's own time: both limits bind on different joints
        "answer_4 = max(\n"
        "    abs(d) / v + v / a if abs(d) >= v**2 / a else 2 * np.sqrt(abs(d) / a)\n"
        "    for d, v, a in zip(delta_4, speed_4, accel_4)\n"
        ")",
        "slower than every joint alone",
    ),
    "answer_5": ("answer_5 = [4]", "Give indices from 0"),
}

# Right answers written another way, run under OTHER_ID (the rest keep the solution's code).
OTHER_RIGHT = {
    "answer_1": (
        'answer_1 = {"v_peak": v_max, "t_total": f"{d1}/{v_max} + {v_max}/{a_max}",'
        ' "t_accel": v_max / a_max}'
    ),
    "answer_2": (  # text with 4 significant digits
        'answer_2 = "[" + ", ".join(f"{x:.4g}" for x in '
        "(np.sqrt(d2 / a_max), 2 * np.sqrt(d2 / a_max), np.sqrt(d2 * a_max))) + ']'"
    ),
    "answer_3": 'answer_3 = f"15/8 * {d3} / {T3}"',
    "answer_4": (  # the one duration, given for every joint
        "V = min(v / abs(d) for d, v in zip(delta_4, speed_4))\n"
        "A = min(a / abs(d) for d, a in zip(delta_4, accel_4))\n"
        "T_4 = 1 / V + V / A if V**2 / A <= 1 else 2 * np.sqrt(1 / A)\n"
        "answer_4 = [T_4, T_4, T_4]"
    ),
    "answer_5": 'answer_5 = "[3]"',
}


def _with_student(path, student_id: str, folder):
    """A copy of the notebook whose student-id cell holds ``student_id``."""
    notebook = read_notebook(path)
    (cell,) = [c for c in notebook.cells if "student-id" in c.metadata.get("tags", [])]
    cell.source = f"student_id = {student_id!r}"
    copy = folder / f"{LESSON}-{path.parent.parent.name}-{student_id}.ipynb"
    nbformat.write(notebook, str(copy))
    return copy


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Each notebook run once, on first use: ``runs(kind)`` → errors by variable."""
    folder = tmp_path_factory.mktemp("lesson_12")
    done: dict[str, dict[str, str]] = {}

    def run(kind: str) -> dict[str, str]:
        if kind not in done:
            if kind == "solutions":
                result = run_with_answers(solutions_path(EXERCISES))
            elif kind == "solutions, other id":
                copy = _with_student(solutions_path(EXERCISES), OTHER_ID, folder)
                result = run_with_answers(copy, OTHER_RIGHT)
            elif kind == "blank":
                result = run_with_answers(EXERCISES)
            elif kind in ("wrong a", "wrong b"):
                wrong = WRONG_A if kind == "wrong a" else WRONG_B
                result = run_with_answers(EXERCISES, {v: code for v, (code, _) in wrong.items()})
            else:  # "demo numbers, other id"
                copy = _with_student(EXERCISES, OTHER_ID, folder)
                result = run_with_answers(copy, _cells_with(_numbers("demo")))
            done[kind] = result
        return done[kind]

    return run


# -- the notebooks' structure and the numbers by hand --------------------------------------


def test_exercises_and_solutions_pair_up():
    exercises, solutions = exercise_cells(EXERCISES), exercise_cells(solutions_path(EXERCISES))
    assert [e.variable for e in exercises] == VARIABLES
    for exercise, solution in zip(exercises, solutions, strict=True):
        assert exercise.check_source == solution.check_source, exercise.variable
        assert exercise.answer_source != solution.answer_source, exercise.variable
        number = exercise.variable.split("_")[1]  # every check through the lesson's checker
        assert f"task.assert_answer({number}, {exercise.variable})" in exercise.check_source
        assert "np.isclose" not in exercise.check_source


@pytest.mark.parametrize(
    "path", [EXERCISES, solutions_path(EXERCISES)], ids=["exercises", "solutions"]
)
def test_one_student_id_cell_feeds_every_assignment(path):
    cells = read_notebook(path).cells
    tagged = [c for c in cells if "student-id" in c.metadata.get("tags", [])]
    assert len(tagged) == 1
    (statement,) = ast.parse(tagged[0].source).body
    assert isinstance(statement, ast.Assign) and statement.value.value == "demo"
    code = "\n".join(c.source for c in cells if c.cell_type == "code")
    assert f'rc.Assignment("{LESSON}", student_id)' in code
    assert code.index("student_id =") < code.index("rc.Assignment(")


def test_demo_numbers_by_hand_agree_with_the_programs():
    n = _numbers("demo")
    # exercises 1–2: a one-joint PTP on the paper robot's joint 3
    robot = rc.preset("paper")
    for d, answer in ((n["d1"], n["answer_1"]), (n["d2"], n["answer_2"])):
        program = rc.Program(
            robot, [rc.PTP(q=[0, 0, d])], joint_speed=n["v_max"], joint_accel=n["a_max"]
        )
        segment = program.segments[0]
        assert program.duration == pytest.approx(answer[1], rel=1e-12)
        assert segment.profile.blend == pytest.approx(answer[0], rel=1e-12)
        assert d * segment.profile.speed == pytest.approx(answer[2], rel=1e-12)
    assert n["d2"] < n["v_max"] ** 2 / n["a_max"]  # exercise 2 is a triangle
    # exercise 3: the quintic's samples peak at 15/8·d/T
    t = np.linspace(0, n["T3"], 4001)
    tau = t / n["T3"]
    assert np.max(30 * n["d3"] * tau**2 * (1 - tau) ** 2 / n["T3"]) == pytest.approx(n["answer_3"])
    # exercise 4: the planner's synchronized duration, and the slip differs from it
    program = rc.Program(
        robot, [rc.PTP(q=n["delta"])], joint_speed=n["speed"], joint_accel=n["accel"]
    )
    assert program.duration == pytest.approx(n["answer_4"], rel=1e-12)
    assert sorted(n["own"])[0] < n["answer_4"] * (1 - 1e-3)
    # the screened numbers: the slowest joint's own time is not the synchronized one
    assert max(n["own"]) < n["answer_4"] * (1 - 5e-3)


def test_demo_joint_speed_by_hand_agrees_with_the_simulation():
    """Exercise 6: |dq2/dt| where the LIN's tip passes x*, from the sampled motion."""
    n = _numbers("demo")
    L = n["l1"] + n["l2"]
    arm = rc.preset("planar_2r", l1=n["l1"], l2=n["l2"])
    moves = [
        rc.PTP(position=[0.55 * L, 0, 0]),
        rc.LIN(position=[0.995 * L, 0, 0], speed=0.2 * L, accel=0.5 * L),
    ]
    program = rc.Program(arm, moves, start=[0.4, 1.4])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the LIN breaks the joint limits: that is the point
        motion = program.simulate(dt=1e-3)
    lin = motion.t >= program.segments[1].start
    x = motion.trace[lin, 0]
    assert np.all(np.diff(x) >= 0)
    measured = np.interp(n["x_star"], x, np.abs(motion.qd[lin, 1]))
    assert measured == pytest.approx(n["answer_6"], rel=1e-4)
    assert measured > 1.0 > np.interp(0.7 * L, x, np.abs(motion.qd[lin, 1]))
    assert np.interp(n["x_star"], x, np.abs(motion.qd[lin, 0])) == pytest.approx(
        n["qd1_6"], rel=1e-4
    )


def test_a_link_length_where_the_tips_x_belongs_is_named():
    """Exercise 6 by hand: q̇2 = v·x*/(l1·l2·sin q2); l1 or l2 (or L) for x* is one slip."""
    task = rc.Assignment("12_trajectories", "demo")
    n = task.numbers
    l1, l2, x, v = n["l1"], n["l2"], n["x_star"], n["v_6"]
    q2 = math.acos((x**2 - l1**2 - l2**2) / (2 * l1 * l2))
    det = l1 * l2 * math.sin(q2)
    assert task.check(6, round(v * x / det, 4)).ok
    for length, words in ((l1, "l1"), (l2, "l2"), (l1 + l2, "length L")):
        result = task.check(6, round(v * length / det, 4))
        assert not result.ok and result.diagnosis == "length_for_x"
        assert words in result.hints[0]


def test_another_student_gets_other_numbers():
    demo, other = _numbers("demo"), _numbers(OTHER_ID)
    for name in ("answer_1", "answer_2", "answer_3", "answer_4", "answer_6"):
        assert demo[name] != other[name], name


# -- the notebooks run --------------------------------------------------------------------


def test_solutions_pass(runs):
    assert runs("solutions") == dict.fromkeys(VARIABLES, "")


def test_another_student_passes_with_their_own_right_answers(runs):
    assert runs("solutions, other id") == dict.fromkeys(VARIABLES, "")


def test_blank_exercises_fail_kindly(runs):
    errors = runs("blank")
    for variable in VARIABLES:
        number = variable.split("_")[1]
        assert f"AssertionError: Exercise {number} is not answered yet" in errors[variable]
        assert "InvalidInputError" not in errors[variable]


def test_the_demo_students_numbers_fail_for_another_student(runs):
    errors = runs("demo numbers, other id")
    for variable in _cells_with(_numbers("demo")):
        assert "AssertionError" in errors[variable], errors[variable]
        assert "not answered yet" not in errors[variable]


@pytest.mark.parametrize("kind", ["wrong a", "wrong b"])
def test_typical_wrong_answers_get_the_right_hint(runs, kind):
    wrong = WRONG_A if kind == "wrong a" else WRONG_B
    errors = runs(kind)
    for variable, (_, words) in wrong.items():
        assert errors[variable].startswith("AssertionError"), errors[variable]
        assert words in errors[variable], errors[variable]
    if kind == "wrong a":  # no hint quotes the demo student's right numbers
        n = _numbers("demo")
        shown = "".join(errors[v] for v in ("answer_1", "answer_2", "answer_3", "answer_4"))
        right = [*n["answer_1"], *n["answer_2"], n["answer_3"], n["answer_4"]]
        assert not [x for x in right if f"{x:.4g}" in shown], shown
