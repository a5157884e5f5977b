"""A small, safe language for signals on a command line: ``q3=repeating:times=0,2;values=0,2``.

Grammar (no ``eval``: every number goes through ``float`` or the ``pi`` pattern below)::

    spec     := NAME "=" KIND [":" args]
    NAME     := "q" digits                      (the coordinate, e.g. q3)
    args     := item (("," | ";") item)*
    item     := key "=" number | number         (a bare number continues the previous key's
                                                 list, or is the only parameter's value)
    number   := float (1, -0.5, 2e-3) | [sign][factor][*]pi[/divisor] (pi/2, -2*pi, 0.5pi)
                of at most MAX_NUMBER_CHARS (40) ASCII characters

Kinds and their parameters (Simulink's blocks; see :mod:`robotconf.signals`)::

    constant     level                                   constant:0.3
    step         time (=step_time), initial, final       step:time=1,final=0.5
    ramp         slope, start_time, initial_output       ramp:slope=0.1
    sine         amplitude, bias, frequency (Hz), phase  sine:amplitude=1,frequency=0.5
    repeating    times (list), values (list)             repeating:times=0,2;values=0,2
    cubic, quintic       start, end, duration, start_time           cubic:end=1,duration=2
    trapezoidal          start, end, duration, start_time, accel_fraction

``repeating`` alone is Simulink's default sawtooth (times 0, 2; values 0, 2).

Parsing takes time linear in the length of the text: a spec is at most
:data:`MAX_SPEC_LENGTH` characters, a number at most :data:`MAX_NUMBER_CHARS` (checked
before any pattern runs), and the number patterns never backtrack more than a step
(``\\d+(\\.\\d*)?`` instead of the ambiguous ``\\d+\\.?\\d*``).
"""

from __future__ import annotations

import dataclasses
import math
import re
from typing import Any

from .._errors import InvalidInputError
from .._validation import one_line
from ._base import Signal
from ._serialize import SIGNAL_TYPES

__all__ = [
    "parse_signal_spec",
    "parse_signal",
    "SIGNAL_KINDS",
    "SPEC_HELP",
    "MAX_SPEC_LENGTH",
    "MAX_NUMBER_CHARS",
]

#: Longest spec accepted (characters): a command line, not a data file.
MAX_SPEC_LENGTH = 10_000

#: Longest number (characters, with sign, exponent or pi): 17 significant digits give
#: every float, so 40 leaves room for ``-1.2345678901234567e-300*pi/2``-like forms.
MAX_NUMBER_CHARS = 40


def _kind(name: str) -> tuple[type[Signal], tuple[str, ...], tuple[str, ...]]:
    # Parameters are the signal class's own public fields, so the spec never drifts.
    cls = SIGNAL_TYPES[name]
    public = dataclasses.fields(cls)  # type: ignore[arg-type]
    fields = tuple(f.name for f in public if f.init and not f.name.startswith("_"))
    lists = fields if name == "RepeatingSequence" else ()
    return cls, fields, lists


#: kind → (signal class, parameters, parameters that take a list)
SIGNAL_KINDS: dict[str, tuple[type[Signal], tuple[str, ...], tuple[str, ...]]] = {
    "constant": _kind("Constant"),
    "step": _kind("Step"),
    "ramp": _kind("Ramp"),
    "sine": _kind("Sine"),
    "repeating": _kind("RepeatingSequence"),
    "cubic": _kind("Cubic"),
    "quintic": _kind("Quintic"),
    "trapezoidal": _kind("Trapezoidal"),
}

_KIND_ALIASES = {"const": "constant", "sin": "sine", "repeating_sequence": "repeating"}
_KEY_ALIASES = {"step": {"time": "step_time"}, "ramp": {"initial": "initial_output"}}

