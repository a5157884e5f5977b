"""Identify a robot's parameters from measured end-effector positions (least squares).

The robot is moved to ``S`` configurations ``q_s`` and its end-effector point is measured
there, ``m_s``. The chosen parameters ``p`` (:mod:`robotconf.calibration._parameters`)
are those that make the robot's own forward kinematics ``f(q_s; p)`` fit the
measurements best, ``min Σ_s |m_s − f(q_s; p)|²``, found by Gauss–Newton from the nominal
values:

- the **identification Jacobian** ``A = ∂f/∂p`` (3S × P) by central differences of the
  robot's kinematics (steps of 1e-6 · L for lengths, L = ``rc.characteristic_length``,
  and 1e-6 rad for angles; columns scaled the same way, so lengths and angles compare);
- its SVD ``A = U Σ Vᵀ``; singular values below 1e-7 of the largest count as zero: the
  **null space** ``V₀`` holds the combinations of parameters that move no measured point
  at all, which these data cannot determine. Each step solves the least-squares problem
  in the other directions only (the pseudo-inverse), so those combinations keep their
  nominal values;
- a step that does not lower the sum of squares is halved; the iteration stops when a
  step changes no parameter by more than 1e-12 (relative) or after ``max_iterations``.

**Which parameters cannot be told apart.** The projector ``N = V₀ V₀ᵀ`` onto the null
space is independent of how the SVD picked its vectors. A parameter with ``N_ii ≥ 0.01``
has a share in an undetermined combination; parameters linked by ``N_ij`` (≥ 0.1 of
``√(N_ii N_jj)``) form one group, reported together (two offsets along the same line:
only their sum is determined).

**Uncertainty.** With independent noise on the measured coordinates, estimated from the
residuals as ``σ̂² = RSS / (3S − r)`` (r the rank), the estimate's covariance is
``σ̂² (AᵀA)⁺`` (scaled back to the parameters' units); a parameter of an undetermined
group has an infinite standard error.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._budget import check_memory
from .._errors import InvalidInputError
from .._validation import check_integer, check_joint_values, one_line
from ..kinematics import Robot, characteristic_length
from ._parameters import Parameter, apply, default_parameters, read_parameters
from ._points import point_set

__all__ = ["Calibration", "calibrate", "RANK_TOL", "MAX_WORK"]

#: Singular values of the scaled identification Jacobian below this fraction of the
#: largest count as zero (directions the data do not see).
RANK_TOL = 1e-7
#: A parameter whose share in the null space reaches this is not identifiable.
NULL_SHARE = 0.01
#: Relative step of the central differences.
DIFFERENCE_STEP = 1e-6
#: A step below this (in units of the robot's size, or rad) ends the iteration.
STEP_TOL = 1e-12
#: The largest samples × parameters² one call may take (about 2 s of work).
MAX_WORK = 5e7


def _link_text(parameters: Sequence[str]) -> str:
    if len(parameters) == 1:
        return parameters[0]
    return ", ".join(parameters[:-1]) + " and " + parameters[-1]


@dataclass(frozen=True, repr=False, eq=False)
class Calibration:
    """What :func:`calibrate` identified, how well, and what the data cannot tell.

    Attributes
    ----------
    robot : Robot
        The calibrated robot: the link and end-effector parameters set to their
        identified values (joint offsets are in :attr:`offsets`).
    parameters : tuple of str
        The names of the parameters, as in the tables below (P of them).
    nominal, values, standard_errors : ndarray, shape (P,)
        Before, identified, and the standard error of each (rad or length units); ``inf``
        for a parameter the data cannot determine (see :attr:`unidentifiable`).
    covariance : ndarray, shape (P, P)
        The identified values' covariance (``σ̂² (AᵀA)⁺``, see the module notes).
    unidentifiable : tuple of tuple of str
        Groups of parameters the data cannot tell apart: only some combination of each
        group is determined (their nominal values are kept along the rest).
    combinations : tuple of str
        Per group, the combination that is determined when it is one simple sum or
        difference of two parameters of one unit (``"M1.az + M2.az"``), else ``""``.
    offsets : ndarray, shape (n,)
        Identified joint zero offsets (0 for the joints not calibrated): the robot's true
        coordinates are ``q + offsets``.
    residuals : ndarray, shape (S, 3)
        Measured minus calibrated end-effector positions.
    rms_before, rms_after : float
        Root mean square distance between measured and modelled points, with the nominal
        and with the identified parameters (length units).
    noise : float
        The noise per coordinate the residuals suggest, ``√(RSS / (3S − r))`` (NaN when
        ``3S ≤ r``).
    rank : int
        How many independent combinations of parameters the data determine.
    singular_values : ndarray
        Of the scaled identification Jacobian, largest first.
    iterations : int
        Gauss–Newton steps taken.
    """

    robot: Robot
    parameters: tuple[str, ...]
    nominal: np.ndarray
    values: np.ndarray
    standard_errors: np.ndarray
    covariance: np.ndarray
    unidentifiable: tuple[tuple[str, ...], ...]
    combinations: tuple[str, ...]
    offsets: np.ndarray
    residuals: np.ndarray
    rms_before: float
    rms_after: float
    noise: float
    rank: int
    singular_values: np.ndarray
    iterations: int

    @property
    def change(self) -> np.ndarray:
        """``values − nominal``, shape (P,)."""
        return self.values - self.nominal

    def end_effector(self, q: Any) -> np.ndarray:
        """The calibrated model's end-effector point(s) at joint readings ``q``.

        ``q`` (n,) or (T, n) as the robot's joints report them; the identified joint
        offsets are added before the calibrated robot's kinematics.
        """
        values, batched = check_joint_values(q, self.robot.n, self.robot.coordinate_names)
        points = self.robot.end_effector(values + self.offsets)
        return points if batched else points[0]

    @property
    def message(self) -> str:
        """The outcome in sentences: the fit, and what the data cannot tell apart."""
        text = (
            f"identified {len(self.parameters)} parameter(s) from {len(self.residuals)} "
            f"samples: rms error {self.rms_before:.4g} before, {self.rms_after:.4g} after"
        )
        for group, combination in zip(self.unidentifiable, self.combinations, strict=True):
            what = f"only {combination} is determined" if combination else "only a combination"
            text += (
                f"; the data cannot tell {_link_text(group)} apart ({what}: they keep "
                "their nominal values along the rest)"
            )
        return text

    def __str__(self) -> str:
        rows = [f"{'parameter':<16} {'nominal':>12} {'identified':>12} {'± std':>10}"]
        for name, before, after, error in zip(
            self.parameters, self.nominal, self.values, self.standard_errors, strict=True
        ):
            shown = "undetermined" if np.isinf(error) else f"{error:.3g}"
            rows.append(f"{name:<16} {before:>12.6g} {after:>12.6g} {shown:>10}")
        return self.message + "\n" + "\n".join(rows)

    def __repr__(self) -> str:
        return f"Calibration({self.message})"

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text(str(self))


class _Model:
    """The robot's end-effector points at the samples as a function of the parameters."""

    def __init__(self, robot: Robot, parameters: Sequence[Parameter], q: np.ndarray):
        self.robot, self.parameters, self.q = robot, tuple(parameters), q
        length = characteristic_length(robot)
        self.scale = np.array([1.0 if p.angle else length for p in parameters])

    def points(self, values: np.ndarray) -> np.ndarray:
        robot, offsets = apply(self.robot, self.parameters, values)
        return robot.end_effector(self.q + offsets)

    def jacobian(self, values: np.ndarray) -> np.ndarray:
        """``∂f/∂(p/scale)``, (3S, P), by central differences."""
        columns = []
        for j, scale in enumerate(self.scale):
            step = np.zeros_like(values)
            step[j] = DIFFERENCE_STEP * scale
            ahead, behind = self.points(values + step), self.points(values - step)
            columns.append(((ahead - behind) / (2.0 * DIFFERENCE_STEP)).ravel())
        return np.stack(columns, axis=1)


