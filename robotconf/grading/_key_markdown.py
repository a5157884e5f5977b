"""The answer key as a Markdown document.

Values sit in fenced code blocks and formulas between ``$$``; the few words taken from
notebooks (a check's name, a student id) go through :func:`robotconf.report.markdown_text`,
so nothing in a notebook can add markup to the key.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from ..teaching import format_number

if TYPE_CHECKING:  # pragma: no cover
    from ._answer_key import AnswerKey, KeyExercise

__all__ = ["key_markdown", "value_text"]

_KINDS = {
    "matrix": "matrix",
    "vector": "vector",
    "value": "number",
    "angle": "angle (rad)",
    "set": "set of values (any order)",
    "interval": "interval [lo, hi]",
    "dh_table": "DH table: θ offset, d offset, a, α, joint (q adds to θ for R, to d for P)",
    "ik_solution": "target: any joint values whose end effector reaches it pass",
    "ik_solutions": "target: every closed-form solution for it, any order, is wanted",
    "profile": "motion-profile values",
}


def _text(value: object) -> str:
    from ..report import markdown_text

    return markdown_text(value)


def _fenced(text: str, info: str = "text") -> list[str]:
    """A code block whose fence is longer than any run of backticks in ``text``.

    >>> _fenced("a ```` b")[0]
    '`````text'
    """
    longest = max((len(run) for run in re.findall("`+", text)), default=0)
    fence = "`" * max(3, longest + 1)
    return [fence + info, text, fence]


def value_text(described: dict[str, Any]) -> str:
    """An expected value as text: a number, ``[a, b]`` or an aligned matrix.

    Examples
    --------
    >>> print(value_text({"kind": "matrix", "entries": [["1", "-20"], ["0", "1"]]}))
    [[1, -20],
     [0,   1]]
    >>> value_text({"kind": "vector", "entries": [["0"], ["35"], ["-40"]]})
    '[0, 35, -40]'
    >>> value_text({"kind": "matrix", "entries": [["30"], ["40"], ["20"], ["1"]]})
    '[30, 40, 20, 1]ᵀ (a column)'
    >>> value_text({"kind": "value", "entries": [["-99"]]})
    '-99'
    """
    entries = described["entries"]
    if len(entries) == 1 and len(entries[0]) == 1:
        return str(entries[0][0])
    if all(len(row) == 1 for row in entries):
        flat = "[" + ", ".join(row[0] for row in entries) + "]"
        return flat + "ᵀ (a column)" if described.get("kind") == "matrix" else flat
    widths = [max(len(row[c]) for row in entries) for c in range(len(entries[0]))]
    rows = [
        "[" + ", ".join(e.rjust(w) for e, w in zip(row, widths, strict=True)) + "]"
        for row in entries
    ]
    return "[" + ",\n ".join(rows) + "]"


def _what(described: dict[str, Any]) -> str:
    rows, cols = described["shape"]
    kind = described.get("kind") or "matrix"
    words = _KINDS.get(kind, kind)
    if kind == "matrix":
        words = f"{rows}×{cols} matrix"
    name = described.get("name")
    if name:
        words = f"{_text(name)}, {words}" if kind != "matrix" else f"{_text(name)} ({words})"
    q = described.get("q")
    if q is not None:
        words += " at q = (" + ", ".join(format_number(v) for v in q) + ")"
    if described.get("symbols"):
        words += " in " + ", ".join(_text(s) for s in described["symbols"])
    return words


def _exercise(exercise: KeyExercise) -> list[str]:
    point_word = "point" if exercise.points == 1 else "points"
    lines = [
        f"### Exercise {exercise.number}: `{exercise.variable}` ({exercise.points:g} {point_word})",
        "",
    ]
    described = exercise.expected
    if described is None:
        lines += ["No expected value: the check used no robotconf checker.", ""]
    else:
        source = {
            "variable": f" (the notebook's expected\\_{exercise.number}: its check used no "
            "robotconf checker)",
            "answer": " (the solution's own answer: its check used no robotconf checker)",
        }.get(exercise.expected_from or "", "")
        lines += [f"Expected: {_what(described)}{source}", ""]
        lines += [*_fenced(value_text(described)), ""]
        if described.get("kind") == "dh_table":
            lines += [
                "One right table: the check takes any table that describes the same robot "
                "(the same joint axes and end-effector).",
                "",
            ]
        if described.get("latex"):
            lines += ["$$", described["latex"], "$$", ""]
    if exercise.solution is not None and "text" in exercise.solution:
        lines += ["The solution notebook's answer:", "", *_fenced(exercise.solution["text"]), ""]
    if exercise.error:
        lines += [
            "**The solution notebook's answer fails this check** (for this student id): "
            + _text(exercise.error),
            "",
        ]
    return lines


def key_markdown(key: AnswerKey) -> str:
    """The whole key as Markdown."""
    total = sum(lesson.points for lesson in key.lessons)
    lines = ["# Answer key", ""]
    varied = [lesson for lesson in key.lessons if lesson.student_id is not None]
    if key.student is not None:
        lines.append(f"For student **{_text(key.student)}**.")
    if varied:
        names = ", ".join(f"`{lesson.lesson}`" for lesson in varied)
        lines.append(
            f"Lessons with per-student numbers ({names}) ran with the id shown under their "
            "heading; `robotconf course key KEY.md --student ID` gives another student's."
        )
    else:
        lines.append("No lesson has per-student numbers: this key is every student's.")
    lines += [
        "",
        f"From the solutions notebooks in `{_text(key.course)}`: each expected value is what "
        "the exercise's check compares a student's answer with. "
        f"{len(key.lessons)} lessons, {total:g} points. Keep this file from students.",
        "",
    ]
    for lesson in key.lessons:
        lines += [f"## {lesson.lesson} ({lesson.points:g} points)", ""]
        if lesson.student_id is not None:
            lines += [f"Student id: **{_text(lesson.student_id)}**", ""]
        for exercise in lesson.exercises:
            lines += _exercise(exercise)
    return "\n".join(lines).rstrip("\n") + "\n"
