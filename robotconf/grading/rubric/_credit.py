"""The points one autograder test cell earns, by the course's rubric.

A released test cell (``robotconf course release``) wraps the course's check in
:class:`Credit` and ends with ``credit.score``. nbgrader reads that number as the cell's
grade: a test cell whose last output is a number between 0 and its points earns that
many points; one that raises earns 0; one that writes to standard error earns 0 too,
which is why the check's standard error and warnings are shown on standard output
instead (a deprecation warning must not cost a student the exercise).

What a wrong answer earns is the rubric's (:mod:`._rubric`): the share of a named slip
of a right method, or the right numbers of an answer of several numbers. An answer cell
that asks robotconf for its own answer earns no automatic credit: the cell says so, and
nbgrader's autograde marks it for manual grading (:mod:`._shortcuts`).
"""

from __future__ import annotations

import contextlib
import sys
import warnings
from collections.abc import Mapping
from types import TracebackType
from typing import Any

from ._recorder import CheckCall, CheckRecorder, original
from ._rubric import DEFAULT_CAP, DEFAULT_SHARE, Award, Rubric, award
from ._shortcuts import FLAG, own_work_calls

__all__ = ["Credit", "HIDDEN_SAMPLES", "HIDDEN_SEED"]

#: The hidden test compares symbolic answers at this many points ...
HIDDEN_SAMPLES = 32
#: ... drawn with this seed (the visible check uses the checker's defaults: 8 and 0).
HIDDEN_SEED = 1


