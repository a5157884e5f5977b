"""report.md: what was run, the points, and what each file holds."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from ._steps import MAX_MODULE_PLOTS, SYMBOLIC_OFF, SYMBOLIC_TOO_LONG, module_plot
from ._text import markdown_text

if TYPE_CHECKING:  # pragma: no cover
    from ..motion import Motion
    from ..programs import Program

__all__ = ["write_summary"]

_ABOUT = {
    "matrices.txt": "A_i, M_i, p_EE step by step (Figure 13), numeric and symbolic",
    "matrices.tex": "the same as LaTeX",
    "dva.csv": "position, displacement, velocity, acceleration of every point",
    "statistics.csv": "Simulink Scope signal statistics of every column",
    "robot.png": "the robot with labelled points (Figure 14)",
    "q.png": "driven coordinates over time (Figure 16)",
    "dva_EE.png": "EE displacement, velocity, acceleration (Figures 17-19)",
    "scene.html": "animated 3D scene, opens offline in a browser",
    "program.json": "the robot program that was run (rc.load_program)",
}


def write_summary(
    motion: Motion,
    source: str,
    out: Path,
    files: list[str],
    symbolic: str,
    program: Program | None = None,
) -> None:
    """report.md: every user-provided string goes through :func:`markdown_text`."""
    from ..kinematics import format_point, robot_points

    robot = motion.robot
    signals = ", ".join(f"{k} = {v!r}" for k, v in motion.signals.items()) or "none"
    lines = [
        f"# robotconf report: {markdown_text(robot.name or 'Robot')} ({markdown_text(source)})",
        "",
        f"{robot.n} modules; t = {motion.t[0]:g} … {motion.t[-1]:g} s, dt = {motion.dt:g} s, "
        f"{motion.method} derivatives; signals: {markdown_text(signals)}",
        "",
        "Points at the configured position (Figure 14):",
        "",
        *[f"- {markdown_text(format_point(name, xyz))}" for name, xyz in robot_points(robot)],
        "",
    ]
    if program is not None:
        lines += _program_lines(motion, program)
    if symbolic != "built":
        note = SYMBOLIC_OFF if symbolic == "off" else SYMBOLIC_TOO_LONG
        lines += [markdown_text(note), ""]
    if robot.n > MAX_MODULE_PLOTS:
        lines += [
            f"DVA figures are written for modules 1 to {MAX_MODULE_PLOTS} of {robot.n}; "
            "draw another with `rc.plot_motion(motion, i)` (i = 0-based module index).",
            "",
        ]
    names = robot.module_names
    about = dict(_ABOUT)
    if symbolic != "built":
        about["matrices.txt"] = "A_i, M_i, p_EE step by step (Figure 13), numeric (see the note)"
    about.update(
        {
            module_plot(i): f"DVA of module {i + 1} ({markdown_text(names[i])})"
            for i in range(robot.n)
        }
    )
    lines += ["| file | content |", "|---|---|"]
    lines += [f"| {markdown_text(f)} | {about.get(f, '')} |" for f in files]
    (out / "report.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


def _program_lines(motion: Motion, program: Program) -> list[str]:
    """The moves and what the program's check found; every text escaped."""
    lines = [f"Program: {len(program.moves)} moves, {program.duration:g} s:", ""]
    lines += [f"{i + 1}. {markdown_text(repr(move))}" for i, move in enumerate(program.moves)]
    found = list(getattr(motion, "report", ()))
    count = f"{len(found)} violation{'s' * (len(found) != 1)}:"
    lines += ["", "Check: " + (count if found else "no violations"), ""]
    lines += [f"- {markdown_text(v.message)}" for v in found]
    return [*lines, ""] if found else lines
