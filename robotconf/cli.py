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
import os
import sys
import unicodedata
import warnings
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

from ._budget import check_memory
from .grading import add_course_parser, run_course
from .motion import METHODS, QUANTITIES, SimulationSettings
from .signals import SPEC_HELP, parse_signal_spec

if TYPE_CHECKING:  # pragma: no cover
    import pandas as pd
    from matplotlib.figure import Figure

    from .kinematics import Robot
    from .motion import Motion
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
DPI = 100

#: Modules that get a dva_M<i>.png of their own. Each 3 × 3 figure takes about 0.6 s to
#: lay out and save, so a 64-module chain would spend 40 s on them; the rest are one
#: ``motion.plot(i)`` away (report.md says so).
MAX_MODULE_PLOTS = 16

#: Peak memory of simulate + table + statistics + CSV, in copies of the results (15
#: floats per sample and point). Measured: 3.2 (results, kernel work arrays, the
#: statistics' sorted copy); pandas writes the CSV in chunks.
RESULT_COPIES = 4

#: Longest error message printed (characters); the rest is cut, it stays one line.
MAX_MESSAGE_CHARS = 1000

DESCRIPTION = """\
Write a report for one robot: step-by-step matrices (matrices.txt, matrices.tex), the
DVA table (dva.csv), statistics (statistics.csv), plots (robot.png = the paper's
Figure 14, q.png = Figure 16, dva_EE.png = Figures 17-19, dva_M<i>.png for the first
16 modules) and the animated 3D scene (scene.html, self-contained). `robotconf report
--preset paper --out out/` reproduces the paper's Figures 13-19."""

SYMBOLIC_TOO_LONG = (
    "No symbolic matrices: this chain is too long for them by default, as sympy's "
    "time grows exponentially with the rotations in the chain, from seconds to many "
    "minutes (robotconf.teaching.symbolic_fits). To get them anyway, run "
    "rc.derivation(robot, symbolic=True) in a notebook and accept the wait."
)
SYMBOLIC_OFF = "No symbolic matrices: --no-symbolic was given."


class BadInput(Exception):
    """Raised for input the user can fix; ``main`` prints it on one line, the panel shows it
    beside its report button."""


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
    add_course_parser(commands)
    return parser


# -- text from untrusted files ----------------------------------------------------------

# Bidirectional-text controls reorder what a reader sees; shown as their code instead.
_BIDI_CONTROLS = frozenset(
    "\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069"
)
_MARKDOWN_ENTITIES = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}
# What means something inline in CommonMark or GitHub Markdown (code, emphasis, links and
# images, tables, strikethrough, $ math, attribute and superscript extensions) gets a
# backslash, which CommonMark allows before any ASCII punctuation. User text never starts
# a line, so list and heading markers need nothing; "(" only matters after "]".
_MARKDOWN_PUNCTUATION = frozenset("\\`*_{}[]#|$~^")


def _visible(text: str) -> str:
    """``text`` on one line: control characters become spaces, bidi controls ``\\u202e``."""
    out = []
    for char in text:
        if char in _BIDI_CONTROLS:
            out.append(f"\\u{ord(char):04x}")
        elif unicodedata.category(char) in ("Cc", "Zl", "Zp"):
            out.append(" ")
        else:
            out.append(char)
    return "".join(out)


def markdown_text(text: object) -> str:
    r"""User text as Markdown that shows exactly that text, on one line, with no markup.

    Parameters
    ----------
    text : object
        A name, label, unit or file name (``str()`` of anything else).

    Returns
    -------
    str
        ``<``, ``>`` and ``&`` as HTML entities, Markdown punctuation backslash-escaped,
        line breaks and other control characters as spaces.

    Examples
    --------
    >>> print(markdown_text("<img src=x onerror=alert(1)> *$x$* | [a](b)\n# h"))
    &lt;img src=x onerror=alert(1)&gt; \*\$x\$\* \| \[a\](b) \# h
    """
    escaped = []
    for char in _visible(str(text)):
        if char in _MARKDOWN_ENTITIES:
            escaped.append(_MARKDOWN_ENTITIES[char])
        elif char in _MARKDOWN_PUNCTUATION:
            escaped.append("\\" + char)
        else:
            escaped.append(char)
    return "".join(escaped)


