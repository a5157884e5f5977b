"""An exercise with per-student numbers, its check, and the mistakes its numbers must reveal.

A course exercise whose numbers come from the student id is written once, here: how its
numbers are drawn, the right answer, the check a notebook runs, and the answers the
typical single slips of the exercise give (the checker's own mistake models, plus the
exercise's own: "the largest move sets the time", "q3 = A just before the drop"). Its
numbers are **screened**: a draw with which a typical slip would still pass the check is
drawn again (:meth:`~robotconf.teaching.Variant.screened`), so for every student each
slip gives a refused answer.

An :class:`Assignment` holds one student's numbers for a lesson and runs its checks; a
notebook calls ``task = rc.Assignment("12_trajectories", student_id)``, reads
``task["d1"]``, and checks with ``task.assert_answer(1, answer_1)``.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

from ..._errors import InvalidInputError
from ..reading._wrapper import passed
from ..variants import Variant

__all__ = ["Assignment", "Exercise", "checkers", "register", "registered"]

#: Every exercise with per-student numbers, by lesson, in order (filled by the lessons'
#: modules when the folder is imported).
_REGISTRY: dict[str, list[Exercise]] = {}

Numbers = Mapping[str, Any]
#: Rounds of drawing a whole lesson, and draws of one exercise per round.
_ROUNDS = 8
_ATTEMPTS = 16


#: Verdicts of :meth:`Exercise.reveals`, by exercise and numbers.
_REVEALS: dict[tuple[str, int, str], bool] = {}
_MAX_REVEALS = 4096


def _numbers_key(numbers: Numbers) -> str:
    """The numbers as text, robots by their description: equal numbers, equal keys."""
    return repr(sorted((name, repr(value)) for name, value in numbers.items()))


def checkers() -> Any:
    """The ``robotconf.teaching`` module, looked up when a check runs.

    Checks call ``checkers().check_profile(…)`` rather than a name bound at import, so
    tools that follow the checkers through the module (the answer key's recorder) see
    these calls as they see a notebook's ``rc.check_profile(…)``.
    """
    return sys.modules["robotconf.teaching"]


@dataclass(frozen=True)
class Exercise:
    """One exercise with per-student numbers.

    Attributes
    ----------
    lesson : str
        The lesson folder, e.g. ``"12_trajectories"``.
    number : int
        The exercise's number in the lesson.
    title : str
        What it asks, in a few words.
    draw : callable
        ``draw(variant, earlier)``: this exercise's new numbers as a dict (``earlier``
        holds the numbers the lesson's previous exercises drew).
    answer : callable
        ``answer(numbers)``: a right answer, as a student would type it.
    check : callable
        ``check(answer, numbers)``: the verdict the notebook's check cell gives
        (a ``check_*`` call, never raising for a wrong answer).
    slips : callable
        ``slips(numbers)``: ``{mistake: the answer it gives}`` for the exercise's typical
        single slips.
    shows : callable, optional
        ``shows(numbers)``: the numbers as the task prints them (Markdown).
    fast : callable, optional
        ``fast(answer, numbers)``: whether the check accepts an answer given as numbers,
        by the checker's own rule without its diagnosis (for screening many draws).
    """

    lesson: str
    number: int
    title: str
    draw: Callable[[Variant, Numbers], dict[str, Any]]
    answer: Callable[[Numbers], Any]
    check: Callable[[Any, Numbers], Any]
    slips: Callable[[Numbers], dict[str, Any]]
    shows: Callable[[Numbers], str] | None = field(default=None, repr=False)
    fast: Callable[[Any, Numbers], bool] | None = field(default=None, repr=False)

    def hidden_slips(self, numbers: Numbers) -> list[str]:
        """The slips whose answers the check would accept with these numbers."""
        return [
            name for name, answer in self.slips(numbers).items() if self.accepts(answer, numbers)
        ]

    def accepts(self, answer: Any, numbers: Numbers, *, full: bool = False) -> bool:
        """Whether the check accepts ``answer`` (an answer it refuses as malformed is not).

        An answer given as numbers is judged by :attr:`fast` when there is one (the
        checker's rule, without its diagnosis), unless ``full``.
        """
        if self.fast is not None and not full and not isinstance(answer, (str, dict)):
            try:
                return bool(self.fast(answer, numbers))
            except (TypeError, ValueError):
                pass
        try:
            return bool(self.check(answer, numbers).ok)
        except InvalidInputError:
            return False

    def reveals(self, numbers: Numbers) -> bool:
        """The right answer passes and every typical slip fails, with these numbers.

        Drawn numbers come from short lists, so many students share them: the verdict is
        kept per numbers (a few thousand at most).
        """
        key = (self.lesson, self.number, _numbers_key(numbers))
        if key not in _REVEALS:
            if len(_REVEALS) >= _MAX_REVEALS:
                del _REVEALS[next(iter(_REVEALS))]
            right = self.accepts(self.answer(numbers), numbers)
            _REVEALS[key] = right and not self.hidden_slips(numbers)
        return _REVEALS[key]


def register(*exercises: Exercise) -> None:
    """Add exercises to the registry (each lesson's module does, once)."""
    for exercise in exercises:
        listed = _REGISTRY.setdefault(exercise.lesson, [])
        if any(e.number == exercise.number for e in listed):
            raise ValueError(f"{exercise.lesson} exercise {exercise.number} is registered twice")
        listed.append(exercise)
        listed.sort(key=lambda e: e.number)


def registered(lesson: str | None = None) -> list[Exercise]:
    """The registered exercises of ``lesson`` (every lesson's, in order, for ``None``)."""
    if lesson is None:
        return [e for name in sorted(_REGISTRY) for e in _REGISTRY[name]]
    return list(_REGISTRY.get(lesson, []))


def _screen(variant: Variant, exercise: Exercise, earlier: Numbers, round_: int) -> dict[str, Any]:
    """Exercise's numbers, drawn given ``earlier`` ones and screened (round ``round_``)."""

    def draw(trial: Variant) -> dict[str, Any]:
        return exercise.draw(trial, earlier)

    def reveals(new: dict[str, Any]) -> bool:
        return exercise.reveals({**earlier, **new})

    draw.__name__ = f"{exercise.lesson} exercise {exercise.number}"
    return variant.screened(draw, reveals, attempts=_ATTEMPTS, first=round_ * _ATTEMPTS)


class Assignment:
    """One student's numbers for a lesson, and the lesson's checks with them.

    Parameters
    ----------
    lesson : str
        The lesson folder, e.g. ``"12_trajectories"``.
    student_id : str
        The student's id, as :class:`~robotconf.teaching.Variant` takes it.
    draw : str, optional
        Draw the numbers under this name too (``"quiz"``, ``"exam-2026"``): the same
        exercises and checks, other numbers than the lesson's homework.

    Attributes
    ----------
    variant : Variant
        The draws (``variant.drawn``: every number by name, what an answer key lists).
    numbers : dict
        Every number of the lesson's exercises, by the name the notebook uses.

    Raises
    ------
    InvalidInputError
        For a lesson without exercises with per-student numbers, or a bad id.

    Examples
    --------
    >>> task = Assignment("12_trajectories", "demo")
    >>> v, a, d = task["v_max"], task["a_max"], task["d1"]
    >>> task.check(1, [v / a, d / v + v / a, v]).ok  # a trapezoid: t_a = v/a, T = d/v + v/a
    True
    >>> task.check(1, [2 * v / a, d / v + 2 * v / a, v]).diagnosis  # 2v/a
    'accel_time_factor'
    >>> task.variant.drawn == Assignment("12_trajectories", " DEMO ").variant.drawn
    True
    >>> Assignment("12_trajectories", "demo", draw="quiz")["d1"] == task["d1"]  # other numbers
    False
    """

    def __init__(self, lesson: str, student_id: str, draw: str | None = None) -> None:
        exercises = registered(lesson)
        if not exercises:
            raise InvalidInputError(
                "lesson",
                lesson,
                ", ".join(sorted(_REGISTRY)),
                problem="no exercises with per-student numbers in",
            )
        self.lesson = lesson
        self._key = lesson if draw is None else f"{lesson}@{draw}"
        self._exercises = {e.number: e for e in exercises}
        # A round draws every exercise, screening each in turn; an exercise that cannot
        # reveal its slips with the numbers drawn before it (it draws none of its own, or
        # they do not help) starts another round, redrawing the lesson from the start.
        for round_ in range(_ROUNDS):
            try:
                self._draw(student_id, exercises, round_)
                return
            except InvalidInputError:
                if round_ == _ROUNDS - 1:
                    raise

    def _draw(self, student_id: str, exercises: list[Exercise], round_: int) -> None:
        self.variant = Variant(student_id, self._key)
        self.numbers: dict[str, Any] = {}
        for exercise in exercises:
            self.numbers.update(_screen(self.variant, exercise, dict(self.numbers), round_))

    def __getitem__(self, name: str) -> Any:
        return self.numbers[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self.numbers)

    def __repr__(self) -> str:
        return f"Assignment({self.lesson!r}, {self.variant.student_id!r})"

    def exercise(self, number: int) -> Exercise:
        """Exercise ``number`` of the lesson."""
        if number not in self._exercises:
            raise InvalidInputError(
                "number", number, f"one of {sorted(self._exercises)}", problem="no exercise"
            )
        return self._exercises[number]

    def answer(self, number: int) -> Any:
        """A right answer of exercise ``number`` (for keys and tests, not for students)."""
        return self.exercise(number).answer(self.numbers)

    def check(self, number: int, answer: Any) -> Any:
        """The verdict on ``answer`` to exercise ``number``."""
        return self.exercise(number).check(answer, self.numbers)

    def assert_answer(self, number: int, answer: Any) -> Any:
        """Like :meth:`check`, but raise ``AssertionError`` with the hints if wrong."""
        __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
        return passed(self.check(number, answer))

    def shows(self, number: int) -> str:
        """The numbers of exercise ``number`` as its task prints them (Markdown)."""
        shows = self.exercise(number).shows
        return "" if shows is None else shows(self.numbers)

    def _repr_markdown_(self) -> str:
        lines = [self.shows(n) for n in sorted(self._exercises)]
        return "\n\n".join(line for line in lines if line)
