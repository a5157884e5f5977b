"""``robotconf report``: every result of the paper's §3 for one robot, written to a folder.

Runs headless (matplotlib's Agg canvas, no pyplot) and reports one progress line per
step. Bad input — a missing or corrupt file, an unknown preset, a bad signal spec, a
non-positive time step — ends with exit code 2 and one line ``robotconf: error: …``;
anything else that fails is a bug and keeps its traceback.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

from .motion import METHODS, SimulationSettings
from .signals import SPEC_HELP, parse_signal_spec

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from .kinematics import Robot
    from .motion import Motion
    from .signals import Signal

__all__ = ["main", "EXIT_BAD_INPUT", "PRESET_DEMOS"]

#: Exit status for bad input (argparse's convention).
EXIT_BAD_INPUT = 2

#: Signals used for a preset when none is given: the paper drives q3 of its R_zR_yR_y
#: robot with Simulink's default Repeating Sequence (§3, Figure 16).
PRESET_DEMOS = {"paper": {"q3": "repeating"}}

#: Simulink's default stop time (s); the paper's Figures 16–19 span 0 … 10 s.
DEFAULT_T_END = 10.0
#: The core's default time step (s).
DEFAULT_DT = SimulationSettings.dt
DPI = 100

DESCRIPTION = """\
Write a report for one robot: step-by-step matrices (matrices.txt, matrices.tex), the
DVA table (dva.csv), statistics (statistics.csv), plots (robot.png = the paper's
Figure 14, q.png = Figure 16, dva_EE.png = Figures 17-19, dva_M<i>.png per module) and
the animated 3D scene (scene.html, self-contained). `robotconf report --preset paper
--out out/` reproduces the paper's Figures 13-19."""


