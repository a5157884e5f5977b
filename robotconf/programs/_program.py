"""A robot program: a list of PTP, LIN, CIRC and Wait moves, checked and simulated."""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_configuration, check_finite_number, one_line
from ..kinematics import Robot
from ..motion import analytic_dva
from ._chain import Chain, make_chain
from ._inputs import check_move_numbers
from ._limits import LIMIT_NAMES, Limits, check_given, resolve_limits
from ._motion import ProgramMotion
from ._moves import Move
from ._plan import Segment, check_held, plan
from ._report import ProgramReport, find_violations
from ._sampling import Samples, sample

__all__ = ["Program", "MAX_MOVES", "SINGULARITY_TOL"]

#: The most moves one program may hold.
MAX_MOVES = 200

#: Default of ``singularity_tolerance``: the smallest singular value of the scaled
#: Jacobian (1 ≈ a unit turn moving the end effector by the robot's size) below which a
#: LIN/CIRC sample counts as near a singularity.
SINGULARITY_TOL = 1e-3


def _check_moves(moves: Any, n: int, names: Sequence[str]) -> tuple[Move, ...]:
    allowed = f"a list of 1 to {MAX_MOVES} moves (PTP, LIN, CIRC, Wait)"
    if isinstance(moves, Move) or not isinstance(moves, (list, tuple)):
        raise InvalidInputError("moves", one_line(moves), allowed, problem="not a list:")
    if not moves:
        raise InvalidInputError("moves", [], allowed, problem="empty program:")
    if len(moves) > MAX_MOVES:
        raise InvalidInputError("moves", f"<{len(moves)} moves>", allowed, problem="too many:")
    checked = []
    for i, move in enumerate(moves):
        if not isinstance(move, Move):
            raise InvalidInputError(
                f"moves[{i}]",
                one_line(move),
                "PTP(…), LIN(…), CIRC(…) or Wait(…)",
                problem="not a move:",
            )
        try:
            check_move_numbers(move)
            checked.append(move.checked(n, names))
        except InvalidInputError as error:
            raise error.within(f"moves[{i}]") from None
    return tuple(checked)


def _tolerance(value: Any) -> float:
    number = check_finite_number(value, "singularity_tolerance")
    if number < 0.0:
        raise InvalidInputError(
            "singularity_tolerance", number, "a number ≥ 0", problem="must be ≥ 0, got"
        )
    return number


