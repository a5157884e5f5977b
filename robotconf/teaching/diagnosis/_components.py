"""Why a value or a vector is wrong: the usual slips, rebuilt and compared by number.

Each candidate mistake turns the expected numbers into what a student who made it would
have written (the sign flipped, two components swapped, degrees for radians, millimetres
for metres, a half turn, too few digits); a candidate that matches the answer within the
tolerance names the mistake. Angles compare modulo their period throughout.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..reading._shown import number_text, sentence
from ..reading._tolerance import KEEP_DIGITS

__all__ = [
    "allowed",
    "tolerance_text",
    "wrap",
    "Setting",
    "close",
    "explain_components",
    "is_rounded",
    "keep_digits",
    "length_unit",
    "names_text",
    "rounded",
]


def tolerance_text(tol: float, rel: float) -> str:
    """How close an answer must be, in words: ``"0.5 % (0.001 near 0)"``."""
    return f"{rel * 100:g} % ({tol:g} near 0)" if rel else f"{tol:g}"


def allowed(expected: np.ndarray, tol: float, rel: float) -> np.ndarray:
    """The largest difference accepted for each expected number: ``max(tol, rel·|e|)``."""
    return np.maximum(tol, rel * np.abs(expected))


def wrap(difference: np.ndarray, period: float | None) -> np.ndarray:
    """A difference taken to the nearest multiple of ``period`` (``None``: unchanged)."""
    if period is None:
        return difference
    return difference - period * np.round(difference / period)


_LENGTH = re.compile(r"(?<![A-Za-z])(?:mm|cm|dm|km|m)(?![A-Za-z])")


def length_unit(unit: str | None) -> bool:
    """Whether a unit involves a length (``mm``, ``m/s``…), so a factor of 1000 or 100 can
    be a unit slip; ``None`` (no unit given) may be one too. A rate in ``rad/s`` or a time
    in ``s`` cannot: a factor there has another cause (a missing ``/dt``).

    >>> length_unit("mm/s²"), length_unit("rad/s"), length_unit("s"), length_unit(None)
    (True, False, False, True)
    """
    return unit is None or bool(_LENGTH.search(unit))


@dataclass(frozen=True)
class Setting:
    """How one check compares numbers and words its hints.

    Attributes
    ----------
    tol, rel : float
        A number is right when ``|answer − expected| ≤ max(tol, rel·|expected|)``.
    period : float or None
        Angles: equal modulo this (``2π``, or 360 in degrees); ``None`` for plain numbers.
    degrees : bool
        The expected angles are in degrees.
    unit : str or None
        Appended to quoted numbers (``"mm/s"``).
    reveal : bool
        Whether hints may quote expected values.
    """

    tol: float
    rel: float
    period: float | None = None
    degrees: bool = False
    unit: str | None = None
    reveal: bool = False

    @property
    def angle(self) -> bool:
        return self.period is not None

    def show(self, value: float) -> str:
        """A number with the unit: ``"-99 rad/s"``."""
        return number_text(value) + (f" {self.unit}" if self.unit else "")


def close(
    student: np.ndarray, candidate: np.ndarray, setting: Setting, period: float | None
) -> np.ndarray:
    """Component-wise: the answer equals the candidate within the tolerance (mod period)."""
    gap = np.abs(wrap(student - candidate, period))
    return np.asarray(gap <= allowed(candidate, setting.tol, setting.rel))


def rounded(student: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """Element-wise: ``student`` is ``expected`` rounded to 1–3 significant digits or to
    0–3 decimals (a rounding that changes it). A 0 keeps no digit: it is never a rounding.

    Parameters
    ----------
    student, expected : ndarray, same shape

    Returns
    -------
    ndarray of bool
    """
    e = np.asarray(expected, dtype=float)
    s = np.asarray(student, dtype=float)[..., None]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        exponent = np.floor(np.log10(np.abs(e)))
        forms = [np.round(e / 10.0 ** (exponent - k)) * 10.0 ** (exponent - k) for k in range(3)]
        forms += [np.round(e, decimals) for decimals in range(4)]
        table = np.stack(forms, axis=-1)
        hit = np.isclose(s, table, rtol=1e-9, atol=1e-12)
        changed = ~np.isclose(table, e[..., None], rtol=1e-9, atol=0.0)
    usable = (e != 0) & np.isfinite(e) & (np.abs(e) <= 1e15) & (s[..., 0] != 0)
    return np.asarray(np.any(hit & changed, axis=-1) & usable)


def is_rounded(student: float, expected: float) -> bool:
    """``student`` is ``expected`` rounded to 1–3 significant digits or 0–3 decimals.

    >>> is_rounded(3.1, math.pi), is_rounded(3.2, math.pi), is_rounded(0.01, 0.0054)
    (True, False, True)
    """
    return bool(rounded(np.array(student), np.array(expected)))


def keep_digits(setting: Setting) -> str:
    """The advice for an over-rounded number."""
    within = tolerance_text(setting.tol, setting.rel)
    return f"{KEEP_DIGITS} (answers within {within} pass)"


def names_text(names: list[str], most: int = 6) -> str:
    """``"x"``, ``"x and z"``, ``"x, y and z"``; past ``most`` names, ``"… and 394 more"``.

    >>> names_text([f"q{i}" for i in range(1, 10)], most=3)
    'q1, q2, q3 and 6 more'
    """
    if len(names) > most:
        return ", ".join(names[:most]) + f" and {len(names) - most} more"
    if len(names) <= 1:
        return "".join(names)
    return ", ".join(names[:-1]) + " and " + names[-1]


def _whole_candidates(
    expected: np.ndarray, setting: Setting, what: str
) -> list[tuple[str, np.ndarray, float | None, str]]:
    """(code, what the answer would be, its period, the hint) for slips of the whole answer."""
    period = setting.period
    turn = "180°" if setting.degrees else "π"
    several = expected.size > 1
    sign = (
        (
            "sign_flipped",
            f"{sentence(what)} points the opposite way: every component has the wrong sign.",
        )
        if several
        else ("sign_error", f"{sentence(what)} has the wrong sign.")
    )
    found = [(sign[0], -expected, period, sign[1])]
    if setting.degrees:
        found.append(
            (
                "radians_as_degrees",
                np.radians(expected),
                None if period is None else math.radians(period),
                f"You gave radians: write {what} in degrees (π = 180°).",
            )
        )
    else:
        found.append(
            (
                "degrees_as_radians",
                np.degrees(expected),
                None if period is None else math.degrees(period),
                f"You gave degrees: write {what} in radians (180° = π).",
            )
        )
    if not setting.angle:
        factors = ((1000, "1 m = 1000 mm"), (100, "1 m = 100 cm"))
        for factor, unit in factors if length_unit(setting.unit) else ():
            found.append(
                (
                    "unit_factor",
                    expected * factor,
                    None,
                    f"{sentence(what)} is {factor} times too large: check the units ({unit}) "
                    "and the factors.",
                )
            )
            found.append(
                (
                    "unit_factor",
                    expected / factor,
                    None,
                    f"{sentence(what)} is {factor} times too small: check the units ({unit}) "
                    "and the factors.",
                )
            )
    elif not several:
        found.append(
            (
                "half_turn",
                expected + period / 2,  # type: ignore[operator]
                period,
                f"{sentence(what)} is off by half a turn ({turn}): check the quadrant "
                "(atan2(y, x), not atan(y/x)) or the direction of an axis.",
            )
        )
    return found


def explain_components(
    student: np.ndarray,
    expected: np.ndarray,
    setting: Setting,
    names: list[str],
    entries: list[str],
    what: str,
) -> tuple[list[int], list[str], list[str]]:
    """The wrong components of an answer of the right length, and why.

    Parameters
    ----------
    student, expected : ndarray, shape (n,)
    setting : Setting
    names : list of str
        The components' names (``x``, ``y``, ``z``); for n = 1 the hints use ``what``.
    entries : list of str
        The student's entries as written, for quoting.
    what : str
        The answer in words (``"the velocity"``).

    Returns
    -------
    wrong : list of int
        0-based wrong components (empty: the answer is right).
    hints : list of str
    codes : list of str
        Diagnosis codes, the main one first (``"wrong"`` when nothing is recognised).

    Examples
    --------
    >>> setting = Setting(tol=1e-3, rel=1e-3)
    >>> explain_components(
    ...     np.array([0.0, 35, 40]), np.array([0.0, 35, -40]), setting, ["x", "y", "z"],
    ...     ["0", "35", "40"], "the velocity")
    ([2], ['The sign of z is wrong.'], ['sign_error'])
    """
    period = setting.period
    wrong = [int(i) for i in np.flatnonzero(~close(student, expected, setting, period))]
    if not wrong:
        return [], [], []
    for code, candidate, candidate_period, hint in _whole_candidates(expected, setting, what):
        if close(student, candidate, setting, candidate_period).all():
            return wrong, [hint], [code]
    hints: list[str] = []
    codes: list[str] = []
    left = set(wrong)
    index = np.array(wrong)
    # fits[a, b]: wrong component a holds what wrong component b should; a pair that fits
    # both ways is two components exchanged
    fits = close(student[index][:, None], expected[index][None, :], setting, period)
    for a, b in np.argwhere(np.triu(fits & fits.T, 1)):
        i, j = int(index[a]), int(index[b])
        if {i, j} <= left:
            hints.append(f"{names[i]} and {names[j]} are swapped.")
            codes.append("swapped_components")
            left -= {i, j}
    single = len(expected) == 1

    def label(i: int) -> str:
        return sentence(what) if single else names[i]

    def per_component(code: str, found: list[int], one: str, many: str) -> None:
        if found:
            hints.append(
                one.format(label(found[0]))
                if len(found) == 1
                else many.format(names_text([names[i] for i in found]))
            )
            codes.append(code)
            left.difference_update(found)

    if not single:
        flipped = [
            i
            for i in sorted(left)
            if close(student[i : i + 1], -expected[i : i + 1], setting, period).all()
        ]
        per_component(
            "sign_error", flipped, "The sign of {} is wrong.", "The signs of {} are wrong."
        )
    if setting.angle and not single:
        half = [
            i
            for i in sorted(left)
            if close(student[i : i + 1], expected[i : i + 1] + period / 2, setting, period).all()  # type: ignore[operator]
        ]
        turn = "180°" if setting.degrees else "π"
        per_component(
            "half_turn",
            half,
            f"{{}} is off by half a turn ({turn}): check the quadrant or an axis direction.",
            f"{{}} are off by half a turn ({turn}): check the quadrant or an axis direction.",
        )
    unexplained = np.array(sorted(left), dtype=int)
    nearest = expected[unexplained]
    if period is not None:
        nearest = nearest + period * np.round((student[unexplained] - nearest) / period)
    too_few = [int(i) for i in unexplained[rounded(student[unexplained], nearest)]]
    keep = keep_digits(setting)
    per_component(
        "too_rounded",
        too_few,
        f"{{}} is rounded too much: {keep}.",
        f"{{}} are rounded too much: {keep}.",
    )
    rest = sorted(left)
    if rest and setting.reveal:
        for i in rest:
            hints.append(
                f"{label(i)}: expected {setting.show(expected[i])}, "
                f"you wrote {entries[i]}{' ' + setting.unit if setting.unit else ''}."
            )
    elif rest and single:
        unit = f" {setting.unit}" if setting.unit else ""
        hints.append(f"{entries[0]}{unit} is not right.")
    elif rest:
        verb = "is" if len(rest) == 1 else "are"
        hints.append(f"{names_text([names[i] for i in rest])} {verb} wrong.")
    if rest:
        codes.append("wrong")
    return wrong, [sentence(hint) for hint in hints], codes
