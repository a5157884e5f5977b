"""Lesson 13 (the work cell): solutions pass, blanks fail kindly, slips are named, ids differ.

The exercises draw their numbers from the student id (``rc.Assignment``, screened so that
every typical slip gives a refused answer). Each right answer is worked out here by hand
and compared with what the cell computes — ``cell.pose_of``, ``cell.reach``,
``cell.place``, ``cell.check``, ``rc.locate_frame`` — for the demo student and for a
sweep of ids. The notebooks run once per case: the solutions as committed, the solutions
under another id with answers written another right way, the blank exercises, two runs
of typical wrong answers, the demo student's numbers under another id (which must fail),
and answer cells that ask the cell for the answer (which a graded copy flags).
"""

from __future__ import annotations

import ast

import nbformat
import numpy as np
import pytest

import robotconf as rc
from robotconf.grading import robotconf_calls

from .course_support import COURSE, exercise_cells, read_notebook, run_with_answers, solutions_path

LESSON = "13_work_cell"
EXERCISES = COURSE / LESSON / "exercises.ipynb"
VARIABLES = [f"answer_{i}" for i in range(1, 6)]
OTHER_ID = "s1234567"
NEAREST = np.sqrt(30**2 + 40**2 - 2 * 30 * 40 * np.cos(np.radians(45)))  # mm
IDS = [f"student-{i:03d}" for i in range(0, 200, 8)]


def _wall_cell(task) -> tuple:
    """Exercise 4's cell and program, built as the notebook builds them."""
    cell = rc.Cell(unit="mm")
    cell.add(rc.Box([320, 200, 10], pose=rc.pose([0, 0, -5]), name="table"))
    cell.add_robot("arm", rc.preset("paper"), mount="table")
    cell.add(rc.Box([10, 40, 50], pose=rc.pose([task["wall_x"] + 5, 0, 25]), name="wall"))
    branches = rc.ik_all(cell.robot("arm"), [task["x0_4"], 0, 20])
    moves = [
        rc.Wait(task["wait_4"]),
        rc.LIN(position=[66, 0, 20], speed=task["v_4"], accel=task["a_4"]),
    ]
    start = branches.q[branches.within_limits][0]
    return cell, rc.Program(cell.robot("arm"), moves, start=start)


def _bare_cell():
    """The arm on its table, nothing else (exercise 2's cell)."""
    cell = rc.Cell(unit="mm")
    cell.add(rc.Box([320, 200, 10], pose=rc.pose([0, 0, -5]), name="table"))
    cell.add_robot("arm", rc.preset("paper"), mount="table")
    return cell


def _numbers(student: str) -> dict:
    """A student's drawn numbers and right answers, worked out by hand."""
    task = rc.Assignment(LESSON, student)
    psi, (a, b), h = task["table_yaw"], task["pick_ab"], task["table_size"][2]
    pick = [
        task["table_xy"][0] + np.cos(psi) * a - np.sin(psi) * b,
        task["table_xy"][1] + np.sin(psi) * a + np.cos(psi) * b,
        task["table_z"] + h / 2,
    ]
    distances = [np.linalg.norm(np.subtract(p, [0, 0, 20])) for p in task["targets_2"]]
    x_t, _, z_t = task["target_3"]
    base = x_t - np.sign(x_t) * np.sqrt(70**2 - (z_t - 20) ** 2)
    contact = task["wait_4"] + (task["wall_x"] - 3.6 - task["x0_4"]) / task["v_4"]
    contact += task["v_4"] / (2 * task["a_4"])
    measured = np.array(task["measured_5"])
    x_hat = (measured[1] - measured[0]) / np.linalg.norm(measured[1] - measured[0])
    y_hat = (measured[2] - measured[0]) / np.linalg.norm(measured[2] - measured[0])
    return {
        "task": task,
        "answer_1": pick,
        "answer_2": [k for k, d in enumerate(distances) if NEAREST <= d <= 70],
        "answer_3": float(base),
        "answer_4": float(contact),
        "answer_5": (measured[0] - 20 * x_hat - 20 * y_hat).tolist(),
    }


def _cells_with(numbers: dict) -> dict[str, str]:
    """Answer cells holding a student's right answers as plain numbers."""
    return {name: f"{name} = {numbers[name]!r}" for name in VARIABLES}


