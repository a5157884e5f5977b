"""matplotlib figure of one point's motion (or of several, one colour each): position (or
displacement), velocity, acceleration × x, y, z, as in the paper's Figures 17–19,
optionally with another method's run dashed over it.

Only draws arrays the core computed; matplotlib is imported inside the function.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
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
    if motion.method != "analytic":
        # Backward differences put the whole jump on one sample, central ones spread it
        # over two: the backward spike is twice as tall, as in Simulink's Derivative block.
        spread = (
            "on one sample, as Simulink's Derivative block shows it"
            if motion.method == "backward"
            else "over two samples, half as tall as Simulink's backward differences"
        )
        return (
            f"Kinks or jumps of the input ({where}): at a kink the velocity jumps by Δv, so "
            "the exact acceleration is an impulse and finite differences show a real spike "
            f"≈ Δv/dt ({spread}); where the value itself jumps (a sawtooth's drop) the "
            "velocity spikes too. Spikes grow as dt shrinks; method='analytic' gives the "
            "one-sided values."
        )
    return (
        f"Kinks or jumps of the input ({where}): there the exact acceleration is an impulse; "
        "the analytic curves show one-sided (right-hand) values and leave the impulses out. "
        "method='backward' (Simulink's Derivative block) or 'numeric' shows them as spikes."
    )


def plot_motion(
    motion: Motion,
    point: str | int | Sequence[str | int] = "EE",
    *,
    displacement: bool = False,
    length_unit: str = "length",
    figsize: tuple[float, float] = (11.0, 7.5),
    compare: Motion | None = None,
) -> Figure:
    """Plot position (or displacement), velocity and acceleration of one or more points.

    Parameters
    ----------
    motion : Motion
    point : str, int or sequence
        ``"EE"`` or a module frame's origin, as :meth:`Robot.index` reads it (``"M2"``,
        the module's own name, ``"q2"`` or the index ``1``); a list of them, or
        ``"all"`` for every frame origin and the EE, draws one line per point.
    displacement : bool
        First row shows displacement (position minus position at ``t0``) instead of
        position.
    length_unit : str
        Unit label for lengths, e.g. ``"mm"``; velocities get ``/s``, accelerations ``/s²``.
    figsize : (float, float)
        Figure size in inches.
    compare : Motion, optional
        Another simulation of the same robot on the same time grid (typically the other
        ``method``), drawn dashed over this one: analytic against numeric derivatives.
        The axes fit this motion's curves, so the finite differences' spikes at a kink
        run off them (the title says so).

    Returns
    -------
    matplotlib.figure.Figure
        3 rows × 3 columns (x, y, z) sharing the time axis. In Jupyter the returned figure
        displays itself; in a script call ``fig.savefig(path)``. It is not registered with
        pyplot, so it never shows twice and never piles up open figures.

    Raises
    ------
    InvalidInputError
        For an unknown point, or a ``compare`` run of another robot or time grid.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import Sine
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    >>> fig = plot_motion(simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.01), "EE")
    >>> len(fig.axes), fig.axes[-1].get_xlabel()
    (9, 'time (s)')

    Every point of the arm at once, the numeric derivatives dashed over the analytic ones:

    >>> robot = rc.Robot([rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 1))], end_effector=(1, 0, 0))
    >>> exact = simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.01)
    >>> fig = plot_motion(exact, "all", compare=simulate(robot, {"q1": Sine()}, t_end=1.0,
    ...                                                     dt=0.01, method="numeric"))
    >>> len(fig.axes[0].lines), fig.axes[0].get_title()
    (6, 'x')
    """
    from ._figures import new_figure

    indices = _point_indices(motion, point)
    names = [motion.points[i] for i in indices]
    if compare is not None:
        _check_comparable(motion, compare)
    first = "displacement" if displacement else "position"
    rows = (
        (first, length_unit),
        ("velocity", f"{length_unit}/s"),
        ("acceleration", f"{length_unit}/s²"),
    )
    runs = [(motion, "-")] + ([] if compare is None else [(compare, "--")])
    note = kink_note(motion)
    fig = new_figure(figsize)
    axes = fig.subplots(3, 3, sharex=True, squeeze=False)
    t = motion.t
    kinks = np.unique(np.concatenate([np.empty(0), *motion.kinks().values()]))
    colors = _colors(len(indices))
    single = len(names) == 1
    clipped = False
    for r, (name, unit) in enumerate(rows):
        for c, axis in enumerate(AXIS_NAMES):
            ax = axes[r, c]
            for run, style in runs:
                values = run.quantity(name)
                for index, label, color in zip(indices, names, colors, strict=True):
                    if single:  # one point: the methods tell the lines apart
                        color, label = ("C0" if run is motion else "C1"), run.method
                    elif run is not motion:
                        label = "_nolegend_"  # the colour names the point already
                    ax.plot(t, values[:, index, c], style, lw=1.2, color=color, label=label)
            if compare is not None:
                clipped |= _fit_limits(
                    ax,
                    motion.quantity(name)[:, indices, c],
                    compare.quantity(name)[:, indices, c],
                )
            ax.grid(True, alpha=0.3)
            if r == 0:
                ax.set_title(f"{names[0]}: {axis}" if single else axis, **PLAIN)
            if c == 0:
                ax.set_ylabel(f"{name} [{unit}]", **PLAIN)
            if r == 2:
                ax.set_xlabel("time (s)")
                if kinks.size <= MAX_KINK_LINES:
                    for k in kinks:
                        ax.axvline(k, color="tab:red", lw=0.6, alpha=0.4, ls="--")
    if single:
        shown = names[0]
    else:
        shown = "all points" if len(names) == len(motion.points) else ", ".join(names)
    method = f"{motion.method} derivatives"
    if compare is not None:
        method += f", {compare.method} dashed"
        if clipped:
            method += ", its spikes cut at the axes"
    fig.suptitle(f"{motion.robot.name or 'Robot'}: {shown} ({method})", **PLAIN)
    if not single or compare is not None:
        # One legend for the nine panels, beside them: inside one it would hide curves.
        legend = fig.legend(
            *axes[0, 0].get_legend_handles_labels(),
            loc="outside right upper",
            fontsize=8,
            frameon=False,
        )
        for entry in legend.get_texts():  # point names come from files: never mathtext
            entry.set(**PLAIN)
    if note is not None:
        fig.text(0.01, 0.0, note, fontsize=8, wrap=True, va="bottom", ha="left", **PLAIN)
        fig.get_layout_engine().set(rect=(0.0, 0.07, 1.0, 0.93))  # type: ignore[union-attr,call-arg]
    return fig


def _point_indices(motion: Motion, point: str | int | Sequence[str | int]) -> list[int]:
    """Indices into ``motion.points`` of one point, a list of points or ``"all"``."""
    if isinstance(point, str) and point == "all" and "all" not in motion.points:
        return list(range(len(motion.points)))
    if isinstance(point, (str, int, np.integer)):
        return [motion.robot.index(point, "point", end_effector=True)]
    chosen = [motion.robot.index(p, "point", end_effector=True) for p in point]
    if not chosen:
        raise InvalidInputError("point", point, "at least one point", "empty:")
    return chosen


def _check_comparable(motion: Motion, other: Motion) -> None:
    """``other`` must be a run of the same robot on the same time grid."""
    from ..motion import Motion as MotionClass

    if not isinstance(other, MotionClass):
        raise InvalidInputError("compare", other, "a Motion from simulate()")
    if other.robot != motion.robot or not np.array_equal(other.t, motion.t):
        raise InvalidInputError(
            "compare",
            other,
            "a simulation of the same robot on the same time grid",
            "another robot or time grid:",
        )


def _fit_limits(ax: Any, shown: np.ndarray, other: np.ndarray) -> bool:
    """Fit ``ax``'s y range to ``shown`` (5 % margin) so the curves being compared stay
    readable; ``True`` if ``other`` (the dashed run) leaves that range.

    Finite differences of a jump are spikes thousands of times the curve's size; scaled
    to them, both curves would be flat lines.
    """
    finite = shown[np.isfinite(shown)]
    if finite.size == 0 or finite.max() == finite.min():
        return False  # a constant curve: matplotlib's own range shows it best
    low, high = float(finite.min()), float(finite.max())
    margin = 0.05 * (high - low)
    low, high = low - margin, high + margin
    ax.set_ylim(low, high)
    with np.errstate(invalid="ignore"):
        return bool(np.any(other < low) or np.any(other > high))


def _colors(count: int) -> list[str]:
    """One colour per point: matplotlib's default cycle (tab10), repeated if needed."""
    cycle = [f"C{i}" for i in range(10)]
    return [cycle[i % 10] for i in range(count)]
