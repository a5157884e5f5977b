"""Numbers as a box shows them and as a student types them.

A degree conversion or a browser slider leaves noise in the last bits (``rad2deg(0.3839…)``
is ``21.99999999999997``; a slider from −45° to 225° sends ``7.1e-15`` for 0). The panel
shows each number rounded to 12 significant digits and to a billionth of the control's
step, so 90° reads ``90`` and noise reads ``0``; the control remembers the exact value it
was given, so an untouched box still gives back exactly that value (see
:class:`~robotconf.panel._number_control.NumberControl`).
"""

from __future__ import annotations

import math

from .._errors import InvalidInputError

__all__ = ["display_number", "snap_to_step", "parse_number"]

#: Significant digits shown: more than anyone types, fewer than float noise reaches.
SIGNIFICANT_DIGITS = 12
#: Below ``step × 10^-STEP_DIGITS`` a number is noise (a billionth of a slider step).
STEP_DIGITS = 9


def display_number(value: float, step: float = 1.0) -> float:
    """``value`` without float noise: 12 significant digits, and no digit finer than
    ``step × 1e-9``.

    Parameters
    ----------
    value : float
        In display units (degrees, length …); NaN and infinities pass unchanged.
    step : float
        The control's step (> 0).

    Returns
    -------
    float
        The number to show; ``-0.0`` becomes ``0.0``.

    Examples
    --------
    >>> display_number(21.99999999999997), display_number(89.99999999999999)
    (22.0, 90.0)
    >>> display_number(-7.105427357601002e-15), display_number(0.4318, 0.01)
    (0.0, 0.4318)
    """
    if not math.isfinite(value):
        return value
    rounded = float(f"{value:.{SIGNIFICANT_DIGITS}g}")
    decimals = STEP_DIGITS - math.floor(math.log10(step)) if step > 0 else SIGNIFICANT_DIGITS
    return round(rounded, decimals) + 0.0  # + 0.0 turns -0.0 into 0.0


def snap_to_step(value: float, step: float) -> float:
    """``value`` moved onto the multiple of ``step`` it is within noise of, else unchanged.

    A browser slider computes its value through percentages of its range, so it sends
    ``7.1e-15`` or ``29.999999999999996`` for a notch at 0 or 30.

    Examples
    --------
    >>> snap_to_step(7.105427357601002e-15, 1.0), snap_to_step(29.999999999999996, 1.0)
    (0.0, 30.0)
    >>> snap_to_step(0.07000000000000001, 0.01), snap_to_step(12.345, 1.0)
    (0.07, 12.345)
    """
    if not math.isfinite(value) or step <= 0:
        return value
    notch = round(value / step) * step
    if abs(value - notch) <= step * 1e-6:
        return display_number(notch, step)
    return display_number(value, step)


def parse_number(text: str, field: str) -> float:
    """The number in a student's typed ``text``, or a message that says why not.

    Accepts what a calculator shows: ``12``, ``-0.5``, ``1e-3``, ``+3``, and a decimal
    comma (``2,5``). Nothing is evaluated (no ``pi``, no ``1/2``).

    Raises
    ------
    InvalidInputError
        Naming ``field``, for text that is no number, and for ``nan`` or an infinity
        (``1e999``), which no robot takes.

    Examples
    --------
    >>> parse_number(" 2,5 ", "q2"), parse_number("1e-3", "q2")
    (2.5, 0.001)
    >>> parse_number("abc", "q2")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: q2: not a number: 'abc'; allowed: a number such as 12, -0.5 or 1e-3
    >>> parse_number("1e999", "q2")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: q2: too large for a number: '1e999'; allowed: a finite number ...
    """
    raw = text.strip() if isinstance(text, str) else ""
    cleaned = raw.replace(" ", "")
    if cleaned.count(",") == 1 and "." not in cleaned:
        cleaned = cleaned.replace(",", ".")
    allowed = "a number such as 12, -0.5 or 1e-3"
    if not cleaned or len(cleaned) > 64 or any(c not in "0123456789+-.eE" for c in cleaned):
        raise InvalidInputError(field, raw[:64], allowed, problem="not a number:")
    try:
        value = float(cleaned)
    except ValueError:
        raise InvalidInputError(field, raw, allowed, problem="not a number:") from None
    if not math.isfinite(value):
        raise InvalidInputError(
            field,
            raw,
            "a finite number (|x| below about 1.8e308)",
            problem="too large for a number:",
        )
    return value
