"""Rest-to-rest time profiles of a normalized path parameter ``u`` from 0 to 1.

Every move of a program runs one profile: a PTP move scales it by each joint's
displacement ``Δ_j`` (``q_j = q_j0 + Δ_j·u``), a LIN or CIRC move by the path length
``L`` and the turn ``θ`` (``s = L·u``, angle ``θ·u``). A limit ``v_j`` on ``|Δ_j·u̇|`` and
``a_j`` on ``|Δ_j·ü|`` is a limit ``V = min_j v_j/|Δ_j|`` on ``u̇`` and
``A = min_j a_j/|Δ_j|`` on ``ü``; the profile is the fastest one under ``V`` and ``A``.
All dimensions then start and stop together (synchronized): the slowest sets the
duration and the others scale down.

The time laws themselves (the trapezoid, time-optimal under V and A, and the quintic,
at rest with zero acceleration at both ends) have one home, shared with the signals and
the course's profile checker: :mod:`robotconf.signals` (``_time_laws``).

At a corner of the trapezoid the acceleration jumps; like the signals, the profile
reports the right-sided value there (docs/conventions.md, "Motion and DVA").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..signals import (
    PEAK_ACCEL,
    PEAK_SPEED,
    fastest_polynomial,
    fastest_trapezoid,
    polynomial_law,
    trapezoid_law,
)

__all__ = ["PROFILES", "Profile", "trapezoidal", "quintic", "still"]

#: The profiles a PTP move may ask for; LIN and CIRC moves are always trapezoidal.
PROFILES = ("trapezoidal", "quintic")


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
        return polynomial_law("quintic", t, self.duration)

    def _trapezoid(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return trapezoid_law(t, self.duration, self.blend, self.speed)


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
    duration, blend, peak = fastest_trapezoid(speed, accel)
    return Profile("trapezoidal", duration, blend, peak, accel)


def quintic(speed: float, accel: float) -> Profile:
    """The quintic from 0 to 1 whose peaks ``15/(8T)`` and ``10/(√3·T²)`` respect the limits.

    Examples
    --------
    >>> p = quintic(speed=15 / 8, accel=100.0)  # the speed limit sets T = 1 s
    >>> p.duration, round(p.accel, 6)
    (1.0, 5.773503)
    """
    duration = fastest_polynomial("quintic", speed, accel)
    return Profile(
        "quintic",
        duration,
        0.0,
        PEAK_SPEED["quintic"] / duration,
        PEAK_ACCEL["quintic"] / duration**2,
    )


def still(duration: float) -> Profile:
    """No motion for ``duration`` seconds (a Wait, or a move already at its target).

    >>> still(0.5).evaluate(np.array([0.1]))
    (array([0.]), array([0.]), array([0.]))
    """
    return Profile("still", float(duration), 0.0, 0.0, 0.0)
