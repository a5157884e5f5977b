"""The usual slips with motion profiles, rebuilt as the answers they would give.

Each slip is a way of computing the move wrongly — a triangle taken for a trapezoid,
the acceleration time as ``2v/a``, the ramps or the deceleration left out, every joint
with its own duration, the cubic's numbers for the quintic's — carried through to the
form the exercise asks for. An answer that equals one of them (within the tolerance)
gets that slip's hint. The hints say what went wrong and how to think about it, never
the right numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ._forms import read
from ._laws import (
    Law,
    box_law,
    cruise_law,
    one_ramp_law,
    optimal_law,
    timed_law,
)
from ._task import ProfileTask

__all__ = ["HINTS", "PROFILE_DIAGNOSES", "Slip", "profile_slips"]

#: The diagnosis codes of :func:`check_profile` beyond those of ``check_value``.
PROFILE_DIAGNOSES = {
    "not_at_rest_end": "the velocity does not come back to zero at the end of the move",
    "not_at_rest_start": "the velocity does not start at zero",
    "not_synchronized": "each joint given its own duration or profile, not the slowest's",
    "mixed_limits": "the slowest joint's own time where two joints' limits both bind",
    "triangle_as_trapezoid": "a triangle treated as a trapezoid: a peak speed the distance "
    "does not allow",
    "accel_time_factor": "the acceleration time off by a factor (2v/a or v/(2a) for v/a)",
    "ramps_forgotten": "the duration d/v, as if the speed jumped to its limit",
    "cubic_quintic_swapped": "the cubic's numbers where the quintic's are asked, or back",
    "one_limit": "a duration from one limit where the other one decides (a polynomial's, or "
    "a triangle where the speed limit makes it a trapezoid)",
    "average_speed": "the average speed d/T given as the peak speed",
    "normalized_time": "polynomial coefficients in τ = t/T instead of t",
    "descending_order": "polynomial coefficients with the highest power first",
    "distance_not_covered": "trapezoid numbers that do not cover the distance",
    "largest_move": "the duration of the joint with the largest move, not the slowest's",
}

_FORMULA = {"cubic": "u = 3τ² − 2τ³", "quintic": "u = 10τ³ − 15τ⁴ + 6τ⁵"}
_OTHER = {"cubic": "quintic", "quintic": "cubic"}

#: The hint of each slip (some are filled in with the joint's name or the kinds).
HINTS = {
    "triangle_as_trapezoid": (
        "The distance is too short to reach the speed limit (d < v_max²/a_max): the "
        "profile is a triangle, not a trapezoid — it accelerates for half the time, "
        "decelerates for the other half, and its peak speed stays below v_max."
    ),
    "accel_time_long": (
        "The acceleration time is twice too long: reaching the speed v at the "
        "acceleration a takes t_a = v/a (v = a·t), not 2v/a."
    ),
    "accel_time_short": (
        "The acceleration time is half what it should be: reaching the speed v at the "
        "acceleration a takes t_a = v/a (v = a·t), not v/(2a)."
    ),
    "triangle_time_long": (
        "Each ramp of a triangle covers only half the distance: d/2 = ½·a·t_a², not d = ½·a·t_a²."
    ),
    "triangle_time_short": (
        "The acceleration time of a triangle is too short: the ramp up covers half the "
        "distance, d/2 = ½·a·t_a²."
    ),
    "ramps_forgotten": (
        "d/v_max would be the duration if the robot jumped to full speed at once and "
        "stopped dead: the ramps at the start and the end are slower and make the move "
        "longer."
    ),
    "one_ramp": (
        "Your profile does not come to rest: it accelerates, then cruises to the end and "
        "would still move at full speed when it arrives. A rest-to-rest move ends with a "
        "deceleration ramp as long as the first one."
    ),
    "own_durations": (
        "Each joint got its own duration: in a synchronized PTP all joints start and stop "
        "together, so there is one duration — the slowest joint's; the others slow down."
    ),
    "own_duration": (
        "That is the duration of {joint} moving alone, and {joint} is not the slowest "
        "joint: the slowest joint sets the duration of a synchronized move."
    ),
    "own_profiles": (
        "Each joint runs its own profile at its own limits: synchronized, all joints "
        "follow the slowest joint's law u(t), q_j = q_j0 + Δ_j·u(t), so the others move "
        "slower than their limits and all arrive together."
    ),
    "mixed_limits": (
        "Here one joint's speed limit and another joint's acceleration limit both bind, "
        "so the synchronized move is slower than every joint alone: take "
        "V = min_j v_j/|Δ_j| and A = min_j a_j/|Δ_j| for the common law u(t), and the "
        "duration from V and A."
    ),
    "largest_move": (
        "The joint with the largest move is not always the slowest: a joint's time "
        "depends on its own speed and acceleration limits. Work out every joint's time "
        "(or V = min_j v_j/|Δ_j| and A = min_j a_j/|Δ_j|) before you pick."
    ),
    "no_triangle_check": (
        "d/v + v/a holds only for a joint that reaches its speed limit (d ≥ v²/a): a "
        "shorter move is a triangle, T = 2·√(d/a). Check each joint before you take "
        "the longest time."
    ),
    "swapped": (
        "These are the {other}'s numbers ({other_formula}): the task asks for the {kind} "
        "({formula})."
    ),
    "one_limit": (
        "Both limits must hold: the speed limit asks for one duration, the acceleration "
        "limit for another — the move takes the longer one."
    ),
    "speed_limit_left_out": (
        "That is a triangle, from the acceleration limit alone: its peak √(d·a) is above "
        "the speed limit, so the robot reaches v_max and cruises — a trapezoid (both limits "
        "must hold)."
    ),
    "average_speed": (
        "That is the average speed d/T: a rest-to-rest profile starts and ends at "
        "speed 0, so its peak is higher than the average."
    ),
    "normalized_time": (
        "These are the coefficients of u in τ = t/T: give q(t)'s coefficients in seconds "
        "(divide the k-th one by T^k, and scale by the distance)."
    ),
    "normalized_speed": (
        "That is the peak of dq/dτ in τ = t/T, the speed per unit of τ: in time it is "
        "divided by T (q̇ = (dq/dτ)/T)."
    ),
    "descending_order": (
        "The coefficients are in reverse order: give them lowest power first, "
        "[a0, a1, a2, …] (numpy's polyval takes the highest first)."
    ),
}


#: Slips that may touch one number of a trapezoid alone (t_accel: 0, t_total: 1); the
#: others change the numbers together.
_ALONE = {"accel_time_factor": 0, "ramps_forgotten": 1}


@dataclass(frozen=True)
class Slip:
    """A wrong way of working out the answer, and the answer it gives.

    Attributes
    ----------
    code : str
        The diagnosis (:data:`PROFILE_DIAGNOSES`).
    values : ndarray
        The answer the slip gives, in the form asked (possibly of another shape: a
        duration per joint where one is asked).
    hint : str
    """

    code: str
    values: np.ndarray
    hint: str


def _trapezoid_laws(task: ProfileTask) -> list[tuple[str, str, Law]]:
    """(code, hint key, law) of the slips of a trapezoidal task, shared by all joints."""
    law = task.law
    V, A = law.speed, law.accel
    found = []
    if law.kind == "triangle":
        limits = task.limits
        assert limits is not None
        moving = task.distance != 0
        reach = np.abs(task.distance[moving])
        speed = float(np.min(limits[0][moving] / reach))  # the V the distance does not allow
        found.append(("triangle_as_trapezoid", "triangle_as_trapezoid", cruise_law(speed, A)))
        found.append(("not_at_rest_end", "one_ramp", one_ramp_law(speed, A)))
        for factor, key in (
            (math.sqrt(2.0), "triangle_time_long"),
            (0.5**0.5, "triangle_time_short"),
        ):
            blend = law.blend * factor
            found.append(
                ("accel_time_factor", key, Law("triangle", 2 * blend, blend, A * blend, A))
            )
    else:
        found.append(("not_at_rest_end", "one_ramp", one_ramp_law(V, A)))
        for factor, key in ((2.0, "accel_time_long"), (0.5, "accel_time_short")):
            found.append(("accel_time_factor", key, cruise_law(V, A, blend=factor * V / A)))
        found.append(("ramps_forgotten", "ramps_forgotten", box_law(V)))
        # the triangle's formulas, the speed limit left out: t_a = √(d/a), peak √(d·a)
        blend = math.sqrt(1.0 / A)
        triangle = Law("triangle", 2 * blend, blend, A * blend, A)
        found.append(("one_limit", "speed_limit_left_out", triangle))
    return found


def _polynomial_laws(task: ProfileTask) -> list[tuple[str, str, Law]]:
    """(code, hint key, law) of the slips of a cubic or quintic task."""
    kind, law = task.kind, task.law
    other = _OTHER[kind]
    found = [("cubic_quintic_swapped", "swapped", timed_law(other, law.duration))]
    limits = task.limits
    if limits is not None:
        moving = task.distance != 0
        reach = np.abs(task.distance[moving])
        V = float(np.min(limits[0][moving] / reach))
        A = float(np.min(limits[1][moving] / reach))
        found.append(("cubic_quintic_swapped", "swapped", optimal_law(other, V, A)))
        speed_only = timed_law(kind, optimal_law(kind, V, 1e300).duration)
        accel_only = timed_law(kind, optimal_law(kind, 1e300, A).duration)
        found += [("one_limit", "one_limit", speed_only), ("one_limit", "one_limit", accel_only)]
    return found


def _fill(key: str, task: ProfileTask, joint: str = "") -> str:
    kind = task.kind
    if key != "swapped":
        return HINTS[key].format(joint=joint)
    other = _OTHER[kind]
    return HINTS[key].format(
        other=other, other_formula=_FORMULA[other], kind=kind, formula=_FORMULA[kind]
    )


def profile_slips(
    task: ProfileTask, form: str, times: Any, *, keep_equal: bool = False
) -> list[Slip]:
    """Every slip this task and form recognise, in order of priority.

    Parameters
    ----------
    task : ProfileTask
    form : str
        A form of :meth:`ProfileTask.forms`.
    times : array-like or None
        The sample times of a ``velocity`` answer.

    keep_equal : bool
        Keep the slips whose answer equals the right one (for screening an exercise's
        numbers: such numbers hide the slip).

    Returns
    -------
    list of Slip
        Slips whose answer equals the right one are left out (they cannot be told
        apart from it), unless ``keep_equal``.

    Examples
    --------
    >>> task = ProfileTask(2.0, speed=1.0, accel=2.0)
    >>> for slip in profile_slips(task, "duration", None):  # T = 2.5 s is right
    ...     print(slip.code, float(slip.values))
    not_at_rest_end 2.25
    accel_time_factor 3.0
    accel_time_factor 2.25
    ramps_forgotten 2.0
    one_limit 2.0
    """
    n, right = task.n, task.expected(form, times)
    found: list[Slip] = []

    def add(code: str, values: np.ndarray, hint: str) -> None:
        values = np.asarray(values, dtype=float)
        same = values.shape == right.shape and np.allclose(values, right, rtol=1e-9, atol=0)
        if np.isfinite(values).all() and (keep_equal or not same):
            found.append(Slip(code, values, hint))

    if n > 1 and task.has_limits and form in ("duration", "peak_speed", "velocity"):
        own = task.own_laws()
        key = "own_durations" if form == "duration" else "own_profiles"
        add(
            "not_synchronized",
            read(task.distance, task.start, form, times, own, shared=False),
            _fill(key, task),
        )
        if form == "duration":
            slowest = max(law.duration for law in own)
            # The joint with the largest move is the one a student picks for a reason (a
            # misconception with a name); any other joint's own time is only unsynchronized.
            # The slowest joint's own time is its own slip (the limits of different joints
            # mixed), whichever joint moves most.
            largest = int(np.argmax(np.abs(task.distance)))
            if own[largest].duration < slowest * (1 - 1e-9):
                add("largest_move", np.array(own[largest].duration), _fill("largest_move", task))
            for name, law in zip(task.joints, own, strict=True):
                if law.kind != "still" and law.duration < slowest * (1 - 1e-9):
                    hint = _fill("own_duration", task, joint=name)
                    add("not_synchronized", np.array(law.duration), hint)
            add("mixed_limits", np.array(slowest), _fill("mixed_limits", task))
            add("largest_move", np.array(own[largest].duration), _fill("largest_move", task))
            if task.kind == "trapezoidal":
                # d/v + v/a for every joint, short moves too: no triangle check
                limits = task.limits
                assert limits is not None
                reach = np.abs(task.distance)
                moving = reach > 0
                formula = reach[moving] / limits[0][moving] + limits[0][moving] / limits[1][moving]
                add("triangle_as_trapezoid", np.array(formula.max()), HINTS["no_triangle_check"])
    laws = _trapezoid_laws(task) if task.kind == "trapezoidal" else _polynomial_laws(task)
    for code, key, law in laws:
        values = read(task.distance, task.start, form, times, [law] * n, shared=True)
        add(code, values, _fill(key, task))
        alone = _ALONE.get(code)
        if form == "parameters" and alone is not None:  # this number slipped, the rest right
            partly = right.copy()
            partly[alone] = values[alone]
            add(code, partly, _fill(key, task))
    if form == "peak_speed":
        average = (np.abs(task.distance) / task.duration).reshape(right.shape)
        add("average_speed", average, HINTS["average_speed"])
        if task.kind != "trapezoidal" and not np.isclose(task.duration, 1.0):
            add("normalized_time", right * task.duration, HINTS["normalized_speed"])
    if form == "parameters":  # the times right, the average d/T for the peak
        partly = right.copy()
        partly[2] = abs(float(task.distance[0])) / task.duration
        add("average_speed", partly, HINTS["average_speed"])
    if form == "coefficients":
        tau = task.law.tau_coefficients() * task.distance[0]
        tau[0] += task.start[0]
        add("normalized_time", tau, HINTS["normalized_time"])
        add("descending_order", right[::-1], HINTS["descending_order"])
    return found
