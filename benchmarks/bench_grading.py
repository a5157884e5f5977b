"""Autograde of a class: 100 submissions of one lesson through nbgrader, timed.

Run: ``PYTHONPATH=. python benchmarks/bench_grading.py`` (``--lesson 12``,
``--submissions 100``; ``--quick``: 10 submissions). Needs nbgrader (the dev extra).
Target: ≤ 2 s per submission for ``nbgrader autograde``; the peak memory is reported.

The lesson is released from course/ (``robotconf course release``), the students'
copies generated (``nbgrader generate_assignment``), and a class of submissions written
from the lesson's registered exercises, one student id each, in five kinds: all right,
one typical slip per exercise, blank, a few right and the rest slips, and answer cells
that ask robotconf (flagged for manual grading). ``nbgrader autograde`` runs them all,
each in its own kernel, as a teacher would; the gradebook's scores are checked against
the kinds (right: every point; blank: none; slips: a share).

Printed: the wall time of the autograde and per submission, and its CPU time (nbgrader
and the kernels: what a busy machine cannot inflate); the time the checks
themselves take per submission (the hidden test cells' work, in this process, without
a kernel); the peak resident memory of the largest process (nbgrader or a kernel).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import robotconf as rc
from robotconf.grading import award, read_notebook, read_weights, release_course
from robotconf.teaching.exercises import registered

COURSE = Path(__file__).resolve().parents[1] / "course"
TARGET_SECONDS = 2.0
KINDS = ("right", "slips", "blank", "mixed", "shortcut")


def _typed(value: object) -> str:
    if isinstance(value, (str, dict)):
        return repr(value)
    return repr(np.asarray(value, dtype=float).tolist())


def _first_slip(task: rc.Assignment, number: int) -> object:
    """The exercise's first typical slip that its check names (a slip a student makes)."""
    slips = task.exercise(number).slips(task.numbers)
    for answer in slips.values():
        typed = answer.tolist() if hasattr(answer, "tolist") else answer
        if task.check(number, typed).diagnosis not in (None, "wrong", "missing", "extra"):
            return typed
    return next(iter(slips.values()))


def answers(lesson: str, student_id: str, kind: str) -> dict[str, str]:
    """The answer cells' code of one submission of ``kind``."""
    task = rc.Assignment(lesson, student_id)
    numbers = [e.number for e in registered(lesson)]
    if kind == "blank":
        return {}
    if kind == "shortcut":
        return {f"answer_{k}": f"answer_{k} = task.answer({k})" for k in numbers}
    cells = {}
    for k in numbers:
        right = kind == "right" or (kind == "mixed" and k % 2 == 1)
        value = task.answer(k) if right else _first_slip(task, k)
        cells[f"answer_{k}"] = f"answer_{k} = {_typed(value)}"
    return cells


def _nbgrader(out: Path, *args: str) -> float:
    path = f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"
    start = time.perf_counter()
    result = subprocess.run(
        [sys.executable, "-m", "nbgrader", *args],
        cwd=out,
        env={**os.environ, "PATH": path, "ROBOTCONF_FAST": "1", "MPLBACKEND": "Agg"},
        capture_output=True,
        text=True,
    )
    if result.returncode != 0:
        raise SystemExit(result.stdout[-3000:] + result.stderr[-3000:])
    return time.perf_counter() - start


def _submit(out: Path, assignment: str, student: str, sources: dict[str, str]) -> None:
    notebook = read_notebook(out / "release" / assignment / f"{assignment}.ipynb")
    for cell in notebook["cells"]:
        grade_id = cell["metadata"].get("nbgrader", {}).get("grade_id")
        if grade_id in sources:
            cell["source"] = sources[grade_id]
        if "student-id" in cell["metadata"].get("tags", []):
            cell["source"] = f"student_id = {sources['student_id']!r}"
    target = out / "submitted" / student / assignment / f"{assignment}.ipynb"
    target.parent.mkdir(parents=True)
    target.write_text(json.dumps(notebook), encoding="utf-8")


def _scores(out: Path, assignment: str) -> dict[str, float]:
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{out / 'gradebook.db'}") as gradebook:
        return {
            s.student.id: sum(g.score for g in s.notebooks[0].grades)
            for s in gradebook.assignment_submissions(assignment)
        }


def check_time(lesson: str, classes: list[tuple[str, str, str]]) -> float:
    """Seconds per submission the checks and the rubric take (no kernel, no nbgrader)."""
    weights = read_weights(COURSE / "kit" / "weights.md")
    start = time.perf_counter()
    for _, student_id, kind in classes:
        task = rc.Assignment(lesson, student_id)
        namespace = {"task": task}
        for variable, source in answers(lesson, student_id, kind).items():
            if "task.answer" in source:
                continue  # flagged: no check runs for the points
            exec(source, namespace)  # our generated literal
            k = int(variable.split("_")[1])
            points = weights.points_of(lesson, k) or 1.0
            award(task.check(k, namespace[variable]), weights.rubric(lesson, k, points))
    return (time.perf_counter() - start) / len(classes)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lesson", default="12", help="lesson number (default 12)")
    parser.add_argument("--submissions", type=int, default=100)
    parser.add_argument("--quick", action="store_true", help="10 submissions")
    options = parser.parse_args()
    count = 10 if options.quick else options.submissions
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "course"
        release = release_course(out, COURSE, options.lesson)
        (lesson,) = release.assignments
        _nbgrader(out, "generate_assignment", lesson)
        classes = [(f"b{i:03d}", f"bench-{i:03d}", KINDS[i % len(KINDS)]) for i in range(count)]
        for student, student_id, kind in classes:
            _submit(
                out,
                lesson,
                student,
                {"student_id": student_id, **answers(lesson, student_id, kind)},
            )
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        seconds = _nbgrader(out, "autograde", lesson)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
        scores = _scores(out, lesson)
        total = release.points(lesson)
        by_kind = {kind: [scores[s] for s, _, k in classes if k == kind] for kind in KINDS}
        assert all(score == total for score in by_kind["right"]), by_kind["right"]
        assert all(score == 0 for score in by_kind["blank"] + by_kind["shortcut"])
        assert all(0 < score < total for score in by_kind["slips"]), by_kind["slips"]
        checks = check_time(lesson, classes)
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024  # KiB → MiB
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    per = seconds / count
    print(f"lesson {lesson}: {count} submissions, {total:g} points each")
    for kind in KINDS:
        found = by_kind[kind]
        print(f"  {kind:8s} {len(found):3d} submissions, mean score {np.mean(found):.2f}")
    verdict = "ok" if per <= TARGET_SECONDS else f"over the {TARGET_SECONDS:g} s target"
    print(f"nbgrader autograde: {seconds:.1f} s, {per:.2f} s per submission ({verdict})")
    print(
        f"  CPU time of nbgrader and its kernels: {cpu / count:.2f} s per submission "
        f"(on {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}: the wall time "
        "on a busy machine is longer)"
    )
    print(f"the checks and the rubric alone: {checks:.3f} s per submission (no kernel)")
    print(
        f"peak memory: {peak:.0f} MiB (the largest process: nbgrader or a kernel); "
        f"this script {own:.0f} MiB"
    )


if __name__ == "__main__":
    main()
