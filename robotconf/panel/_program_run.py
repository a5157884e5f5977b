"""What the Program tab's Run does with the core: check and simulate a program, sort the
violations by move, and hand the motion to the Motion tab and the 3D view.
"""

from __future__ import annotations

import html
import warnings
from typing import TYPE_CHECKING, Any

from ..programs import Program, ProgramMotion, ProgramReport

if TYPE_CHECKING:
    from ._motion_section import MotionSection

__all__ = ["run_program", "violations_by_move", "run_summary", "show_program_motion"]

_OK, _WARN = "color:#1b7a1b", "color:#c2410c"


def run_program(program: Program, dt: Any) -> tuple[ProgramReport, ProgramMotion]:
    """``program.check(dt)`` and ``program.simulate(dt)`` (one sampling, shared).

    The simulation's warning about violations is not raised: the tab shows every
    violation beside its move instead.

    Raises
    ------
    InvalidInputError
        ``dt`` outside the limits of a run, a program that takes no time.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import PTP
    >>> report, motion = run_program(Program(rc.preset("paper"), [PTP(q=[0, 0, 0.5])]), 0.1)
    >>> report.ok, motion.t.size
    (True, 11)
    """
    report = program.check(dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        motion = program.simulate(dt)
    return report, motion


def violations_by_move(report: ProgramReport, moves: int) -> list[list[str]]:
    """The core's message of every violation, listed under the move that causes it.

    >>> import robotconf as rc
    >>> from robotconf.programs import LIN, PTP
    >>> program = Program(rc.preset("paper"), [PTP(position=[10, -10, 50]),
    ...                                        LIN(position=[-10, 10, 50], speed=10)])
    >>> [len(messages) for messages in violations_by_move(program.check(0.01), 2)]
    [0, 1]
    """
    found: list[list[str]] = [[] for _ in range(moves)]
    for violation in report:
        if 0 <= violation.move < moves:
            found[violation.move].append(violation.message)
    return found


def run_summary(motion: ProgramMotion, report: ProgramReport, app: bool = False) -> str:
    """The status line after a Run (HTML): duration, samples, and the violations' count.

    >>> import robotconf as rc
    >>> from robotconf.programs import Wait
    >>> report, motion = run_program(Program(rc.preset("paper"), [Wait(1.0)]), 0.5)
    >>> run_summary(motion, report, app=True)
    '<span style="color:#1b7a1b">✓ 1 s, 3 samples (dt = 0.5 s): no violations</span>'
    """
    dt = float(motion.t[1] - motion.t[0]) if motion.t.size > 1 else float("nan")
    head = f"{motion.program.duration:.6g} s, {motion.t.size} samples (dt = {dt:.6g} s)"
    if report.ok:
        text = f'<span style="{_OK}">✓ {head}: no violations</span>'
    else:
        moves = sorted({v.move + 1 for v in report})
        where = ", ".join(f"P{m}" for m in moves)
        text = (
            f'<span style="{_WARN}">⚠ {head}: {len(report)} violation(s), at {where} '
            "(each under its move)</span>"
        )
    if not app:
        text += (
            " <small>Numbers: <code>panel.program.check(dt)</code>, "
            "<code>panel.motion</code></small>"
        )
    return text


def show_program_motion(section: MotionSection, scene: Any, motion: ProgramMotion) -> None:
    """Show a program's motion as the panel's last simulation: the Motion tab's tables,
    statistics and plot, and an animation with the end effector's trace in the 3D view."""
    section.motion = motion
    section.results.show(motion)
    section.status.value = (
        f"<small>showing the Program tab's run: {motion.t.size} samples, "
        f"{html.escape(motion.method)}</small>"
    )
    animate = getattr(scene, "animate", None)
    if animate is None:
        return
    animate(motion)
    if hasattr(scene, "show_trace") and not getattr(scene, "trace_shown", True):
        scene.show_trace(True)  # the scene's own trace toggle follows
