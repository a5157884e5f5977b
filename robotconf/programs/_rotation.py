"""Orientation along a path, and the turn still needed (the maps live in the kinematics).

Orientation along a LIN or CIRC path is slerp: ``R(u) = R0 · exp(u·θ k̂)`` with
``θ k̂ = log(R0ᵀ R1)``, the shortest turn from the start to the end orientation. The
turn's axis ``R0 k̂`` is fixed in the base frame, so the angular velocity is
``ω = R0 k̂ · θ u̇`` and its rate ``ω̇ = R0 k̂ · θ ü`` (no other terms).
"""

from __future__ import annotations

import numpy as np

from ..kinematics import rotation_vector

__all__ = ["rotation_error"]


def rotation_error(target: np.ndarray, actual: np.ndarray) -> np.ndarray:
    """The turn still needed, in the base frame: ``log(R_target · R_actualᵀ)``, (..., 3).

    >>> from robotconf.kinematics import rotation_matrix
    >>> rotation_error(rotation_matrix(np.array([0.1, 0, 0])), np.eye(3)).round(12) + 0.0
    array([0.1, 0. , 0. ])
    """
    return rotation_vector(target @ np.swapaxes(actual, -1, -2))
