"""The answer of :func:`ik_all`: every closed-form solution, labelled."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["IKSolutions", "Candidates"]


@dataclass(frozen=True, eq=False)
class IKSolutions:
    """Every closed-form solution of one inverse-kinematics problem.

    Attributes
    ----------
    q : ndarray, shape (k, n)
        One row per solution, in the robot's coordinates (radians for revolute joints,
        wrapped to (−π, π]; length units for prismatic ones; modules without a joint or
        held constant keep their own ``q``). Every row was checked by forward kinematics:
        its end-effector matches the target within 1e-9 of the robot's size (and its
        orientation within 1e-9 when the target is a pose). ``k = 0`` when there is none.
    labels : tuple of str, length k
        Which branch each row is, e.g. ``"shoulder left, elbow up, wrist no flip"``
        (docs/ik.md, "Closed-form solutions", defines the words).
    within_limits : ndarray of bool, shape (k,)
        Whether the row lies within :meth:`Robot.joint_limits` (a revolute joint counts
        as within when its angle plus some whole number of turns is).
    family : str
        ``"planar 2R"``, ``"planar 3R"``, ``"SCARA"``, ``"3R elbow"``,
        ``"spherical-wrist 6R"`` or ``"UR"``.
    reason : str
        Why there is no solution (``k = 0``: e.g. "the target is 4.2 beyond the reach
        …"), or what is special about the ones given (a free joint shown at its current
        value); ``""`` otherwise.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.inverse_kinematics import ik_all
    >>> sols = ik_all(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0])
    >>> len(sols), sols.labels
    (2, ('elbow down', 'elbow up'))
    >>> sols.q.round(6) + 0.0
    array([[ 0.      ,  1.570796],
           [ 1.570796, -1.570796]])
    """

    q: np.ndarray
    labels: tuple[str, ...]
    within_limits: np.ndarray
    family: str
    reason: str = ""

    def __post_init__(self) -> None:
        for array in (self.q, self.within_limits):
            array.setflags(write=False)

    def __len__(self) -> int:
        return int(self.q.shape[0])

    def __str__(self) -> str:
        count = len(self)
        lines = [f"{self.family}: {count} solution{'' if count == 1 else 's'}"]
        for row, label, ok in zip(self.q, self.labels, self.within_limits, strict=True):
            values = np.array2string(row, precision=6, suppress_small=True, separator=", ")
            lines.append(f"  {label}: q = {values}{'' if ok else '  (outside the limits)'}")
        if self.reason:
            lines.append(f"  note: {self.reason}" if count else f"  {self.reason}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        return f"<IKSolutions {self}>"

    def _repr_pretty_(self, printer: object, cycle: bool) -> None:
        printer.text(str(self))  # type: ignore[attr-defined]


@dataclass
class Candidates:
    """What a family's solver found, before the forward-kinematics check.

    ``rows`` holds, per branch, one value per moving joint (in chain order) and a label;
    ``reason`` says why there is none; ``notes`` describe degenerate branches.
    """

    rows: list[tuple[list[float], str]] = field(default_factory=list)
    reason: str = ""
    notes: list[str] = field(default_factory=list)

    def note(self, text: str) -> None:
        """Record a note once."""
        if text not in self.notes:
            self.notes.append(text)
