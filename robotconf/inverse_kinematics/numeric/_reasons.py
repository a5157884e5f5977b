"""Why a target failed, in words: out of reach, at a singularity, past a joint limit.

The numbers behind each sentence come from :mod:`._ik`; this module
finds the joints to name (from the Jacobian's null space, or from a solution outside the
ranges) and writes the sentences.
"""

from __future__ import annotations

import numpy as np

from ..model._problem import FULL_TURN, Problem
from ..model._reach import Reach

__all__ = [
    "fit_into_limits",
    "dependent_joints",
    "converged_message",
    "beyond_reach_message",
    "closest_message",
    "joint_limit_message",
    "singular_message",
    "iteration_message",
]

#: A singular value below this fraction of the largest counts as lost.
SINGULAR_TOL = 1e-6
#: A joint takes part in a null-space motion when its share is at least this.
NULL_SHARE = 0.1


def _number(value: float) -> str:
    return f"{value:.4g}"


def _point(point: np.ndarray) -> str:
    return "(" + ", ".join(_number(v + 0.0) for v in point) + ")"


def _joints(indices: list[int]) -> str:
    labels = [str(j + 1) for j in indices]
    if len(labels) == 1:
        return f"joint {labels[0]}"
    return f"joints {', '.join(labels[:-1])} and {labels[-1]}"


