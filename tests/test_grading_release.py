"""``robotconf course release`` and ``robotconf course key``: nbgrader metadata and the key.

The release of lesson 01 is read back as JSON and checked cell by cell against the
course's own notebooks (found by their tags); the student version is made by the same
rules as nbgrader's ``ClearSolutions``/``ClearHiddenTests`` (re-implemented here, so the
check does not need nbgrader). The key's values are compared with hand-derived matrices
and, for a lesson with per-student numbers, with ``rc.Variant`` computed here.
"""

from __future__ import annotations

import ast
import json
import re
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

import robotconf as rc
from robotconf.cli import main
from robotconf.grading import answer_key, find_exercises, read_notebook, release_course
from robotconf.grading._notebook_cells import cell_source, cell_tags

COURSE = Path(__file__).resolve().parents[1] / "course"
LESSON = "01_homogeneous_transforms"
VARIANT_LESSON = "90_variant_lab"


# -- a small course with per-student numbers --------------------------------------------


def _cell(kind: str, source: str, tags: tuple[str, ...] = ()) -> dict:
    cell = {"cell_type": kind, "metadata": {}, "source": source}
    if tags:
        cell["metadata"]["tags"] = list(tags)
    if kind == "code":
        cell.update(outputs=[], execution_count=None)
    return cell


def _notebook(cells: list[dict]) -> dict:
    return {
        "cells": [dict(c, id=f"c{i:02d}") for i, c in enumerate(cells)],
        "metadata": {
            "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"}
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }


def variant_l2(student_id: str) -> float:
    """The length l2 the variant lab draws for a student (computed here, not in a kernel)."""
    return rc.Variant(student_id, VARIANT_LESSON).length("l2", 20, 60, step=5)


def variant_course(root: Path) -> Path:
    """A course of one lesson whose exercise depends on the student id.

    One Rz module with a = (l2, 0, 0) and the end-effector point (10, 0, 0): at q = 0 the
    end-effector is at (l2 + 10, 0, 0), with l2 drawn per student.
    """
    setup = (
        "import robotconf as rc\n\n"
        f'variant = rc.Variant(student_id, "{VARIANT_LESSON}")\n'
        'l2 = variant.length("l2", 20, 60, step=5)\n'
        'arm = rc.Robot([rc.Module("Rz", a=(l2, 0, 0))], end_effector=(10, 0, 0))'
    )
    check = (
        'assert answer_1 is not None, "Exercise 1 is not answered yet."\n'
        'rc.assert_matrix(answer_1, rc.expected_matrix(arm, "p_EE", q=[0]))'
    )

    def cells(answer: str, title: str, check_tags: tuple[str, ...]) -> list[dict]:
        return [
            _cell("markdown", f"# {title}"),
            _cell("code", 'student_id = "demo"  # your student id', ("student-id",)),
            _cell("code", setup),
            _cell("markdown", "### Exercise 1\n\nWhere is the end-effector at q = 0?"),
            _cell("code", answer, ("answer",)),
            _cell("code", check, check_tags),
        ]

    for folder, answer, title, tags in (
        (root / "course" / "solutions", "answer_1 = [l2 + 10, 0, 0]", "Lab (solutions)", ()),
        (root / "course", "answer_1 = None  # your position", "Lab", ("raises-exception",)),
    ):
        path = folder / VARIANT_LESSON / "exercises.ipynb"
        path.parent.mkdir(parents=True)
        notebook = _notebook(cells(answer, title, ("check", *tags)))
        path.write_text(json.dumps(notebook, indent=1), encoding="utf-8")
    return root / "course"


# -- the release of lesson 01 -----------------------------------------------------------


@pytest.fixture(scope="module")
def released(tmp_path_factory):
    out = tmp_path_factory.mktemp("nbgrader")
    release = release_course(out, COURSE, "01")
    notebook = read_notebook(out / "source" / LESSON / f"{LESSON}.ipynb")
    return out, release, notebook


def _meta(cell: dict) -> dict:
    return cell["metadata"]["nbgrader"]


def _solution_region(source: str) -> str:
    match = re.search(r"### BEGIN SOLUTION\n(.*)\n### END SOLUTION", source, re.S)
    assert match, source
    return match.group(1)


def test_the_release_writes_the_nbgrader_tree(released):
    out, release, _ = released
    assert release.assignments == [LESSON]
    assert (out / "source" / LESSON / f"{LESSON}.ipynb").is_file()
    assert sorted(p.name for p in out.iterdir()) == ["README.md", "nbgrader_config.py", "source"]
    # Nothing outside source/ holds a solution.
    assert "[[0, 1, 0, 10]" not in (out / "README.md").read_text(encoding="utf-8")


