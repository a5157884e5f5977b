"""Lessons 9 (DH frame assignment) and 10 (the paper's lab): checks, hints, per-student numbers.

Each lesson's exercises draw their numbers from the student id (``rc.Variant``), typed in
the one cell tagged ``student-id``. The notebooks run a few times each: the solutions as
committed (id ``"demo"``), the solutions under another id with some answers written
another right way, the blank exercises, the exercises with typical wrong answers, and the
exercises under another id with the demo student's numbers (which must fail: the numbers
follow the id).
"""

from __future__ import annotations

import ast

import nbformat
import numpy as np
import pytest

import robotconf as rc
from robotconf.teaching.exercises import registered

from .course_support import COURSE, exercise_cells, read_notebook, run_with_answers, solutions_path

DH = "09_dh_frame_assignment"
LAB = "10_paper_lab"
LESSONS = (DH, LAB)
OTHER_ID = "s1234567"

# lesson -> {answer variable: (code of a wrong answer cell, words the hint must contain)}
WRONG_ANSWERS: dict[str, dict[str, tuple[str, str]]] = {
    DH: {
        # a and d exchanged: the link length read along z
        "answer_1": ('answer_1 = [("q1", l1, 0, 0), ("q2", 0, l2, 0)]', "look swapped"),
        # the twist turning z0 onto -y: joint 2 would turn backwards
        "answer_2": (
            'answer_2 = [("q1 + pi/2", h, 0, "-pi/2"), ("q2", 0, u, 0), ("q3", 0, f, 0)]',
            "check the sign of α1",
        ),
        # no quarter turn between x1 and x2: the radial slide points along y
        "answer_3": (
            'answer_3 = [("q1", 0, 0, 0), (0, f"q2 + {h3}", 0, "pi/2"), (0, f"q3 + {e}", 0, 0)]',
            "check the constant in θ2",
        ),
        # the standard table of exercise 2 where the modified one is asked
        "answer_4": (
            'answer_4 = [("q1 + pi/2", h, 0, "pi/2"), ("q2", 0, u, 0), ("q3", 0, f, 0)]',
            "asks for the modified convention",
        ),
    },
    LAB: {
        # the calculator fed degrees
        "answer_1": (
            "q_deg = np.degrees(q_star)\n"
            "reach = l2 * np.cos(q_deg[1]) + l3 * np.cos(q_deg[1] + q_deg[2])\n"
            "answer_1 = [np.cos(q_deg[0]) * reach, np.sin(q_deg[0]) * reach,"
            " l1 - l2 * np.sin(q_deg[1]) - l3 * np.sin(q_deg[1] + q_deg[2])]",
            "angles in degrees fed to sin and cos",
        ),
        # the mean taken as the midpoint of max and min
        "answer_2": ("answer_2 = [0, -l3, -l3 / 2]", "not (max + min)/2"),
        # dp/dq3 without the factor dq3/dt = A/T
        "answer_3": (
            "q3_now = A * (t3 % T) / T\nanswer_3 = [-l3 * np.sin(q3_now), 0, -l3 * np.cos(q3_now)]",
            "You left out dq3/dt",
        ),
        # the centripetal term alone, as on the sawtooth's ramps
        "answer_4": (
            "w4 = 2 * np.pi * f4\n"
            "q, qd = B * np.sin(w4 * t4), B * w4 * np.cos(w4 * t4)\n"
            "answer_4 = l3 * np.array([-np.cos(q), 0, np.sin(q)]) * qd**2",
            "Only the centripetal term",
        ),
        # the central difference where Simulink's backward one is asked
        "answer_5": (
            "answer_5 = l3 * (np.cos(A * dt5 / T) - np.cos(A * (T - dt5) / T)) / (2 * dt5)",
            "That is the central difference",
        ),
    },
}

