"""Rest-to-rest time laws: how a path parameter ``u`` goes from 0 to 1 in ``T`` seconds.

The one home of the course's three time laws. A motion from ``q0`` by ``Δ`` follows
``q(t) = q0 + Δ·u(t)``; the signals (:class:`~robotconf.signals.Cubic`,
:class:`~robotconf.signals.Quintic`, :class:`~robotconf.signals.Trapezoidal`), the robot
programs' PTP/LIN/CIRC moves and the profile checker of the course all evaluate ``u``
here, and take their durations from here.

Cubic
    ``u = 3τ² − 2τ³`` with ``τ = t/T``: at rest at both ends; peaks ``u̇ = 3/(2T)``
    (at ``τ = 1/2``) and ``|ü| = 6/T²`` (at both ends, where ``ü`` jumps).
Quintic
    ``u = 10τ³ − 15τ⁴ + 6τ⁵``: velocity and acceleration 0 at both ends; peaks
    ``u̇ = 15/(8T)`` and ``|ü| = 10/(√3·T²)`` (at ``τ = (3 ∓ √3)/6``).
Trapezoid
    constant acceleration ``a`` for a blend time ``t_b``, a cruise at ``v = a·t_b``,
    the mirror ramp down. The fastest one under ``u̇ ≤ V`` and ``|ü| ≤ A``:
    ``t_b = V/A``, ``T = 1/V + V/A`` when ``V²/A ≤ 1``; otherwise a triangle,
    ``t_b = √(1/A)``, ``T = 2·t_b``, peak ``A·t_b``. In length units (a move of length
    ``d`` under ``v`` and ``a``): ``T = d/v + v/a``, a triangle when ``d < v²/a``.

Where ``ü`` jumps (the cubic's ends, the trapezoid's corners) the right-sided value is
given, as everywhere in robotconf (docs/conventions.md, "Motion and DVA"); before the
start and from ``T`` on, ``u̇ = ü = 0``.

>>> u, ud, udd = polynomial_law("quintic", np.array([0.0, 1.0, 2.0]), 2.0)
>>> u.tolist(), ud.tolist()
([0.0, 0.5, 1.0], [0.0, 0.9375, 0.0])
>>> fastest_trapezoid(speed=0.5, accel=1.0)  # (T, t_b, peak u̇)
(2.5, 0.5, 0.5)
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "PEAK_ACCEL",
    "PEAK_SPEED",
    "POLYNOMIAL_LAWS",
    "TAU_COEFFICIENTS",
    "fastest_polynomial",
    "fastest_trapezoid",
    "polynomial_law",
    "trapezoid_law",
]

#: Coefficients of ``u(τ)``, lowest power first.
TAU_COEFFICIENTS = {
    "cubic": (0.0, 0.0, 3.0, -2.0),
    "quintic": (0.0, 0.0, 0.0, 10.0, -15.0, 6.0),
}
#: The polynomial laws by name.
POLYNOMIAL_LAWS = tuple(TAU_COEFFICIENTS)
#: Peak ``u̇·T`` of each polynomial law.
PEAK_SPEED = {"cubic": 1.5, "quintic": 15.0 / 8.0}
#: Peak ``|ü|·T²`` of each polynomial law.
PEAK_ACCEL = {"cubic": 6.0, "quintic": 10.0 / math.sqrt(3.0)}


def polynomial_law(
    kind: str, t: np.ndarray, duration: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``u``, ``u̇`` (1/s) and ``ü`` (1/s²) of the cubic or quintic at times ``t`` (s).

    Parameters
    ----------
    kind : {"cubic", "quintic"}
    t : ndarray, shape (k,)
        Times from the start of the motion (s); before 0 the motion has not started,
        from ``duration`` on it is over.
    duration : float
        ``T`` (s), > 0.

    Returns
    -------
    u, u̇, ü : ndarray, shape (k,)

    Examples
    --------
    >>> polynomial_law("cubic", np.array([-1.0, 0.0, 2.0]), 2.0)[2].tolist()  # right-sided
    [0.0, 1.5, 0.0]
    """
    t = np.asarray(t, dtype=float)
    tau = np.clip(t / duration, 0.0, 1.0)
    inside = (t >= 0.0) & (t < duration)
    if kind == "cubic":
        u = tau * tau * (3.0 - 2.0 * tau)
        rate = 6.0 * tau * (1.0 - tau)
        curvature = 6.0 - 12.0 * tau
    else:
        u = tau**3 * (10.0 + tau * (-15.0 + 6.0 * tau))
        rate = 30.0 * (tau * (1.0 - tau)) ** 2
        curvature = 60.0 * tau * (1.0 - tau) * (1.0 - 2.0 * tau)
    ud = np.where(inside, rate / duration, 0.0)
    udd = np.where(inside, curvature / duration**2, 0.0)
    return u, ud, udd


