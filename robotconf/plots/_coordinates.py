"""The driven coordinates over time: the paper's Figure 16."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..kinematics import JOINT_UNITS
from ._figures import new_figure
from ._grid_layout import grid_of, place_grid
from ._plain_text import PLAIN

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..motion import Motion

__all__ = ["plot_coordinates"]


def plot_coordinates(motion: Motion, length_unit: str = "length") -> Figure:
    """q(t) of the driven coordinates (all when none is driven): the paper's Figure 16.

    Parameters
    ----------
    motion : Motion
    length_unit : str
        Unit label of prismatic coordinates.

    Returns
    -------
    matplotlib.figure.Figure
        One row per coordinate, sharing the time axis, laid out when it is built.

    Examples
    --------
    >>> from robotconf.kinematics import Module, Robot
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import Ramp
    >>> motion = simulate(Robot([Module("Rz"), Module("Tz")]), {"q2": Ramp()}, t_end=1.0)
    >>> [ax.get_ylabel() for ax in plot_coordinates(motion, "mm").axes]
    ['q2 [mm]']
    """
    robot = motion.robot
    names = list(motion.signals) or list(robot.coordinate_names)
    fig = new_figure((9.0, 2.2 + 1.6 * len(names)), layout="none")
    axes = fig.subplots(len(names), 1, sharex=True, squeeze=False)[:, 0]
    for ax, name in zip(axes, names, strict=True):
        i = robot.index(name)
        unit = robot.modules[i].unit
        unit = length_unit if unit == JOINT_UNITS["prismatic"] else unit
        ax.plot(motion.t, motion.q[:, i], lw=1.4)
        ax.set_ylabel(f"{name} [{unit}]" if unit else name, **PLAIN)
        signal = motion.signals.get(name)
        ax.set_title(f"{name}(t) = {signal!r}" if signal is not None else f"{name}(t)", **PLAIN)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time (s)")
    for ax in axes[:-1]:
        ax.xaxis.set_label_coords(0.5, 0.0)  # no label: nothing to place at each draw
    place_grid(fig, grid_of(axes))
    return fig
