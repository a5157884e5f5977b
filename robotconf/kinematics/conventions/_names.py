"""Names of links and robots: text of bounded length, and one module per name.

A module, its coordinate and the end-effector are all found by name
(:meth:`Robot.index`), and plots, the 3D scene and reports label points by the modules'
display names (a module's own name, else ``M1, M2, …``). So within one robot every display
name is unique, and no module takes the end-effector's name ``EE`` or another module's
coordinate name (``q2``): two modules called ``EE`` would otherwise draw over each other's
label, and ``robot.index("base")`` could not say which module it means.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..._errors import InvalidInputError
from ..._validation import one_line

__all__ = ["MAX_NAME_CHARS", "check_name", "check_module_names"]

#: Longest robot or link name (characters); the file format has the same limit.
MAX_NAME_CHARS = 200


def check_name(value: Any, field: str = "name") -> str | None:
    """``None``, or text of at most :data:`MAX_NAME_CHARS` characters.

    >>> check_name("shoulder")
    'shoulder'
    >>> check_name(5)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: name: invalid value 5; allowed: text or None
    """
    if value is None:
        return None
    if not isinstance(value, str):
        raise InvalidInputError(field, one_line(value), "text or None")
    if len(value) > MAX_NAME_CHARS:
        raise InvalidInputError(
            field,
            value,
            f"text of at most {MAX_NAME_CHARS} characters, or None",
            problem=f"longer than {MAX_NAME_CHARS} characters:",
        )
    return value


def check_module_names(names: Sequence[str | None]) -> None:
    """Refuse module names that would make a robot's names ambiguous.

    Parameters
    ----------
    names : sequence of str or None
        Each module's own name (``None``: the default ``M<i+1>``).

    Raises
    ------
    InvalidInputError
        Field ``modules[i].name`` for the name ``EE`` (any case), another module's
        coordinate name (``q<j>``, any case), or a display name that another module
        already has; the message names both indices.

    Examples
    --------
    >>> check_module_names([None, "elbow", "q3"])
    >>> check_module_names(["base", "base"])
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: modules[1].name: modules[0] and modules[1] are both named ...
    >>> check_module_names(["M2", None])
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: modules[0].name: the unnamed modules[1] is shown as 'M2', ...
    """
    n = len(names)
    coordinates = {f"q{k + 1}" for k in range(n)}
    seen: dict[str, int] = {}
    for i, name in enumerate(names):
        display = name if name is not None else f"M{i + 1}"
        if name is not None:
            label = name.strip().lower()
            if label == "ee" or label in coordinates - {f"q{i + 1}"}:
                raise InvalidInputError(
                    f"modules[{i}].name",
                    name,
                    f"a name other than 'EE' and the coordinate names q1 to q{n} "
                    f"(q{i + 1} is fine)",
                    problem="ambiguous module name",
                )
        if display in seen:
            raise _duplicate(names, seen[display], i, display)
        seen[display] = i


def _duplicate(names: Sequence[str | None], first: int, second: int, display: str) -> Exception:
    allowed = "a different name for each module (unnamed modules are shown as M1, M2, …)"
    if names[first] is not None and names[second] is not None:
        return InvalidInputError(
            f"modules[{second}].name",
            display,
            allowed,
            problem=f"modules[{first}] and modules[{second}] are both named",
        )
    named, unnamed = (first, second) if names[first] is not None else (second, first)
    return InvalidInputError(
        f"modules[{named}].name",
        display,
        allowed,
        problem=f"the unnamed modules[{unnamed}] is shown as {display!r}, and modules[{named}] "
        "is named",
    )