class BadInput(Exception):
    """Raised for input the user can fix; ``main`` prints it on one line."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        raise BadInput(message)


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="robotconf", description="robotconf command-line tools.")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    report = commands.add_parser(
        "report",
        help="write matrices, DVA table, statistics, plots and 3D scene for a robot",
        description=DESCRIPTION,
        epilog=SPEC_HELP,
    )
    source = report.add_mutually_exclusive_group(required=True)
    source.add_argument("robot", nargs="?", metavar="ROBOT.json", help="robot or setup file")
    source.add_argument("--preset", metavar="NAME", help="a built-in robot, e.g. paper, puma560")
    report.add_argument(
        "--signal",
        action="append",
        default=[],
        metavar="SPEC",
        help="drive a coordinate, e.g. q3=repeating:times=0,2;values=0,2 (repeatable; "
        "overrides the file's signal for that coordinate; grammar below)",
    )
    report.add_argument("--t-end", type=float, help=f"end time in s (default {DEFAULT_T_END:g})")
    report.add_argument("--dt", type=float, help=f"time step in s (default {DEFAULT_DT:g})")
    report.add_argument(
        "--method",
        choices=METHODS,
        help="derivatives: analytic (exact, default) or numeric (finite differences)",
    )
    report.add_argument("--out", required=True, metavar="DIR", help="output folder (created)")
    report.add_argument("--length-unit", default="length", help="axis label unit, e.g. mm or m")
    report.add_argument(
        "--no-symbolic", action="store_true", help="skip the symbolic matrices (long chains)"
    )
    report.add_argument("--no-scene", action="store_true", help="skip scene.html")
    report.add_argument("--quiet", action="store_true", help="no progress lines")
    return parser


# -- steps ------------------------------------------------------------------------------


def _load(
    args: argparse.Namespace,
) -> tuple[Robot, dict[str, Signal], SimulationSettings | None, str]:
    """Robot, its signals and simulation settings from ``--preset`` or a JSON file."""
    from .io import load_setup
    from .presets import preset

    if args.preset is not None:
        robot = preset(args.preset)
        demo = PRESET_DEMOS.get(args.preset.strip().lower(), {})
        signals = {name: parse_signal_spec(f"{name}={spec}")[1] for name, spec in demo.items()}
        return robot, signals, None, f"preset {args.preset!r}"
    path = Path(args.robot)
    if not path.is_file():
        raise BadInput(f"ROBOT.json: no such file: {str(path)!r}")
    setup = load_setup(path)
    return setup.robot, dict(setup.signals or {}), setup.settings, str(path)


def _settings(
    args: argparse.Namespace, file_settings: SimulationSettings | None
) -> SimulationSettings:
    """t_end, dt, t0 and method: command line, else the file, else the defaults.

    The combination is checked as a whole, with the core's limits and messages.
    """
    base = file_settings or SimulationSettings(DEFAULT_T_END, DEFAULT_DT)
    given = {"t_end": args.t_end, "dt": args.dt, "method": args.method}
    return base.with_changes(**{key: value for key, value in given.items() if value is not None})


def _write_matrices(robot: Robot, out: Path, symbolic: bool) -> list[str]:
    from .teaching import derivation

    numeric = derivation(robot)
    text = [
        "Forward kinematics at the configured position (the paper's Figure 13)",
        "=" * 70,
        str(numeric),
    ]
    tex = [
        "\\section*{Forward kinematics at the configured position}",
        "\\[" + numeric.latex() + "\\]",
    ]
    if symbolic:
        steps = derivation(robot, symbolic=True, lengths=True)
        text += ["", "Symbolic (q1 … qn and lengths l1, l2, … as symbols)", "=" * 70, str(steps)]
        tex += ["\\section*{Symbolic}", "\\[" + steps.latex() + "\\]"]
    (out / "matrices.txt").write_text("\n".join(text) + "\n", encoding="utf-8")
    document = [
        "\\documentclass{article}",
        "\\usepackage{amsmath}",
        "\\usepackage[margin=1.5cm,landscape]{geometry}",
        "\\begin{document}",
        "\\allowdisplaybreaks",
        *tex,
        "\\end{document}",
    ]
    (out / "matrices.tex").write_text("\n".join(document) + "\n", encoding="utf-8")
    return ["matrices.txt", "matrices.tex"]


def _save(fig: Figure, path: Path) -> None:
    fig.savefig(path, dpi=DPI)


def _write_plots(motion: Motion, out: Path, unit: str) -> list[str]:
    import numpy as np

    from .plots import plot_coordinates, plot_robot

    written = []
    # One decimal as in the paper's Figure 14, three for arms measured in metres.
    size = float(np.ptp(motion.robot.frame_origins(), axis=0).max())
    digits = 1 if size >= 10 else 3
    _save(plot_robot(motion.robot, length_unit=unit, digits=digits), out / "robot.png")
    _save(plot_coordinates(motion, unit), out / "q.png")
    written += ["robot.png", "q.png"]
    for point in ("EE", *motion.robot.module_names):
        name = f"dva_{_file_part(point)}.png"
        _save(motion.plot(point, displacement=True, length_unit=unit), out / name)
        written.append(name)
    return written


def _file_part(name: str) -> str:
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in name) or "point"


def _write_scene(motion: Motion, out: Path) -> list[str]:
    from .scene import RecordingChannel, Scene

    # The HTML export needs no front end: a recording channel stands in for the widget.
    scene = Scene(motion.robot, channel=RecordingChannel())
    scene.animate(motion)
    scene.export_html(out / "scene.html")
    return ["scene.html"]


def _write_summary(motion: Motion, source: str, out: Path, files: list[str]) -> None:
    from .kinematics import robot_points

    robot = motion.robot
    lines = [
        f"# robotconf report: {robot.name or 'Robot'} ({source})",
        "",
        f"{robot.n} modules; t = {motion.t[0]:g} … {motion.t[-1]:g} s, dt = {motion.dt:g} s, "
        f"{motion.method} derivatives; signals: "
        + (", ".join(f"{k} = {v!r}" for k, v in motion.signals.items()) or "none"),
        "",
        "Points at the configured position (Figure 14):",
        "",
        *[f"- {point}" for point in robot_points(robot)],
        "",
        "| file | content |",
        "|---|---|",
    ]
    about = {
        "matrices.txt": "A_i, M_i, p_EE step by step (Figure 13), numeric and symbolic",
        "matrices.tex": "the same as LaTeX",
        "dva.csv": "position, displacement, velocity, acceleration of every point",
        "statistics.csv": "Simulink Scope signal statistics of every column",
        "robot.png": "the robot with labelled points (Figure 14)",
        "q.png": "driven coordinates over time (Figure 16)",
        "dva_EE.png": "EE displacement, velocity, acceleration (Figures 17-19)",
        "scene.html": "animated 3D scene, opens offline in a browser",
    }
    lines += [f"| {f} | {about.get(f, 'DVA of module ' + f[4:-4])} |" for f in files]
    (out / "report.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


def _report(args: argparse.Namespace) -> int:
    from .motion import simulate

    say: Callable[[str], None] = (lambda _: None) if args.quiet else print
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise BadInput(f"--out: {str(out)!r} exists and is not a folder")
    robot, from_file, file_settings, source = _load(args)
    signals: dict[str | int, Signal | float] = {k: v for k, v in from_file.items()}
    for spec in args.signal:
        name, signal = parse_signal_spec(spec)
        signals[name] = signal
    settings = _settings(args, file_settings)
    total = 7 - args.no_scene
    say(f"[1/{total}] robot from {source}: {robot.name or 'Robot'}, {robot.n} modules")
    motion = simulate(robot, signals, **settings.to_dict())
    say(
        f"[2/{total}] simulated {motion.t.size} samples ({motion.method}), signals: "
        + (", ".join(f"{k}={v!r}" for k, v in motion.signals.items()) or "none")
    )
    out.mkdir(parents=True, exist_ok=True)
    files = _write_matrices(robot, out, symbolic=not args.no_symbolic)
    say(f"[3/{total}] {', '.join(files)}")
    motion.to_csv(out / "dva.csv")
    motion.stats().to_csv(out / "statistics.csv")
    files += ["dva.csv", "statistics.csv"]
    say(f"[4/{total}] dva.csv, statistics.csv")
    plots = _write_plots(motion, out, args.length_unit)
    files += plots
    say(f"[5/{total}] {', '.join(plots)}")
    if not args.no_scene:
        scene = _write_scene(motion, out)
        files += scene
        say(f"[6/{total}] scene.html")
    _write_summary(motion, source, out, files)
    say(f"[{total}/{total}] report.md — done: {out}")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``robotconf`` command (also ``python -m robotconf``).

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments without the program name; default ``sys.argv[1:]``.

    Returns
    -------
    int
        0 on success, 2 on bad input (after printing ``robotconf: error: …``).

    Examples
    --------
    >>> main(["report", "--preset", "paper"])
    2
    """
    try:
        args = _parser().parse_args(argv)
        return _report(args)
    except SystemExit as done:  # --help
        return done.code if isinstance(done.code, int) else 0
    except (BadInput, ValueError, OSError) as error:
        message = " ".join(str(error).split())
        print(f"robotconf: error: {message}", file=sys.stderr)
        return EXIT_BAD_INPUT