def test_answer_cells_hold_the_solution_between_markers(released):
    _, _, notebook = released
    solutions = read_notebook(COURSE / "solutions" / LESSON / "exercises.ipynb")
    exercises = find_exercises(notebook)
    assert [e.variable for e in exercises] == ["answer_1", "answer_2", "answer_3", "answer_4"]
    for exercise, original in zip(exercises, find_exercises(solutions), strict=True):
        cell = notebook["cells"][exercise.answer_index]
        assert _meta(cell) == {
            "grade": False,
            "grade_id": exercise.variable,
            "locked": False,
            "schema_version": 3,
            "solution": True,
        }
        source = cell_source(cell)
        solution = cell_source(solutions["cells"][original.answer_index]).strip()
        assert _solution_region(source) == solution
        stub = ast.parse(source.split("### BEGIN SOLUTION")[0]).body
        assert len(stub) == 1 and stub[0].value.value is None  # `answer_k = None`


def test_check_cells_are_graded_tests_with_points(released):
    _, release, notebook = released
    points = {}
    for exercise in find_exercises(notebook):
        cell = notebook["cells"][exercise.check_index]
        meta = _meta(cell)
        assert (meta["grade"], meta["solution"], meta["locked"]) == (True, False, True)
        assert meta["grade_id"] == f"test_{exercise.variable}"
        assert "raises-exception" in cell_tags(cell)
        source = cell_source(cell).splitlines()
        assert source[0].startswith(f"{exercise.variable}  # your answer, worth")
        assert source[1] == "### BEGIN HIDDEN TESTS"
        assert source[2] == "from robotconf.grading import Credit"
        assert f"    credit.own_work({exercise.variable!r})" in source
        assert source[-2:] == ["credit.score", "### END HIDDEN TESTS"]
        points[exercise.variable] = meta["points"]
    # course/kit/weights.md: the axes 1, the turned frame 2, the point 1, the symbolic A1 2.
    assert points == {"answer_1": 1, "answer_2": 2, "answer_3": 1, "answer_4": 2}
    assert release.points(LESSON) == 6
    # Only exercise 4 is symbolic (A1 in q1): only it has a hidden test.
    hidden = [e.variable for e in release.exercises if e.hidden]
    assert hidden == ["answer_4"]
    assert all(e.partial for e in release.exercises)


def test_grade_ids_are_unique_and_every_other_cell_is_locked(released):
    _, _, notebook = released
    ids = [_meta(c)["grade_id"] for c in notebook["cells"]]
    assert len(ids) == len(set(ids)) == len(notebook["cells"])
    assert all(re.fullmatch(r"[A-Za-z0-9_-]+", i) for i in ids)
    graded = {e.answer_index for e in find_exercises(notebook)}
    graded |= {e.check_index for e in find_exercises(notebook)}
    for index, cell in enumerate(notebook["cells"]):
        if index not in graded:
            meta = _meta(cell)
            assert (meta["locked"], meta["grade"], meta["solution"]) == (True, False, False)
    # The text is the students': their title has no "(solutions)".
    title = cell_source(notebook["cells"][0]).splitlines()[0]
    assert title == "# Lesson 1 — Homogeneous transforms — exercises"
    # Right after it, how the copy is graded: points, rounding, the rubric, own work.
    intro = cell_source(notebook["cells"][1])
    assert intro.startswith("### How this copy is graded")
    assert "6 in all (exercise 1: 1, exercise 2: 2, exercise 3: 1, exercise 4: 2)" in intro
    assert "3 significant digits" in intro and "calls robotconf" in intro


def _student_version(notebook: dict, stub: str) -> dict:
    """nbgrader's ClearSolutions and ClearHiddenTests, by their documented rules."""
    student = json.loads(json.dumps(notebook))
    for cell in student["cells"]:
        kept, inside = [], False
        for line in cell_source(cell).split("\n"):
            if "BEGIN SOLUTION" in line or "BEGIN HIDDEN TESTS" in line:
                inside = True
                if "SOLUTION" in line:
                    kept.append(line[: len(line) - len(line.lstrip())] + stub)
            elif "END SOLUTION" in line or "END HIDDEN TESTS" in line:
                inside = False
            elif not inside:
                kept.append(line)
        cell["source"] = "\n".join(kept)
    return student


def test_the_student_version_has_no_solution(released):
    out, _, notebook = released
    config = (out / "nbgrader_config.py").read_text(encoding="utf-8")
    stub = json.loads(re.search(r'code_stub = \{"python": (".*")\}', config).group(1))
    student = _student_version(notebook, stub)
    text = "\n".join(cell_source(c) for c in student["cells"])
    solutions = read_notebook(COURSE / "solutions" / LESSON / "exercises.ipynb")
    for exercise in find_exercises(solutions):
        solution = cell_source(solutions["cells"][exercise.answer_index]).split("=", 1)[1]
        assert solution.strip() not in text
    assert "BEGIN" not in text and "recheck" not in text
    # No check is left in the students' copy: no expected value, no code computing one.
    assert "assert_matrix" not in text and "expected_1" not in text and "import Credit" not in text
    for exercise in find_exercises(student):
        body = ast.parse(cell_source(student["cells"][exercise.answer_index])).body
        assert len(body) == 1 and body[0].value.value is None


