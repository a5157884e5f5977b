"""Plots: matplotlib figures of a robot, a motion, a workspace and the coordinates.

Presentation: every number drawn comes from the core. matplotlib is imported inside the
functions, and each figure shows itself as a picture in a notebook.

:func:`plot_robot` (the paper's Figure 14), :func:`plot_motion` (Figures 17–19),
:func:`plot_coordinates` (Figure 16), :func:`plot_workspace`, :func:`new_figure`;
:class:`MotionFigure` redraws one DVA figure for point after point and
:func:`save_figure` saves a figure without matplotlib's repeated tick work (the report's
way).

>>> from robotconf.kinematics import Module, Robot
>>> fig = plot_robot(Robot([Module("Rz")], end_effector=(1, 0, 0)))
>>> type(fig).__name__
'Figure'
"""

from ._coordinates import plot_coordinates
from ._drawing import save_figure
from ._figures import new_figure
from ._kink_note import kink_note
from ._motion import plot_motion
from ._motion_figure import MotionFigure
from ._robot import EE_COLOR, MODULE_COLOR, TRIAD_COLORS, plot_robot
from ._workspace import PROJECTIONS, plot_workspace

__all__ = [
    "plot_robot",
    "plot_motion",
    "MotionFigure",
    "plot_coordinates",
    "plot_workspace",
    "new_figure",
    "save_figure",
    "kink_note",
    "MODULE_COLOR",
    "EE_COLOR",
    "TRIAD_COLORS",
    "PROJECTIONS",
]
