"""Mistakes any matrix allows: a transposed matrix or rotation part, swapped rows or columns.

These need no robot: they are rebuilt from the expected values alone. Their wording speaks
of frame axes only when the expected matrix is a rotation or a homogeneous transform
(:func:`is_rotation_like`).
"""

from __future__ import annotations

import numpy as np

from ._candidate import GENERIC, Candidate

__all__ = ["generic_candidates", "is_rotation_like"]


def is_rotation_like(values: np.ndarray, tol: float = 1e-3) -> bool:
    """Whether a matrix is a rotation (3×3) or a homogeneous transform (4×4).

    Parameters
    ----------
    values : ndarray, shape (K, rows, cols)
        The matrix at the K sample points.
    tol : float
        Absolute tolerance of ``RᵀR = I`` (and of the bottom row ``(0, 0, 0, 1)``).

    Returns
    -------
    bool
        True when the top-left 3×3 block is orthonormal at every point and, for a 4×4
        matrix, the bottom row is ``(0, 0, 0, 1)``.

    Examples
    --------
    >>> is_rotation_like(np.eye(4)[np.newaxis]), is_rotation_like(np.ones((1, 3, 3)))
    (True, False)
    """
    shape = values.shape[1:]
    if shape not in ((3, 3), (4, 4)) or not np.all(np.isfinite(values)):
        return False
    block = values[:, :3, :3]
    gram = np.swapaxes(block, 1, 2) @ block
    if not np.allclose(gram, np.eye(3), atol=tol, rtol=0.0):
        return False
    return shape == (3, 3) or bool(np.allclose(values[:, 3, :], [0, 0, 0, 1], atol=tol, rtol=0.0))


def generic_candidates(values: np.ndarray) -> list[Candidate]:
    """Wrong answers that any matrix allows: transposes and swapped rows or columns.

    Parameters
    ----------
    values : ndarray, shape (K, rows, cols)
        The expected matrix at the sample points.

    Returns
    -------
    list of Candidate
        A transposed rotation part only for a rotation or homogeneous transform (its
        wording speaks of frame axes), a transposed matrix only for a square one (a
        non-square one has another shape when transposed: see the checker's shape hint).

    Examples
    --------
    >>> [c.code for c in generic_candidates(np.arange(4.0).reshape(1, 2, 2))]
    ['transposed_matrix', 'row_swap', 'column_swap']
    """
    _, rows, cols = values.shape
    candidates = []
    rotation = is_rotation_like(values)
    if rotation:
        wrong = values.copy()
        wrong[:, :3, :3] = np.swapaxes(values[:, :3, :3], 1, 2)
        message = (
            "The rotation part (rows 1–3, columns 1–3) is transposed: each column of the "
            "rotation part is an axis of the new frame written in the old frame — write the "
            "axes as columns, not as rows."
        )
        reading = "writing the rotation part transposed (its axes as rows)"
        candidates.append(Candidate("transposed_rotation", message, wrong, reading, GENERIC))
    if rows == cols and rows >= 2:
        transposed = np.swapaxes(values, 1, 2)
        if not (candidates and np.allclose(candidates[0].values, transposed)):
            message = (
                "The whole matrix is transposed (yours is the transpose of the expected "
                "one): write each row as a row, not as a column."
            )
            if rotation and rows == 4:
                message = (
                    "The whole matrix is transposed: the translation belongs in the last "
                    "column and the row (0, 0, 0, 1) at the bottom."
                )
            reading = "transposing the whole matrix"
            candidates.append(Candidate("transposed_matrix", message, transposed, reading, GENERIC))
    for axis, word in ((1, "Rows"), (2, "Columns")):
        size = values.shape[axis]
        for a in range(size):
            for b in range(a + 1, size):
                order = list(range(size))
                order[a], order[b] = b, a
                wrong = values[:, order, :] if axis == 1 else values[:, :, order]
                message = (
                    f"{word} {a + 1} and {b + 1} are swapped: check which "
                    f"{'coordinate (x, y, z) each row' if axis == 1 else 'axis each column'}"
                    " stands for."
                )
                reading = f"swapping {word.lower()} {a + 1} and {b + 1}"
                code = f"{word[:-1].lower()}_swap"
                candidates.append(Candidate(code, message, wrong, reading, GENERIC))
    return candidates
