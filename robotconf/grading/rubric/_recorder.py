"""Record every call of robotconf's checkers while a block of notebook code runs.

The course's check cells call a checker: ``rc.assert_matrix``, ``rc.assert_vector``,
``rc.assert_value``, ``rc.assert_angle``, ``rc.assert_set``, ``rc.assert_interval``,
``rc.assert_dh_table``, ``rc.assert_ik_solution(s)``, ``rc.assert_profile`` or their
``check_*`` forms (course README, "How the exercises
are built"). To grade per entry or to read the expected value for an answer key, the
grading tools need each call's verdict, whatever else the cell does. So for the
duration of a block every checker is replaced, in ``robotconf`` (the ``rc`` of a
notebook) and in ``robotconf.teaching``, by a twin that checks exactly as before and
keeps the verdict. The facade is found in ``sys.modules`` rather than imported: it is
the module object the notebook itself holds.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from types import ModuleType, TracebackType
from typing import Any

from ... import teaching

__all__ = ["CHECKERS", "CheckCall", "CheckRecorder"]

#: Each kind of answer: its checker and the twin that raises ``AssertionError``.
CHECKERS = {
    "matrix": ("check_matrix", "assert_matrix"),
    "value": ("check_value", "assert_value"),
    "vector": ("check_vector", "assert_vector"),
    "angle": ("check_angle", "assert_angle"),
    "set": ("check_set", "assert_set"),
    "interval": ("check_interval", "assert_interval"),
    "dh_table": ("check_dh_table", "assert_dh_table"),
    "ik_solution": ("check_ik_solution", "assert_ik_solution"),
    "ik_solutions": ("check_ik_solutions", "assert_ik_solutions"),
    "profile": ("check_profile", "assert_profile"),
}

# Taken before any twin is installed; a checker this version lacks is left out.
_ORIGINALS: dict[str, Callable[..., Any]] = {
    name: getattr(teaching, name)
    for pair in CHECKERS.values()
    for name in pair
    if callable(getattr(teaching, name, None))
}


def original(name: str) -> Callable[..., Any]:
    """The checker ``name`` itself (never a recording twin).

    >>> original("check_matrix") is teaching.check_matrix
    True
    """
    return _ORIGINALS[name]


@dataclass(frozen=True)
class CheckCall:
    """One call of a checker.

    Attributes
    ----------
    label : str or None
        What the recorder was told it is checking (an answer variable), if anything.
    kind : str
        A key of :data:`CHECKERS`: ``"matrix"``, ``"vector"``, ...
    student : object
        The answer as handed to the checker.
    expected : object
        The reference as handed to the checker (for the IK checks, which take a robot
        and a target, the tuple ``(robot, target)``).
    options : dict
        Keyword options (``tol``, ``samples``, ...).
    result : MatrixCheck, AnswerCheck or DHTableCheck
        The verdict.
    asserted : bool
        Made through an ``assert_*`` checker (one that raises when wrong): the check
        cell's verdict, where ``check_*`` calls may only pick a hint.
    """

    label: str | None
    kind: str
    student: Any
    expected: Any
    options: dict[str, Any]
    result: Any
    asserted: bool = False


@dataclass
class CheckRecorder:
    """Replaces the checkers by recording twins while installed.

    Attributes
    ----------
    calls : list of CheckCall
        Every call made while installed, in order.
    label : str or None
        Stamped on each new call (set it before a check cell runs).
    raised : (CheckCall, AssertionError) or None
        The last ``assert_*`` call that failed, with the very error it raised.

    Examples
    --------
    >>> import numpy as np
    >>> with CheckRecorder() as recorder:
    ...     verdict = teaching.check_matrix([[1, 0], [0, 2]], np.eye(2))
    >>> len(recorder.calls), recorder.calls[0].kind, recorder.calls[0].result.wrong_entries
    (1, 'matrix', [(1, 1)])
    >>> teaching.check_matrix is original("check_matrix")  # the original is back
    True
    """

    calls: list[CheckCall] = field(default_factory=list)
    label: str | None = None
    raised: tuple[CheckCall, AssertionError] | None = None
    _saved: list[tuple[ModuleType, str, Any]] = field(default_factory=list, repr=False)

    def _twins(self, kind: str) -> dict[str, Callable[..., Any]]:
        check_name, assert_name = CHECKERS[kind]
        if check_name not in _ORIGINALS or assert_name not in _ORIGINALS:
            return {}
        check, raise_ = _ORIGINALS[check_name], _ORIGINALS[assert_name]

        def checked(
            student: Any,
            expected: Any,
            rest: tuple[Any, ...],
            options: dict[str, Any],
            asserted: bool,
        ) -> Any:
            result = check(student, expected, *rest, **options)
            reference = (expected, *rest) if rest else expected
            call = CheckCall(self.label, kind, student, reference, options, result, asserted)
            self.calls.append(call)
            return call

        @functools.wraps(check)
        def check_twin(student: Any, expected: Any, *rest: Any, **options: Any) -> Any:
            __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
            return checked(student, expected, rest, options, False).result

        @functools.wraps(raise_)
        def assert_twin(student: Any, expected: Any, *rest: Any, **options: Any) -> Any:
            __tracebackhide__ = True  # noqa: F841
            call = checked(student, expected, rest, options, True)
            if call.result.ok:
                return call.result
            try:
                raise_(student, expected, *rest, **options)  # the checker's own message
            except AssertionError as error:
                self.raised = (call, error)
                raise
            raise AssertionError(str(call.result))  # pragma: no cover (raise_ raised)

        return {check_name: check_twin, assert_name: assert_twin}

    def install(self) -> CheckRecorder:
        """Put the recording twins in place; returns the recorder."""
        if self._saved:
            return self
        twins: dict[str, Callable[..., Any]] = {}
        for kind in CHECKERS:
            twins.update(self._twins(kind))
        for module in (teaching, sys.modules.get("robotconf")):
            if module is None:
                continue
            for name, twin in twins.items():
                if hasattr(module, name):
                    self._saved.append((module, name, getattr(module, name)))
                    setattr(module, name, twin)
        return self

    def uninstall(self) -> None:
        """Put the checkers back as they were."""
        while self._saved:
            module, name, before = self._saved.pop()
            setattr(module, name, before)

    def __enter__(self) -> CheckRecorder:
        return self.install()

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.uninstall()
