"""matplotlib figure of one point's motion (or of several, one colour each): position (or
displacement), velocity, acceleration × x, y, z, as in the paper's Figures 17–19,
optionally with another method's run dashed over it.

Only draws arrays the core computed; matplotlib is imported inside the function.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ._motion_figure import MotionFigure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..motion import Motion

__all__ = ["plot_motion"]


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
        3 rows × 3 columns (x, y, z) sharing the time axis, laid out when it is built
        (no layout engine runs at each draw; call ``fig.set_layout_engine("constrained")``
        after adding artists of your own). In Jupyter the returned figure displays
        itself; in a script call ``fig.savefig(path)``. It is not registered with
        pyplot, so it never shows twice and never piles up open figures. To draw many
        points one after another, :class:`MotionFigure` redraws one figure quicker.

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
    figure = MotionFigure(
        motion,
        displacement=displacement,
        length_unit=length_unit,
        figsize=figsize,
        compare=compare,
    )
    return figure.show(point)
