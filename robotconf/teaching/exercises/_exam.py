"""Quizzes and exams drawn per student from the course's exercises.

An exam is a list of **slots**; each slot offers one or more course exercises with
per-student numbers (``("11_inverse_kinematics", 4)``). For each student, :class:`Exam`
draws one exercise per slot and that exercise's numbers — both from the student id and
the exam's name, so the same id gets the same exam everywhere (the student's laptop,
nbgrader, the teacher's key) and numbers other than the lesson's homework. The checks
are the exercises' own: the same diagnoses, the same rubric. A quiz is an exam whose
slots offer one exercise each.

A notebook does::

    exam = rc.Exam(student_id, [[("09_dh_frame_assignment", 2), ("09_dh_frame_assignment", 3)],
                                [("12_trajectories", 4)]], draw="exam-2026")
    display(Markdown(exam.shows(1)))        # which exercise, and its numbers
    exam.assert_answer(1, answer_1)

``robotconf course quiz`` and ``robotconf course exam`` write such notebooks from the
course's kit (course/kit/quizzes.md, course/kit/exam_bank.md).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..._errors import InvalidInputError
from ..variants import Variant
from ._exercise import Assignment, Exercise, registered

__all__ = ["Exam"]

Slot = Sequence[tuple[str, int]]


def _option(lesson: str, number: int) -> str:
    return f"{lesson}:{number}"


class Exam:
    """One student's items of an exam or quiz, with their numbers and checks.

    Parameters
    ----------
    student_id : str
    slots : sequence of sequences of (lesson, number)
        Each slot's options: course exercises with per-student numbers.
    draw : str
        The exam's name: which option each slot takes, and the numbers, are drawn under
        it (default ``"exam"``).

    Raises
    ------
    InvalidInputError
        For no slot, an empty slot, or an exercise that is not registered.

    Examples
    --------
    >>> slots = [[("12_trajectories", 1), ("12_trajectories", 2)], [("11_inverse_kinematics", 4)]]
    >>> exam = Exam("s1234567", slots, draw="exam-2026")
    >>> exam.item(2)
    ('11_inverse_kinematics', 4)
    >>> exam.check(2, exam.answer(2)).ok
    True
    >>> exam.item(1) == Exam("S1234567 ", slots, draw="exam-2026").item(1)
    True
    """

    def __init__(self, student_id: str, slots: Sequence[Slot], draw: str = "exam") -> None:
        if not slots:
            raise InvalidInputError("slots", slots, "at least one slot of exercises")
        variant = Variant(student_id, f"exam@{draw}")
        self.draw = draw
        self._items: list[tuple[str, int]] = []
        self._tasks: dict[str, Assignment] = {}
        for i, options in enumerate(slots, start=1):
            listed = [(str(lesson), int(number)) for lesson, number in options]
            if not listed:
                raise InvalidInputError(f"slots[{i - 1}]", options, "at least one exercise")
            for lesson, number in listed:
                if number not in {e.number for e in registered(lesson)}:
                    raise InvalidInputError(
                        f"slots[{i - 1}]",
                        _option(lesson, number),
                        "an exercise with per-student numbers (robotconf.teaching.exercises)",
                    )
            chosen = variant.choice(f"slot {i}", [_option(*o) for o in listed])
            lesson, number = chosen.rsplit(":", 1)
            self._items.append((lesson, int(number)))
            if lesson not in self._tasks:
                self._tasks[lesson] = Assignment(lesson, student_id, draw=draw)
        self.variant = variant

    def __len__(self) -> int:
        return len(self._items)

    def __repr__(self) -> str:
        return f"Exam({self.variant.student_id!r}, {len(self)} items, draw={self.draw!r})"

    def item(self, i: int) -> tuple[str, int]:
        """``(lesson, exercise number)`` of item ``i`` (1-based)."""
        if not 1 <= i <= len(self._items):
            raise InvalidInputError("i", i, f"an item from 1 to {len(self._items)}")
        return self._items[i - 1]

    def task(self, i: int) -> Assignment:
        """The student's numbers of item ``i``'s lesson (drawn under the exam's name)."""
        return self._tasks[self.item(i)[0]]

    def exercise(self, i: int) -> Exercise:
        """The course exercise item ``i`` asks."""
        lesson, number = self.item(i)
        return self.task(i).exercise(number)

    def numbers(self, i: int) -> dict[str, Any]:
        """Every number of item ``i``'s lesson, by the name the lesson's notebook uses."""
        return dict(self.task(i).numbers)

    def shows(self, i: int) -> str:
        """Which exercise item ``i`` is, and its numbers (Markdown)."""
        lesson, number = self.item(i)
        exercise = self.exercise(i)
        numbers = self.task(i).shows(number)
        head = f"**Item {i}: lesson {int(lesson[:2])}, exercise {number} — {exercise.title}.**"
        return f"{head} Your numbers: {numbers}" if numbers else head

    def answer(self, i: int) -> Any:
        """A right answer of item ``i`` (for keys and tests)."""
        return self.task(i).answer(self.item(i)[1])

    def check(self, i: int, answer: Any) -> Any:
        """The verdict on ``answer`` to item ``i``: the exercise's own check."""
        return self.task(i).check(self.item(i)[1], answer)

    def assert_answer(self, i: int, answer: Any) -> Any:
        """Like :meth:`check`, but raise ``AssertionError`` with the hints if wrong."""
        __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
        return self.task(i).assert_answer(self.item(i)[1], answer)