def _rank(singular: np.ndarray) -> int:
    if not singular.size or not singular[0] > 0.0:
        return 0
    return int(np.sum(singular > RANK_TOL * singular[0]))


def _groups(null: np.ndarray, names: Sequence[str]) -> list[list[int]]:
    """Parameters with a share in the null space, grouped by the projector's links."""
    projector = null @ null.T
    share = np.diag(projector).copy()
    members = [i for i in range(len(names)) if share[i] >= NULL_SHARE]
    groups: list[list[int]] = []
    for i in members:
        linked = [
            g
            for g in groups
            if any(abs(projector[i, j]) >= 0.1 * np.sqrt(share[i] * share[j]) for j in g)
        ]
        merged = [i] + [k for g in linked for k in g]
        groups = [g for g in groups if g not in linked] + [sorted(merged)]
    return sorted(groups)


def _combination(group: list[int], null: np.ndarray, model: _Model) -> str:
    """``"M1.az + M2.az"`` for a pair of one unit whose only freedom is one direction."""
    if len(group) != 2 or model.scale[group[0]] != model.scale[group[1]]:
        return ""
    part = null[group]
    u, s, _ = np.linalg.svd(part)
    if s.size > 1 and s[1] > 1e-6 * s[0]:
        return ""
    v = u[:, 0]  # the pair moves along (v1, v2): v2·p1 − v1·p2 stays
    ratio = -v[0] / v[1]
    first, second = (model.parameters[k].name for k in group)
    if abs(ratio - 1.0) < 1e-6:
        return f"{first} + {second}"
    if abs(ratio + 1.0) < 1e-6:
        return f"{first} − {second}"
    return f"{first} {'+' if ratio > 0 else '−'} {abs(ratio):.4g}·{second}"


