"""Rest-to-rest time profiles of a normalized path parameter ``u`` from 0 to 1.

Every move of a program runs one profile: a PTP move scales it by each joint's
displacement ``Δ_j`` (``q_j = q_j0 + Δ_j·u``), a LIN or CIRC move by the path length
``L`` and the turn ``θ`` (``s = L·u``, angle ``θ·u``). A limit ``v_j`` on ``|Δ_j·u̇|`` and
``a_j`` on ``|Δ_j·ü|`` is a limit ``V = min_j v_j/|Δ_j|`` on ``u̇`` and
``A = min_j a_j/|Δ_j|`` on ``ü``; the profile is the fastest one under ``V`` and ``A``.
All dimensions then start and stop together (synchronized): the slowest sets the
duration and the others scale down.

Trapezoidal (time-optimal under V and A)
    ``T = 1/V + V/A`` with blend time ``t_b = V/A`` when ``V²/A ≤ 1`` (the cruise speed
    is reached); otherwise a triangle, ``t_b = √(1/A)``, ``T = 2·t_b``, peak speed
    ``A·t_b``. In length units: ``T = L/v + v/a``, a triangle when ``L < v²/a``.
Quintic (rest-to-rest, zero acceleration at both ends)
    ``u = 10τ³ − 15τ⁴ + 6τ⁵`` with ``τ = t/T``: peak ``u̇ = 15/(8T)`` at ``τ = 1/2`` and
    peak ``|ü| = 10/(√3·T²)`` at ``τ = (3 ∓ √3)/6``, so
    ``T = max(15/(8V), √(10/(√3·A)))``.

At a corner of the trapezoid the acceleration jumps; like the signals, the profile
reports the right-sided value there (docs/conventions.md, "Motion and DVA").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["PROFILES", "Profile", "trapezoidal", "quintic", "still"]

#: The profiles a PTP move may ask for; LIN and CIRC moves are always trapezoidal.
PROFILES = ("trapezoidal", "quintic")

_QUINTIC_SPEED = 15.0 / 8.0
_QUINTIC_ACCEL = 10.0 / float(np.sqrt(3.0))


@dataclass(frozen=True)
class Profile:
    """The time law ``u(t)`` of one move, ``u(0) = 0`` and ``u(T) = 1``, at rest at both ends.

    Attributes
    ----------
    kind : str
        ``"trapezoidal"``, ``"quintic"`` or ``"still"`` (a Wait, or a move that goes
        nowhere: ``u`` stays 0).
    duration : float
        ``T`` (s).
    blend : float
        Trapezoid: the time ``t_b`` (s) spent accelerating (and decelerating); 0 otherwise.
    speed, accel : float
        Peak ``u̇`` (1/s) and peak ``|ü|`` (1/s²) reached.

    Examples
    --------
    >>> p = trapezoidal(speed=0.5, accel=1.0)  # 1/V = 2 s cruising, V/A = 0.5 s ramps
    >>> p.duration, p.blend
    (2.5, 0.5)
    >>> p.evaluate(np.array([0.25, 1.25, 2.5]))[0]
    array([0.03125, 0.5    , 1.     ])
    """

    kind: str
    duration: float
    blend: float
    speed: float
    accel: float

    @property
    def corners(self) -> tuple[float, ...]:
        """Times (s, from the move's start) where ``ü`` jumps inside the move."""
        if self.kind != "trapezoidal" or self.duration == 0.0:
            return ()
        if 2.0 * self.blend >= self.duration:
            return (self.blend,)
        return (self.blend, self.duration - self.blend)

    def evaluate(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``u``, ``u̇`` (1/s) and ``ü`` (1/s²) at times ``t`` (s) from the move's start.

        Times before 0 count as 0; from ``T`` on the move is over (``u = 1``, at rest; a
        ``still`` profile stays at 0).
        """
        t = np.clip(np.asarray(t, dtype=float), 0.0, None)
        if self.kind == "still" or self.duration == 0.0:
            zero = np.zeros_like(t)
            return zero, zero.copy(), zero.copy()
        if self.kind == "quintic":
            return self._quintic(t)
        return self._trapezoid(t)

    def _quintic(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        T = self.duration
        tau = np.minimum(t / T, 1.0)
        u = tau**3 * (10.0 + tau * (-15.0 + 6.0 * tau))
        ud = 30.0 * tau**2 * (1.0 - tau) ** 2 / T
        udd = 60.0 * tau * (1.0 + tau * (-3.0 + 2.0 * tau)) / T**2
        over = t >= T
        udd[over] = 0.0
        ud[over] = 0.0
        return u, ud, udd

    def _trapezoid(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        T, tb, a, peak = self.duration, self.blend, self.accel, self.speed
        rising = t < tb
        falling = (t >= T - tb) & (t < T)
        over = t >= T
        left = T - t
        u = np.where(rising, 0.5 * a * t**2, 0.5 * a * tb**2 + peak * (t - tb))
        u = np.where(falling, 1.0 - 0.5 * a * left**2, u)
        ud = np.where(rising, a * t, peak)
        ud = np.where(falling, a * left, ud)
        udd = np.where(rising, a, np.where(falling, -a, 0.0))
        u[over] = 1.0
        ud[over] = 0.0
        udd[over] = 0.0
        return u, ud, udd


def trapezoidal(speed: float, accel: float) -> Profile:
    """The time-optimal trapezoid from 0 to 1 with ``u̇ ≤ speed`` and ``|ü| ≤ accel``.

    Parameters
    ----------
    speed : float
        ``V`` (1/s), > 0 (``inf`` when nothing limits it).
    accel : float
        ``A`` (1/s²), > 0 and finite.

    Returns
    -------
    Profile

    Examples
    --------
    >>> trapezoidal(2.0, 1.0).kind, trapezoidal(2.0, 1.0).duration  # V²/A = 4 > 1: triangle
    ('trapezoidal', 2.0)
    """
    if speed * speed <= accel:  # the cruise speed is reached (V²/A ≤ 1)
        blend = speed / accel
        return Profile("trapezoidal", 1.0 / speed + blend, blend, speed, accel)
    blend = float(np.sqrt(1.0 / accel))
    return Profile("trapezoidal", 2.0 * blend, blend, accel * blend, accel)


def quintic(speed: float, accel: float) -> Profile:
    """The quintic from 0 to 1 whose peaks ``15/(8T)`` and ``10/(√3·T²)`` respect the limits.

    Examples
    --------
    >>> p = quintic(speed=15 / 8, accel=100.0)  # the speed limit sets T = 1 s
    >>> p.duration, round(p.accel, 6)
    (1.0, 5.773503)
    """
    duration = max(_QUINTIC_SPEED / speed, float(np.sqrt(_QUINTIC_ACCEL / accel)))
    return Profile(
        "quintic", duration, 0.0, _QUINTIC_SPEED / duration, _QUINTIC_ACCEL / duration**2
    )


def still(duration: float) -> Profile:
    """No motion for ``duration`` seconds (a Wait, or a move already at its target).

    >>> still(0.5).evaluate(np.array([0.1]))
    (array([0.]), array([0.]), array([0.]))
    """
    return Profile("still", float(duration), 0.0, 0.0, 0.0)