def _one_line(text: object) -> str:
    """A message for the terminal: one line, no control characters, bounded length.

    >>> _one_line("a\\n  b\\x1b[31m")
    'a b [31m'
    """
    line = " ".join(_visible(str(text)).split())
    if len(line) > MAX_MESSAGE_CHARS:
        line = line[: MAX_MESSAGE_CHARS - 1] + "…"
    return line


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


def _check_report_memory(robot: Robot, settings: SimulationSettings) -> None:
    """Refuse, before anything is allocated, a run whose results would not fit in memory."""
    samples = settings.samples
    values = float(samples) * (robot.n + 1) * len(QUANTITIES) * 3
    coordinates = 3.0 * robot.n * samples  # q, q̇, q̈
    check_memory(
        "dt",
        settings.dt,
        8.0 * (RESULT_COPIES * values + coordinates),
        "a larger dt or a shorter run (t_end − t0), or a larger ROBOTCONF_MEMORY_BUDGET",
    )


def _check_finite(motion: Motion, stats: pd.DataFrame) -> None:
    """Refuse results that overflowed to inf or NaN, naming the first such column.

    The inputs were finite (the core checks them), but large lengths or fast signals can
    still overflow along the chain or in a statistic (RMS squares its values).
    """
    import numpy as np

    data = motion.columns()
    if not np.isfinite(data).all():
        column, sample = np.argwhere(~np.isfinite(data))[0]
        point, rest = divmod(int(column), 3 * len(QUANTITIES))
        quantity, axis = divmod(rest, 3)
        raise BadInput(
            f"dva.csv: the {QUANTITIES[quantity]} ({'xyz'[axis]}) of {motion.points[point]} "
            f"overflows to inf or NaN at t = {motion.t[sample]:g} s; allowed: smaller "
            "lengths and signal values (well below 1e308)"
        )
    table = stats.to_numpy()
    if not np.isfinite(table).all():
        row, column = np.argwhere(~np.isfinite(table))[0]
        point, quantity, axis = stats.index[row]
        raise BadInput(
            f"statistics.csv: the {stats.columns[column]} of the {quantity} ({axis}) of "
            f"{point} overflows to inf or NaN; allowed: smaller lengths and signal values "
            "(well below 1e154, as squares enter the RMS)"
        )


def _symbolic_state(robot: Robot, wanted: bool) -> str:
    """``"built"``, ``"off"`` (--no-symbolic) or ``"too long"`` (over the symbolic limit)."""
    from .teaching import symbolic_fits

    if not wanted:
        return "off"
    return "built" if symbolic_fits(robot) else "too long"


def _write_matrices(robot: Robot, out: Path, symbolic: str) -> list[str]:
    from .teaching import derivation, latex_text

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
    if symbolic == "built":
        steps = derivation(robot, symbolic=True, lengths=True)
        text += ["", "Symbolic (q1 … qn and lengths l1, l2, … as symbols)", "=" * 70, str(steps)]
        tex += ["\\section*{Symbolic}", "\\[" + steps.latex() + "\\]"]
    else:
        note = SYMBOLIC_OFF if symbolic == "off" else SYMBOLIC_TOO_LONG
        text += ["", note]
        tex += ["\\section*{Symbolic}", latex_text(note)]
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

    from .plots import plot_coordinates, plot_motion, plot_robot

    written = []
    # One decimal as in the paper's Figure 14, three for arms measured in metres.
    size = float(np.ptp(motion.robot.frame_origins(), axis=0).max())
    digits = 1 if size >= 10 else 3
    _save(plot_robot(motion.robot, length_unit=unit, digits=digits), out / "robot.png")
    _save(plot_coordinates(motion, unit), out / "q.png")
    written += ["robot.png", "q.png"]
    _save(plot_motion(motion, "EE", displacement=True, length_unit=unit), out / "dva_EE.png")
    written.append("dva_EE.png")
    # By index, never by name: the file name is always safe and always distinct.
    for i in range(min(motion.robot.n, MAX_MODULE_PLOTS)):
        name = _module_plot(i)
        _save(plot_motion(motion, i, displacement=True, length_unit=unit), out / name)
        written.append(name)
    return written