# variable -> (code of a wrong answer cell, words the failure must contain)
WRONG_A = {
    "answer_1": (  # the box's centre taken for its top
        "a, b = pick_ab\n"
        "answer_1 = [table_xy[0] + np.cos(psi) * a - np.sin(psi) * b,\n"
        "            table_xy[1] + np.sin(psi) * a + np.cos(psi) * b, table_z]",
        "half its thickness",
    ),
    "answer_2": (  # within 70 mm of the shoulder, the joint limits left aside
        "answer_2 = [k for k, p in enumerate(targets_2)\n"
        "            if np.linalg.norm(np.subtract(p, [0, 0, 20])) <= 70]",
        "the elbow folds by at most 135°",
    ),
    "answer_3": (  # the reach measured from the base
        "x_T, _, z_T = target_3\nanswer_3 = x_T - np.sign(x_T) * np.sqrt(70**2 - z_T**2)",
        "20 mm above the base",
    ),
    "answer_4": (  # counted from the LIN's start
        "answer_4 = (wall_x - 3.6 - x0_4) / v_4 + v_4 / (2 * a_4)",
        "the wait before the LIN counts",
    ),
    "answer_5": (  # the centroids matched without the rotation
        "answer_5 = measured_5.mean(axis=0) - nominal_5.mean(axis=0)",
        "only after the rotation",
    ),
}
WRONG_B = {
    "answer_1": (  # the point in the table's frame, turned, without the table's position
        "a, b = pick_ab\n"
        "answer_1 = [np.cos(psi) * a - np.sin(psi) * b, np.sin(psi) * a + np.cos(psi) * b,\n"
        "            table_size[2] / 2]",
        "add the table's position",
    ),
    "answer_3": (  # the base moved away from the target
        "x_T, _, z_T = target_3\n"
        "answer_3 = -(x_T - np.sign(x_T) * np.sqrt(70**2 - (z_T - 20) ** 2))",
        "wrong sign",
    ),
    "answer_4": (  # the time in samples of 0.01 s
        "answer_4 = 100 * (wait_4 + (wall_x - 3.6 - x0_4) / v_4 + v_4 / (2 * a_4))",
        "give seconds",
    ),
    "answer_5": ("answer_5 = measured_5[0]", "20 mm in from both edges"),
}