# Right answers written another way, run under OTHER_ID (the others keep the solution's code).
OTHER_RIGHT_ANSWERS: dict[str, dict[str, str]] = {
    DH: {
        "answer_1": 'answer_1 = f"[[q1, 0, {l1}, 0], [q2, 0, {l2}, 0]]"',  # text
        # x1 = -y instead of +y: θ1 a quarter turn the other way, the twist -π/2, θ2 + π
        "answer_2": (
            'answer_2 = [("q1 - pi/2", h, 0, "-pi/2"), ("q2 + pi", 0, u, 0), ("q3", 0, f, 0)]'
        ),
        # the slide height in row 1 (z0 and z1 are one line), θ2 = -π/2 with α2 = -π/2
        "answer_3": (
            'answer_3 = [("q1", h3, 0, 0), ("-pi/2", "q2", 0, "-pi/2"), (0, f"q3 + {e}", 0, 0)]'
        ),
        "answer_4": 'answer_4 = [("q1 + pi/2", h, 0, 0), ("q2", 0, 0, 1.5708), ("q3", 0, u, 0)]',
    },
    LAB: {
        "answer_1": (  # text with three decimals
            "reach = l2 * np.cos(q_star[1]) + l3 * np.cos(q_star[1] + q_star[2])\n"
            "p = [np.cos(q_star[0]) * reach, np.sin(q_star[0]) * reach,"
            " l1 - l2 * np.sin(q_star[1]) - l3 * np.sin(q_star[1] + q_star[2])]\n"
            'answer_1 = "[" + ", ".join(f"{x:.3f}" for x in p) + "]"'
        ),
        "answer_2": 'answer_2 = f"[0, {-l3}, {-l3 * (1 - np.cos(A)) / A:.3f}]"',  # text, rounded
    },
}


def _exercises(lesson: str):
    return COURSE / lesson / "exercises.ipynb"


def _with_student(path, student_id: str, folder) -> object:
    """A copy of the notebook whose student-id cell holds ``student_id``."""
    notebook = read_notebook(path)
    (cell,) = [c for c in notebook.cells if "student-id" in c.metadata.get("tags", [])]
    cell.source = f"student_id = {student_id!r}"
    copy = folder / f"{path.parent.name}-{student_id}.ipynb"
    nbformat.write(notebook, str(copy))
    return copy


