"""Time laws of a rest-to-rest move: the right one, and the ones a usual slip gives.

A law is the normalized path parameter ``u(t)`` going from 0 to 1 in ``T`` seconds; a
joint that moves by ``Δ`` follows ``q(t) = q0 + Δ·u(t)``. The profile checker builds the
right law of an exercise and the laws a student who made a usual slip would have used
(the acceleration time doubled, a ramp left out, the cubic for the quintic), and reads
every kind of answer off them: the trapezoid's times, the duration, the peaks, the
polynomial's coefficients, the velocity at given times. The right laws are the ones the
signals and the robot programs run (:mod:`robotconf.signals`, one home for the time
laws); the formulas are the course's (lesson 12, docs/programs.md "Time laws"):

- trapezoid under ``u̇ ≤ V``, ``|ü| ≤ A``: ``t_a = V/A``, ``T = 1/V + V/A`` when
  ``V²/A ≤ 1``; otherwise a triangle, ``t_a = √(1/A)``, ``T = 2·t_a``, peak ``A·t_a``;
- cubic ``u = 3τ² − 2τ³`` (``τ = t/T``): peaks ``u̇ = 3/(2T)``, ``|ü| = 6/T²``;
- quintic ``u = 10τ³ − 15τ⁴ + 6τ⁵``: peaks ``u̇ = 15/(8T)``, ``|ü| = 10/(√3·T²)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...signals import (
    PEAK_ACCEL,
    PEAK_SPEED,
    TAU_COEFFICIENTS,
    fastest_polynomial,
    fastest_trapezoid,
    polynomial_law,
    trapezoid_law,
)

__all__ = [
    "LAW_KINDS",
    "PEAK_ACCEL",
    "PEAK_SPEED",
    "Law",
    "box_law",
    "cruise_law",
    "one_ramp_law",
    "optimal_law",
    "timed_law",
]

#: Shapes a law may have. Two are slips: ``one_ramp`` accelerates and never slows down,
#: ``box`` jumps to its speed and stops dead (no ramps at all).
LAW_KINDS = ("trapezoid", "triangle", "one_ramp", "box", "cubic", "quintic", "still")


@dataclass(frozen=True)
class Law:
    """A normalized time law ``u(t)``: 0 at ``t = 0``, 1 at ``t = duration``.

    Attributes
    ----------
    kind : str
        One of :data:`LAW_KINDS`.
    duration : float
        ``T`` (s).
    blend : float
        Trapezoid, triangle and one ramp: the time ``t_a`` (s) spent accelerating; 0
        for the polynomials.
    speed : float
        Peak ``u̇`` (1/s).
    accel : float
        Peak ``|ü|`` (1/s²); for the piecewise laws the slope of the ramps.

    Examples
    --------
    >>> law = optimal_law("trapezoidal", speed=0.5, accel=1.0)
    >>> law.kind, law.blend, law.duration
    ('trapezoid', 0.5, 2.5)
    >>> law.rate(np.array([0.25, 1.0, 2.5])).tolist()
    [0.25, 0.5, 0.0]
    """

    kind: str
    duration: float
    blend: float
    speed: float
    accel: float

    def rate(self, t: np.ndarray) -> np.ndarray:
        """``u̇`` (1/s) at the times ``t`` (s); 0 before the start and after the end.

        A trapezoid's velocity is 0 at ``t = T`` itself; a ``one_ramp`` law is still at
        its peak there (it stops only after ``T``).
        """
        t = np.asarray(t, dtype=float)
        inside = (t >= 0.0) & (t <= self.duration)
        if self.kind in ("trapezoid", "triangle"):
            value = trapezoid_law(t, self.duration, self.blend, self.speed)[1]
        elif self.kind in ("cubic", "quintic"):
            value = polynomial_law(self.kind, t, self.duration)[1]
        elif self.kind == "one_ramp":
            value = np.minimum(self.accel * t, self.speed)
        elif self.kind == "box":
            value = np.full_like(t, self.speed)
        else:
            value = np.zeros_like(t)
        return np.where(inside, np.maximum(value, 0.0), 0.0)

    def tau_coefficients(self) -> np.ndarray:
        """The polynomial's coefficients of ``u(τ)``, ``τ = t/T``, lowest power first.

        >>> timed_law("cubic", 2.0).tau_coefficients().tolist()
        [0.0, 0.0, 3.0, -2.0]
        """
        return np.array(TAU_COEFFICIENTS[self.kind])

    def coefficients(self) -> np.ndarray:
        """The polynomial's coefficients of ``u(t)`` (t in s), lowest power first.

        Shape (4,) for a cubic, (6,) for a quintic: ``a_k = c_k / T^k``.

        >>> timed_law("cubic", 2.0).coefficients().tolist()
        [0.0, 0.0, 0.75, -0.25]
        """
        tau = self.tau_coefficients()
        return tau / self.duration ** np.arange(tau.size)


def optimal_law(kind: str, speed: float, accel: float) -> Law:
    """The fastest law of ``kind`` with ``u̇ ≤ speed`` and ``|ü| ≤ accel``.

    Parameters
    ----------
    kind : {"trapezoidal", "cubic", "quintic"}
    speed, accel : float
        ``V`` (1/s) and ``A`` (1/s²), both > 0.

    Returns
    -------
    Law
        A trapezoid, or a triangle when ``V²/A > 1`` (the distance is too short to
        reach ``V``); a polynomial whose duration is the larger of the two the limits
        ask for.

    Examples
    --------
    >>> optimal_law("trapezoidal", speed=2.0, accel=1.0).kind  # V²/A = 4 > 1
    'triangle'
    >>> optimal_law("quintic", speed=15 / 8, accel=100.0).duration  # the speed limit decides
    1.0
    """
    if kind == "trapezoidal":
        # The time law robot programs and signals run: the right answer is what they do.
        duration, blend, peak = fastest_trapezoid(speed, accel)
        shape = "trapezoid" if speed * speed <= accel else "triangle"
        return Law(shape, duration, blend, peak, accel)
    return timed_law(kind, fastest_polynomial(kind, speed, accel))


def timed_law(kind: str, duration: float) -> Law:
    """The cubic or quintic law that takes ``duration`` seconds.

    >>> law = timed_law("quintic", 2.0)
    >>> law.speed, round(law.accel, 6)  # 15/(8·2), 10/(√3·4)
    (0.9375, 1.443376)
    """
    return Law(
        kind,
        duration,
        0.0,
        PEAK_SPEED[kind] / duration,
        PEAK_ACCEL[kind] / duration**2,
    )


def cruise_law(speed: float, accel: float, blend: float | None = None) -> Law:
    """A trapezoid that cruises at ``speed`` whatever the distance, ramps ``blend`` long.

    What a student writes who takes the speed limit as reached (a triangle treated as a
    trapezoid), or who computes the acceleration time another way (``blend`` = 2V/A):
    the ramps' slope is ``speed/blend`` and ``T = 1/speed + blend``, so that the
    cruise covers the rest of the distance. For a triangle the ramps overlap.

    >>> cruise_law(2.0, 1.0).duration  # 1/2 + 2/1
    2.5
    """
    blend = speed / accel if blend is None else blend
    return Law("trapezoid", 1.0 / speed + blend, blend, speed, speed / blend)


def box_law(speed: float) -> Law:
    """Full speed from start to end, ``T = 1/V``: the duration of a move without ramps.

    >>> box_law(0.5).duration
    2.0
    """
    return Law("box", 1.0 / speed, 0.0, speed, 0.0)


def one_ramp_law(speed: float, accel: float) -> Law:
    """A law that accelerates and then cruises to the end: it never comes to rest.

    It covers the distance (``½·V·t_a + V·(T − t_a) = 1``, so ``T = 1/V + V/(2A)``)
    but arrives at full speed. When the speed is not reached, the ramp alone covers the
    distance: ``T = √(2/A)``.

    >>> law = one_ramp_law(0.5, 1.0)
    >>> law.duration, float(law.rate(np.array([law.duration]))[0])
    (2.25, 0.5)
    """
    if speed * speed <= 2.0 * accel:
        blend = speed / accel
        return Law("one_ramp", 1.0 / speed + blend / 2.0, blend, speed, accel)
    duration = math.sqrt(2.0 / accel)
    return Law("one_ramp", duration, duration, accel * duration, accel)