def trapezoid_law(
    t: np.ndarray, duration: float, blend: float, speed: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``u``, ``u̇`` (1/s) and ``ü`` (1/s²) of a trapezoid at times ``t`` (s).

    Parameters
    ----------
    t : ndarray, shape (k,)
        Times from the start of the motion (s).
    duration, blend : float
        ``T`` and the ramp time ``t_b`` (s), ``0 < t_b ≤ T/2`` (``t_b = T/2``: a
        triangle).
    speed : float
        The cruise (peak) ``u̇ = 1/(T − t_b)`` (1/s): the area under ``u̇`` is 1. Given
        rather than computed, so a caller's own value (the planner's limit ``V``) is
        the peak exactly.

    Returns
    -------
    u, u̇, ü : ndarray, shape (k,)
        Each ramp's formula is evaluated only over its own stretch of time, so none
        overflows where it is not used.

    Examples
    --------
    >>> u, ud, udd = trapezoid_law(np.array([0.25, 1.25, 2.5]), 2.5, 0.5, 0.5)
    >>> u.tolist(), ud.tolist(), udd.tolist()
    ([0.03125, 0.5, 1.0], [0.25, 0.5, 0.0], [1.0, 0.0, 0.0])
    """
    t = np.asarray(t, dtype=float)
    accel = speed / blend
    elapsed = np.clip(t, 0.0, duration)
    rise = np.minimum(elapsed, blend)
    left = np.minimum(duration - elapsed, blend)
    rising = elapsed < blend
    falling = elapsed >= duration - blend
    u = np.where(rising, 0.5 * accel * rise * rise, speed * (elapsed - 0.5 * blend))
    u = np.where(falling & ~rising, 1.0 - 0.5 * accel * left * left, u)
    ud = np.minimum(np.minimum(accel * elapsed, speed), accel * (duration - elapsed))
    udd = np.where(rising, accel, np.where(falling, -accel, 0.0))
    inside = (t >= 0.0) & (t < duration)
    u = np.where(t >= duration, 1.0, u)
    return u, np.where(inside, ud, 0.0), np.where(inside, udd, 0.0)


def fastest_trapezoid(speed: float, accel: float) -> tuple[float, float, float]:
    """The time-optimal trapezoid with ``u̇ ≤ speed`` and ``|ü| ≤ accel``.

    Parameters
    ----------
    speed : float
        ``V`` (1/s), > 0 (``inf`` when nothing limits it).
    accel : float
        ``A`` (1/s²), > 0 and finite.

    Returns
    -------
    (duration, blend, peak) : tuple of float
        ``T`` (s), the ramp time ``t_b`` (s) and the peak ``u̇`` (1/s): ``V`` when the
        cruise speed is reached (``V²/A ≤ 1``), else ``A·t_b`` (a triangle).

    Examples
    --------
    >>> fastest_trapezoid(2.0, 1.0)  # V²/A = 4 > 1: a triangle, t_b = 1 s
    (2.0, 1.0, 1.0)
    """
    if speed * speed <= accel:  # the cruise speed is reached
        blend = speed / accel
        return 1.0 / speed + blend, blend, speed
    blend = math.sqrt(1.0 / accel)
    return 2.0 * blend, blend, accel * blend


def fastest_polynomial(kind: str, speed: float, accel: float) -> float:
    """The shortest duration (s) of the cubic or quintic whose peaks respect both limits.

    ``T = max(PEAK_SPEED/V, √(PEAK_ACCEL/A))``: each limit asks for a duration, the
    longer one holds both.

    Examples
    --------
    >>> fastest_polynomial("quintic", speed=15 / 8, accel=100.0)  # the speed limit sets T
    1.0
    """
    return max(PEAK_SPEED[kind] / speed, math.sqrt(PEAK_ACCEL[kind] / accel))
