"""The Motion tab: a signal per coordinate, time settings, Run, and the run's results
(DVA table, statistics, plot), drawn from the state."""

from ._results import ALL_POINTS, MAX_TABLE_ROWS, ResultsView
from ._signal_rows import PARAMETER_KINDS, parameter_unit, settings_rows, signal_rows
from ._tab import MotionTab
from ._tables import TABLE_CLASS, dva_table_html, stats_table_html

__all__ = [
    "MotionTab",
    "ResultsView",
    "signal_rows",
    "settings_rows",
    "parameter_unit",
    "PARAMETER_KINDS",
    "dva_table_html",
    "stats_table_html",
    "TABLE_CLASS",
    "MAX_TABLE_ROWS",
    "ALL_POINTS",
]
