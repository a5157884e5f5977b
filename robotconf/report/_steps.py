"""The steps of a report: memory check, matrices, figures, the 3D scene, finite results."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from .._budget import check_memory
from ..motion import QUANTITIES, SimulationSettings
from ..teaching import SYMBOLIC_TOO_LONG as _REFUSAL
from ._bad_input import BadInput

if TYPE_CHECKING:  # pragma: no cover
    import pandas as pd
    from matplotlib.figure import Figure

    from ..kinematics import Robot
    from ..motion import Motion

__all__ = [
    "DPI",
    "DVA_SIZE",
    "MAX_MODULE_PLOTS",
    "RESULT_COPIES",
    "SYMBOLIC_OFF",
    "SYMBOLIC_TOO_LONG",
    "check_report_memory",
    "check_finite",
    "symbolic_state",
    "write_matrices",
    "write_plots",
    "module_plot",
    "write_scene",
]

DPI = 100

#: Size of the DVA figures in inches: 1000 × 650 pixels at ``DPI``, as the panel's plot
#: tab draws them.
DVA_SIZE = (10.0, 6.5)

#: Modules that get a dva_M<i>.png of their own. Each redrawn 3 × 3 figure takes about
#: 0.1 s to draw and save, so a 64-module chain would still spend 7 s on them; the rest
#: are one ``motion.plot(i)`` away (report.md says so).
MAX_MODULE_PLOTS = 16

#: Peak memory of simulate + table + statistics + CSV, in copies of the results (15
#: floats per sample and point). Measured: 3.2 (results, kernel work arrays, the
#: statistics' sorted copy); pandas writes the CSV in chunks.
RESULT_COPIES = 4

# The sentence rc.derivation refuses such a chain with: one text for both.
SYMBOLIC_TOO_LONG = "No symbolic matrices: " + _REFUSAL
SYMBOLIC_OFF = "No symbolic matrices: --no-symbolic was given."


def check_report_memory(robot: Robot, settings: SimulationSettings) -> None:
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


def check_finite(motion: Motion, stats: pd.DataFrame) -> None:
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


def symbolic_state(robot: Robot, wanted: bool) -> str:
    """``"built"``, ``"off"`` (--no-symbolic) or ``"too long"`` (over the symbolic limit)."""
    from ..teaching import symbolic_fits

    if not wanted:
        return "off"
    return "built" if symbolic_fits(robot) else "too long"


def write_matrices(robot: Robot, out: Path, symbolic: str) -> list[str]:
    from ..teaching import derivation, latex_text

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


def write_plots(motion: Motion, out: Path, unit: str, say: Callable[[str], None]) -> list[str]:
    """Write robot.png, q.png, dva_EE.png and dva_M<i>.png; after each, ``say`` gets
    ``"dva_M2.png (figure 5 of 6)"``.

    The DVA figures are one figure redrawn point after point (:class:`MotionFigure`),
    several times quicker than a new figure each.
    """
    import numpy as np

    from ..plots import MotionFigure, plot_coordinates, plot_robot, save_figure

    names: list[str] = []
    count = 3 + min(motion.robot.n, MAX_MODULE_PLOTS)

    def save(fig: Figure, name: str) -> None:
        save_figure(fig, out / name, dpi=DPI)
        names.append(name)
        say(f"{name} (figure {len(names)} of {count})")

    # One decimal as in the paper's Figure 14, three for arms measured in metres.
    size = float(np.ptp(motion.robot.frame_origins(), axis=0).max())
    digits = 1 if size >= 10 else 3
    save(plot_robot(motion.robot, length_unit=unit, digits=digits), "robot.png")
    save(plot_coordinates(motion, unit), "q.png")
    dva = MotionFigure(motion, displacement=True, length_unit=unit, figsize=DVA_SIZE, dpi=DPI)
    save(dva.show("EE"), "dva_EE.png")
    # By index, never by name: the file name is always safe and always distinct.
    for i in range(min(motion.robot.n, MAX_MODULE_PLOTS)):
        save(dva.show(i), module_plot(i))
    return names


def module_plot(index: int) -> str:
    return f"dva_M{index + 1}.png"


def write_scene(motion: Motion, out: Path) -> list[str]:
    from ..scene import RecordingChannel, Scene

    # The HTML export needs no front end: a recording channel stands in for the widget.
    scene = Scene(motion.robot, channel=RecordingChannel())
    scene.animate(motion)
    scene.export_html(out / "scene.html")
    return ["scene.html"]
