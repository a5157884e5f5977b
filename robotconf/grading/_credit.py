"""The points one autograder test cell earns: full, partial per entry, or none.

A released test cell (``robotconf course release``) wraps the course's check in
:class:`Credit` and ends with ``credit.score``. nbgrader reads that number as the cell's
grade: a test cell whose last output is a number between 0 and its points earns that
many points; one that raises earns 0; one that writes to standard error earns 0 too,
which is why the check's standard error and warnings are shown on standard output
instead (a deprecation warning must not cost a student the exercise).
"""

from __future__ import annotations

import contextlib
import math
import sys
import warnings
from types import TracebackType
from typing import Any

from .._errors import InvalidInputError
from ._points import answer_credit, credit_counts
from ._recorder import CheckCall, CheckRecorder, original

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
        Give partial credit per entry (:func:`~robotconf.grading.answer_credit`) when
        the error that ends the block is the one an ``assert_*`` checker raised (or the
        hidden :meth:`recheck`). Release it only for a check with a single ``assert_*``
        call: with several parts, one part's entries say little about the whole.
        Otherwise, and for any other error (an unanswered exercise, a typing slip), the
        error propagates and the cell earns 0.

    Attributes
    ----------
    score : float
        Points earned, set when the block ends: ``points`` when it ran without error;
        the partial credit, rounded to 0.01, when an assertion failed with some graded
        entries right (the block then ends quietly, printing the checker's message and
        the credit); else 0, and the error propagates.

    Notes
    -----
    The checkers are followed through the modules (``rc.assert_matrix``, as the course's
    check cells call them); a checker imported by name before the block is not seen,
    and its exercise is then graded as a whole.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz", a=(30, 0, 20))])
    >>> wrong = "[[cos(q1), sin(q1), 0, 30], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]"
    >>> with Credit(2) as credit:  # doctest: +ELLIPSIS
    ...     rc.assert_matrix(wrong, rc.expected_matrix(robot, "A1"))
    A1: 1 wrong entry.
    ...
    Partial credit: 1.67 of 2 points (1 of the 6 entries that count is wrong).
    >>> credit.score
    1.67
    """

    def __init__(self, points: float, *, partial: bool = True) -> None:
        if (
            isinstance(points, bool)
            or not isinstance(points, (int, float))
            or not math.isfinite(points)
            or points < 0
        ):
            raise InvalidInputError("points", points, "a finite number ≥ 0")
        self.points = float(points)
        self.partial = bool(partial)
        self.score = 0.0
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
        if error is None:
            self.score = self.points
            return False
        self.score = 0.0
        if not (self.partial and isinstance(error, AssertionError)):
            return False
        call = self._failed_check(error)
        if call is None:
            return False
        score = min(self.points, round(self.points * answer_credit(call.kind, call.result), 2))
        if score <= 0:
            return False
        self.score = score
        wrong, graded = credit_counts(call.kind, call.result) or (0, 0)
        print(str(error).strip() or str(call.result))
        print(
            f"\nPartial credit: {score:g} of {self.points:g} points ({wrong} of the {graded} "
            f"entr{'y' if graded == 1 else 'ies'} that count {'is' if wrong == 1 else 'are'} "
            "wrong)."
        )
        return True

    def _failed_check(self, error: BaseException) -> CheckCall | None:
        """The checker call whose failure ends the block, if a checker's error does."""
        for failure in (self._recheck_failure, self._recorder.raised):
            if failure is not None and failure[1] is error:
                return failure[0]
        return None

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