def calibrate(
    robot: Robot,
    q_samples: Any,
    measured_positions: Any,
    parameters: Any = None,
    *,
    max_iterations: int = 50,
) -> Calibration:
    """Identify robot parameters from end-effector positions measured at known joint values.

    Parameters
    ----------
    robot : Robot
        The nominal robot.
    q_samples : array-like, shape (S, n)
        The joint readings at each measurement (rad, length units).
    measured_positions : array-like, shape (S, 3)
        The end-effector point measured there, in the robot's base frame (length units).
    parameters : list of str, optional
        What to identify, by name (:mod:`robotconf.calibration._parameters`): ``"M2.az"``,
        ``"M3.theta"``, ``"q2.offset"``, ``"EE.x"``, …; default every number of the active
        links and the end-effector point.
    max_iterations : int
        Most Gauss–Newton steps, 1 … 1000.

    Returns
    -------
    Calibration
        The calibrated robot, each parameter with its standard error, the residuals, and
        the groups of parameters these data cannot tell apart.

    Raises
    ------
    InvalidInputError
        Naming ``robot``, ``q_samples``, ``measured_positions`` (shapes, NaN, ``|x| >
        1e150``, rows that do not match), ``parameters[i]`` (unknown, twice) or
        ``max_iterations``; ``q_samples`` also when samples × parameters² exceeds
        :data:`MAX_WORK` or the memory budget; ``measured_positions`` when the fit would
        take a parameter past ``1e150``.

    Examples
    --------
    The paper robot's upper arm is 0.5 longer than drawn (30.5); 20 measured points find
    it, while the column height M2.az and the base offset M1.az, both along the base z
    axis, cannot be told apart:

    >>> from robotconf.presets import preset
    >>> nominal = preset("paper")
    >>> true = nominal.with_module(2, nominal.modules[2].with_parameters(ax=30.5))
    >>> q = np.random.default_rng(0).uniform(-1, 1, (20, 3))
    >>> found = calibrate(nominal, q, true.end_effector(q), ["M3.ax", "M1.az", "M2.az"])
    >>> round(float(found.values[0]), 9), found.unidentifiable
    (30.5, (('M1.az', 'M2.az'),))
    >>> found.combinations
    ('M1.az + M2.az',)
    """
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", one_line(robot), "a Robot", problem="not a robot:")
    q, _ = check_joint_values(q_samples, robot.n, robot.coordinate_names, "q_samples")
    measured = point_set(measured_positions, "measured_positions", count=len(q))
    chosen = default_parameters(robot) if parameters is None else read_parameters(robot, parameters)
    iterations_allowed = check_integer(max_iterations, "max_iterations", 1, 1000)
    count, size = len(q), len(chosen)
    if float(count) * size * size > MAX_WORK:
        raise InvalidInputError(
            "q_samples",
            f"<{count} samples for {size} parameters>",
            f"samples × parameters² ≤ {MAX_WORK:.0e}",
            problem="too much work:",
        )
    check_memory(
        "q_samples", f"<{count} samples>", 8.0 * 3 * count * (3 * size + 20), "fewer samples"
    )
    model = _Model(robot, chosen, q)
    nominal = np.array([p.value(robot) for p in chosen])
    values = nominal.copy()
    residual = measured - model.points(values)
    rss = float(np.sum(residual**2))
    rms_before = float(np.sqrt(rss / count))
    steps = 0
    for _ in range(iterations_allowed):
        u, singular, vt = np.linalg.svd(model.jacobian(values), full_matrices=False)
        rank = _rank(singular)
        if rank == 0:
            break
        step = vt[:rank].T @ ((u[:, :rank].T @ residual.ravel()) / singular[:rank])
        accepted = _line_search(model, measured, values, step, rss)
        if accepted is None:
            break
        values, residual, rss, length = accepted
        steps += 1
        if length <= STEP_TOL * (1.0 + float(np.max(np.abs(values / model.scale)))):
            break
    return _result(model, nominal, values, residual, rss, rms_before, steps)