def _numbers_of(lesson: str, student: str = "demo") -> dict[str, str]:
    """A student's right answers as plain numbers (what a copied notebook would hold)."""
    task = rc.Assignment(lesson, student)
    if lesson == DH:
        l1, l2, h, u, f = (task[name] for name in ("l1", "l2", "h", "u", "f"))
        return {
            "answer_1": f'answer_1 = [("q1", 0, {l1}, 0), ("q2", 0, {l2}, 0)]',
            "answer_2": (
                f'answer_2 = [("q1 + pi/2", {h}, 0, "pi/2"), ("q2", 0, {u}, 0), ("q3", 0, {f}, 0)]'
            ),
        }
    l1, l2, l3, a, q = (task[name] for name in ("l1", "l2", "l3", "A", "q_star"))
    reach = l2 * np.cos(q[1]) + l3 * np.cos(q[1] + q[2])
    z = l1 - l2 * np.sin(q[1]) - l3 * np.sin(q[1] + q[2])
    p = [np.cos(q[0]) * reach, np.sin(q[0]) * reach, z]
    return {
        "answer_1": f"answer_1 = {[round(float(x), 4) for x in p]}",
        "answer_2": f"answer_2 = [0, {-l3}, {round(-l3 * (1 - np.cos(a)) / a, 4)}]",
    }


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Each notebook run once, on first use: ``runs(kind, lesson)`` → errors by variable."""
    folder = tmp_path_factory.mktemp("lessons_9_10")
    done: dict[tuple[str, str], dict[str, str]] = {}

    def run(kind: str, lesson: str) -> dict[str, str]:
        if (kind, lesson) not in done:
            exercises = _exercises(lesson)
            if kind == "solutions":
                result = run_with_answers(solutions_path(exercises))
            elif kind == "solutions, other id":
                copy = _with_student(solutions_path(exercises), OTHER_ID, folder)
                result = run_with_answers(copy, OTHER_RIGHT_ANSWERS[lesson])
            elif kind == "blank":
                result = run_with_answers(exercises)
            elif kind == "wrong":
                answers = {v: code for v, (code, _) in WRONG_ANSWERS[lesson].items()}
                result = run_with_answers(exercises, answers)
            else:  # "demo numbers, other id"
                copy = _with_student(exercises, OTHER_ID, folder)
                result = run_with_answers(copy, _numbers_of(lesson))
            done[(kind, lesson)] = result
        return done[(kind, lesson)]

    return run


@pytest.mark.parametrize("lesson", LESSONS)
def test_exercises_and_solutions_match(lesson):
    exercises = exercise_cells(_exercises(lesson))
    solutions = exercise_cells(solutions_path(_exercises(lesson)))
    assert 4 <= len(exercises) <= 5
    assert sorted(WRONG_ANSWERS[lesson]) == [e.variable for e in exercises]
    for exercise, solution in zip(exercises, solutions, strict=True):
        assert exercise.check_source == solution.check_source, exercise.variable
        assert exercise.answer_source != solution.answer_source, exercise.variable


NOTEBOOKS = [_exercises(n) for n in LESSONS] + [solutions_path(_exercises(n)) for n in LESSONS]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: f"{p.parent.parent.name}/{p.parent.name}")
def test_one_student_id_cell_feeds_every_assignment(path):
    """The contract the answer-key exporter relies on."""
    cells = read_notebook(path).cells
    tagged = [c for c in cells if "student-id" in c.metadata.get("tags", [])]
    assert len(tagged) == 1
    (statement,) = ast.parse(tagged[0].source).body
    assert isinstance(statement, ast.Assign) and statement.targets[0].id == "student_id"
    assert statement.value.value == "demo"
    code = "\n".join(c.source for c in cells if c.cell_type == "code")
    lesson = path.parent.name
    assert f'rc.Assignment("{lesson}", student_id)' in code
    assert code.index("student_id =") < code.index("rc.Assignment(")


@pytest.mark.parametrize("lesson", LESSONS)
def test_solutions_pass(runs, lesson):
    errors = runs("solutions", lesson)
    assert len(errors) == len(WRONG_ANSWERS[lesson])
    assert not any(errors.values()), errors


@pytest.mark.parametrize("lesson", LESSONS)
def test_another_student_passes_with_their_own_right_answers(runs, lesson):
    errors = runs("solutions, other id", lesson)
    assert len(errors) == len(WRONG_ANSWERS[lesson])
    assert not any(errors.values()), errors


@pytest.mark.parametrize("lesson", LESSONS)
def test_the_demo_students_numbers_fail_for_another_student(runs, lesson):
    demo, other = _numbers_of(lesson), _numbers_of(lesson, OTHER_ID)
    assert all(demo[variable] != other[variable] for variable in demo), (demo, other)
    errors = runs("demo numbers, other id", lesson)
    for variable in demo:
        assert "AssertionError" in errors[variable], errors[variable]
        assert "not answered yet" not in errors[variable]


@pytest.mark.parametrize("lesson", LESSONS)
def test_blank_exercises_fail_kindly(runs, lesson):
    errors = runs("blank", lesson)
    assert len(errors) == len(WRONG_ANSWERS[lesson])
    for variable, error in errors.items():
        number = variable.split("_")[1]
        assert f"AssertionError: Exercise {number} is not answered yet" in error, error


@pytest.mark.parametrize(
    ("lesson", "variable"), [(n, v) for n in LESSONS for v in WRONG_ANSWERS[n]]
)
def test_typical_wrong_answer_gets_the_right_hint(runs, lesson, variable):
    error = runs("wrong", lesson)[variable]
    _, words = WRONG_ANSWERS[lesson][variable]
    assert "AssertionError" in error, error
    assert words in error, error


def test_lab_numbers_by_hand_match_the_paper_case():
    """The lab's formulas, at the paper's own numbers (l = 20, 30, 40; A = T = 2)."""
    robot = rc.preset("paper")
    saw = rc.signals.RepeatingSequence(times=[0, 2], values=[0, 2])
    lab = rc.simulate(robot, {"q3": saw}, t_end=6.0, dt=1e-4)
    z = lab.stats().loc[("EE", "displacement", "z")]
    assert z["max"] == 0 and np.isclose(z["min"], -40, atol=1e-6)
    assert np.isclose(z["mean"], -40 * (1 - np.cos(2)) / 2, rtol=1e-3)  # -28.32 mm
    backward = rc.simulate(robot, {"q3": saw}, t_end=4.0, dt=1e-3, method="backward")
    assert np.isclose(backward.velocity[2000, 3, 0], 40 * (1 - np.cos(2 * 1.999 / 2)) / 1e-3)


def test_the_lab_asks_for_x_y_z_not_the_homogeneous_point():
    """The paper's arm (l = 20, 30, 40 mm) at q = 0: by hand p = (l2 + l3, 0, l1) =
    (70, 0, 20). Exercise 1 asks for [x, y, z]: [70, 0, 20, 1] has the right numbers in
    another answer's shape, and is named as the homogeneous coordinate."""
    exercise = registered(LAB)[0]
    numbers = {"robot": rc.preset("paper"), "q_star": [0.0, 0.0, 0.0]}
    assert exercise.check([70, 0, 20], numbers).ok
    for four in ([70, 0, 20, 1], "[70, 0, 20, 1]"):
        result = exercise.check(four, numbers)
        assert not result.ok and result.diagnosis == "homogeneous_coordinate", result
        assert "drop the homogeneous coordinate 1" in result.hints[0]
    assert not exercise.accepts([70, 0, 20, 1], numbers)  # the fast rule agrees
    assert exercise.check([70, 0, 25, 1], numbers).diagnosis != "homogeneous_coordinate"


