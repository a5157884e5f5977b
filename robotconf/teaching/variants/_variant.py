"""Per-student exercise parameters: the same student id gives the same numbers everywhere.

A course hands every student their own lengths and angles so that answers cannot be
copied, while the instructor can still rebuild each student's numbers (and answer key)
from the id alone. Each value comes from SHA-256 of ``(student id, lesson, name)``:

- no Python ``hash`` (randomized per process) and no numpy stream whose algorithm may
  change between numpy versions decides a drawn value, so the numbers agree on every
  machine, operating system and Python or numpy version;
- each name has its own digest, so the value of ``"l1"`` does not depend on what was
  drawn before it or in which order a notebook's cells ran.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number

__all__ = ["Variant", "MAX_ATTEMPTS", "MAX_ID_CHARS", "MAX_CHOICES"]

#: Longest student id, lesson name or parameter name (characters).
MAX_ID_CHARS = 64
#: Largest number of values one draw chooses among.
MAX_CHOICES = 1_000_000
#: Most draws :meth:`Variant.screened` tries before it gives up.
MAX_ATTEMPTS = 64

_DOMAIN = "robotconf-variant-v1"

T = TypeVar("T")


def _check_text(value: Any, field: str) -> str:
    """A non-empty, printable id of at most 64 characters, spaces around it removed."""
    allowed = f"non-empty printable text of at most {MAX_ID_CHARS} characters"
    if not isinstance(value, str):
        raise InvalidInputError(field, value, allowed, problem="not text:")
    text = value.strip()
    if not text:
        raise InvalidInputError(field, value, allowed, problem="empty:")
    if len(text) > MAX_ID_CHARS:
        raise InvalidInputError(field, value, allowed, problem=f"{len(text)} characters:")
    if not text.isprintable():
        raise InvalidInputError(field, value, allowed, problem="holds a control character:")
    return text


def _index(digest: bytes, count: int) -> int:
    # 64 bits modulo at most 1e6 values: the bias is below 1e-13, invisible in a course.
    return int.from_bytes(digest[:8], "big") % count


class Variant:
    """The exercise parameters of one student in one lesson.

    Parameters
    ----------
    student_id : str
        The student's id (matriculation number, login, …): at most 64 printable
        characters. Spaces around it are removed and case is ignored (``"S123"`` and
        ``" s123 "`` are the same student), so a typo in case cannot change the numbers.
    lesson : str
        The lesson's name, e.g. ``"10_paper_lab"``; the same id gets other numbers in
        another lesson.

    Attributes
    ----------
    drawn : dict of str to object
        Every value drawn so far, by name, as returned (lengths as floats, angles in
        radians): what an answer key lists.

    Raises
    ------
    InvalidInputError
        For an id or lesson that is not text, empty, longer than 64 characters or holds
        a control character.

    Notes
    -----
    A value depends only on the id, the lesson, its name and its range: drawing a name
    twice with the same range returns the same value, with another range raises. Values
    come from SHA-256, not from a numpy stream, so they are the same on every machine
    and with every numpy version; :meth:`generator` gives a numpy ``Generator`` (seeded
    the same way) for arrays where only reproducibility on one installation matters.

    Examples
    --------
    >>> v = Variant("s1234567", "10_paper_lab")
    >>> l1 = v.length("l1", 15, 30, step=5)
    >>> l1 in (15.0, 20.0, 25.0, 30.0)
    True
    >>> Variant(" S1234567", "10_paper_lab").length("l1", 15, 30, step=5) == l1
    True
    >>> v.angle("q1", [30, 45, 60]) in (np.radians(30), np.radians(45), np.radians(60))
    True
    >>> sorted(v.drawn)
    ['l1', 'q1']
    >>> Variant("", "10_paper_lab")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: student_id: empty: ''; allowed: non-empty printable text ...
    """

    __slots__ = ("_student_id", "_lesson", "_drawn", "_specs", "_attempt")

    def __init__(self, student_id: str, lesson: str) -> None:
        self._student_id = _check_text(student_id, "student_id").casefold()
        self._lesson = _check_text(lesson, "lesson")
        self._drawn: dict[str, Any] = {}
        self._specs: dict[str, tuple[Any, ...]] = {}
        self._attempt = 0

    @property
    def student_id(self) -> str:
        """The id as used for drawing: stripped and case-folded."""
        return self._student_id

    @property
    def lesson(self) -> str:
        """The lesson name."""
        return self._lesson

    @property
    def drawn(self) -> dict[str, Any]:
        """A copy of every value drawn so far, by name, in the order drawn."""
        return dict(self._drawn)

    def __repr__(self) -> str:
        return f"Variant(student_id={self._student_id!r}, lesson={self._lesson!r})"

    def _digest(self, name: str) -> bytes:
        parts = [_DOMAIN, self._student_id, self._lesson, name]
        if self._attempt:  # a redraw: other numbers, as reproducible as the first
            parts.append(f"attempt {self._attempt}")
        return hashlib.sha256("\0".join(parts).encode("utf-8")).digest()

    def screened(
        self,
        draw: Callable[[Variant], T],
        reveals: Callable[[T], bool],
        *,
        attempts: int = MAX_ATTEMPTS,
        first: int = 0,
    ) -> T:
        """Numbers drawn by ``draw`` that reveal every typical mistake of the exercise.

        The first draw is the plain one (the numbers the student would get without
        screening); while ``reveals`` says a typical mistake would still pass with these
        numbers, the same names are drawn again from the next attempt's digests. Every
        attempt is as reproducible as the first: the same id gets the same numbers on
        every machine.

        Parameters
        ----------
        draw : callable
            Draws the exercise's numbers from the variant it is given (``length``,
            ``angle``, ``choice``) and returns them.
        reveals : callable
            Whether numbers make every typical mistake give a refused answer.
        attempts : int
            How many draws to try.
        first : int
            The first attempt's number (0: the plain draw).

        Returns
        -------
        object
            What ``draw`` returned, for the first attempt that reveals; the values it
            drew are recorded in :attr:`drawn` under their own names.

        Raises
        ------
        InvalidInputError
            When no attempt reveals (the ranges leave a mistake invisible too often).

        Examples
        --------
        >>> v = Variant("demo", "lesson")
        >>> q = v.screened(lambda w: w.angle("q", [0, 30]), lambda q: q != 0)
        >>> round(float(np.degrees(q)), 6), round(float(np.degrees(v.drawn["q"])), 6)
        (30.0, 30.0)
        """
        for attempt in range(first, first + attempts):
            trial = Variant(self._student_id, self._lesson)
            trial._attempt = attempt
            value = draw(trial)
            if reveals(value):
                for name, drawn in trial._drawn.items():
                    self._adopt(name, trial._specs[name], drawn)
                return value
            if not trial._drawn:  # nothing to draw again: every attempt is this one
                break
        raise InvalidInputError(
            "draw",
            getattr(draw, "__name__", "draw"),
            "ranges in which the typical mistakes change the answer",
            problem=f"no draw in {attempts} attempts reveals every mistake:",
        )

    def _adopt(self, name: str, spec: tuple[Any, ...], value: Any) -> None:
        if name in self._specs and self._specs[name] != spec:
            raise InvalidInputError(
                "name",
                name,
                "a new name, or the same range as before",
                problem="already drawn with another range:",
            )
        self._specs[name] = spec
        self._drawn[name] = value

    def _draw(
        self, name: Any, spec: tuple[Any, ...], count: int, pick: Callable[[int], Any]
    ) -> Any:
        """Value number ``index(digest(name), count)``, via ``pick``; recorded in ``drawn``."""
        name = _check_text(name, "name")
        if name in self._specs and self._specs[name] != spec:
            raise InvalidInputError(
                "name",
                name,
                "a new name, or the same range as before",
                problem="already drawn with another range:",
            )
        value = pick(_index(self._digest(name), count))
        self._specs[name] = spec
        self._drawn[name] = value
        return value

    def length(self, name: str, lo: float, hi: float, step: float = 1.0) -> float:
        """A length from ``lo, lo + step, …`` up to ``hi`` (both ends included).

        Parameters
        ----------
        name : str
            What it is called in the task and in the key, e.g. ``"l1"``.
        lo, hi : float
            The range (length units), ``lo ≤ hi``.
        step : float
            Spacing of the values, > 0; at most 1 000 000 values.

        Returns
        -------
        float
            Rounded to 10 decimals, so ``step=0.1`` gives 2.3, not 2.3000000000000003.

        Raises
        ------
        InvalidInputError
            For a bad range or step, or a name drawn before with another range.

        Examples
        --------
        >>> Variant("demo", "lesson").length("l2", 30, 30)
        30.0
        """
        lo = check_finite_number(lo, "lo")
        hi = check_finite_number(hi, "hi")
        step = check_finite_number(step, "step")
        if step <= 0:
            raise InvalidInputError("step", step, "a number > 0")
        if hi < lo:
            raise InvalidInputError("hi", hi, f"a number ≥ lo = {lo}")
        count = math.floor((hi - lo) / step + 1e-9) + 1
        if count > MAX_CHOICES:
            raise InvalidInputError(
                "step",
                step,
                f"a step giving at most {MAX_CHOICES} values from lo to hi",
                problem=f"{count} values from lo to hi with step",
            )
        spec = ("length", lo, hi, step)
        return float(self._draw(name, spec, count, lambda k: round(lo + k * step, 10)))

    def angle(self, name: str, choices_deg: Sequence[float]) -> float:
        """An angle chosen among ``choices_deg`` (degrees), returned in radians.

        Parameters
        ----------
        name : str
        choices_deg : sequence of float
            The angles a student may get, in degrees (what a task text shows).

        Returns
        -------
        float
            Radians (what robotconf and ``np.sin`` expect); ``np.degrees`` gives the
            choice back.

        Examples
        --------
        >>> round(float(np.degrees(Variant("demo", "lesson").angle("q", [90]))), 9)
        90.0
        """
        choices = self._choices(choices_deg, "choices_deg")
        degrees = [check_finite_number(c, f"choices_deg[{i}]") for i, c in enumerate(choices)]
        radians = [float(np.radians(d)) for d in degrees]
        return float(self._draw(name, ("angle", tuple(degrees)), len(radians), radians.__getitem__))

    def choice(self, name: str, seq: Sequence[Any]) -> Any:
        """One item of ``seq`` (any objects: numbers, robots' names, signal tables).

        Examples
        --------
        >>> Variant("demo", "lesson").choice("robot", ["scara"])
        'scara'
        """
        items = self._choices(seq, "seq")
        spec = ("choice", tuple(repr(item) for item in items))
        return self._draw(name, spec, len(items), items.__getitem__)

    def generator(self, name: str) -> np.random.Generator:
        """A numpy ``Generator`` seeded from SHA-256 of the id, the lesson and ``name``.

        For arrays (random test configurations, noise). The seed is the same everywhere;
        the stream is numpy's and may differ between numpy versions, so draw the numbers
        a task text shows with :meth:`length`, :meth:`angle` or :meth:`choice` instead.

        Examples
        --------
        >>> a = Variant("demo", "lesson").generator("q").uniform(size=3)
        >>> bool(np.all(a == Variant("demo", "lesson").generator("q").uniform(size=3)))
        True
        """
        digest = self._digest("generator:" + _check_text(name, "name"))
        return np.random.default_rng(int.from_bytes(digest[:16], "big"))

    @staticmethod
    def _choices(seq: Any, field: str) -> list[Any]:
        allowed = f"a non-empty list of at most {MAX_CHOICES} items"
        if isinstance(seq, (str, bytes)) or not isinstance(seq, (Sequence, np.ndarray)):
            raise InvalidInputError(field, seq, allowed, problem="not a list:")
        items = list(seq)
        if not items or len(items) > MAX_CHOICES:
            raise InvalidInputError(field, seq, allowed, problem=f"{len(items)} items:")
        return items