def fit_into_limits(problem: Problem, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Turn revolute joints by whole turns to fit their ranges where possible.

    Parameters
    ----------
    problem : Problem
    q : ndarray, shape (B, n)

    Returns
    -------
    q : ndarray, shape (B, n)
        Each revolute angle replaced by its twin (± k·2π) inside the range, or, when no
        twin fits, by the twin nearest to the range.
    outside : ndarray of bool, shape (B, n)
        Joints still outside their range.
    """
    lower, upper = problem.lower, problem.upper
    revolute = np.array([t == "revolute" for t in problem.robot.joint_types])
    up = q + FULL_TURN * np.ceil((lower - q) / FULL_TURN)  # smallest twin ≥ lower
    down = up - FULL_TURN
    twin = np.where(up - upper <= lower - down, up, down)
    twin = np.where(up <= upper, up, twin)
    fitted = np.where(revolute & problem.moving, twin, q)
    margin = 1e-9 * np.maximum(upper - lower, 1.0)
    outside = problem.moving & ((fitted < lower - margin) | (fitted > upper + margin))
    fitted = np.where(problem.moving & ~outside, np.clip(fitted, lower, upper), fitted)
    return fitted, outside


def dependent_joints(
    problem: Problem, scaled_jacobian: np.ndarray, full_jacobian: np.ndarray
) -> tuple[list[int], bool]:
    """The joints whose Jacobian columns lost their independence (at a singularity).

    Parameters
    ----------
    problem : Problem
    scaled_jacobian : ndarray, shape (m, n)
        Constrained rows in the solver's units at the final configuration, known to have
        lost rank.
    full_jacobian : ndarray, shape (6, n)
        The geometric Jacobian there (base frame), to tell aligned axes.

    Returns
    -------
    joints : list of int
        The 0-based joints that move in the null space of the moving joints' columns.
    aligned : bool
        Whether they are two revolute joints turning about the same line.
    """
    moving = np.flatnonzero(problem.moving)
    _, values, vh = np.linalg.svd(scaled_jacobian[:, moving])
    top = values[0] if values.size else 0.0
    found = int(np.sum(values > SINGULAR_TOL * top)) if top > 0 else 0
    share = np.asarray(np.linalg.norm(vh[found:], axis=0))
    joints = [int(moving[i]) for i in np.flatnonzero(share >= NULL_SHARE * float(np.max(share)))]
    aligned = False
    types = problem.robot.joint_types
    if len(joints) == 2 and all(types[j] == "revolute" for j in joints):
        a, b = full_jacobian[:, joints[0]], full_jacobian[:, joints[1]]
        scale = max(float(np.linalg.norm(a)), float(np.linalg.norm(b)), 1e-300)
        gap = min(float(np.linalg.norm(a - b)), float(np.linalg.norm(a + b)))
        aligned = gap <= 1e-6 * scale
    return joints, aligned


def _errors(position: float, orientation: float, digits: int) -> str:
    """``"3e-10 in position and 2e-12 rad in orientation"``, leaving out NaN parts."""
    parts = []
    if not np.isnan(position):
        parts.append(f"{position:.{digits}g} in position")
    if not np.isnan(orientation):
        parts.append(f"{orientation:.{digits}g} rad in orientation")
    return " and ".join(parts)


def converged_message(iterations: int, position: float, orientation: float) -> str:
    """``"converged after 7 iterations: error 3e-15 in position"``."""
    return f"converged after {iterations} iterations: error {_errors(position, orientation, 2)}"


def beyond_reach_message(
    reach: Reach, point: np.ndarray, distance: float, closest: float | None = None
) -> str:
    """A target proved out of reach, with the numbers of the bound that proves it; and,
    when the closest configuration found stays farther (``closest``), how far."""
    where = (
        "the base origin"
        if reach.axis_joint is None
        else f"{_point(reach.center)} on joint {reach.axis_joint + 1}'s axis"
    )
    radius = float(np.linalg.norm(point - reach.center))
    sphere = float(reach.sphere_distance(point[np.newaxis])[0])
    cylinder = reach.cylinder
    if cylinder is not None and distance > sphere:
        text = f"the target is {_number(distance)} out of reach: {_cylinder_text(reach, point)}"
    elif radius > reach.outer:
        text = (
            f"the target is {_number(distance)} beyond the reach (reach sphere radius "
            f"{_number(reach.outer)} about {where})"
        )
    else:
        text = (
            f"the target is {_number(distance)} inside the hole the arm cannot reach (no "
            f"point closer than {_number(reach.inner)} to {where})"
        )
    if closest is not None:
        text += f"; the closest configuration found misses it by {_number(closest)}"
    return text


def _cylinder_text(reach: Reach, point: np.ndarray) -> str:
    """Where an arm with parallel revolute axes keeps its end effector, and the target."""
    cylinder = reach.cylinder
    assert cylinder is not None
    direction = _point(cylinder.direction)
    planar = cylinder.high - cylinder.low <= 1e-12 * max(1.0, abs(cylinder.high))
    if planar:
        stays = f"in the plane at height {_number(cylinder.low)} along {direction}"
    else:
        stays = (
            f"between heights {_number(cylinder.low)} and {_number(cylinder.high)} along "
            f"{direction}"
        )
    height = float(point @ cylinder.direction)
    off, across = (float(v[0]) for v in cylinder.parts(point[np.newaxis]))
    parts = [f"at height {_number(height)}"]
    rho, outer = 0.0, 0.0
    if cylinder.radii is not None:
        inner, outer = cylinder.radii
        axis = "" if reach.axis_joint is None else f" joint {reach.axis_joint + 1}'s axis"
        stays += f", {_number(inner)} to {_number(outer)} from{axis}"
        rho = float(
            np.linalg.norm(
                (point - cylinder.point)
                - ((point - cylinder.point) @ cylinder.direction) * cylinder.direction
            )
        )
        parts.append(f"{_number(rho)} from that axis")
    missing = []
    if off > 0:
        missing.append(f"{_number(off)} off {'that plane' if planar else 'those heights'}")
    if across > 0:
        missing.append(f"{_number(across)} {'beyond' if rho > outer else 'inside'} those radii")
    return (
        f"the end effector stays {stays}; the target is {' and '.join(parts)} "
        f"({' and '.join(missing)})"
    )


def closest_message(starts: int, position: float, orientation: float) -> str:
    """A target the search could not get closer to, from any start."""
    return (
        f"the target looks out of reach: the closest configuration found from {starts} "
        f"start(s) misses it by {_errors(position, orientation, 4)}, and no joint motion "
        "brings it closer (a local search, not a proof)"
    )


def joint_limit_message(problem: Problem, solution: np.ndarray, outside: np.ndarray) -> str:
    """Which joints a solution found without the ranges puts past them."""
    parts = []
    names = problem.robot.coordinate_names
    for j in np.flatnonzero(outside):
        value = float(solution[j])
        high = value > problem.upper[j]
        limit = problem.upper[j] if high else problem.lower[j]
        side = "upper" if high else "lower"
        if problem.robot.joint_types[j] == "revolute":
            shown, bound = f"{np.degrees(value):.4g}°", f"{np.degrees(limit):.4g}°"
        else:
            shown, bound = _number(value), _number(limit)
        parts.append(f"joint {j + 1} ({names[j]}) at {shown}, past its {side} limit {bound}")
    return (
        "no solution within the joint ranges was found: the solution found without them "
        "needs " + "; ".join(parts)
    )


def singular_message(joints: list[int], aligned: bool) -> str:
    """A solve stuck where the Jacobian lost rank, naming the joints involved."""
    if aligned:
        detail = f"{_joints(joints)} are aligned (they turn about the same line)"
    else:
        detail = (
            f"the Jacobian columns of {_joints(joints)} are dependent (together they move "
            "the end effector in fewer directions than usual, as an arm stretched out or "
            "folded)"
        )
    return (
        f"stuck at a singularity: {detail}; the error points in a direction the joints "
        "cannot move, so try another q0 or more seeds"
    )


def iteration_message(
    max_iterations: int, starts: int, position: float, orientation: float, rounding: bool
) -> str:
    """Out of iterations (or of progress) on every start, with the best error.

    ``rounding``: the best error is already at the level of float64 rounding, so the
    tolerances asked for cannot be met at all.
    """
    best = _errors(position, orientation, 3)
    if rounding:
        return (
            f"stopped at an error of {best}, the level of float64 rounding for this robot: "
            "tolerances below it cannot be met, so loosen tol or orientation_tol"
        )
    return (
        f"no convergence within {max_iterations} iterations on each of {starts} start(s): "
        f"the best is {best} from the target; raise max_iterations or seeds, or loosen "
        "tol"
    )