SPEC_HELP = (
    "SPEC is NAME=KIND[:ARGS], e.g. q3=repeating:times=0,2;values=0,2 | "
    "q1=sine:amplitude=1,frequency=0.5 | q2=step:time=1,final=0.5 | q2=ramp:slope=0.1 | "
    "q1=constant:0.3 | q2=cubic:end=1,duration=2. Kinds: "
    + ", ".join(SIGNAL_KINDS)
    + ". ARGS are key=value items separated by ',' or ';'; a bare number continues the "
    "previous key's list (times=0,1,2). Numbers may use pi: pi/2, -2*pi."
)

_NAME = re.compile(r"q[1-9][0-9]{0,3}", re.ASCII)
# Unambiguous pieces (each digit can belong to one quantifier only), ASCII digits only:
# Python's \d also matches Arabic-Indic and other digits, which float() would accept.
_DECIMAL = r"(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)"
_PI = re.compile(
    rf"([+-]?)(?:({_DECIMAL}(?:e[+-]?[0-9]+)?)[ \t]*\*?[ \t]*)?pi(?:[ \t]*/[ \t]*({_DECIMAL}))?",
    re.ASCII,
)
_FLOAT = re.compile(rf"[+-]?{_DECIMAL}(?:e[+-]?[0-9]+)?", re.ASCII)


def _shown(token: str) -> str:
    """A token for a message: quoted, and cut short when long."""
    text = token.strip()
    return repr(text if len(text) <= 24 else text[:20] + "…")


def _number(token: str, spec: str) -> float:
    text = token.strip().lower()
    allowed = "a finite number such as 0.5, -2, 1e-3, pi/2 or 2*pi"
    if len(text) > MAX_NUMBER_CHARS:
        raise InvalidInputError(
            "signal",
            spec,
            f"{allowed}, of at most {MAX_NUMBER_CHARS} characters",
            problem=f"the number {_shown(token)} ({len(text)} characters) is too long in",
        )
    if _FLOAT.fullmatch(text):
        value = float(text)
    elif match := _PI.fullmatch(text):
        sign, factor, divisor = match.groups()
        value = (float(factor) if factor else 1.0) * math.pi
        if divisor is not None:
            if float(divisor) == 0.0:
                raise InvalidInputError("signal", spec, allowed, problem="division by zero in")
            value /= float(divisor)
        value = -value if sign == "-" else value
    else:
        raise InvalidInputError(
            "signal", spec, allowed, problem=f"{_shown(token)} is not a number in"
        )
    if not math.isfinite(value):
        raise InvalidInputError(
            "signal", spec, allowed, problem=f"{_shown(token)} is not finite in"
        )
    return value


def _arguments(kind: str, text: str, spec: str) -> dict[str, Any]:
    _, names, lists = SIGNAL_KINDS[kind]
    aliases = _KEY_ALIASES.get(kind, {})
    allowed = f"{kind} parameters: {', '.join(names)}"
    values: dict[str, list[float]] = {}
    current: str | None = None
    for item in re.split(r"[,;]", text):
        if not item.strip():
            raise InvalidInputError("signal", spec, allowed, problem="empty item in")
        if "=" in item:
            key, _, number = item.partition("=")
            key = aliases.get(key.strip().lower(), key.strip().lower())
            if key not in names:
                raise InvalidInputError(
                    "signal", spec, allowed, problem=f"unknown parameter {key!r} in"
                )
            if key in values:
                raise InvalidInputError("signal", spec, allowed, problem=f"{key!r} given twice in")
            current = key
            values[key] = [_number(number, spec)]
        elif current is None:
            if len(names) != 1:
                raise InvalidInputError(
                    "signal", spec, allowed, problem=f"{kind} needs key=value items, got"
                )
            current = names[0]
            values[current] = [_number(item, spec)]
        else:
            values[current].append(_number(item, spec))
    result: dict[str, Any] = {}
    for key, numbers in values.items():
        if key in lists:
            result[key] = numbers
        elif len(numbers) != 1:
            raise InvalidInputError(
                "signal", spec, allowed, problem=f"{key!r} takes one number, got {len(numbers)} in"
            )
        else:
            result[key] = numbers[0]
    return result


