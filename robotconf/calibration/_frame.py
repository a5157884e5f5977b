"""Locate a frame (a table, a robot base, a fixture) from points measured on it.

Points ``n_i`` are known in the frame's own coordinates (the nominal points: a table's
corners on its drawing, a robot's end-effector points in its base frame); the same points
are measured in the world as ``m_i``. The frame's pose ``T = [R | t]`` is the least-squares
fit ``min Σ |R n_i + t − m_i|²`` over rotations R, solved in closed form (Kabsch; Arun,
Huang & Blostein 1987): with both sets centred on their centroids ``n̄``, ``m̄``, the SVD
``H = Σ (n_i − n̄)(m_i − m̄)ᵀ = U S Vᵀ`` gives ``R = V diag(1, 1, d) Uᵀ`` with
``d = sign det(V Uᵀ)`` (never a reflection), and ``t = m̄ − R n̄``.

**Uncertainty.** With independent noise of standard deviation σ on every measured
coordinate, the linearized fit gives (``u_i = R(n_i − n̄)``, ``a = R n̄``):

- the centroid ``m̄`` to ``σ²/N`` per axis;
- the small turn ``δθ`` (a rotation vector, world frame) with covariance
  ``σ² K⁻¹``, ``K = Σ_i (|u_i|² I − u_i u_iᵀ)`` — the points' inertia about their
  centroid;
- the frame origin ``t = m̄ − a`` with covariance ``σ²/N · I + [a]× σ² K⁻¹ [a]×ᵀ``.

``K`` loses rank when the points lie on a line: the turn about that line is then not
determined (refused), and poorly determined when they nearly do (a warning).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from ._points import point_set

__all__ = ["FrameFit", "locate_frame", "COLLINEAR_WARNING", "COLLINEAR_ERROR"]

#: Spread across the points' best line below this fraction of the spread along it: the
#: turn about the line is poorly determined, and :func:`locate_frame` warns.
COLLINEAR_WARNING = 1e-2
#: Below this fraction (rounding level) the points lie on one line and are refused.
COLLINEAR_ERROR = 1e-10


def _cross_matrix(a: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


@dataclass(frozen=True, repr=False, eq=False)
class FrameFit:
    """A frame located from measured points: its pose, the residuals and their statistics.

    Attributes
    ----------
    pose : ndarray, shape (4, 4)
        The frame in the measuring (world) frame: ``measured ≈ pose · nominal``.
    residuals : ndarray, shape (N, 3)
        ``measured − pose · nominal`` per point (length units).
    errors : ndarray, shape (N,)
        Their lengths: how far each measured point lies from where the fit puts it.
    spread : ndarray, shape (3,)
        The nominal points' spread about their centroid along their principal axes
        (root of the sum of squares, largest first): ``spread[1] / spread[0]`` small means
        nearly collinear.
    """

    pose: np.ndarray
    residuals: np.ndarray
    errors: np.ndarray
    spread: np.ndarray
    _centred: np.ndarray  # (N, 3) the nominal points about their centroid, turned by R
    _centroid: np.ndarray  # (3,) R n̄

    @property
    def rotation(self) -> np.ndarray:
        """The frame's rotation R, shape (3, 3)."""
        return self.pose[:3, :3].copy()

    @property
    def translation(self) -> np.ndarray:
        """The frame's origin t in the world, shape (3,) (length units)."""
        return self.pose[:3, 3].copy()

    @property
    def rms(self) -> float:
        """Root mean square of :attr:`errors` (length units)."""
        return float(np.sqrt(np.mean(self.errors**2)))

    @property
    def max_error(self) -> float:
        """The largest of :attr:`errors` (length units)."""
        return float(np.max(self.errors))

    @property
    def noise(self) -> float:
        """The noise per measured coordinate the residuals suggest: ``√(Σ r² / (3N − 6))``
        (6 numbers of the pose are fitted), in length units."""
        count = len(self.errors)
        return float(np.sqrt(np.sum(self.errors**2) / (3 * count - 6)))

    def covariance(self, noise: float | None = None) -> np.ndarray:
        """Covariance (6, 6) of the pose estimate: a small turn ``δθ`` (rad, world axes),
        then the origin's shift ``δt`` (length), for independent noise ``noise`` (length
        units) on each measured coordinate (default: :attr:`noise`). See the module notes.

        Examples
        --------
        Four corners of a 1 × 1 square, noise 0.01: the centroid sits at the origin here,
        so the origin is known to 0.01/√4 = 0.005 per axis.

        >>> square = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]) / 2
        >>> fit = locate_frame(square, square)
        >>> np.sqrt(np.diag(fit.covariance(0.01)))[3:].round(6)
        array([0.005, 0.005, 0.005])
        """
        sigma = self.noise if noise is None else float(noise)
        u = self._centred
        inertia = np.sum(u * u) * np.eye(3) - u.T @ u
        turn = sigma**2 * np.linalg.pinv(inertia)
        a = _cross_matrix(self._centroid)
        out = np.empty((6, 6))
        out[:3, :3] = turn
        out[3:, :3] = a @ turn
        out[:3, 3:] = out[3:, :3].T
        out[3:, 3:] = sigma**2 / len(u) * np.eye(3) + a @ turn @ a.T
        return out

    def __repr__(self) -> str:
        t = ", ".join(f"{v:.6g}" for v in self.translation + 0.0)
        return (
            f"FrameFit(origin ({t}), {len(self.errors)} points, rms error {self.rms:.3g}, "
            f"largest {self.max_error:.3g})"
        )

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text(repr(self))


