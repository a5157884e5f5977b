"""``robotconf report``: every result of the paper's §3 for one robot, written to a folder.

Runs headless (matplotlib's Agg canvas, no pyplot) and reports one progress line per
step. Robot files come from students and instructors and are treated as untrusted: every
name, label and unit they carry is escaped in ``report.md`` and drawn literally in the
figures and the 3D scene.

Every failure ends with exit status 2 and exactly one line on standard error, never a
traceback: ``robotconf: error: …`` for input the user can fix (a missing or corrupt
file, an unknown preset, a bad signal spec, a non-positive time step, a run that needs
more memory than the budget, results that overflow, an unwritable folder), and
``robotconf: internal error: <type>: …`` for a bug. Ctrl-C ends with status 130.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

from .grading import add_course_parser, run_course
from .motion import METHODS, SimulationSettings
from .report import MAX_MODULE_PLOTS, BadInput, markdown_text, one_line, write_report
from .signals import SPEC_HELP, parse_signal_spec

if TYPE_CHECKING:  # pragma: no cover
    from .kinematics import Robot
    from .programs import Program
    from .signals import Signal

__all__ = [
    "main",
    "write_report",
    "BadInput",
    "markdown_text",
    "EXIT_BAD_INPUT",
    "EXIT_INTERRUPTED",
    "PRESET_DEMOS",
    "MAX_MODULE_PLOTS",
]

#: Exit status for every failure (argparse's convention for bad input).
EXIT_BAD_INPUT = 2
#: Exit status after Ctrl-C (128 + SIGINT, the shell's convention).
EXIT_INTERRUPTED = 130

#: Signals used for a preset when none is given: the paper drives q3 of its R_zR_yR_y
#: robot with Simulink's default Repeating Sequence (§3, Figure 16).
PRESET_DEMOS = {"paper": {"q3": "repeating"}}

#: Simulink's default stop time (s); the paper's Figures 16–19 span 0 … 10 s.
DEFAULT_T_END = 10.0
#: The core's default time step (s).
DEFAULT_DT = SimulationSettings.dt
DESCRIPTION = """\
Write a report for one robot: step-by-step matrices (matrices.txt, matrices.tex), the
DVA table (dva.csv), statistics (statistics.csv), plots (robot.png = the paper's
Figure 14, q.png = Figure 16, dva_EE.png = Figures 17-19, dva_M<i>.png for the first
16 modules) and the animated 3D scene (scene.html, self-contained). `robotconf report
--preset paper --out out/` reproduces the paper's Figures 13-19."""


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
        help=(
            "derivatives: analytic (exact, default), numeric (central differences) or "
            "backward (Simulink's Derivative block)"
        ),
    )
    report.add_argument("--out", required=True, metavar="DIR", help="output folder (created)")
    report.add_argument("--length-unit", default="length", help="axis label unit, e.g. mm or m")
    report.add_argument(
        "--no-symbolic",
        action="store_true",
        help="skip the symbolic matrices (long chains skip them anyway)",
    )
    report.add_argument("--no-scene", action="store_true", help="skip scene.html")
    report.add_argument("--quiet", action="store_true", help="no progress lines")
    report.add_argument(
        "--no-program",
        action="store_true",
        help="run the file's signals, not its robot program (a setup file may hold both)",
    )
    add_course_parser(commands)
    return parser


# -- steps ------------------------------------------------------------------------------


def _load(
    args: argparse.Namespace,
) -> tuple[Robot, dict[str, Signal], SimulationSettings | None, str, Program | None]:
    """Robot, its signals, simulation settings and program from ``--preset`` or a file."""
    from .io import load_setup
    from .presets import preset

    if args.preset is not None:
        robot = preset(args.preset)
        demo = PRESET_DEMOS.get(args.preset.strip().lower(), {})
        signals = {name: parse_signal_spec(f"{name}={spec}")[1] for name, spec in demo.items()}
        return robot, signals, None, f"preset {args.preset!r}", None
    path = Path(args.robot)
    if not path.is_file():
        raise BadInput(f"ROBOT.json: no such file: {str(path)!r}")
    setup = load_setup(path)
    program = None if args.no_program else setup.program
    return setup.robot, dict(setup.signals or {}), setup.settings, str(path), program


def _settings(
    args: argparse.Namespace, file_settings: SimulationSettings | None
) -> SimulationSettings:
    """t_end, dt, t0 and method: command line, else the file, else the defaults.

    The combination is checked as a whole, with the core's limits and messages.
    """
    base = file_settings or SimulationSettings(DEFAULT_T_END, DEFAULT_DT)
    given = {"t_end": args.t_end, "dt": args.dt, "method": args.method}
    return base.with_changes(**{key: value for key, value in given.items() if value is not None})


def _report(args: argparse.Namespace) -> int:
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise BadInput(f"--out: {str(out)!r} exists and is not a folder")
    robot, from_file, file_settings, source, program = _load(args)
    if program is not None and (args.signal or args.t_end is not None or args.method):
        raise BadInput(
            "--signal/--t-end/--method: the file's program drives the coordinates and sets "
            "the duration; allowed: --dt, or --no-program to run the signals instead"
        )
    signals: dict[str | int, Signal | float] = {k: v for k, v in from_file.items()}
    for spec in args.signal:
        name, signal = parse_signal_spec(spec)
        signals[name] = signal
    write_report(
        robot,
        signals,
        _settings(args, file_settings),
        out,
        source=source,
        length_unit=args.length_unit,
        symbolic=not args.no_symbolic,
        scene=not args.no_scene,
        say=None if args.quiet else print,
        program=program,
    )
    return 0


# -- entry point ------------------------------------------------------------------------

#: Errors whose message tells the user what to change (InvalidInputError is a ValueError).
_USER_ERRORS = (BadInput, ValueError, ArithmeticError, OSError)


def _fail(message: str) -> int:
    print(f"robotconf: {one_line(message)}", file=sys.stderr)
    return EXIT_BAD_INPUT


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``robotconf`` command (also ``python -m robotconf``).

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments without the program name; default ``sys.argv[1:]``.

    Returns
    -------
    int
        0 on success; 2 on any failure, after printing one line on standard error
        (``robotconf: error: …``, or ``robotconf: internal error: <type>: …`` for a bug);
        130 after Ctrl-C.

    Examples
    --------
    >>> main(["report", "--preset", "paper"])
    2
    """
    try:
        # stderr carries the one error line and nothing else: numpy's overflow warnings
        # are replaced by explicit checks, and font or layout warnings change no result.
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            args = _parser().parse_args(argv)
            return run_course(args) if args.command == "course" else _report(args)
    except SystemExit as done:  # --help
        return done.code if isinstance(done.code, int) else 0
    except KeyboardInterrupt:
        print("robotconf: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except _USER_ERRORS as error:
        return _fail(f"error: {error}")
    except MemoryError:
        return _fail("error: out of memory; allowed: a larger dt or a shorter run (t_end − t0)")
    except Exception as error:  # noqa: BLE001 - a bug, but still one line and exit 2
        return _fail(f"internal error: {type(error).__name__}: {error}")
