"""``write_report``: every result of the paper's §3 for one robot, into one folder."""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from ..io import program_to_json
from ._bad_input import BadInput
from ._steps import (
    check_finite,
    check_report_memory,
    symbolic_state,
    write_matrices,
    write_plots,
    write_scene,
)
from ._summary import write_summary
from ._text import one_line

if TYPE_CHECKING:  # pragma: no cover
    from ..kinematics import Robot
    from ..motion import Motion, SimulationSettings
    from ..programs import Program
    from ..signals import Signal

__all__ = ["write_report"]


def write_report(
    robot: Robot,
    signals: Mapping[str | int, Signal | float],
    settings: SimulationSettings,
    out: str | os.PathLike[str],
    *,
    source: str = "robotconf",
    length_unit: str = "length",
    symbolic: bool = True,
    scene: bool = True,
    say: Callable[[str], None] | None = None,
    program: Program | None = None,
) -> list[str]:
    """Write every result of the paper's §3 for one robot into the folder ``out``.

    This is ``robotconf report`` without its command line: the command and the panel's
    report download both call it, so they write the same files.

    Parameters
    ----------
    robot : Robot
    signals : mapping
        Coordinate name or index → signal (a number holds it), as for
        :func:`~robotconf.simulate`.
    settings : SimulationSettings
        t_end, dt, t0 and method.
    out : path-like
        The folder (created with its parents).
    source : str
        Where the robot came from, named in ``report.md`` (escaped there).
    length_unit : str
        Axis label unit of the figures.
    symbolic : bool
        Also write the symbolic matrices (long chains skip them anyway).
    scene : bool
        Write ``scene.html``.
    say : callable, optional
        Receives one progress line per step.
    program : Program, optional
        A robot program to run instead of the signals: its motion (sampled every
        ``settings.dt``, exact derivatives) is what the tables, figures and scene show,
        ``report.md`` lists its moves and the violations its check found, and
        ``program.json`` holds it.

    Returns
    -------
    list of str
        The files written, ``report.md`` last.

    Raises
    ------
    InvalidInputError
        Bad signals or settings, or a run larger than the memory budget.
    BadInput
        Results that overflow, or a folder that cannot be created.

    Examples
    --------
    >>> import tempfile, robotconf as rc
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     files = write_report(
    ...         rc.preset("paper"), {}, rc.SimulationSettings(1.0, 0.5), folder, scene=False
    ...     )
    >>> files[0], files[-1]
    ('matrices.txt', 'report.md')
    """
    say = say or (lambda _: None)
    out = Path(out)
    if program is not None:
        settings = settings.with_changes(t0=0.0, t_end=program.duration, method="analytic")
    check_report_memory(robot, settings)
    state = symbolic_state(robot, symbolic)
    total = 7 - (not scene)
    title = one_line(robot.name or "Robot")
    say(f"[1/{total}] robot from {one_line(source)}: {title}, {robot.n} modules")
    motion = _run(robot, signals, settings, program)
    stats = motion.stats()
    check_finite(motion, stats)
    say(f"[2/{total}] {_what_ran(motion, program)}")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise BadInput(f"--out: cannot create {str(out)!r}: {error.strerror or error}") from None
    files = write_matrices(robot, out, state)
    if program is not None:
        (out / "program.json").write_text(program_to_json(program) + "\n", encoding="utf-8")
        files.append("program.json")
    skipped = {"off": " (symbolic: --no-symbolic)", "too long": " (symbolic: chain too long)"}
    say(f"[3/{total}] {', '.join(files)}{skipped.get(state, '')}")
    motion.to_csv(out / "dva.csv")
    stats.to_csv(out / "statistics.csv")
    files += ["dva.csv", "statistics.csv"]
    say(f"[4/{total}] dva.csv, statistics.csv")
    plots = write_plots(motion, out, length_unit)
    files += plots
    say(f"[5/{total}] {', '.join(plots)}")
    if scene:
        files += write_scene(motion, out)
        say(f"[6/{total}] scene.html")
    write_summary(motion, source, out, files, state, program)
    say(f"[{total}/{total}] report.md — done: {one_line(out)}")
    return [*files, "report.md"]


def _run(
    robot: Robot,
    signals: Mapping[str | int, Signal | float],
    settings: SimulationSettings,
    program: Program | None,
) -> Motion:
    """The motion the report shows: the program's, or the signals' over the settings."""
    import warnings

    from ..motion import simulate

    if program is None:
        return simulate(robot, dict(signals), **settings.to_dict())
    with warnings.catch_warnings():
        # Its violations are listed in report.md; the warning would only repeat them.
        warnings.simplefilter("ignore", UserWarning)
        return program.simulate(dt=settings.dt)


def _what_ran(motion: Motion, program: Program | None) -> str:
    if program is None:
        return f"simulated {motion.t.size} samples ({motion.method}), signals: " + (
            ", ".join(f"{k}={v!r}" for k, v in motion.signals.items()) or "none"
        )
    found = len(getattr(motion, "report", ()))
    return (
        f"ran the program: {len(program.moves)} moves, {program.duration:g} s, "
        f"{motion.t.size} samples; {found} violation{'s' * (found != 1)}"
    )
