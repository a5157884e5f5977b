"""Calibration: where things really are, from measured points (docs/calibration.md).

A cell is drawn with nominal numbers; a real table stands a little elsewhere and a real
arm's links are a little longer. Measuring a few points finds out by how much, by least
squares, with the uncertainty of every number and a clear word where the measurements
cannot tell.

Frames
    :func:`locate_frame` (a table, a fixture, a robot base from ≥ 3 measured points),
    :class:`FrameFit` (its pose, the residual of every point, the pose's covariance)
Robot parameters
    :func:`calibrate` (module offsets, DH parameters, joint zero offsets and the
    end-effector point from measured end-effector positions), :class:`Calibration`
    (identified values with standard errors, and the groups of parameters the data
    cannot tell apart)
Limits
    :data:`MAX_POINTS`, :data:`MAX_WORK`, :data:`MAX_PARAMETERS`

A table's corners measured after it was moved by (500, 200, 0):

>>> import numpy as np
>>> corners = np.array([[0, 0, 0], [800, 0, 0], [800, 600, 0], [0, 600, 0]])
>>> locate_frame(corners + [500, 200, 0], corners).translation.round(9) + 0.0
array([500., 200.,   0.])
"""

from ._frame import COLLINEAR_WARNING, FrameFit, locate_frame
from ._identify import MAX_WORK, Calibration, calibrate
from ._parameters import MAX_PARAMETERS
from ._points import MAX_POINTS

__all__ = [
    # frames
    "locate_frame",
    "FrameFit",
    "COLLINEAR_WARNING",
    # robot parameters
    "calibrate",
    "Calibration",
    # limits
    "MAX_POINTS",
    "MAX_WORK",
    "MAX_PARAMETERS",
]
