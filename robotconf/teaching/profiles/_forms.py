"""The forms an answer about a move may take, read off the joints' time laws.

A joint that moves by ``Δ`` from ``q0`` along a law ``u(t)`` has the trapezoid numbers
``[t_a, T, |Δ|·max u̇]``, a duration, peaks ``|Δ|·max u̇`` and ``|Δ|·max |ü|``, the
polynomial coefficients ``q0 + Δ·a_k`` and velocities ``Δ·u̇(t)``: :func:`read` gives
each, for the right laws of a task and for the laws of a slip alike.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ._laws import Law

__all__ = ["MAX_TIMES", "PROFILE_FORMS", "check_times", "read"]

#: The forms an answer may take, and what each is.
PROFILE_FORMS = {
    "parameters": "[t_accel, t_total, v_peak] of a trapezoid or triangle (one joint)",
    "duration": "the move's duration T (s)",
    "peak_speed": "the peak speed |Δ|·max u̇, one number per joint",
    "peak_accel": "the peak acceleration |Δ|·max |ü|, one number per joint",
    "coefficients": "[a0, a1, …] of a cubic (4) or quintic (6) q(t), lowest power first",
    "velocity": "the velocity at the given times: shape (k,) for one joint, (k, n) for n",
}

#: Most times a velocity answer may be sampled at.
MAX_TIMES = 10_000


def check_times(times: Any) -> np.ndarray:
    """Sample times (s) as a 1-D float array: 1 … :data:`MAX_TIMES` finite numbers."""
    if isinstance(times, (str, bytes)) or times is None:
        raise InvalidInputError("times", times, "a list of times (s)")
    array = np.asarray(times, dtype=object).reshape(-1)
    if array.size == 0 or array.size > MAX_TIMES:
        raise InvalidInputError("times", times, f"1 … {MAX_TIMES} times (s)")
    if array.size and np.ndim(times) > 1:
        raise InvalidInputError("times", times, "a flat list of times (s)")
    return np.array([check_finite_number(x, "times") for x in array], dtype=float)


def read(
    distance: np.ndarray,
    start: np.ndarray,
    form: str,
    times: Any,
    laws: list[Law],
    shared: bool,
) -> np.ndarray:
    """The answer in ``form`` of a move whose joint j follows ``laws[j]``.

    ``shared`` says all joints follow one law (a synchronized move): its duration is one
    number. Otherwise ``duration`` lists each joint's own, shape (n,).
    """
    delta = distance
    reach = np.abs(delta)
    one = delta.size == 1
    if form == "parameters":
        law = laws[0]
        return np.array([law.blend, law.duration, reach[0] * law.speed])
    if form == "duration":
        if shared or one:
            return np.array(laws[0].duration)
        return np.array([law.duration for law in laws])
    if form in ("peak_speed", "peak_accel"):
        peaks = np.array([law.speed if form == "peak_speed" else law.accel for law in laws])
        values = reach * peaks
        return np.array(values[0]) if one else values
    if form == "coefficients":
        law = laws[0]
        coefficients = law.coefficients() * delta[0]
        coefficients[0] += start[0]
        return coefficients
    t = check_times(times)
    values = np.stack([law.rate(t) * d for law, d in zip(laws, delta, strict=True)], axis=1)
    return values[:, 0] if one else values
