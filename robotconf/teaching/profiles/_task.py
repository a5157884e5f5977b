"""What a motion-profile exercise asks: a rest-to-rest move, and its answer in every form.

A :class:`ProfileTask` holds the move as the task states it — each joint's distance, the
kind of profile and either the limits (trapezoid, and the time-optimal cubic or quintic)
or the duration (a cubic or quintic in a given time) — and computes the right numbers in
each form an answer may take (:data:`PROFILE_FORMS`). Several joints move
**synchronized**, as a robot controller's PTP does: one law ``u(t)`` for all, under
``V = min_j v_j/|Δ_j|`` and ``A = min_j a_j/|Δ_j|``, so the slowest joint sets the
duration (docs/programs.md, "Time laws"). The numbers are computed here, independently
of :mod:`robotconf.programs`; the tests compare the two.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ._forms import check_times, read
from ._laws import Law, optimal_law, timed_law

__all__ = ["MAX_JOINTS", "PROFILE_KINDS", "ProfileTask"]

#: The profiles a task may ask for.
PROFILE_KINDS = ("trapezoidal", "cubic", "quintic")

#: Most joints a task may move.
MAX_JOINTS = 64


def _per_joint(value: Any, n: int | None, field: str, positive: bool) -> np.ndarray:
    """One number or one per joint, as a float array; finite, and > 0 if ``positive``."""
    if isinstance(value, (str, bytes)) or value is None:
        raise InvalidInputError(field, value, "a number or a list of numbers")
    array = np.asarray(value, dtype=object)
    if array.ndim > 1 or array.size == 0 or array.size > MAX_JOINTS:
        raise InvalidInputError(field, value, f"a number or a list of 1 … {MAX_JOINTS} numbers")
    items = [check_finite_number(x, field) for x in array.reshape(-1)]
    numbers = np.array(items, dtype=float)
    if positive and not (numbers > 0).all():
        raise InvalidInputError(field, value, "numbers > 0")
    if n is not None:
        if numbers.size == 1:
            return np.full(n, numbers[0])
        if numbers.size != n:
            raise InvalidInputError(field, value, f"one number, or {n} (one per joint)")
    return numbers


def _names(joints: Any, n: int) -> tuple[str, ...]:
    if joints is None:
        return ("q",) if n == 1 else tuple(f"q{i + 1}" for i in range(n))
    names = [joints] if isinstance(joints, str) else list(joints)
    if len(names) != n or not all(isinstance(x, str) and 0 < len(x) <= 40 for x in names):
        raise InvalidInputError("joints", joints, f"{n} names (text of 1 … 40 characters)")
    return tuple(names)


class ProfileTask:
    """A rest-to-rest move as an exercise states it; the reference of :func:`check_profile`.

    Parameters
    ----------
    distance : float or array-like, shape (n,)
        Each joint's displacement ``Δ_j`` (rad, or length for a slide); the sign is the
        direction. A joint with ``Δ = 0`` stays; at least one must move.
    kind : {"trapezoidal", "cubic", "quintic"}
        The profile.
    speed, accel : float or array-like, shape (n,), optional
        The joints' limits ``v_j`` (per s) and ``a_j`` (per s²), > 0. Required for a
        trapezoid; a cubic or quintic takes either these (the fastest one within
        them) or ``duration``.
    duration : float, optional
        ``T`` (s) of a cubic or quintic given its time.
    start : float or array-like, shape (n,)
        ``q(0)``, the constant term of the coefficients (default 0).
    joints : sequence of str, optional
        Names for the messages; default ``q`` for one joint, ``q1 … qn`` for several.

    Attributes
    ----------
    law : Law
        The normalized law ``u(t)`` all joints follow: ``q_j = q_j0 + Δ_j·u``.
    duration, blend : float
        ``T`` and the trapezoid's acceleration time ``t_a`` (s; 0 for a polynomial).
    shape : str
        ``"trapezoid"``, ``"triangle"`` (the speed limit is not reached), ``"cubic"`` or
        ``"quintic"``.
    peak_speed, peak_accel : ndarray, shape (n,)
        Each joint's ``|Δ_j|·max u̇`` and ``|Δ_j|·max |ü|``.
    own_durations : ndarray, shape (n,)
        Each joint's duration moving alone under its own limits (0 for a joint that
        stays): the numbers of a forgotten synchronization.

    Raises
    ------
    InvalidInputError
        For a bad kind, a distance or limit that is not a finite number (or list of
        them), limits ≤ 0, a missing or extra limit or duration, and numbers so extreme
        that the profile leaves the float range.

    Examples
    --------
    A trapezoid (t_a = v/a = 0.5 s, T = d/v + v/a = 2.5 s) and a triangle (d < v²/a):

    >>> ProfileTask(2.0, speed=1.0, accel=2.0).expected().tolist()  # [t_accel, t_total, v_peak]
    [0.5, 2.5, 1.0]
    >>> ProfileTask(0.125, speed=1.0, accel=2.0).shape
    'triangle'

    Three joints, synchronized: the slowest (joint 3) sets T; each alone would be faster.

    >>> task = ProfileTask([0.5, -1.0, 1.5], speed=1.0, accel=2.0)
    >>> task.duration, task.own_durations.tolist()
    (2.0, [1.0, 1.5, 2.0])
    """

    __slots__ = ("_kind", "_delta", "_speed", "_accel", "_given", "_start", "_joints", "_law")

    def __init__(
        self,
        distance: Any,
        *,
        kind: str = "trapezoidal",
        speed: Any = None,
        accel: Any = None,
        duration: Any = None,
        start: Any = 0.0,
        joints: Sequence[str] | None = None,
    ) -> None:
        if not isinstance(kind, str) or kind not in PROFILE_KINDS:
            raise InvalidInputError("kind", kind, ", ".join(PROFILE_KINDS))
        self._kind = kind
        self._delta = _per_joint(distance, None, "distance", positive=False)
        n = self._delta.size
        if not self._delta.any():
            raise InvalidInputError("distance", distance, "at least one distance ≠ 0")
        limits = speed is not None or accel is not None
        both = "both speed= and accel="
        if kind == "trapezoidal" and duration is not None:
            raise InvalidInputError(
                "duration", duration, "none for a trapezoid: it follows from speed= and accel="
            )
        if kind != "trapezoidal" and limits and duration is not None:
            raise InvalidInputError(
                "duration", duration, "either duration= or speed= and accel=, not both"
            )
        if kind != "trapezoidal" and not limits and duration is None:
            raise InvalidInputError(
                "duration", duration, f"a {kind} takes duration= or speed= and accel="
            )
        if (limits or kind == "trapezoidal") and (speed is None or accel is None):
            raise InvalidInputError("speed" if speed is None else "accel", None, both)
        self._speed = _per_joint(speed, n, "speed", positive=True) if limits else None
        self._accel = _per_joint(accel, n, "accel", positive=True) if limits else None
        self._given: float | None = None
        if duration is not None:
            self._given = float(_per_joint(duration, 1, "duration", positive=True)[0])
        self._start = _per_joint(start, n, "start", positive=False)
        self._joints = _names(joints, n)
        # Extreme ratios (1e-300 rad/s over 1e300 rad) underflow to 0 or overflow: refused.
        numbers = [math.nan]
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
            try:
                self._law = self._own_law(None)
                numbers = [self._law.duration, self._law.speed, self._law.accel]
                if self._kind != "trapezoidal":
                    numbers.extend(self.coefficients().reshape(-1))
                numbers.extend(self.peak_accel)
                numbers.extend(self.own_durations)
                numbers.extend(1.0 / np.array(numbers[:3]))
            except (ZeroDivisionError, OverflowError):
                pass
        if not np.isfinite(numbers).all():
            field, value = ("distance", distance) if duration is None else ("duration", duration)
            raise InvalidInputError(
                field,
                value,
                "distances, limits and durations whose profile stays within the float range",
                problem="the profile overflows for",
            )

    # -- the move -----------------------------------------------------------------------

    def _own_law(self, j: int | None) -> Law:
        """The law of all joints together (``j=None``) or of joint ``j`` alone."""
        if self._given is not None:
            return timed_law(self._kind, self._given)
        assert self._speed is not None and self._accel is not None
        moving = self._delta != 0 if j is None else np.arange(self._delta.size) == j
        reach = np.abs(self._delta[moving])
        speed = float(np.min(self._speed[moving] / reach))
        accel = float(np.min(self._accel[moving] / reach))
        return optimal_law(self._kind, speed, accel)

    @property
    def kind(self) -> str:
        """``"trapezoidal"``, ``"cubic"`` or ``"quintic"``."""
        return self._kind

    @property
    def n(self) -> int:
        """The number of joints."""
        return int(self._delta.size)

    @property
    def distance(self) -> np.ndarray:
        """Each joint's displacement ``Δ_j``, shape (n,)."""
        return self._delta.copy()

    @property
    def start(self) -> np.ndarray:
        """Each joint's ``q(0)``, shape (n,)."""
        return self._start.copy()

    @property
    def joints(self) -> tuple[str, ...]:
        """The joints' names."""
        return self._joints

    @property
    def has_limits(self) -> bool:
        """Whether the task gives speed and acceleration limits (not a duration)."""
        return self._speed is not None

    @property
    def limits(self) -> tuple[np.ndarray, np.ndarray] | None:
        """``(speed, accel)``, each shape (n,), or None for a task given its duration."""
        if self._speed is None or self._accel is None:
            return None
        return self._speed.copy(), self._accel.copy()

    @property
    def law(self) -> Law:
        """The normalized law every joint follows."""
        return self._law

    @property
    def duration(self) -> float:
        """``T`` (s)."""
        return self._law.duration

    @property
    def blend(self) -> float:
        """The acceleration time ``t_a`` (s) of a trapezoid or triangle; 0 otherwise."""
        return self._law.blend

    @property
    def shape(self) -> str:
        """``"trapezoid"``, ``"triangle"``, ``"cubic"`` or ``"quintic"``."""
        return self._law.kind

    @property
    def peak_speed(self) -> np.ndarray:
        """Each joint's peak speed ``|Δ_j|·max u̇``, shape (n,)."""
        return np.abs(self._delta) * self._law.speed

    @property
    def peak_accel(self) -> np.ndarray:
        """Each joint's peak acceleration ``|Δ_j|·max |ü|``, shape (n,)."""
        return np.abs(self._delta) * self._law.accel

    def own_laws(self) -> list[Law]:
        """Each joint's law moving alone under its own limits (a still law when Δ = 0)."""
        still = Law("still", 0.0, 0.0, 0.0, 0.0)
        return [self._own_law(j) if d != 0 else still for j, d in enumerate(self._delta)]

    @property
    def own_durations(self) -> np.ndarray:
        """Each joint's duration alone under its own limits, shape (n,)."""
        return np.array([law.duration for law in self.own_laws()])

    def coefficients(self) -> np.ndarray:
        """A cubic's or quintic's ``q_j(t) = Σ a_k t^k``, lowest power first.

        Returns
        -------
        ndarray, shape (4,) or (6,) for one joint; (n, 4) or (n, 6) for several.

        Raises
        ------
        InvalidInputError
            For a trapezoid (it is piecewise: no single polynomial).
        """
        if self._kind == "trapezoidal":
            raise InvalidInputError("form", "coefficients", "a cubic or quintic task")
        rows = self._start[:, None] * np.eye(1, 4 if self._kind == "cubic" else 6)
        rows = rows + self._delta[:, None] * self._law.coefficients()[None, :]
        return rows[0] if self.n == 1 else rows

    def velocity(self, times: Any) -> np.ndarray:
        """Each joint's velocity at ``times`` (s from the start).

        Returns
        -------
        ndarray, shape (k,) for one joint, (k, n) for several.
        """
        t = check_times(times)
        values = self._law.rate(t)[:, None] * self._delta[None, :]
        return values[:, 0] if self.n == 1 else values

    # -- answers ------------------------------------------------------------------------

    def forms(self) -> tuple[str, ...]:
        """The forms an answer to this task may take (keys of :data:`PROFILE_FORMS`)."""
        forms = ["duration", "peak_speed", "peak_accel", "velocity"]
        if self.n == 1:
            forms.insert(0, "parameters" if self._kind == "trapezoidal" else "coefficients")
        return tuple(forms)

    def default_form(self) -> str:
        """``parameters`` (one-joint trapezoid), ``coefficients`` (one-joint
        polynomial), else ``duration``."""
        return self.forms()[0] if self.n == 1 else "duration"

    def expected(self, form: str | None = None, times: Any = None) -> np.ndarray:
        """The right answer in ``form`` (default :meth:`default_form`).

        Returns
        -------
        ndarray
            ``parameters`` (3,); ``duration`` (); ``peak_speed``/``peak_accel`` () for
            one joint, else (n,); ``coefficients`` (4,) or (6,); ``velocity`` (k,) or
            (k, n) at ``times``.
        """
        form = self.check_form(form, times)
        return read(self._delta, self._start, form, times, [self._law] * self.n, shared=True)

    def check_form(self, form: Any, times: Any) -> str:
        """``form`` if this task has it (``None``: the default); ``times`` only with
        ``velocity``."""
        if form is None:
            form = self.default_form()
        if not isinstance(form, str) or form not in self.forms():
            raise InvalidInputError("form", form, f"for this task: {', '.join(self.forms())}")
        if (form == "velocity") != (times is not None):
            raise InvalidInputError(
                "times", times, "the sample times (s) with form='velocity', and only then"
            )
        return form

    def __repr__(self) -> str:
        def show(values: np.ndarray | None) -> str:
            if values is None:
                return "None"
            items = [f"{x:g}" for x in values]
            return items[0] if len(set(items)) == 1 and self.n == 1 else f"[{', '.join(items)}]"

        given = (
            f"duration={self._given:g}"
            if self._given is not None
            else f"speed={show(self._speed)}, accel={show(self._accel)}"
        )
        return f"ProfileTask({show(self._delta)}, kind={self._kind!r}, {given})"
