"""A 3 × 3 DVA figure of a motion that can be redrawn for another point.

Position (or displacement), velocity, acceleration × x, y, z, as in the paper's Figures
17–19, for one point or several (one colour each), optionally with another method's run
dashed over it. The figure is built once; :meth:`MotionFigure.show` puts another point's
curves, limits and titles into the same axes and lays the figure out again, which is
about four times quicker than a new figure (the report draws its per-point figures so).

Only draws arrays the core computed; matplotlib is imported inside the methods.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from ..kinematics import AXIS_NAMES
from ._kink_note import kink_note
from ._plain_text import PLAIN

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..motion import Motion

__all__ = ["MotionFigure", "MAX_KINK_LINES"]

#: Most kink instants marked with a vertical line (more would only grey the plot).
MAX_KINK_LINES = 200

#: Where the axes start before the first layout: close to where they end, so the
#: layout's measuring pass sees the ticks they end with.
_FIRST_GUESS = {"left": 0.08, "right": 0.98, "bottom": 0.1, "top": 0.9, "wspace": 0.22}


class MotionFigure:
    """One 3 × 3 figure of a motion's points, redrawn point after point.

    Parameters
    ----------
    motion : Motion
    displacement : bool
        First row shows displacement (position minus position at ``t0``) instead of
        position.
    length_unit : str
        Unit label for lengths, e.g. ``"mm"``; velocities get ``/s``, accelerations ``/s²``.
    figsize : (float, float)
        Figure size in inches.
    compare : Motion, optional
        Another simulation of the same robot on the same time grid, drawn dashed.
    dpi : float, optional
        The figure's resolution (default: matplotlib's ``figure.dpi``). Saving at the
        same dpi reuses the renderer the layout measured with, and its text caches.

    Attributes
    ----------
    figure : matplotlib.figure.Figure
        The figure :meth:`show` draws into (always the same one).
    axes : ndarray of Axes, shape (3, 3)
        Rows: position (or displacement), velocity, acceleration; columns: x, y, z.

    Raises
    ------
    InvalidInputError
        For a ``compare`` run of another robot or time grid.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import Sine
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    >>> dva = MotionFigure(simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.01))
    >>> dva.show("EE").axes[0].get_title(), dva.show("M1").axes[0].get_title()
    ('EE: x', 'M1: x')
    """

    def __init__(
        self,
        motion: Motion,
        *,
        displacement: bool = False,
        length_unit: str = "length",
        figsize: tuple[float, float] = (11.0, 7.5),
        compare: Motion | None = None,
        dpi: float | None = None,
    ) -> None:
        from ._drawing import wrap_to_width
        from ._figures import new_figure
        from ._grid_layout import PAD

        if compare is not None:
            _check_comparable(motion, compare)
        self.motion = motion
        self.compare = compare
        first = "displacement" if displacement else "position"
        self._quantities = (first, "velocity", "acceleration")
        units = (length_unit, f"{length_unit}/s", f"{length_unit}/s²")
        self.figure = new_figure(figsize, layout="none", dpi=dpi)
        self.axes = self.figure.subplots(3, 3, sharex=True, squeeze=False, gridspec_kw=_FIRST_GUESS)
        for r, (name, unit) in enumerate(zip(self._quantities, units, strict=True)):
            self.axes[r, 0].set_ylabel(f"{name} [{unit}]", **PLAIN)
        for ax in self.axes.flat:
            ax.grid(True, alpha=0.3)
        for ax in self.axes[2]:
            ax.set_xlabel("time (s)")
        for ax in self.axes[:2].flat:
            ax.xaxis.set_label_coords(0.5, 0.0)  # no label: nothing to place at each draw
        for ax in self.axes[:, 1:].flat:
            ax.yaxis.set_label_coords(0.0, 0.5)
        kinks = np.unique(np.concatenate([np.empty(0), *motion.kinks().values()]))
        self._kinks = kinks if kinks.size <= MAX_KINK_LINES else np.empty(0)
        self._shown: list[int] | None = None
        self._title: Any = None
        self._legend: Any = None
        self._laid_out_for: Any = None
        note = kink_note(motion)
        self._note = None
        if note is not None:
            self._note = self.figure.text(0, 0, note, fontsize=8, va="bottom", ha="left", **PLAIN)
            wrap_to_width(self._note, self.figure.bbox.width - 2 * PAD * self.figure.dpi)

    def show(self, point: str | int | Sequence[str | int] = "EE") -> Figure:
        """Draw ``point`` (as :func:`plot_motion` reads it) and return :attr:`figure`.

        Raises
        ------
        InvalidInputError
            For an unknown point; the figure keeps what it showed.
        """
        from ._grid_layout import place_grid

        indices = _point_indices(self.motion, point)
        if indices == self._shown:
            return self.figure
        names = [self.motion.points[i] for i in indices]
        single = len(names) == 1
        if self._shown is None or len(self._shown) != len(indices):
            self._new_lines(len(indices))
        runs = [self.motion] + ([] if self.compare is None else [self.compare])
        clipped = False
        for r, name in enumerate(self._quantities):
            values = [run.quantity(name)[:, indices] for run in runs]
            for c, ax in enumerate(self.axes[r]):
                lines = iter(ax.lines)
                for run, value in zip(runs, values, strict=True):
                    for k, (label, color) in enumerate(
                        zip(names, _colors(len(names)), strict=True)
                    ):
                        if single:  # one point: the methods tell the lines apart
                            color, label = ("C0" if run is self.motion else "C1"), run.method
                        elif run is not self.motion:
                            label = "_nolegend_"  # the colour names the point already
                        line = next(lines)
                        line.set_ydata(value[:, k, c])
                        line.set_color(color)
                        line.set_label(label)
                ax.set_autoscaley_on(True)
                ax.relim()
                ax.autoscale_view(scalex=False)
                if len(values) > 1:
                    clipped |= _fit_limits(ax, values[0][..., c], values[1][..., c])
        for ax, axis in zip(self.axes[0], AXIS_NAMES, strict=True):
            ax.set_title(f"{names[0]}: {axis}" if single else axis, **PLAIN)
        self._titles(names, single, clipped)
        self._shown = indices
        # The layout depends on these only (ticks and their labels follow the limits): a
        # point whose curves get the last one's limits (a module at rest) keeps its layout.
        decides = (
            [(ax.get_xlim(), ax.get_ylim(), self._title_overflow(ax)) for ax in self.axes.flat],
            self._title.get_text().count("\n"),  # its height: centred, its width is free
            None if self._legend is None else [t.get_text() for t in self._legend.texts],
        )
        if decides != self._laid_out_for:
            place_grid(
                self.figure, self.axes, title=self._title, note=self._note, legend=self._legend
            )
            self._laid_out_for = decides
        return self.figure

    def _title_overflow(self, ax: Any) -> float:
        """How far ``ax``'s title is wider than the axes, in pixels (0 if it fits)."""
        from ._drawing import renderer_of, text_width

        if not ax.get_title():
            return 0.0
        width = text_width(renderer_of(self.figure), ax.title, ax.get_title())
        return max(0.0, width - ax.bbox.width)

    def _new_lines(self, points: int) -> None:
        """(Re)create each axes' lines for ``points`` points: the runs' curves first (in
        the order :meth:`show` fills them), then the kink markers of the last row."""
        t = self.motion.t
        styles = ["-"] + ([] if self.compare is None else ["--"])
        for r, row in enumerate(self.axes):
            for ax in row:
                for line in list(ax.lines):
                    line.remove()
                for style in styles:
                    for _ in range(points):
                        ax.plot(t, np.zeros_like(t), style, lw=1.2)
                if r == 2:
                    for k in self._kinks:
                        ax.axvline(k, color="tab:red", lw=0.6, alpha=0.4, ls="--")

    def _titles(self, names: list[str], single: bool, clipped: bool) -> None:
        """The figure's title and, for several points or two runs, its legend."""
        motion, compare = self.motion, self.compare
        if single:
            shown = names[0]
        else:
            shown = "all points" if len(names) == len(motion.points) else ", ".join(names)
        method = f"{motion.method} derivatives"
        if compare is not None:
            method += f", {compare.method} dashed"
            if clipped:
                method += ", its spikes cut at the axes"
        text = f"{motion.robot.name or 'Robot'}: {shown} ({method})"
        if self._title is None:
            self._title = self.figure.suptitle(text, **PLAIN)
        else:  # where the layout put it (a new suptitle call would move it back)
            self._title.set_text(text)
        if self._legend is not None:
            self._legend.remove()
            self._legend = None
        if not single or compare is not None:
            # One legend for the nine panels, beside them: inside one it would hide curves.
            self._legend = self.figure.legend(
                *self.axes[0, 0].get_legend_handles_labels(),
                loc="upper right",
                fontsize=8,
                frameon=False,
            )
            for entry in self._legend.get_texts():
                entry.set(**PLAIN)  # point names come from files: never mathtext


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