def test_the_nbgrader_config_names_the_course_and_assignments(released):
    out, _, _ = released
    tree = ast.parse((out / "nbgrader_config.py").read_text(encoding="utf-8"))
    values = {}
    for node in tree.body:
        if isinstance(node, ast.Assign):
            values[ast.unparse(node.targets[0])] = node.value
    assert ast.literal_eval(values["c.CourseDirectory.course_id"]) == "robotconf"
    assert ast.literal_eval(values["ASSIGNMENTS"]) == [LESSON]
    assert ast.literal_eval(values["c.Execute.timeout"]) == 120
    # autograde marks exercises flagged for manual grading, right after saving the scores
    config = (out / "nbgrader_config.py").read_text(encoding="utf-8")
    assert "robotconf.grading.nbgrader_flags.FlagForManualGrading" in config
    readme = (out / "README.md").read_text(encoding="utf-8")
    for step in ("generate_assignment", "autograde", "generate_feedback", "| 6 |"):
        assert step in readme


def test_the_released_source_earns_full_points_when_run(released):
    """The instructor's notebook runs: every test cell's last output is its points."""
    nbclient = pytest.importorskip("nbclient")
    import nbformat

    out, _, notebook = released
    node = nbformat.reads(json.dumps(notebook), as_version=4)
    folder = out / "source" / LESSON
    nbclient.NotebookClient(
        node, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(folder)}}
    ).execute()
    scores = {}
    for cell in node.cells:
        meta = cell.metadata.get("nbgrader", {})
        if meta.get("grade"):
            results = [o for o in cell.outputs if o.output_type == "execute_result"]
            assert not [o for o in cell.outputs if o.output_type == "error"]
            scores[meta["grade_id"]] = float(results[-1].data["text/plain"])
    assert scores == {
        "test_answer_1": 1.0,
        "test_answer_2": 2.0,
        "test_answer_3": 1.0,
        "test_answer_4": 2.0,
    }


def test_a_second_release_keeps_the_first_and_an_instructors_config(released, tmp_path):
    out = tmp_path / "out"
    shutil.copytree(released[0], out)
    (out / "nbgrader_config.py").write_text("c = get_config()  # my own\n", encoding="utf-8")
    release = release_course(out, variant_course(tmp_path), VARIANT_LESSON)
    readme = (out / "README.md").read_text(encoding="utf-8")  # still the release's: rewritten
    assert f"| `{LESSON}` | 6 |" in readme and f"| `{VARIANT_LESSON}` | 1 |" in readme
    config = (out / "nbgrader_config.py").read_text(encoding="utf-8")
    assert config == "c = get_config()  # my own\n"
    assert [note for note in release.notes if "nbgrader_config.py" in note]
    # The student-id cell stays the student's to edit.
    notebook = read_notebook(out / "source" / VARIANT_LESSON / f"{VARIANT_LESSON}.ipynb")
    id_cell = notebook["cells"][2]  # after the title and how the copy is graded
    assert "nbgrader" not in id_cell["metadata"] and id_cell["metadata"]["deletable"] is False
    assert cell_source(notebook["cells"][0]) == "# Lab"


# -- the answer key ---------------------------------------------------------------------


@pytest.fixture(scope="module")
def key01():
    return answer_key(COURSE, "01")


def test_key_values_are_the_checks_expected_values(key01):
    (lesson,) = key01.lessons
    assert lesson.lesson == LESSON and lesson.student_id is None and lesson.points == 6
    by = {e.variable: e for e in lesson.exercises}
    # Exercise 1: axes x1 = (0,0,1), y1 = (1,0,0), z1 = (0,1,0) as columns, origin (10,20,30).
    assert by["answer_1"].expected["values"] == [
        [0, 1, 0, 10],
        [0, 0, 1, 20],
        [1, 0, 0, 30],
        [0, 0, 0, 1],
    ]
    # Exercise 2: Rz(90°) with the origin at (30, 0, 20).
    assert by["answer_2"].expected["values"] == [
        [0, -1, 0, 30],
        [1, 0, 0, 0],
        [0, 0, 1, 20],
        [0, 0, 0, 1],
    ]
    assert by["answer_2"].expected["name"] == "A1"
    assert by["answer_2"].expected["q"] == pytest.approx([np.pi / 2])
    # Exercise 3: (30, 0, 20) + Rz(90°)·(40, 0, 0) = (30, 40, 20).
    assert by["answer_3"].expected["values"] == [[30], [40], [20], [1]]
    # Exercise 4: symbolic, as text and LaTeX.
    symbolic = by["answer_4"].expected
    assert symbolic["values"] is None and symbolic["symbols"] == ["q1"]
    assert symbolic["entries"][0] == ["cos(q1)", "-sin(q1)", "0", "30"]
    assert symbolic["latex"].startswith(r"\begin{bmatrix}\cos{\left(q_{1} \right)}")
    assert [e.points for e in lesson.exercises] == [1, 2, 1, 2]
    assert all(e.error == "" and e.expected_from == "check" for e in lesson.exercises)


