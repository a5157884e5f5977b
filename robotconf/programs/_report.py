"""What ``Program.check`` finds: each violation with its move, its time and its joint.

One :class:`Violation` is reported per kind, move and joint: from the first sample where
it happens, with the worst value over the move. The kinds, in the order reported:

``ik failure``
    ``rc.ik`` did not reach a LIN/CIRC sample (out of reach, or stuck): its reason.
``singularity``
    The smallest generic singular value of the scaled Jacobian (see
    :mod:`robotconf.programs._chain`) fell below the tolerance on a LIN/CIRC: the joint
    velocities ``J⁺ ẋ`` grow like ``1/σ`` there.
``jump``
    A joint moved between two samples by much more than its velocities explain: the
    trapezoidal rule's miss ``|Δq − ½(q̇_k + q̇_{k+1})·Δt|`` exceeds
    ``max(10⁻⁶·s, ¼·|Δq|, (|q̈_k| + |q̈_{k+1}|)·Δt²)`` (``s`` is 1 rad, or ``L`` for a
    prismatic joint; the last term allows for an acceleration that jumps within the
    step, where the rule misses by up to ``|Δq̈|·Δt²/8``): the inverse kinematics
    changed branch.
``joint limit``
    A coordinate left its range (``robot.joint_limits()``).
``joint speed``
    ``|q̇|`` (or ``|Δq|/Δt`` between samples) above the joint's speed limit.
``joint accel``
    ``|q̈|`` above the joint's acceleration limit.

A value counts as over a limit when it exceeds it by more than ``10⁻⁹`` relative, so a
PTP move that runs exactly at a limit is not reported.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from ._chain import Chain
    from ._limits import Limits
    from ._sampling import Samples

__all__ = ["VIOLATIONS", "Violation", "ProgramReport", "find_violations"]

VIOLATIONS = ("ik failure", "singularity", "jump", "joint limit", "joint speed", "joint accel")

_OVER = 1.0 + 1e-9


@dataclass(frozen=True)
class Violation:
    """One problem of a program.

    Attributes
    ----------
    kind : str
        One of :data:`VIOLATIONS`.
    move : int
        The move's index in the program, from 0 (the message counts from 1: "move 2" is
        index 1).
    time : float
        The first sample time where it happens (s).
    joint : str or None
        The coordinate's name (``"q2"``), or None for the whole arm.
    value : float
        The worst value over the move: the coordinate, speed or acceleration, the
        singular value, the jump, or ``rc.ik``'s position error.
    limit : float or None
        The limit it broke, where there is one.
    worst_time : float
        When the worst value happens (s).
    message : str
        All of it in a sentence.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import PTP, Program
    >>> (found,) = Program(rc.preset("paper"), [PTP(q=[0, 0, 3.0])]).check(dt=0.01)
    >>> found.kind, found.move, found.joint, found.time
    ('joint limit', 0, 'q3', 2.61)
    """

    kind: str
    move: int
    time: float
    joint: str | None
    value: float
    limit: float | None
    worst_time: float
    message: str


class ProgramReport:
    """The violations ``Program.check`` found, in program order.

    ``report.ok`` is True when there are none; ``len(report)``, iteration and indexing
    go over the :class:`Violation` objects; ``str(report)`` lists their messages.

    Examples
    --------
    >>> ProgramReport(()).ok, str(ProgramReport(()))
    (True, 'no violations')
    """

    def __init__(self, violations: tuple[Violation, ...], dt: float = float("nan")):
        self.violations = violations
        self.dt = dt

    @property
    def ok(self) -> bool:
        """Whether nothing was found."""
        return not self.violations

    @property
    def kinds(self) -> tuple[str, ...]:
        """The kinds found, in the order of :data:`VIOLATIONS`."""
        found = {v.kind for v in self.violations}
        return tuple(kind for kind in VIOLATIONS if kind in found)

    def of_kind(self, kind: str) -> tuple[Violation, ...]:
        """The violations of one kind."""
        return tuple(v for v in self.violations if v.kind == kind)

    def __len__(self) -> int:
        return len(self.violations)

    def __iter__(self) -> Iterator[Violation]:
        return iter(self.violations)

    def __getitem__(self, i: int) -> Violation:
        return self.violations[i]

    def __str__(self) -> str:
        if self.ok:
            return "no violations"
        return "\n".join(v.message for v in self.violations)

    def __repr__(self) -> str:
        if self.ok:
            return "ProgramReport(no violations)"
        return f"ProgramReport({len(self)} violations: {', '.join(self.kinds)})"

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text(str(self))


def _unit(chain: Chain, j: int) -> str:
    return "rad" if chain.robot.joint_types[j] == "revolute" else "length"


def _groups(mask: np.ndarray, move: np.ndarray) -> Iterator[tuple[int, np.ndarray]]:
    """Per move, the sample indices where ``mask`` holds."""
    hits = np.flatnonzero(mask)
    if not hits.size:
        return
    for m in np.unique(move[hits]):
        yield int(m), hits[move[hits] == m]


class _Collector:
    def __init__(self, samples: Samples, labels: list[str]):
        self.samples = samples
        self.labels = labels
        self.found: list[Violation] = []

    def add(
        self,
        kind: str,
        mask: np.ndarray,
        values: np.ndarray,
        joint: str | None,
        limit: float | None,
        describe: Any,
        worst_is_min: bool = False,
    ) -> None:
        t = self.samples.t
        for move, rows in _groups(mask, self.samples.move):
            pick = np.argmin(values[rows]) if worst_is_min else np.argmax(values[rows])
            worst = int(rows[pick])
            first = int(rows[0])
            value = float(values[worst])
            # Counted from 1 in the text, as a program listing and the panel number them.
            where = f"move {move + 1} ({self.labels[move]})"
            text = describe(value, float(t[first]), float(t[worst]), first)
            self.found.append(
                Violation(
                    kind,
                    move,
                    float(t[first]),
                    joint,
                    value,
                    limit,
                    float(t[worst]),
                    f"{where}: {text}",
                )
            )


def find_violations(
    samples: Samples, chain: Chain, limits: Limits, labels: list[str], tolerance: float
) -> ProgramReport:
    """Every violation in ``samples`` (see the module notes)."""
    s, robot = samples, chain.robot
    names = robot.coordinate_names
    collect = _Collector(s, labels)
    failed = ~s.solved

    def ik_text(value: float, first: float, worst: float, k: int) -> str:
        reason, message = s.failures.get(k, ("", ""))
        return f"inverse kinematics failed from t = {first:.6g} s ({reason}: {message})"

    collect.add("ik failure", failed, np.nan_to_num(s.error, nan=np.inf), None, None, ik_text)
    sigma = np.where(s.cartesian, s.sigma, np.inf)

    def singular_text(value: float, first: float, worst: float, k: int) -> str:
        return (
            f"near a singularity from t = {first:.6g} s: smallest singular value of the "
            f"scaled Jacobian {value:.3g} < {tolerance:.3g} (lowest at t = {worst:.6g} s); "
            "joint speeds grow like 1/σ there"
        )

    collect.add("singularity", sigma < tolerance, sigma, None, tolerance, singular_text, True)
    step = np.diff(s.t)
    lower, upper = robot.joint_limits().T
    for j in np.flatnonzero(chain.moving).tolist():
        unit, name = _unit(chain, j), names[j]
        _joint_checks(collect, s, j, name, unit, step, chain, limits, lower[j], upper[j])
    order = {kind: i for i, kind in enumerate(VIOLATIONS)}
    found = sorted(collect.found, key=lambda v: (v.move, order[v.kind], v.time))
    return ProgramReport(tuple(found))


def _joint_checks(
    collect: _Collector,
    s: Samples,
    j: int,
    name: str,
    unit: str,
    step: np.ndarray,
    chain: Chain,
    limits: Limits,
    lo: float,
    hi: float,
) -> None:
    q, qd, qdd = s.q[:, j], s.qd[:, j], s.qdd[:, j]
    dq = np.diff(q)
    scale = 1.0 if unit == "rad" else chain.length
    mismatch = np.abs(dq - 0.5 * (qd[:-1] + qd[1:]) * step)
    allowed = np.maximum(0.25 * np.abs(dq), (np.abs(qdd[:-1]) + np.abs(qdd[1:])) * step**2)
    jumped = np.append((mismatch > 1e-6 * scale) & (mismatch > allowed), False)
    size = np.append(np.abs(dq), 0.0)

    def jump_text(value: float, first: float, worst: float, k: int) -> str:
        return (
            f"{name} jumps by {size[k]:.4g} {unit} between t = {first:.6g} s and the next "
            f"sample (largest {value:.4g} {unit} at t = {worst:.6g} s): the inverse "
            "kinematics changed branch"
        )

    collect.add("jump", jumped, size, name, None, jump_text)
    room = (hi - lo) * 1e-9
    outside = np.maximum(lo - q, q - hi)

    def limit_text(value: float, first: float, worst: float, k: int) -> str:
        return (
            f"{name} leaves its range [{lo:.6g}, {hi:.6g}] {unit} at t = {first:.6g} s "
            f"(by up to {value:.4g} {unit}, at t = {worst:.6g} s)"
        )

    collect.add("joint limit", outside > room, outside, name, None, limit_text)
    v_max, a_max = float(limits.joint_speed[j]), float(limits.joint_accel[j])
    rate = np.abs(qd)
    rate[:-1] = np.maximum(rate[:-1], np.abs(dq) / step)

    def speed_text(value: float, first: float, worst: float, k: int) -> str:
        return (
            f"{name} moves faster than its limit {v_max:.4g} {unit}/s from t = {first:.6g} s "
            f"(up to {value:.4g} {unit}/s at t = {worst:.6g} s)"
        )

    collect.add("joint speed", rate > v_max * _OVER, rate, name, v_max, speed_text)
    accel = np.abs(qdd)

    def accel_text(value: float, first: float, worst: float, k: int) -> str:
        return (
            f"{name} accelerates beyond its limit {a_max:.4g} {unit}/s² from t = "
            f"{first:.6g} s (up to {value:.4g} {unit}/s² at t = {worst:.6g} s)"
        )

    collect.add("joint accel", accel > a_max * _OVER, accel, name, a_max, accel_text)
