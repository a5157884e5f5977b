"""The motion of a program: a :class:`~robotconf.motion.Motion` that knows its moves."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..motion import Motion

if TYPE_CHECKING:
    from ._plan import Segment
    from ._report import ProgramReport

__all__ = ["ProgramMotion"]


class ProgramMotion(Motion):
    """A sampled program: everything a :class:`~robotconf.motion.Motion` has, plus its moves.

    ``method`` is ``"analytic"`` and ``signals`` is empty; ``.table``, ``.stats()``,
    ``.plot()``, the per-frame DVA and ``to_csv`` work as for any motion.

    Attributes
    ----------
    program : Program
        The program sampled.
    segments : tuple of Segment
        One per move: ``index``, ``kind``, ``start``/``end`` times (s), ``q_start``,
        ``q_end``, ``point_start``/``point_end`` (end-effector positions), the
        ``profile`` and, for LIN/CIRC, the ``path`` (and a CIRC's ``via``).
    report : ProgramReport
        What :meth:`Program.check <robotconf.programs.Program.check>` finds at this ``dt``.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import PTP, Program, Wait
    >>> motion = Program(rc.preset("paper"), [PTP(q=[0, 0.3, -0.5]), Wait(0.5)]).simulate(0.1)
    >>> motion.boundaries, motion.taught_points[0]
    (array([0. , 1. , 1.5]), array([70.,  0., 20.]))
    >>> motion.table.shape  # 16 samples × 4 points × 5 quantities × 3 axes
    (16, 60)
    """

    def __init__(
        self,
        t: np.ndarray,
        q: np.ndarray,
        qd: np.ndarray,
        qdd: np.ndarray,
        data: np.ndarray,
        *,
        program: Any,
        report: ProgramReport,
    ):
        # ``program`` is the Program sampled (typed loosely: the Program builds this).
        super().__init__(program.robot, t, q, qd, qdd, data, "analytic", {})
        self.program = program
        self.segments: tuple[Segment, ...] = program.segments
        self.report = report

    @property
    def boundaries(self) -> np.ndarray:
        """The times where moves start, then the program's end (s), shape (moves + 1,)."""
        return np.array([s.start for s in self.segments] + [self.segments[-1].end])

    @property
    def taught_points(self) -> np.ndarray:
        """End-effector positions where the moves end, after the start, shape (moves + 1, 3).

        Row 0 is the start; row ``i + 1`` where move ``i`` ends. A CIRC's via point is in
        :attr:`via_points`.
        """
        return np.array([self.segments[0].point_start] + [s.point_end for s in self.segments])

    @property
    def via_points(self) -> np.ndarray:
        """The via points of the CIRC moves, shape (k, 3)."""
        vias = [s.via for s in self.segments if s.via is not None]
        return np.array(vias).reshape(-1, 3)

    @property
    def trace(self) -> np.ndarray:
        """The end effector's path: its position at every sample, shape (T, 3)."""
        return self.position[:, -1]

    def move_at(self, time: float) -> int:
        """The index of the move running at ``time`` (s)."""
        starts = np.array([s.start for s in self.segments if s.duration > 0.0])
        moves = [s.index for s in self.segments if s.duration > 0.0]
        k = int(np.clip(np.searchsorted(starts, time, side="right") - 1, 0, len(moves) - 1))
        return moves[k]

    def __repr__(self) -> str:
        kinds = " ".join(s.kind for s in self.segments)
        return (
            f"ProgramMotion({len(self.segments)} moves: {kinds}; {self.t.size} samples, "
            f"t = {self.t[0]:.6g} … {self.t[-1]:.6g} s, dt = {self.dt:.6g} s, "
            f"{'no violations' if self.report.ok else repr(self.report)})"
        )
