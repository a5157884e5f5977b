"""What each export of the panel contains: bytes or text made by the core's own functions.

Nothing here is drawn or computed by the panel itself: the report is
:func:`robotconf.report.write_report` (what ``robotconf report`` writes), the figures are
:func:`~robotconf.plot_robot` and :meth:`Motion.plot <robotconf.Motion.plot>`, the scene
page is :meth:`Scene.export_html <robotconf.scene.Scene.export_html>`, the URDF is
:func:`~robotconf.to_urdf` and the LaTeX is a step of :func:`~robotconf.derivation`.
"""

from __future__ import annotations

import io
import re
import tempfile
import zipfile
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from ..._errors import InvalidInputError
from ...kinematics import Robot
from ...motion import Motion, SimulationSettings
from ...signals import Signal
from .._ranges import length_scale

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ...teaching import Derivation

__all__ = [
    "FIGURE_FORMATS",
    "file_stem",
    "report_zip",
    "figure_file",
    "robot_figure",
    "scene_page",
    "step_latex",
]

#: Figure formats offered, with their MIME type.
FIGURE_FORMATS = {"png": "image/png", "svg": "image/svg+xml"}
#: Resolution of PNG figures, as in the report.
DPI = 100
_UNSAFE = re.compile(r"[^A-Za-z0-9_.-]+")


def file_stem(name: str | None, default: str = "robot") -> str:
    """A file-name stem from a robot's name: letters, digits, ``_ . -`` only.

    The name comes from a file, so it never chooses a folder or an extension.

    >>> file_stem("RzRyRy (paper)"), file_stem("../../etc/passwd"), file_stem(None)
    ('RzRyRy_paper', 'etc_passwd', 'robot')
    """
    stem = _UNSAFE.sub("_", name or "").strip("._-")[:40]
    return stem or default


def report_zip(
    robot: Robot,
    signals: Mapping[str, Signal],
    settings: SimulationSettings,
    *,
    source: str = "configurator panel",
    stem: str | None = None,
    length_unit: str = "length",
    progress: Callable[[int, int, str], None] | None = None,
) -> bytes:
    """The folder ``robotconf report`` writes for this setup, as a zip archive.

    The files sit in a folder ``<stem>_report/`` inside the archive (``stem``: default the
    robot's name made safe). ``progress(done, total, what)`` hears of every step.

    Raises
    ------
    InvalidInputError
        Bad settings, or a run larger than the memory budget (checked before anything
        is computed).
    robotconf.report.BadInput
        Results that overflow to inf or NaN.
    """
    from ...report import write_report

    folder = f"{stem or file_stem(robot.name)}_report"
    buffer = io.BytesIO()
    with tempfile.TemporaryDirectory(prefix="robotconf-report-") as scratch:
        out = Path(scratch) / folder
        chosen: dict[str | int, Signal | float] = {k: v for k, v in signals.items()}
        files = write_report(
            robot,
            chosen,
            settings,
            out,
            source=source,
            length_unit=length_unit,
            say=None if progress is None else _steps(progress),
        )
        with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
            for name in files:
                archive.write(out / name, f"{folder}/{name}")
    return buffer.getvalue()


def _steps(progress: Callable[[int, int, str], None]) -> Callable[[str], None]:
    """The report's progress lines (``[3/7] matrices.txt, …``) as ``(done, total, what)``."""

    def say(line: str) -> None:
        match = re.match(r"\[(\d+)/(\d+)\]\s*(.*)", line)
        if match is not None:
            what = match.group(3).split(" — ")[0][:60]
            progress(int(match.group(1)), int(match.group(2)), what)

    return say


def figure_file(figure: Figure, fmt: str) -> bytes:
    """The figure as PNG or SVG bytes (drawn off-screen).

    >>> from robotconf.plots import new_figure
    >>> figure_file(new_figure((2, 2)), "png")[:4]
    b'\\x89PNG'
    """
    if fmt not in FIGURE_FORMATS:
        raise InvalidInputError("format", fmt, ", ".join(FIGURE_FORMATS))
    buffer = io.BytesIO()
    figure.savefig(buffer, format=fmt, dpi=DPI)
    return buffer.getvalue()


def robot_figure(robot: Robot, length_unit: str = "length") -> Figure:
    """The robot with its labelled points, as the report's ``robot.png`` (Figure 14),
    its axes labelled in ``length_unit``."""
    from ...plots import plot_robot

    # One decimal for the paper's sizes, three for an arm measured in metres.
    digits = 1 if length_scale(robot) >= 10 else 3
    return plot_robot(robot, digits=digits, length_unit=length_unit)


def scene_page(robot: Robot, motion: Motion | None = None, title: str | None = None) -> str:
    """The 3D scene of ``robot`` as one self-contained HTML page (animated with ``motion``).

    ``motion`` is played only when it is a motion of this very robot; ``title`` names the
    page (default: the robot's name).
    """
    from ...scene import RecordingChannel, Scene

    # The HTML export needs no front end: a recording channel stands in for the widget.
    scene = Scene(robot, channel=RecordingChannel())
    if motion is not None and motion.robot == robot:
        scene.animate(motion)
    with tempfile.TemporaryDirectory(prefix="robotconf-scene-") as scratch:
        path = scene.export_html(Path(scratch) / "scene.html", title=title)
        return path.read_text(encoding="utf-8")


def step_latex(steps: Derivation, name: str) -> str:
    r"""One step of a derivation (``"A2"``, ``"M3"``, ``"p_EE"``) as LaTeX to paste.

    An ``aligned`` block, to put inside ``\[ … \]`` or an ``equation*``.

    >>> import robotconf as rc
    >>> text = step_latex(rc.derivation(rc.Robot([rc.Module("Tz", q=2.0)])), "A1")
    >>> print(text.splitlines()[0]); print(text.splitlines()[-1])
    \begin{aligned}
    \end{aligned}
    >>> "A_{1} &=" in text, "\\begin{bmatrix}" in text
    (True, True)
    """
    return "\\begin{aligned}\n" + steps[name].latex() + "\n\\end{aligned}"