# Right answers written another way, run under OTHER_ID (the rest keep the solution's code).
OTHER_RIGHT = {
    "answer_1": (  # through the cell itself is a shortcut; a homogeneous matrix is not
        "T = np.eye(4)\n"
        "T[:2, :2] = [[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]]\n"
        "T[:3, 3] = [*table_xy, table_z]\n"
        "answer_1 = (T @ [*pick_ab, table_size[2] / 2, 1])[:3]"
    ),
    "answer_3": 'answer_3 = f"{target_3[0]} - {np.sign(target_3[0])} * '
    '(70**2 - ({target_3[2]} - 20)**2)**0.5"',
    "answer_4": "answer_4 = round(wait_4 + (wall_x - 3.6 - x0_4) / v_4 + v_4 / (2 * a_4), 3)",
}
# Answers asked of robotconf (a graded copy flags them).
SHORTCUTS = {
    "answer_2": "answer_2 = [int(k) for k in np.flatnonzero("
    'cell_4.reach("arm", targets_2).reachable)]',
    "answer_5": "answer_5 = rc.locate_frame(measured_5, nominal_5).pose[:3, 3]",
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
    folder = tmp_path_factory.mktemp("lesson_13")
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
        number = exercise.variable.split("_")[1]
        assert f"task.assert_answer({number}, {exercise.variable})" in exercise.check_source


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


@pytest.mark.parametrize("student", ["demo", OTHER_ID])
def test_the_answers_by_hand_are_the_assignments(student):
    n = _numbers(student)
    for number in range(1, 6):
        assert n["task"].check(number, n[f"answer_{number}"]).ok, number
    assert n["task"].answer(2) == n["answer_2"]


@pytest.mark.parametrize("student", ["demo", *IDS])
def test_the_answers_by_hand_agree_with_the_cell(student):
    """What the cell computes: the frame on the table, reach, the base, the contact, the fit."""
    n = _numbers(student)
    task = n["task"]
    # 1: a frame on the table, through the cell's parents
    cell = rc.Cell(unit="mm")
    table_pose = rc.pose([*task["table_xy"], task["table_z"]], [0, 0, task["table_yaw"]])
    cell.add(rc.Box(task["table_size"], pose=table_pose, name="table"))
    cell.add_frame("pick", rc.pose([*task["pick_ab"], task["table_size"][2] / 2]), parent="table")
    assert np.allclose(cell.pose_of("table/pick")[:3, 3], n["answer_1"], atol=1e-9)
    # 2: reach in the lesson's cell (distance and limits decide; no hidden collision)
    assert (
        np.flatnonzero(_bare_cell().reach("arm", task["targets_2"]).reachable).tolist()
        == (n["answer_2"])
    )
    # 3: just outside the base position the target is out of reach, just inside within
    rail = rc.Cell(unit="mm")
    rail.add(rc.Box([400, 120, 10], pose=rc.pose([0, 0, -5]), name="rail"))
    rail.add_robot("arm", rc.preset("paper"), mount="rail")
    toward = np.sign(task["target_3"][0])
    for shift, reached in ((-0.05, False), (0.05, True)):
        rail.set_pose("arm", rc.pose([n["answer_3"] + toward * shift, 0, 0]))
        assert bool(rail.reach("arm", [task["target_3"]]).reachable[0]) is reached, shift
    # 4: cell.check's first contact is the first sample at or after the exact time
    cell_4, program_4 = _wall_cell(task)
    contact = cell_4.check(program_4, dt=0.01).contacts[0]
    assert (contact.other, contact.move, contact.move_kind) == ("wall", 2, "LIN")
    assert n["answer_4"] - 1e-9 <= contact.start < n["answer_4"] + 0.01 + 1e-9
    # 5: the fitted frame's origin
    fit = rc.locate_frame(task["measured_5"], task["nominal_5"])
    assert np.allclose(fit.pose[:3, 3], n["answer_5"], atol=1e-9)
    assert np.max(np.abs(fit.residuals)) < 1e-9


def test_the_reach_rule_is_what_the_cell_finds_for_200_ids():
    """Exercise 2's answer is the rule (distance and joint limits); no drawn target is
    hidden by a collision, so cell.reach agrees with it for every id."""
    cell = _bare_cell()
    for i in range(200):
        task = rc.Assignment(LESSON, f"student-{i:03d}")
        found = np.flatnonzero(cell.reach("arm", task["targets_2"]).reachable).tolist()
        assert found == task.answer(2), (i, task["targets_2"])


def test_the_base_from_cell_place_agrees():
    n = _numbers("demo")
    target = n["task"]["target_3"]
    rail = rc.Cell(unit="mm")
    rail.add(rc.Box([400, 120, 10], pose=rc.pose([0, 0, -5]), name="rail"))
    rail.add_robot("arm", rc.preset("paper"), mount="rail")
    plan = rail.place("arm", [target], [(-150, 0, 0), (150, 0, 0)], step=1)
    good = plan.positions[plan.feasible][:, 0]
    nearest = good[np.argmin(np.abs(good))]
    assert abs(nearest - n["answer_3"]) < 1.0
    assert abs(nearest) >= abs(n["answer_3"])


def test_another_student_gets_other_numbers():
    demo, other = _numbers("demo"), _numbers(OTHER_ID)
    for name in ("answer_1", "answer_3", "answer_4", "answer_5"):
        assert not np.allclose(demo[name], other[name]), name


def test_a_cell_call_in_an_answer_cell_is_a_shortcut():
    names = {"np": np, "rc": rc, "cell_4": _bare_cell()}
    assert robotconf_calls(SHORTCUTS["answer_2"], names) == ["cell_4.reach"]
    assert robotconf_calls(SHORTCUTS["answer_5"], names) == ["rc.locate_frame"]


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
    for variable in VARIABLES:
        assert "AssertionError" in errors[variable], errors[variable]
        assert "not answered yet" not in errors[variable]


@pytest.mark.parametrize("kind", ["wrong a", "wrong b"])
def test_typical_wrong_answers_get_the_right_hint(runs, kind):
    wrong = WRONG_A if kind == "wrong a" else WRONG_B
    errors = runs(kind)
    for variable, (_, words) in wrong.items():
        assert errors[variable].startswith("AssertionError"), errors[variable]
        assert words in errors[variable], errors[variable]
