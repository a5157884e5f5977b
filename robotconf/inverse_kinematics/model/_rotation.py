"""The rotation vector (axis times angle) of many rotation matrices at once.

The numeric solver measures an orientation error as the rotation vector of
``R_target · Rᵀ``: its direction is the axis and its length the angle (0 … π) of the
turn still needed. Two formulas cover the whole range without losing digits:

- angles up to 90° (``cos θ ≥ 0``): the skew part ``s = vee(R − Rᵀ)/2 = sin θ · u`` gives
  the axis, and ``θ = atan2(|s|, cos θ)`` the angle (exact for tiny angles too);
- larger angles: ``sin θ`` shrinks towards 180°, so the axis comes from the symmetric
  part instead, ``(R + Rᵀ)/2 − cos θ · I = (1 − cos θ) · u uᵀ``, its sign from ``s``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["rotation_vector_last"]


def rotation_vector_last(rotation: np.ndarray) -> np.ndarray:
    """:func:`robotconf.kinematics.rotation_vector` with the batch last: (3, 3, B) matrices
    → (3, B) vectors.

    The solver's layout: each entry is a contiguous row over the batch, so every step is
    one operation over all B (and each matrix gets the same operations whatever B is); it
    runs in the solver's innermost loop, so it keeps its own copy of the formula, which
    ``tests/test_ik_numeric.py`` checks against the kinematics' one.

    >>> turn = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    >>> rotation_vector_last(turn[:, :, np.newaxis])[:, 0].round(12) + 0.0
    array([0.        , 0.        , 1.57079633])
    """
    r = rotation
    skew = np.empty((3, r.shape[-1]))
    np.subtract(r[2, 1], r[1, 2], out=skew[0])
    np.subtract(r[0, 2], r[2, 0], out=skew[1])
    np.subtract(r[1, 0], r[0, 1], out=skew[2])
    skew *= 0.5
    cos = r[0, 0] + r[1, 1]
    cos += r[2, 2]
    cos -= 1.0
    cos *= 0.5
    np.clip(cos, -1.0, 1.0, out=cos)
    squares = skew * skew
    sin = squares[0] + squares[1]
    sin += squares[2]
    np.sqrt(sin, out=sin)
    angle = np.arctan2(sin, cos)
    # Small turns: θ/sin θ → 1, so s itself is the answer where sin θ underflows.
    ratio = np.divide(angle, sin, out=np.ones_like(angle), where=sin > 1e-300)
    out = skew * ratio
    wide = np.flatnonzero(cos < 0.0)
    if wide.size:
        out[:, wide] = _wide(r[:, :, wide], cos[wide], skew[:, wide], angle[wide])
    return out


def _wide(r: np.ndarray, cos: np.ndarray, skew: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Turns beyond 90°: the axis from the symmetric part ``(R + Rᵀ)/2 − cos θ·I``, whose
    column with the largest diagonal entry is the best-conditioned multiple of ``u``."""
    symmetric = r + r.transpose(1, 0, 2)
    symmetric *= 0.5
    diagonal = [symmetric[i, i] - cos for i in range(3)]
    for i in range(3):
        symmetric[i, i] = diagonal[i]
    first = (diagonal[0] >= diagonal[1]) & (diagonal[0] >= diagonal[2])
    second = ~first & (diagonal[1] >= diagonal[2])
    column = np.where(first, symmetric[:, 0], np.where(second, symmetric[:, 1], symmetric[:, 2]))
    squares = column * column
    length = np.sqrt(squares[0] + squares[1] + squares[2])
    axis = column / length
    dot = axis[0] * skew[0] + axis[1] * skew[1] + axis[2] * skew[2]
    axis *= np.where(dot < 0.0, -angle, angle)
    return axis
