"""A wrong DH table explained by repairing it.

The robot to match is sampled once (:class:`Reference`: every joint's axis as a line with
a direction, and the end-effector, at seeded joint values); a table is compared with it
(:func:`compare`); each usual mistake is undone in turn (the other convention, degrees,
the sign of one α, a and d swapped in one row or in every row, a θ offset of a quarter
turn, a constant left out of one d or a) and the first repair that gives the robot names
the mistake (:func:`diagnose`).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...kinematics import Robot, characteristic_length, joint_axes
from ._dh_hints import (
    convention_hint,
    degrees_hint,
    exchanged_hint,
    generic_hint,
    negative_lengths_hint,
    repair_hint,
    swapped_columns_hint,
)
from ._dh_table_text import DHRow

__all__ = ["Match", "Reference", "compare", "diagnose", "reference"]

_TURNS = (np.pi / 2, np.pi, -np.pi / 2)
_TWISTS = (0.0, np.pi / 2, -np.pi / 2, np.pi)


@dataclass(frozen=True)
class Reference:
    """The robot to match, sampled once: axes and end-effector at K joint values."""

    letters: tuple[str, ...]
    q: np.ndarray  # (K, m) joint values, one column per joint
    direction: np.ndarray  # (K, m, 3)
    moment: np.ndarray  # (K, m, 3)
    end_effector: np.ndarray  # (K, 3)
    scale: float
    tol: float


@dataclass(frozen=True)
class Match:
    wrong: tuple[int, ...]  # 0-based joints with a wrong axis
    first_reversed: bool  # the first wrong axis is the right line, pointing the other way
    end_effector_ok: bool

    @property
    def axes_ok(self) -> bool:
        return not self.wrong

    @property
    def ok(self) -> bool:
        return self.axes_ok and self.end_effector_ok


def _axes(robot: Robot, q: np.ndarray, columns: Any) -> tuple[np.ndarray, np.ndarray]:
    axes = joint_axes(robot, q)
    direction = axes.direction[:, columns]
    return direction, np.cross(axes.point[:, columns], direction)


def reference(robot: Robot, samples: int, seed: int, tol: float) -> Reference:
    letters_all = joint_axes(robot, robot.q).joints
    columns = np.array([i for i, letter in enumerate(letters_all) if letter is not None])
    letters = tuple(str(letters_all[i]) for i in columns)
    if not letters:
        raise InvalidInputError("expected", robot, "a robot with at least one joint")
    scale = characteristic_length(robot)
    rng = np.random.default_rng(seed)
    joints = np.zeros((samples + 1, len(letters)))  # sample 0: the zero position
    for j, letter in enumerate(letters):
        span = np.pi if letter == "R" else 0.5 * scale
        joints[1:, j] = rng.uniform(-span, span, samples)
    q_full = np.tile(robot.q, (samples + 1, 1))
    q_full[:, columns] = joints
    direction, moment = _axes(robot, q_full, columns)
    return Reference(letters, joints, direction, moment, robot.end_effector(q_full), scale, tol)


def compare(
    ref: Reference, rows: tuple[DHRow, ...], convention: str, end_effector: Any
) -> Match | None:
    """How the robot of ``rows`` differs from the reference; None if it cannot be built."""
    try:
        robot = Robot.from_dh(rows, convention=convention, end_effector=end_effector)
    except InvalidInputError:
        return None
    direction, moment = _axes(robot, ref.q, slice(None))
    revolute = np.array([letter == "R" for letter in ref.letters])
    # A prismatic joint's line does not matter, only its direction: no moment for it.
    moment_gap = np.where(revolute, np.abs(moment - ref.moment).max(axis=(0, 2)), 0.0)
    moment_flip = np.where(revolute, np.abs(moment + ref.moment).max(axis=(0, 2)), 0.0)
    same = (np.abs(direction - ref.direction).max(axis=(0, 2)) <= ref.tol) & (
        moment_gap <= ref.tol * ref.scale
    )
    flipped = (np.abs(direction + ref.direction).max(axis=(0, 2)) <= ref.tol) & (
        moment_flip <= ref.tol * ref.scale
    )
    wrong = tuple(int(j) for j in np.flatnonzero(~same))
    gap = np.abs(robot.end_effector(ref.q) - ref.end_effector).max()
    return Match(wrong, bool(wrong) and bool(flipped[wrong[0]]), gap <= ref.tol * ref.scale)


def _looks_like_degrees(angle: float) -> bool:
    return abs(angle) > 2 * np.pi + 1e-9


def _radians(angle: float) -> float:
    """An angle too large to be radians, read as degrees; others kept."""
    return float(np.radians(angle)) if _looks_like_degrees(angle) else angle


def _with(row: DHRow, **changes: float) -> DHRow:
    theta, d, a, alpha, joint = row
    new = {"theta": theta, "d": d, "a": a, "alpha": alpha, **changes}
    return (new["theta"], new["d"], new["a"], new["alpha"], joint)


def _row_repairs(row: DHRow) -> Iterator[tuple[str, DHRow]]:
    """The single-row mistakes, undone: (code, the repaired row)."""
    theta, d, a, alpha, _ = row
    flat = abs(np.sin(alpha)) < 1e-9  # α = 0 or ±π: its sign changes nothing
    if not flat:
        yield "alpha_sign", _with(row, alpha=-alpha)
    if not np.isclose(a, d):
        yield "swapped_a_d", _with(row, a=d, d=a)
    for turn in _TURNS:
        yield "theta_offset", _with(row, theta=theta + turn)
    for twist in _TWISTS:
        if abs(np.sin(alpha - twist)) > 1e-9 or np.cos(alpha - twist) < 0:
            yield "twist", _with(row, alpha=twist)
    if a != 0:
        yield "a_sign", _with(row, a=-a)
    if d != 0:
        yield "d_sign", _with(row, d=-d)


_ROW_ORDER = ("alpha_sign", "swapped_a_d", "theta_offset", "twist", "a_sign", "d_sign")
#: Repaired tables tried at most (each builds and samples a robot): a 64-row table is
#: judged in about a second, a course-sized one in milliseconds.
_MAX_REPAIRS = 200


def diagnose(
    ref: Reference,
    rows: tuple[DHRow, ...],
    convention: str,
    end_effector: Any,
    own: Match,
    reveal: bool,
) -> tuple[str, str]:
    """(code, hint) of the first repair that gives the robot, else a generic hint."""
    other = "modified" if convention == "standard" else "standard"
    swapped = compare(ref, rows, other, end_effector)
    if swapped is not None and (swapped.ok or (swapped.axes_ok and not own.axes_ok)):
        return "convention", convention_hint(convention, other, swapped.ok)
    if any(_looks_like_degrees(row[0]) or _looks_like_degrees(row[3]) for row in rows):
        # every angle in degrees, or only those too large for radians (a 90 among pi/2s)
        every = tuple(_with(r, theta=np.radians(r[0]), alpha=np.radians(r[3])) for r in rows)
        some = tuple(_with(r, theta=_radians(r[0]), alpha=_radians(r[3])) for r in rows)
        for radians in (every, some):
            match = compare(ref, radians, convention, end_effector)
            if match is not None and match.ok:
                return "degrees", degrees_hint()
    negative = [r for r, row in enumerate(rows) if row[2] < 0]
    if len(negative) > 1:  # every link length negative: one sign slip, not a turned frame
        flipped = tuple(_with(row, a=abs(row[2])) for row in rows)
        match = compare(ref, flipped, convention, end_effector)
        if match is not None and match.ok:
            return "a_sign", negative_lengths_hint([r + 1 for r in negative], convention)
    # Joint j's axis is placed by rows 1..j-1 (standard) or 1..j (modified): a one-row
    # mistake that misplaces the first wrong axis sits in one of those rows.
    suspects = len(rows)
    if own.wrong:
        suspects = min(suspects, own.wrong[0] + (0 if convention == "standard" else 1))
    repairs = [
        (code, r, repaired)
        for r, row in enumerate(rows[:suspects])
        for code, repaired in _row_repairs(row)
    ]
    # A zero offset between joints on one line fits either row; the later row is where a
    # forgotten quarter turn (x_i against x_(i-1)) is usually missing.
    repairs.sort(
        key=lambda item: (
            _ROW_ORDER.index(item[0]),
            -item[1] if item[0] == "theta_offset" else item[1],
        )
    )
    for code, r, repaired in repairs[:_MAX_REPAIRS]:
        table = rows[:r] + (repaired,) + rows[r + 1 :]
        match = compare(ref, table, convention, end_effector)
        if match is not None and match.ok:
            return code, repair_hint(code, r, convention, repaired if reveal else None)
    both = [r for r, row in enumerate(rows) if not np.isclose(row[1], row[2])]
    if len(both) > 1:  # a and d swapped in several rows: the columns mixed up
        table = tuple(
            _with(row, a=row[1], d=row[2]) if r in both else row for r, row in enumerate(rows)
        )
        match = compare(ref, table, convention, end_effector)
        if match is not None and match.ok:
            return "swapped_a_d", swapped_columns_hint([r + 1 for r in both], convention)
    found = _length_repair(ref, rows[:suspects], rows, convention, end_effector)
    if found is not None:
        code, r, repaired = found
        written = float(rows[r][1 if code == "d_value" else 2])
        shown = repaired if reveal else None
        return code, repair_hint(code, r, convention, shown, written=written or None)
    exchanged = _exchanged_lengths(ref, rows, convention, end_effector)
    if exchanged is not None:
        code, pair = exchanged
        return code, exchanged_hint(code, pair, convention)
    first = own.wrong[0] if own.wrong else None
    tool = bool(np.any(np.asarray(end_effector) != 0))
    return generic_hint(first, own.first_reversed, convention, len(rows), tool)


def _exchanged_lengths(
    ref: Reference, rows: tuple[DHRow, ...], convention: str, end_effector: Any
) -> tuple[str, tuple[int, int]] | None:
    """Two rows' d (or two rows' a) written in each other's place: two link lengths
    exchanged. Returns the code and the two 0-based rows, or None. Neighbouring rows are
    tried first, at most :data:`_MAX_REPAIRS` exchanges (a long table stays fast)."""
    pairs = sorted(
        ((i, j) for i in range(len(rows)) for j in range(i + 1, len(rows))),
        key=lambda pair: (pair[1] - pair[0], pair[0]),
    )
    tried = 0
    for code, column in (("a_value", 2), ("d_value", 1)):
        field = "da"[column - 1]
        for i, j in pairs:
            if np.isclose(rows[i][column], rows[j][column]):
                continue
            if tried == _MAX_REPAIRS:
                return None
            tried += 1
            table = list(rows)
            table[i] = _with(rows[i], **{field: float(rows[j][column])})
            table[j] = _with(rows[j], **{field: float(rows[i][column])})
            match = compare(ref, tuple(table), convention, end_effector)
            if match is not None and match.ok:
                return code, (i, j)
    return None


def _length_repair(
    ref: Reference,
    suspects: tuple[DHRow, ...],
    rows: tuple[DHRow, ...],
    convention: str,
    end_effector: Any,
) -> tuple[str, int, DHRow] | None:
    """A wrong constant in one row's d or a: left out (a forgotten height, a slide's
    start: the row has 0 there) or another length written there (f for h, a length
    measured from the wrong joint).

    Adding ``c`` to ``d_r`` moves everything after it along joint r's axis; adding it to
    ``a_r`` along ``x_r`` (standard) or ``x_(r-1)`` (modified: row r holds the link
    before joint r). ``c`` is read off the end-effector's offset from the robot's along
    that direction, averaged over the sample configurations, and kept when the repaired
    table describes the robot. A forgotten constant is tried before a wrong one.
    """
    try:
        robot = Robot.from_dh(rows, convention=convention, end_effector=end_effector)
    except InvalidInputError:
        return None
    gap = ref.end_effector - robot.end_effector(ref.q)  # (K, 3)
    axes = joint_axes(robot, ref.q).direction  # (K, n, 3): z of joint r's own frame
    poses = robot.frame_poses(ref.q)  # (K, n, 4, 4)
    # Where two rows' d lie along one line either fixes the table: the later row (a slide
    # written without its start, a height left out of the row that has it) comes first.
    for forgotten in (True, False):
        for r in reversed(range(len(suspects))):
            # d_r is along the axis joint r moves about (standard: z_(r-1), modified: z_r)
            along_d = axes[:, r, :]
            if convention == "standard":
                along_a = poses[:, r, :3, 0]
            elif r:
                along_a = poses[:, r - 1, :3, 0]
            else:  # the modified table's a0 is along the base frame's x
                along_a = np.tile([1.0, 0.0, 0.0], (len(gap), 1))
            for code, direction in (("d_value", along_d), ("a_value", along_a)):
                column = 1 if code == "d_value" else 2
                row = rows[r]
                if (row[column] == 0) != forgotten:
                    continue
                c = float(np.mean(np.einsum("kj,kj->k", gap, direction)))
                if abs(c) <= ref.tol * ref.scale:
                    continue
                repaired = _with(row, **{"da"[column - 1]: float(row[column]) + c})
                table = rows[:r] + (repaired,) + rows[r + 1 :]
                match = compare(ref, table, convention, end_effector)
                if match is not None and match.ok:
                    return code, r, repaired
    return None
