"""``cell.check``: every contact along a motion, when it starts and ends, how deep it goes.

A robot's motion (``rc.simulate``), program motion (``Program.simulate``) or program
(sampled at ``dt``) is measured at every sample against the objects, itself and the
other robots (:mod:`._pairs`). Two or more robots' motions, given as ``{name: motion}``,
run side by side from t = 0 on one time grid; a robot whose motion has ended holds its
last configuration. A contact interval is a run of samples of one pair closer than
``margin`` (default 0: touching or penetrating); its times are sample times, so the true
start lies within one sample before ``start``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, one_line
from ..motion import Motion
from ..programs import Program, ProgramMotion
from ._answers import CellCheck, Contact, format_length
from ._clearance import least
from ._entries import planning_robot
from ._limits import MAX_SAMPLES
from ._pairs import PairDistances, measure_pairs

if TYPE_CHECKING:
    from ._cell import Cell

__all__ = ["check", "MAX_CONTACTS", "DEFAULT_DT"]

#: The most contact intervals listed (the rest are counted).
MAX_CONTACTS = 1000

#: Sampling step of a program given without a motion (s).
DEFAULT_DT = 0.01


def _as_motion(value: Any, field: str, dt: float) -> Motion:
    if isinstance(value, Program):
        import warnings

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the program's own violations are its report
            return value.simulate(dt)
    if isinstance(value, Motion):
        return value
    raise InvalidInputError(field, one_line(value), "a Motion, a ProgramMotion or a Program")


def _grid(motions: dict[str, Motion]) -> np.ndarray:
    if len(motions) == 1:
        return next(iter(motions.values())).t
    steps = [m.dt for m in motions.values() if m.t.size > 1]
    step = min(steps) if steps else 1.0
    end = max(float(m.t[-1]) for m in motions.values())
    count = int(np.floor(end / step + 1e-9)) + 1
    if count > MAX_SAMPLES:
        raise InvalidInputError(
            "dt", step, f"at most {MAX_SAMPLES} samples", problem="too many samples:"
        )
    grid = np.arange(count) * step
    return grid if grid[-1] >= end - 1e-12 else np.append(grid, end)


def _on_grid(motion: Motion, grid: np.ndarray) -> np.ndarray:
    if motion.t.shape == grid.shape and np.array_equal(motion.t, grid):
        return motion.q
    q = motion.q
    return np.stack([np.interp(grid, motion.t, q[:, j]) for j in range(q.shape[1])], axis=1)


def _runs(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Columns, first and last rows of every run of True down each column."""
    padded = np.zeros((mask.shape[0] + 2, mask.shape[1]), dtype=np.int8)
    padded[1:-1] = mask
    change = np.diff(padded, axis=0)
    column, first = np.nonzero(change.T == 1)  # sorted by column, then time
    _, after = np.nonzero(change.T == -1)
    return column, first, after - 1


def _verb(kind: str, other: str) -> str:
    if kind == "self":
        return f"touches its own {other}"
    if kind == "robot":
        robot, link = other.split("/", 1)
        return f"meets robot '{robot}' {link}"
    return f"enters '{other}'"


def _contacts(
    pairs: PairDistances, t: np.ndarray, motions: dict[str, Motion], margin: float, unit: str | None
) -> tuple[list[Contact], int]:
    mask = pairs.distance < margin
    touched = np.flatnonzero(mask.any(axis=0))  # contacts are rare: scan only those pairs
    column, first, last = _runs(mask[:, touched])
    column = touched[column]
    order = np.lexsort((column, first))
    found = []
    several = len(motions) > 1
    for k in order[:MAX_CONTACTS]:
        c, a, b = int(column[k]), int(first[k]), int(last[k])
        run = pairs.distance[a : b + 1, c]
        deep = a + int(np.argmin(run))
        depth = -float(run.min())
        robot = pairs.robot[c]
        motion = motions.get(robot)
        move = kind = None
        prefix = f"{robot}: " if several else ""
        if isinstance(motion, ProgramMotion):
            index = motion.move_at(float(t[a]))
            move, kind = index + 1, motion.segments[index].kind
            prefix += f"move {move} ({kind}): "
        how = (
            f"{format_length(depth, unit)} deep"
            if depth > 0 or margin <= 0
            else f"{format_length(-depth, unit)} away (margin {format_length(margin, unit)})"
        )
        text = (
            f"{prefix}{pairs.link[c]} {_verb(pairs.kind[c], pairs.other[c])} at t = {t[a]:.2f} s, "
            f"{how}, until t = {t[b]:.2f} s"
        )
        found.append(
            Contact(
                robot,
                pairs.link[c],
                pairs.other[c],
                pairs.kind[c],
                float(t[a]),
                float(t[b]),
                depth,
                float(t[deep]),
                move,
                kind,
                text,
            )
        )
    return found, max(len(order) - MAX_CONTACTS, 0)


