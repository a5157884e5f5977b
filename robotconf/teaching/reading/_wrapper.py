"""The one wrapper every public check, assert and parse goes through.

A student reads what a check says, not the checker's frames: a malformed answer ends as
one :class:`~robotconf.InvalidInputError` line (with a caret under a typing slip), a
wrong answer in an ``assert_*`` as one ``AssertionError`` whose message is the verdict.
:func:`answer_check` is the prologue and epilogue of every ``check_*`` (and of the
parser), :func:`passed` the epilogue of every ``assert_*``; the ``AssertionError`` it
raises carries the verdict as ``.check``, so a grader reads the diagnosis without
parsing the message.
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Callable
from typing import Any, TypeVar

from ..._errors import InvalidInputError

__all__ = ["answer_check", "passed", "short_traceback"]

E = TypeVar("E", bound=BaseException)
F = TypeVar("F", bound=Callable[..., Any])
R = TypeVar("R")


def _render(name: str, message: str) -> list[str]:
    head = f"{name}: "
    first, *rest = message.split("\n")
    # The caret line is aligned for the message alone; the type name shifts it here.
    return [head + first, *(" " * len(head) + line for line in rest)]


def short_traceback(error: E) -> E:
    """``error`` without the checker's internal frames, shown in IPython as its message.

    The frames below the public call say nothing to a student. IPython uses an
    exception's ``_render_traceback_`` instead of its traceback (and would show the
    innermost frame even when marked ``__tracebackhide__``).

    >>> error = short_traceback(ValueError("`2 q1`: write 2*q1\\n   ^"))
    >>> error._render_traceback_()
    ['ValueError: `2 q1`: write 2*q1', '               ^']
    """
    name = type(error).__name__
    render = functools.partial(_render, name, str(error))
    error._render_traceback_ = render  # type: ignore[attr-defined]
    return error.with_traceback(None)


def answer_check(function: F | None = None, *, kind: str | None = None) -> Any:
    """Decorate a public check: bad input ends as one short ``InvalidInputError``.

    The decorated function keeps its name, signature and docstring; an
    :class:`~robotconf.InvalidInputError` raised anywhere below it reaches the caller
    without the checker's internal frames (:func:`short_traceback`). With ``kind``
    (``@answer_check(kind="set")``), the verdict's ``kind`` says which check made it, so
    a grader can count its numbers without knowing the call.

    >>> @answer_check
    ... def check_positive(x):
    ...     if x <= 0:
    ...         raise InvalidInputError("x", x, "a number > 0")
    ...     return x
    >>> check_positive(-1)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: x: invalid value -1; allowed: a number > 0
    """
    if function is None:
        return functools.partial(answer_check, kind=kind)

    @functools.wraps(function)
    def check(*args: Any, **kwargs: Any) -> Any:
        __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
        try:
            result = function(*args, **kwargs)
        except InvalidInputError as error:
            raise short_traceback(error) from None
        if kind is not None and dataclasses.is_dataclass(result):
            result = dataclasses.replace(result, kind=kind)  # type: ignore[type-var]
        return result

    # A plain traceback's last line then names the public call (check_matrix), not "check".
    check.__code__ = check.__code__.replace(co_name=function.__name__)  # type: ignore[attr-defined]
    return check


def passed(result: R) -> R:
    """The epilogue of an ``assert_*``: ``result`` if it is ok, else ``AssertionError``.

    The error's message is ``str(result)`` (the headline and one line per hint) and its
    ``check`` attribute is ``result`` itself.

    >>> from robotconf.teaching import check_value
    >>> passed(check_value(2, 2)).ok
    True
    >>> try:
    ...     passed(check_value(-2, 2, name="x"))
    ... except AssertionError as error:
    ...     print(error.check.diagnosis)
    sign_error
    """
    __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
    if not result.ok:  # type: ignore[attr-defined]
        error = AssertionError(str(result))
        error.check = result  # type: ignore[attr-defined]
        raise short_traceback(error)
    return result
