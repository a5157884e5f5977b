"""matplotlib figure of one point's motion: position (or displacement), velocity,
acceleration × x, y, z, as in the paper's Figures 17–19.

Only draws arrays the core computed; matplotlib is imported inside the function.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..kinematics import AXIS_NAMES
from ._plain_text import PLAIN

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..motion import Motion

__all__ = ["plot_motion", "kink_note"]

#: Most kink instants marked with a vertical line (more would only grey the plot).
MAX_KINK_LINES = 200


def kink_note(motion: Motion) -> str | None:
    """The explanation printed under the plot when a driven coordinate has kinks.

    Returns ``None`` when every signal is smooth over the run.
    """
    kinks = motion.kinks()
    if not kinks:
        return None
    where = "; ".join(
        f"{name} at t = "
        + ", ".join(f"{t:g}" for t in times[:5])
        + (", …" if times.size > 5 else "")
        + " s"
        for name, times in kinks.items()
    )
    if motion.method == "numeric":
        return (
            f"Kinks or jumps of the input ({where}): at a kink the velocity jumps by Δv, so "
            "the exact acceleration is an impulse and finite differences show a real spike "
            "≈ Δv/dt; where the value itself jumps (a sawtooth's drop) the velocity spikes "
            "too. Spikes grow as dt shrinks; method='analytic' gives the one-sided values."
        )
    return (
        f"Kinks or jumps of the input ({where}): there the exact acceleration is an impulse; "
        "the analytic curves show one-sided (right-hand) values and leave the impulses out. "
        "method='numeric' shows them as spikes."
    )


def plot_motion(
    motion: Motion,
    point: str | int = "EE",
    *,
    displacement: bool = False,
    length_unit: str = "length",
    figsize: tuple[float, float] = (11.0, 7.5),
) -> Figure:
    """Plot position (or displacement), velocity and acceleration of one point.

    Parameters
    ----------
    motion : Motion
    point : str or int
        ``"EE"`` or a module frame's origin, as :meth:`Robot.index` reads it (``"M2"``,
        the module's own name, ``"q2"`` or the index ``1``).
    displacement : bool
        First row shows displacement (position minus position at ``t0``) instead of
        position.
    length_unit : str
        Unit label for lengths, e.g. ``"mm"``; velocities get ``/s``, accelerations ``/s²``.
    figsize : (float, float)
        Figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
        3 rows × 3 columns (x, y, z) sharing the time axis. In Jupyter the returned figure
        displays itself; in a script call ``fig.savefig(path)``. It is not registered with
        pyplot, so it never shows twice and never piles up open figures.

    Raises
    ------
    InvalidInputError
        For an unknown point.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import Sine
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    >>> fig = plot_motion(simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.01), "EE")
    >>> len(fig.axes), fig.axes[-1].get_xlabel()
    (9, 'time (s)')
    """
    from ._figures import new_figure

    index = motion.robot.index(point, "point", end_effector=True)
    point = motion.points[index]
    first = "displacement" if displacement else "position"
    rows = (
        (first, getattr(motion, first), length_unit),
        ("velocity", motion.velocity, f"{length_unit}/s"),
        ("acceleration", motion.acceleration, f"{length_unit}/s²"),
    )
    note = kink_note(motion)
    fig = new_figure(figsize)
    axes = fig.subplots(3, 3, sharex=True, squeeze=False)
    t = motion.t
    kinks = np.unique(np.concatenate([np.empty(0), *motion.kinks().values()]))
    for r, (name, values, unit) in enumerate(rows):
        for c, axis in enumerate(AXIS_NAMES):
            ax = axes[r, c]
            ax.plot(t, values[:, index, c], lw=1.2)
            ax.grid(True, alpha=0.3)
            if r == 0:
                ax.set_title(f"{point}: {axis}", **PLAIN)
            if c == 0:
                ax.set_ylabel(f"{name} [{unit}]", **PLAIN)
            if r == 2:
                ax.set_xlabel("time (s)")
                if kinks.size <= MAX_KINK_LINES:
                    for k in kinks:
                        ax.axvline(k, color="tab:red", lw=0.6, alpha=0.4, ls="--")
    title = f"{motion.robot.name or 'Robot'}: {point} ({motion.method} derivatives)"
    fig.suptitle(title, **PLAIN)
    if note is not None:
        fig.text(0.01, 0.0, note, fontsize=8, wrap=True, va="bottom", ha="left", **PLAIN)
        fig.get_layout_engine().set(rect=(0.0, 0.07, 1.0, 0.93))  # type: ignore[union-attr,call-arg]
    return fig