def check(
    cell: Cell, motion: Any, robot: Any = None, *, margin: Any = 0.0, dt: Any = DEFAULT_DT
) -> CellCheck:
    """Every contact along a motion, its interval and depth, and the least clearance.

    Parameters
    ----------
    cell : Cell
    motion : Motion, ProgramMotion, Program, or dict of them by robot name
        One robot's motion (``robot`` names it when the cell has several), or several
        robots' side by side from t = 0. A program is sampled every ``dt`` seconds.
    robot : str, optional
    margin : float
        Pairs closer than this count as in contact (length units; 0: touching).
    dt : float
        Sampling step for programs (s).

    Returns
    -------
    CellCheck
        ``contacts`` (with ``.table`` and ``.sentences``) and the motion's least
        clearance ``min_clearance`` (each sample's: ``cell.clearance(robot, motion.q)``).

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> cell.add(rc.Box([10, 10, 40], pose=rc.pose([0, 50, 20]), name="post"))
    'post'
    >>> prog = rc.Program(cell.robot("arm"), [rc.PTP(q=[2.0, 0, 0])])
    >>> result = cell.check(prog)
    >>> print(result.contacts[0].message)
    move 1 (PTP): link 3 enters 'post' at t = 1.64 s, 8.56 mm deep, until t = 2.01 s
    >>> result.table[["link", "other", "start", "end"]]
         link other  start   end
    0  link 3  post   1.64  2.01
    """
    step = check_finite_number(dt, "dt")
    limit = check_finite_number(margin, "margin")
    given = motion if isinstance(motion, dict) else {cell.robot_entry(robot).name: motion}
    if not given:
        raise InvalidInputError("motion", {}, "a motion, or {robot name: motion}")
    motions = {
        cell.robot_entry(name).name: _as_motion(m, f"motion[{name!r}]", step)
        for name, m in given.items()
    }
    for name, m in motions.items():
        entry = cell.robot_entry(name)
        if m.robot != entry.robot and m.robot != planning_robot(entry):
            raise InvalidInputError(
                f"motion[{name!r}]", one_line(m), f"a motion of the robot placed as {name!r}"
            )
    t = _grid(motions)
    if t.size > MAX_SAMPLES:
        raise InvalidInputError("motion", f"<{t.size} samples>", f"at most {MAX_SAMPLES} samples")
    q = {name: _on_grid(m, t) for name, m in motions.items()}
    obstacles, names = cell.obstacles()
    pairs = measure_pairs(
        cell._robot_entries(),
        cell._world(),
        obstacles,
        names,
        q,
        t.size,
        margin=limit,
        focus=tuple(motions),
        per_sample=False,  # contacts and the least clearance: far fewer exact pairs
    )
    contacts, more = _contacts(pairs, t, motions, limit, cell.unit)
    distance, column = least(pairs)
    k = int(np.argmin(distance)) if distance.size else 0
    pair = (
        (pairs.robot[column[k]], pairs.link[column[k]], pairs.other[column[k]])
        if pairs.distance.shape[1]
        else ("", "", "")
    )
    best = float(distance[k]) if distance.size else float("inf")
    return CellCheck(tuple(contacts), t, best, float(t[k]), pair, more, cell.unit)