def locate_frame(measured: Any, nominal: Any) -> FrameFit:
    """The frame whose nominal points were measured: the least-squares pose (Kabsch).

    Parameters
    ----------
    measured : array-like, shape (N, 3)
        The points as measured, in the world (the measuring frame), length units.
    nominal : array-like, shape (N, 3)
        The same points in the frame's own coordinates, in the same order and units.
        At least 3, not on one line.

    Returns
    -------
    FrameFit
        ``pose`` (4, 4) with ``measured ≈ pose · nominal``, the residual of every point,
        and the pose's covariance for a given noise.

    Raises
    ------
    InvalidInputError
        Naming ``measured`` or ``nominal``: fewer than 3 points, shapes that are not
        (N, 3) or do not match, NaN or infinite numbers, ``|x| > 1e150``, more than
        :data:`~robotconf.calibration.MAX_POINTS` points, or nominal points on one line
        (the turn about it is not determined).

    Warns
    -----
    UserWarning
        When the nominal points are nearly on one line (their spread across it under 1 %
        of that along it): the fit is made, but the turn about the line is poor.

    Examples
    --------
    A table's three corners, measured after the table was turned 90° about z and moved
    to (500, 200, 0):

    >>> corners = [[0, 0, 0], [800, 0, 0], [0, 600, 0]]
    >>> measured = [[500, 200, 0], [500, 1000, 0], [-100, 200, 0]]
    >>> fit = locate_frame(measured, corners)
    >>> fit.pose.round(9) + 0.0
    array([[  0.,  -1.,   0., 500.],
           [  1.,   0.,   0., 200.],
           [  0.,   0.,   1.,   0.],
           [  0.,   0.,   0.,   1.]])
    >>> fit.max_error < 1e-9
    True
    """
    m = point_set(measured, "measured", minimum=3)
    n = point_set(nominal, "nominal", minimum=3, count=len(m))
    n_bar, m_bar = n.mean(axis=0), m.mean(axis=0)
    # Scaled to the size of the points, so that coordinates near 1e150 square safely.
    size = float(np.max(np.abs(np.concatenate([n - n_bar, m - m_bar])), initial=0.0))
    spread = np.linalg.svd(n - n_bar, compute_uv=False)
    if not size > 0.0 or not spread[0] > 0.0:
        raise InvalidInputError(
            "nominal",
            f"<{len(n)} points>",
            "points that span a plane",
            problem="all points coincide:",
        )
    ratio = spread[1] / spread[0]
    if ratio <= COLLINEAR_ERROR:
        raise InvalidInputError(
            "nominal",
            f"<{len(n)} points>",
            "at least 3 points not on one line",
            problem="the points lie on one line, so the turn about it is not determined:",
        )
    if ratio < COLLINEAR_WARNING:
        warnings.warn(
            f"nominal: the points are nearly on one line (their spread across it is "
            f"{ratio:.2%} of the spread along it): the turn about that line is poorly "
            "determined; measure a point farther off the line",
            UserWarning,
            stacklevel=2,
        )
    a, b = (n - n_bar) / size, (m - m_bar) / size
    u, _, vt = np.linalg.svd(a.T @ b)
    d = 1.0 if np.linalg.det(vt.T @ u.T) >= 0.0 else -1.0
    rotation = vt.T @ np.diag([1.0, 1.0, d]) @ u.T
    pose = np.eye(4)
    pose[:3, :3] = rotation
    pose[:3, 3] = m_bar - rotation @ n_bar
    residuals = m - (n @ rotation.T + pose[:3, 3])
    return FrameFit(
        pose=pose,
        residuals=residuals,
        errors=np.linalg.norm(residuals, axis=1),
        spread=spread,
        _centred=(n - n_bar) @ rotation.T,
        _centroid=rotation @ n_bar,
    )
