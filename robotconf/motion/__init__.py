"""Motion: drive coordinates with signals and get the DVA of every frame and the EE.

Simulation
    :func:`simulate`, :class:`Motion`, :class:`SimulationSettings`, :data:`METHODS`
Limits of a run (docs/conventions.md, "Limits of a run")
    :data:`MAX_TIME_SAMPLES`, :data:`MAX_SAMPLE_POINTS`, :data:`MIN_TIME_STEP`,
    :data:`MAX_TIME`, :data:`TIME_RESOLUTION`; the memory budget is
    :func:`robotconf.set_memory_budget`
Displacement, velocity, acceleration (numpy)
    :data:`QUANTITIES`, :func:`analytic_dva`, :func:`numeric_dva` (central differences),
    :func:`backward_dva` (Simulink's Derivative block), :func:`first_derivative`,
    :func:`second_derivative`, :func:`backward_derivative`,
    :func:`backward_second_derivative`
Tables and statistics (pandas, imported on use)
    :func:`motion_table`, :func:`motion_stats`, :func:`compare_motions`, :data:`STATS`, :data:`TIE`

>>> from robotconf.kinematics import Module, Robot
>>> from robotconf.signals import Ramp
>>> motion = simulate(Robot([Module("Tx")]), {"q1": Ramp(slope=2.0)}, t_end=1.0, dt=0.5)
>>> motion.position[:, -1, 0]
array([0., 1., 2.])
"""

from ._dva import (
    QUANTITIES,
    analytic_dva,
    backward_derivative,
    backward_dva,
    backward_second_derivative,
    first_derivative,
    numeric_dva,
    second_derivative,
)
from ._motion import Motion
from ._settings import MAX_SAMPLE_POINTS, MAX_TIME_SAMPLES, METHODS, SimulationSettings
from ._simulation import simulate
from ._table import (
    EXCEL_MAX_ROWS,
    STATS,
    TIE,
    compare_motions,
    motion_stats,
    motion_table,
    motion_to_csv,
    motion_to_excel,
)
from ._time_grid import MAX_TIME, MIN_TIME_STEP, TIME_RESOLUTION

__all__ = [
    # simulation
    "simulate",
    "Motion",
    "SimulationSettings",
    "METHODS",
    "MAX_TIME_SAMPLES",
    "MAX_SAMPLE_POINTS",
    "MIN_TIME_STEP",
    "MAX_TIME",
    "TIME_RESOLUTION",
    # DVA
    "QUANTITIES",
    "analytic_dva",
    "numeric_dva",
    "backward_dva",
    "first_derivative",
    "second_derivative",
    "backward_derivative",
    "backward_second_derivative",
    # tables
    "motion_table",
    "motion_stats",
    "compare_motions",
    "motion_to_csv",
    "motion_to_excel",
    "STATS",
    "TIE",
    "EXCEL_MAX_ROWS",
]