def test_the_lab_names_a_calculator_in_degree_mode_and_an_upward_displacement():
    """The paper's arm (l3 = 40 mm), A = T = 2: by hand the z displacement's mean is
    -40·(1 − cos 2)/2 = -28.32 mm; with the calculator in degree mode cos 2° makes it
    -40·(1 − cos 2°)/2 = -0.01218 mm. Measured upward the statistics are [40, 0, 28.32].
    The spike (dt = 0.1 s) in degree mode: 40·(1 − cos 1.9°)/0.1 = 0.2199 mm/s. The
    acceleration with B = 1 rad, f = 0.25 Hz at t4 = 1 s in degree mode: q3 = sin(π/2 °)
    = 0.02741, q3' = (π/2)·cos(π/2 °) = 1.5702, q3'' = -(π²/4)·0.02741 = -0.06763, so
    a = 40·((−cos q3°, 0, sin q3°)·q3'² + (−sin q3°, 0, −cos q3°)·q3'') = (-98.62, 0, 2.753)."""
    robot = rc.preset("paper")
    numbers = {
        "robot": robot,
        "l3": 40.0,
        "A": 2.0,
        "T": 2.0,
        "saw": rc.signals.RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0)),
        "B": 1.0,
        "f4": 0.25,
        "t4": 1.0,
        "wave": rc.signals.Sine(amplitude=1.0, frequency=0.25),
        "dt5": 0.1,
    }
    statistics, acceleration, spike = (registered(LAB)[k] for k in (1, 3, 4))
    assert statistics.check([0, -40, -40 * (1 - np.cos(2)) / 2], numbers).ok
    for answer, code in (
        ([0, -40, -0.01218], "radians_as_degrees"),
        ([40, 0, 28.32], "sign_flipped"),
        ([-40, 0, -28.32], "swapped_components"),  # max and min exchanged
    ):
        assert statistics.check(answer, numbers).diagnosis == code, answer
    assert spike.check(0.2199, numbers).diagnosis == "radians_as_degrees"
    assert acceleration.check([-98.62, 0, 2.753], numbers).diagnosis == "radians_as_degrees"


def test_the_lab_velocity_names_radians_typed_into_a_degree_mode_calculator():
    """Student s2041: l3 = 35, A = 2, T = 3, t3 = 3.9 s, so q3 = 2·0.9/3 = 0.6 rad and
    dq3/dt = 2/3. By hand v = l3·(−sin q3, 0, −cos q3)·dq3/dt; in degree mode sin 0.6° =
    0.010472 and cos 0.6° = 0.999945 give (−0.2443, 0, −23.33)."""
    task = rc.Assignment(LAB, "s2041")
    rate, q3 = 2 / 3, 0.6
    assert task.check(3, [-35 * np.sin(q3) * rate, 0, -35 * np.cos(q3) * rate]).ok
    result = task.check(3, [-0.2443, 0.0, -23.33])
    assert result.diagnosis == "degrees_in_sin" and "degree mode" in result.hints[0]


def test_the_drop_of_the_scope_exercise_falls_on_a_sample_for_every_student():
    """Exercise 5 reads the backward difference at t = T: T must be a whole number of
    samples dt (T = 2.5 s with dt = 0.2 s would put no sample on the drop)."""
    for k in range(200):
        n = rc.Assignment(LAB, f"s{k:05d}").numbers
        samples = n["T"] / n["dt5"]
        assert samples == pytest.approx(round(samples), abs=1e-9), (k, n["T"], n["dt5"])