def _module_plot(index: int) -> str:
    return f"dva_M{index + 1}.png"


def _write_scene(motion: Motion, out: Path) -> list[str]:
    from .scene import RecordingChannel, Scene

    # The HTML export needs no front end: a recording channel stands in for the widget.
    scene = Scene(motion.robot, channel=RecordingChannel())
    scene.animate(motion)
    scene.export_html(out / "scene.html")
    return ["scene.html"]


_ABOUT = {
    "matrices.txt": "A_i, M_i, p_EE step by step (Figure 13), numeric and symbolic",
    "matrices.tex": "the same as LaTeX",
    "dva.csv": "position, displacement, velocity, acceleration of every point",
    "statistics.csv": "Simulink Scope signal statistics of every column",
    "robot.png": "the robot with labelled points (Figure 14)",
    "q.png": "driven coordinates over time (Figure 16)",
    "dva_EE.png": "EE displacement, velocity, acceleration (Figures 17-19)",
    "scene.html": "animated 3D scene, opens offline in a browser",
}


def _write_summary(motion: Motion, source: str, out: Path, files: list[str], symbolic: str) -> None:
    """report.md: every user-provided string goes through :func:`markdown_text`."""
    from .kinematics import format_point, robot_points

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
            _module_plot(i): f"DVA of module {i + 1} ({markdown_text(names[i])})"
            for i in range(robot.n)
        }
    )
    lines += ["| file | content |", "|---|---|"]
    lines += [f"| {markdown_text(f)} | {about.get(f, '')} |" for f in files]
    (out / "report.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


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
    from .motion import simulate

    say = say or (lambda _: None)
    out = Path(out)
    _check_report_memory(robot, settings)
    state = _symbolic_state(robot, symbolic)
    total = 7 - (not scene)
    title = _one_line(robot.name or "Robot")
    say(f"[1/{total}] robot from {_one_line(source)}: {title}, {robot.n} modules")
    motion = simulate(robot, dict(signals), **settings.to_dict())
    stats = motion.stats()
    _check_finite(motion, stats)
    say(
        f"[2/{total}] simulated {motion.t.size} samples ({motion.method}), signals: "
        + (", ".join(f"{k}={v!r}" for k, v in motion.signals.items()) or "none")
    )
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise BadInput(f"--out: cannot create {str(out)!r}: {error.strerror or error}") from None
    files = _write_matrices(robot, out, state)
    skipped = {"off": " (symbolic: --no-symbolic)", "too long": " (symbolic: chain too long)"}
    say(f"[3/{total}] {', '.join(files)}{skipped.get(state, '')}")
    motion.to_csv(out / "dva.csv")
    stats.to_csv(out / "statistics.csv")
    files += ["dva.csv", "statistics.csv"]
    say(f"[4/{total}] dva.csv, statistics.csv")
    plots = _write_plots(motion, out, length_unit)
    files += plots
    say(f"[5/{total}] {', '.join(plots)}")
    if scene:
        files += _write_scene(motion, out)
        say(f"[6/{total}] scene.html")
    _write_summary(motion, source, out, files, state)
    say(f"[{total}/{total}] report.md — done: {_one_line(out)}")
    return [*files, "report.md"]


def _report(args: argparse.Namespace) -> int:
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise BadInput(f"--out: {str(out)!r} exists and is not a folder")
    robot, from_file, file_settings, source = _load(args)
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
    )
    return 0


# -- entry point ------------------------------------------------------------------------

#: Errors whose message tells the user what to change (InvalidInputError is a ValueError).
_USER_ERRORS = (BadInput, ValueError, ArithmeticError, OSError)


def _fail(message: str) -> int:
    print(f"robotconf: {_one_line(message)}", file=sys.stderr)
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