def test_key_files_in_markdown_and_json(key01, tmp_path):
    from robotconf.grading import write_answer_key

    text = write_answer_key(tmp_path / "key.md", key01).read_text(encoding="utf-8")
    assert "## 01_homogeneous_transforms (6 points)" in text
    assert "[[cos(q1), -sin(q1), 0, 30]," in text
    assert "$$\n\\begin{bmatrix}" in text
    data = json.loads(write_answer_key(tmp_path / "key.json", key01).read_text("utf-8"))
    assert data["lessons"][0]["exercises"][2]["expected"]["values"] == [[30], [40], [20], [1]]
    with pytest.raises(ValueError, match="OUT: .* allowed: a file name"):
        write_answer_key(tmp_path / "key.txt", key01)


def test_the_key_of_one_student(tmp_path):
    course = variant_course(tmp_path)
    (lesson,) = answer_key(course, student=" s001 ").lessons
    assert lesson.student_id == "s001"
    (exercise,) = lesson.exercises
    assert exercise.expected["values"] == [[variant_l2("s001") + 10], [0], [0], [1]]
    assert exercise.solution["values"] == [variant_l2("s001") + 10, 0, 0]
    (lesson,) = answer_key(course).lessons  # no --student: the notebook's own id
    assert lesson.student_id == "demo"
    assert lesson.exercises[0].expected["values"][0] == [variant_l2("demo") + 10]


def test_course_command_line(tmp_path, capsys):
    course = variant_course(tmp_path)
    key = tmp_path / "keys" / "s002.json"
    assert main(["course", "key", str(key), "--course", str(course), "--student", "s002"]) == 0
    data = json.loads(key.read_text(encoding="utf-8"))
    assert data["student"] == "s002"
    assert data["lessons"][0]["exercises"][0]["expected"]["values"][0] == [variant_l2("s002") + 10]
    assert variant_l2("s001") != variant_l2("s002")  # so the two students' keys differ
    assert "wrote" in capsys.readouterr().out
    bad = [
        (["course", "key", str(tmp_path / "k.txt"), "--course", str(course)], "OUT:"),
        (["course", "key", str(key), "--course", str(course), "--lessons", "7"], "--lessons:"),
        (["course", "key", str(key), "--course", str(tmp_path)], "--course:"),
        (["course", "key", str(key), "--course", str(course), "--student", "a\tb"], "--student"),
        (["course", "release", str(tmp_path / "o"), "--course-id", "a b"], "--course-id:"),
        (["course", "release", str(key), "--course", str(course)], "OUT:"),
        (["course"], "ACTION"),
    ]
    for argv, field in bad:
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith("robotconf: error: ") and field in err and err.count("\n") == 1


def test_a_solution_that_fails_its_check_stops_the_release(tmp_path):
    course = variant_course(tmp_path)
    path = course / "solutions" / VARIANT_LESSON / "exercises.ipynb"
    notebook = read_notebook(path)
    notebook["cells"][4]["source"] = "answer_1 = [l2, 0, 0]"  # forgot the tool point
    path.write_text(json.dumps(notebook), encoding="utf-8")
    with pytest.raises(ValueError, match="exercise 1 .answer_1.: the solution fails its check"):
        release_course(tmp_path / "out", course)
    assert not (tmp_path / "out" / "source").exists()
    # The key still says what the check expects, and that the solution fails it.
    (exercise,) = answer_key(course, student="s001").lessons[0].exercises
    assert exercise.expected["values"][0] == [variant_l2("s001") + 10]
    assert exercise.error.startswith("AssertionError")


def test_each_cell_has_a_time_limit(tmp_path):
    course = variant_course(tmp_path)
    path = course / "solutions" / VARIANT_LESSON / "exercises.ipynb"
    notebook = read_notebook(path)
    notebook["cells"][2]["source"] += "\nimport time\ntime.sleep(60)"
    path.write_text(json.dumps(notebook), encoding="utf-8")
    with pytest.raises(ValueError, match="a cell ran longer than '1 s'"):
        answer_key(course, timeout=1)


def test_running_notebooks_needs_the_lab_extra(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "nbclient", None)  # as if it were not installed
    with pytest.raises(ValueError, match=r"robotconf\[lab\]"):
        answer_key(variant_course(tmp_path))