class Program:
    """A robot program: moves between taught positions, as a robot controller runs them.

    Parameters
    ----------
    robot : Robot
    moves : list of PTP, LIN, CIRC, Wait
        Run in order, each from where the previous one ended (1 … :data:`MAX_MOVES`).
    start : array-like, shape (n,), optional
        Where the program starts; default the robot's own ``q``.
    joint_speed, joint_accel : float or array-like of n floats, optional
        Limits of PTP moves (rad/s, rad/s²; length units for prismatic joints), checked
        along LIN/CIRC moves.
    cartesian_speed, cartesian_accel : float, optional
        Path speed (length/s) and acceleration (length/s²) of LIN/CIRC moves without
        their own.
    angular_speed, angular_accel : float, optional
        Limits on the tool's turning along LIN/CIRC moves (rad/s, rad/s²).

    The defaults are in :mod:`robotconf.programs._limits`; docs/programs.md has the
    profiles and their formulas. Planning (at construction) solves every target with
    ``rc.ik`` and fixes every move's duration.

    Raises
    ------
    InvalidInputError
        Naming the move and the field, e.g. ``moves[2].speed``: an empty program, a
        wrong shape, NaN, a speed ≤ 0, an unreachable target, a LIN that goes nowhere,
        a CIRC whose points lie on one line, coordinates of joints that do not move
        changed.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import LIN, PTP, Wait
    >>> robot = rc.preset("paper")
    >>> moves = [PTP(q=[0, 0.3, -0.5]), LIN(position=[50, 10, 30], speed=10, accel=10), Wait(0.5)]
    >>> prog = Program(robot, moves)
    >>> [round(s.duration, 4) for s in prog.segments]
    [1.0, 3.3201, 0.5]
    >>> prog.check(dt=0.01).ok
    True
    >>> motion = prog.simulate(dt=0.01)
    >>> motion.trace[-1].round(9) + 0.0  # the end effector ends on the LIN's target
    array([50., 10., 30.])
    """

    def __init__(
        self,
        robot: Robot,
        moves: Sequence[Move],
        *,
        start: Any = None,
        joint_speed: Any = None,
        joint_accel: Any = None,
        cartesian_speed: Any = None,
        cartesian_accel: Any = None,
        angular_speed: Any = None,
        angular_accel: Any = None,
    ):
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", one_line(robot), "a Robot", problem="not a robot:")
        names = robot.coordinate_names
        self._robot = robot
        self._moves = _check_moves(moves, robot.n, names)
        values = (joint_speed, joint_accel, cartesian_speed, cartesian_accel)
        given = dict(zip(LIMIT_NAMES, (*values, angular_speed, angular_accel), strict=True))
        self._given = check_given(robot, given)
        self._start: tuple[float, ...] | None = None
        q0 = robot.q.copy()
        if start is not None:
            q0 = check_configuration(start, robot.n, names, "start")
            self._start = tuple(q0.tolist())
        self._chain: Chain = make_chain(robot, q0)
        check_held(self._chain, q0, "start")
        self._limits = resolve_limits(robot, self._given)
        self._segments = tuple(plan(self._chain, self._moves, q0, self._limits))
        self._cache: tuple[float, Samples] | None = None

    # -- what it is ---------------------------------------------------------------------

    @property
    def robot(self) -> Robot:
        """The robot that runs the program."""
        return self._robot

    @property
    def moves(self) -> tuple[Move, ...]:
        """The moves as checked (plain floats and tuples)."""
        return self._moves

    @property
    def start(self) -> np.ndarray:
        """Where the program starts, shape (n,)."""
        return self._segments[0].q_start.copy()

    @property
    def settings(self) -> dict[str, Any]:
        """``start`` and the limits as given (``None`` for a default), for the JSON form."""
        return {"start": self._start, **self._given}

    @property
    def limits(self) -> Limits:
        """The limits in force, defaults filled in."""
        return self._limits

    @property
    def mode(self) -> str:
        """``"pose"`` when LIN/CIRC moves steer position and orientation, else ``"position"``."""
        return self._chain.mode

    @property
    def segments(self) -> tuple[Segment, ...]:
        """The planned moves: times, end configurations, paths and profiles."""
        return self._segments

    @property
    def duration(self) -> float:
        """How long the program runs (s)."""
        return self._segments[-1].end

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Program):
            return NotImplemented
        return (
            self._robot == other._robot
            and self._moves == other._moves
            and self.settings == other.settings
        )

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        kinds = " ".join(m.kind for m in self._moves)
        return (
            f"Program({self._robot.name or 'robot'!s}, {len(self._moves)} moves: {kinds}; "
            f"{self.duration:.6g} s, mode={self.mode!r})"
        )

    # -- running it ---------------------------------------------------------------------

    def _sample(self, dt: Any) -> Samples:
        step = check_finite_number(dt, "dt")
        if self._cache is None or self._cache[0] != step:
            self._cache = (step, sample(self._chain, self._segments, step))
        return self._cache[1]

    def _report(self, samples: Samples, tolerance: Any) -> ProgramReport:
        labels = [m.kind for m in self._moves]
        report = find_violations(samples, self._chain, self._limits, labels, _tolerance(tolerance))
        report.dt = float(samples.t[1] - samples.t[0]) if samples.t.size > 1 else float("nan")
        return report

    def check(
        self, dt: float = 1e-3, *, singularity_tolerance: float = SINGULARITY_TOL
    ) -> ProgramReport:
        """Sample the program every ``dt`` seconds and list what goes wrong.

        Parameters
        ----------
        dt : float
            Sampling step (s).
        singularity_tolerance : float
            Smallest singular value of the scaled Jacobian counted as regular
            (:data:`SINGULARITY_TOL`).

        Returns
        -------
        ProgramReport
            Joint limits, joint speed and acceleration limits, IK failures, jumps between
            IK branches and near-singularities, each with the move, the time and the
            joint (see :mod:`robotconf.programs._report`).

        Examples
        --------
        >>> import robotconf as rc
        >>> from robotconf.programs import PTP
        >>> Program(rc.preset("paper"), [PTP(q=[0, 0.3, -0.5])]).check(dt=0.01).ok
        True
        """
        return self._report(self._sample(dt), singularity_tolerance)

    def simulate(
        self, dt: float = 1e-3, *, singularity_tolerance: float = SINGULARITY_TOL
    ) -> ProgramMotion:
        """Sample the program into a motion (method ``"analytic"``).

        The samples are ``0, dt, 2dt, …`` and the program's end (the last step may be
        shorter). Joint velocities and accelerations are exact (closed forms for PTP,
        ``J⁺ ẋ`` and ``J⁺(ẍ − J̇ q̇)`` along LIN/CIRC), so the motion's DVA of every
        frame is too.

        Returns
        -------
        ProgramMotion
            A :class:`~robotconf.motion.Motion` with ``segments``, ``taught_points``,
            ``trace`` and the :meth:`check` ``report`` at this ``dt``.

        Warns
        -----
        UserWarning
            When the report is not empty (the motion is still returned).

        Raises
        ------
        InvalidInputError
            ``dt`` outside the limits of a run, or too many samples for the memory
            budget; ``moves`` when the program takes no time.

        Examples
        --------
        >>> import robotconf as rc
        >>> from robotconf.programs import PTP
        >>> motion = Program(rc.preset("paper"), [PTP(q=[0, 0, 0.5])]).simulate(dt=0.1)
        >>> motion.t.size, float(motion.qd[:, 2].max())  # 0.5 rad at 1 rad/s, 2 rad/s²
        (11, 1.0)
        """
        samples = self._sample(dt)
        report = self._report(samples, singularity_tolerance)
        if not report.ok:
            first = report.violations[0].message
            warnings.warn(
                f"the program has {len(report)} violation(s), first: {first}; "
                "see Program.check() or motion.report",
                UserWarning,
                stacklevel=2,
            )
        data = analytic_dva(self._robot, samples.q, samples.qd, samples.qdd)
        return ProgramMotion(
            samples.t.copy(),
            np.ascontiguousarray(samples.q.T),
            np.ascontiguousarray(samples.qd.T),
            np.ascontiguousarray(samples.qdd.T),
            data,
            program=self,
            report=report,
        )