def _line_search(
    model: _Model, measured: np.ndarray, values: np.ndarray, step: np.ndarray, rss: float
) -> tuple[np.ndarray, np.ndarray, float, float] | None:
    """The step (scaled), halved until the sum of squares does not grow; None if none does."""
    factor = 1.0
    for _ in range(40):
        trial = values + factor * step * model.scale
        try:
            residual = measured - model.points(trial)
        except InvalidInputError:
            residual = None  # a parameter past 1e150: a shorter step
        if residual is not None:
            trial_rss = float(np.sum(residual**2))
            if trial_rss <= rss:
                return trial, residual, trial_rss, factor * float(np.max(np.abs(step)))
        factor *= 0.5
    if not np.all(np.isfinite(values + step * model.scale)):
        raise InvalidInputError(
            "measured_positions",
            "<the measured points>",
            "positions the robot's parameters can fit",
            problem="the fit diverges:",
        )
    return None


def _result(
    model: _Model,
    nominal: np.ndarray,
    values: np.ndarray,
    residual: np.ndarray,
    rss: float,
    rms_before: float,
    steps: int,
) -> Calibration:
    _, singular, vt = np.linalg.svd(model.jacobian(values), full_matrices=False)
    rank = _rank(singular)
    count = len(residual)
    freedom = 3 * count - rank
    noise = float(np.sqrt(rss / freedom)) if freedom > 0 else float("nan")
    kept = vt[:rank].T / singular[:rank]
    covariance = noise**2 * (kept @ kept.T) * np.outer(model.scale, model.scale)
    null = vt[rank:].T
    names = [p.name for p in model.parameters]
    groups = _groups(null, names) if null.size else []
    errors = np.sqrt(np.abs(np.diag(covariance)))
    for group in groups:
        errors[group] = np.inf
    calibrated, offsets = apply(model.robot, model.parameters, values)
    return Calibration(
        robot=calibrated,
        parameters=tuple(names),
        nominal=nominal,
        values=values,
        standard_errors=errors,
        covariance=covariance,
        unidentifiable=tuple(tuple(names[k] for k in g) for g in groups),
        combinations=tuple(_combination(g, null, model) for g in groups),
        offsets=offsets,
        residuals=residual,
        rms_before=rms_before,
        rms_after=float(np.sqrt(rss / count)),
        noise=noise,
        rank=rank,
        singular_values=singular,
        iterations=steps,
    )