class Credit:
    """Grade one check cell: run the check inside ``with Credit(points) as credit:``.

    Parameters
    ----------
    points : float
        What the exercise is worth (the test cell's nbgrader points).
    partial : bool
        Give rubric credit to a wrong answer (:func:`~robotconf.grading.award`) when the
        error that ends the block is the one an ``assert_*`` checker raised (or the hidden
        :meth:`recheck`). With several ``assert_*`` parts, only a named slip counts, not
        the right numbers of one part. Otherwise, and for any other error (an unanswered
        exercise, a typing slip), the error propagates and the cell earns 0.
    share : float
        The share of the points a named slip of a right method earns (default 0.5).
    slips : mapping of str to float, optional
        Shares for particular slips (diagnosis codes).
    cap : float
        The most a wrong answer earns by its right numbers (default 0.75).
    several : bool
        The check has several ``assert_*`` parts (set by the release).

    Attributes
    ----------
    score : float
        Points earned, set when the block ends: ``points`` when it ran without error;
        the rubric's credit, rounded to 0.01, when an assertion failed and the answer
        earns some (the block then ends quietly, printing the checker's message and what
        cost the points); else 0, and the error propagates.
    award : Award or None
        How the score was reached, for a wrong answer.
    flagged : list of str
        robotconf calls found in the answer cell by :meth:`own_work`: the exercise then
        earns no automatic credit and is marked for manual grading.

    Notes
    -----
    The verdict is read from the ``AssertionError`` the checker raised (its ``check``
    attribute); checkers called as ``rc.assert_*`` are also followed through the modules
    (for :meth:`recheck`).

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz", a=(30, 0, 20))])
    >>> wrong = "[[cos(q1), sin(q1), 0, 30], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]"
    >>> with Credit(2) as credit:  # doctest: +ELLIPSIS
    ...     rc.assert_matrix(wrong, rc.expected_matrix(robot, "A1"))
    A1: 1 wrong entry.
    ...
    Credit: 1.5 points of 2 points: 5 of the 6 numbers that count are right (a wrong answer ...
    >>> credit.score
    1.5
    """

    def __init__(
        self,
        points: float,
        *,
        partial: bool = True,
        share: float = DEFAULT_SHARE,
        slips: Mapping[str, float] | None = None,
        cap: float = DEFAULT_CAP,
        several: bool = False,
    ) -> None:
        self.rubric = Rubric(points, share, dict(slips or {}), cap, per_number=not several)
        self.points = self.rubric.points
        self.partial = bool(partial)
        self.score = 0.0
        self.award: Award | None = None
        self.flagged: list[str] = []
        self._recorder = CheckRecorder()
        self._recheck_failure: tuple[CheckCall, AssertionError] | None = None
        self._stack: contextlib.ExitStack | None = None
        self._caught: list[warnings.WarningMessage] = []

    def __enter__(self) -> Credit:
        stack = contextlib.ExitStack()
        self._caught = stack.enter_context(warnings.catch_warnings(record=True))
        warnings.simplefilter("always")
        stack.enter_context(contextlib.redirect_stderr(sys.stdout))
        stack.enter_context(self._recorder)
        self._stack = stack
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        traceback: TracebackType | None,
    ) -> bool:
        if self._stack is not None:
            self._stack.close()
            self._stack = None
        for caught in self._caught:
            print(f"(a warning during the check: {caught.category.__name__}: {caught.message})")
        if self.flagged:
            self.score = 0.0
            if error is not None:
                print(str(error).strip())
            calls = ", ".join(self.flagged)
            print(
                f"\n{FLAG}: your answer cell calls robotconf ({calls}), which can compute "
                "this answer. The exercise asks for your own derivation, so it earns no "
                "automatic points: your teacher will look at it and grade it by hand."
            )
            return error is None or isinstance(error, AssertionError)
        if error is None:
            self.score = self.points
            return False
        self.score = 0.0
        if not (self.partial and isinstance(error, AssertionError)):
            return False
        result = self._verdict(error)
        if result is None:
            return False
        self.award = award(result, self.rubric)
        if self.award.score <= 0:
            return False
        self.score = self.award.score
        print(str(error).strip() or str(result))
        print(f"\nCredit: {self.award.reason}")
        return True

    def _verdict(self, error: BaseException) -> Any:
        """The verdict of the checker whose failure ends the block, if one does."""
        for failure in (self._recheck_failure, self._recorder.raised):
            if failure is not None and failure[1] is error:
                return failure[0].result
        return getattr(error, "check", None)

    def own_work(self, variable: str, namespace: Mapping[str, Any] | None = None) -> list[str]:
        """Flag the answer cell of ``variable`` if it calls robotconf.

        Reads the last cell run that assigns ``variable`` from IPython's input history
        (``In``) and lists its calls of robotconf functions and of methods of robotconf
        objects (``rc.ik(…)``, ``arm.end_effector(…)``, ``rc.derivation(…).matrix``). A
        flagged exercise earns 0 automatic points and a note (see the module notes).

        Parameters
        ----------
        variable : str
            The answer variable, e.g. ``"answer_4"``.
        namespace : mapping, optional
            The notebook's globals (default: IPython's user namespace).

        Returns
        -------
        list of str
            The calls found (empty when the cell is the student's own work).
        """
        self.flagged = own_work_calls(variable, namespace)
        return self.flagged

    def recheck(self, *, seed: int = HIDDEN_SEED, samples: int = HIDDEN_SAMPLES) -> None:
        """Repeat every symbolic matrix check of the block at other values of the symbols.

        The visible check compares at the checker's 8 seeded points; these points are
        reproducible, so an answer could be fitted to them. Checks against numbers (a
        configuration given in numbers) and of other kinds are not repeated.

        Raises
        ------
        AssertionError
            When an answer that passed is wrong at the new points.
        """
        __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
        for call in list(self._recorder.calls):
            if call.kind != "matrix" or not call.result.expected.matrix.free_symbols:
                continue
            options: dict[str, Any] = {**call.options, "seed": seed, "samples": samples}
            reference = call.result.expected
            result = original("check_matrix")(call.student, reference, **options)
            if not result.ok:
                error = AssertionError(
                    "The answer agrees with the expected one at the points checked first, "
                    f"but not everywhere:\n{result}"
                )
                recheck = CheckCall(call.label, "matrix", call.student, reference, options, result)
                self._recheck_failure = (recheck, error)
                raise error

    def __repr__(self) -> str:
        return f"<Credit {self.score:g} of {self.points:g} points>"