def parse_signal(text: str, spec: str | None = None) -> Signal:
    """A signal from ``KIND[:ARGS]`` (the part after ``q3=``).

    Parameters
    ----------
    text : str
        E.g. ``"sine:amplitude=1,frequency=0.5"`` (see the module notes for the grammar).
    spec : str, optional
        The whole spec, quoted in error messages.

    Returns
    -------
    Signal

    Raises
    ------
    InvalidInputError
        For text longer than :data:`MAX_SPEC_LENGTH`, an unknown kind or parameter, a
        malformed or too long number, NaN or infinity, a repeated parameter, or
        parameters the signal itself refuses (e.g. times that decrease).

    Examples
    --------
    >>> parse_signal("sine:amplitude=1,frequency=0.5")
    Sine(frequency=0.5)
    >>> parse_signal("repeating:times=0,1,2;values=0,1,0").value(0.5)
    0.5
    >>> parse_signal("constant:pi/2").level
    1.5707963267948966
    """
    spec = text if spec is None else spec
    if not isinstance(text, str):
        raise InvalidInputError("signal", one_line(text), "KIND[:ARGS] text", problem="not text:")
    if len(text) > MAX_SPEC_LENGTH:
        raise InvalidInputError(
            "signal",
            spec,
            f"KIND[:ARGS] text of at most {MAX_SPEC_LENGTH} characters",
            problem=f"longer than {MAX_SPEC_LENGTH} characters:",
        )
    kind_text, has_args, args = text.partition(":")
    key = kind_text.strip().lower()
    kind = _KIND_ALIASES.get(key, key)
    if kind not in SIGNAL_KINDS:
        raise InvalidInputError(
            "signal", spec, f"kinds: {', '.join(SIGNAL_KINDS)}", problem=f"unknown kind {key!r} in"
        )
    cls = SIGNAL_KINDS[kind][0]
    arguments = _arguments(kind, args, spec) if has_args else {}
    try:
        return cls(**arguments)
    except InvalidInputError as error:
        # The signal's own check (e.g. times must increase) with the spec that caused it.
        raise InvalidInputError(
            "signal",
            spec,
            error.allowed,
            problem=f"{error.field}: {error.problem} {error.value!r} in",
        ) from None


def parse_signal_spec(spec: Any) -> tuple[str, Signal]:
    """``"q3=repeating:times=0,2;values=0,2"`` → ``("q3", RepeatingSequence(...))``.

    Parameters
    ----------
    spec : str
        ``NAME=KIND[:ARGS]`` with NAME a coordinate ``q1``, ``q2``, …

    Returns
    -------
    (str, Signal)

    Raises
    ------
    InvalidInputError
        For text that is too long, a missing ``=``, a bad coordinate name, or a bad signal
        (see :func:`parse_signal`).

    Examples
    --------
    >>> parse_signal_spec("q2=step:time=1,final=0.5")
    ('q2', Step(final=0.5))
    >>> parse_signal_spec("q3=repeating")
    ('q3', RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0)))
    >>> parse_signal_spec("q1=sine:amplitude=nan")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: signal: 'nan' is not a number in 'q1=sine:amplitude=nan'; ...
    """
    allowed = "NAME=KIND[:ARGS] such as q3=repeating:times=0,2;values=0,2"
    if not isinstance(spec, str):
        raise InvalidInputError("signal", one_line(spec), allowed, problem="not text:")
    if len(spec) > MAX_SPEC_LENGTH:
        raise InvalidInputError(
            "signal", spec, allowed, problem=f"longer than {MAX_SPEC_LENGTH} characters:"
        )
    name, has_equal, rest = spec.partition("=")
    if not has_equal or not rest.strip():
        raise InvalidInputError("signal", spec, allowed, problem="expected NAME=KIND, got")
    name = name.strip().lower()
    if not _NAME.fullmatch(name):
        raise InvalidInputError(
            "signal", spec, allowed, problem=f"{name!r} is not a coordinate name (q1, q2, …) in"
        )
    return name, parse_signal(rest, spec)
