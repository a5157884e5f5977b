"""The signed distance of a segment and a solid cylinder, vectorized.

In the cylinder's frame (centred, axis along z, radius ``R``, half length ``H``), the
signed distance of two convex bodies is ``sd = −min_{|n|=1} F(n)`` with

    F(n) = h_seg(n) + h_cyl(−n) = max(n·a, n·b) + R·|n_⊥| + H·|n_z|

(``h`` are support functions; ``n_⊥`` the part of ``n`` across the axis). The formula
holds apart (``sd`` is the distance) and overlapping (``−sd`` is the penetration depth,
the shortest translation that separates them), so one search serves both. ``F`` is
smooth except where ``n·d = 0`` (the band: the segment's ends tie), ``n_z = 0`` (the
equator) and ``n_⊥ = 0`` (the poles). The global minimum lies in one of these strata,
and each gives candidate directions:

- the poles ``±z`` and the band's crossings of the equator ``±(d × z)/|d × z|``;
- the equator with an end ``e`` leading: ``n = −e_⊥/|e_⊥|``;
- the smooth regions, with ``w = e ± H z``: ``F = n·w + R|n_⊥|`` is stationary where
  ``n_⊥ ∥ w_⊥`` and ``n = (sin β ŵ_⊥, cos β)`` with
  ``(sin β, cos β) ∥ ±(|w_⊥| ∓ R, w_z)`` (closed forms, 16 directions);
- the band, a great circle: a 1-D search (64 samples, then Newton's method from the
  two best local minima and from the band's points nearest the poles, where the
  ``R|n_⊥|`` term dips in a cusp narrower than the samples; Newton converges
  quadratically to round-off).

``F`` is evaluated exactly at every candidate and the least value kept: an extra
candidate can only overestimate ``min F``, so the answer is exact once the minimizer is
among them. Near a smooth minimum an error δ in direction changes ``F`` by O(δ²).
"""

from __future__ import annotations

import numpy as np

from ._segments import dot

__all__ = ["segment_cylinder_distance", "BAND_SAMPLES", "BAND_MINIMA", "BAND_STEPS"]

#: Samples of the band circle, how many of its local minima are refined, and Newton steps.
BAND_SAMPLES = 64
BAND_MINIMA = 2
BAND_STEPS = 8


def _support(n: np.ndarray, a: np.ndarray, b: np.ndarray, radius: np.ndarray, half: np.ndarray):
    """``F(n)`` for directions ``n`` (N, K, 3), segments (N, 3), sizes (N,)."""
    na = np.einsum("nkj,nj->nk", n, a)
    nb = np.einsum("nkj,nj->nk", n, b)
    across = np.sqrt(np.maximum(n[..., 0] ** 2 + n[..., 1] ** 2, 0.0))
    return np.maximum(na, nb) + radius[:, None] * across + half[:, None] * np.abs(n[..., 2])


def _unit(v: np.ndarray) -> np.ndarray:
    norm = np.sqrt(dot(v, v))
    return np.where(norm[..., None] > 0.0, v / np.where(norm > 0.0, norm, 1.0)[..., None], 0.0)


def _closed_form_directions(a, b, radius, half) -> np.ndarray:
    n = a.shape[0]
    z = np.broadcast_to(np.array([0.0, 0.0, 1.0]), (n, 3))
    out = [z, -z]
    band_equator = _unit(np.cross(b - a, z))
    out += [band_equator, -band_equator]
    for end in (a, b):
        flat = end * np.array([1.0, 1.0, 0.0])
        out.append(-_unit(flat))
        for sigma in (1.0, -1.0):
            w = end + sigma * half[:, None] * z
            w_flat = w * np.array([1.0, 1.0, 0.0])
            w_across = np.sqrt(dot(w_flat, w_flat))
            heading = _unit(w_flat)
            for lean in (w_across - radius, w_across + radius):
                for sign in (1.0, -1.0):
                    sin_cos = _unit(np.stack([sign * lean, sign * w[:, 2]], axis=-1))
                    out.append(sin_cos[:, :1] * heading + sin_cos[:, 1:] * z)
    return np.stack(out, axis=1)


def _band_basis(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Orthonormal ``u, v`` across each segment direction (any pair where ``d = 0``)."""
    axis = _unit(d)
    helper = np.where(np.abs(axis[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    u = _unit(np.cross(axis, helper))
    u = np.where(dot(u, u)[:, None] > 0.0, u, [[1.0, 0.0, 0.0]])
    v = np.cross(axis, u)
    v = np.where(dot(v, v)[:, None] > 0.0, v, [[0.0, 1.0, 0.0]])
    return u, v


def _band_directions(a, b, radius, half) -> np.ndarray:
    u, v = _band_basis(b - a)
    # On the band n ⊥ d, so n·a = n·b: with n = cos θ u + sin θ v and z = n_z,
    # G(θ) = α cos θ + β sin θ + R √(1 − z²) + H |z|, four numbers per pair.
    alpha, beta = dot(u, a)[:, None], dot(v, a)[:, None]
    gamma, delta = u[:, 2:3], v[:, 2:3]
    r, h = radius[:, None], half[:, None]

    def value(theta: np.ndarray) -> np.ndarray:
        z = np.cos(theta) * gamma + np.sin(theta) * delta
        return (
            np.cos(theta) * alpha
            + np.sin(theta) * beta
            + r * np.sqrt(np.maximum(1.0 - z * z, 0.0))
            + h * np.abs(z)
        )

    step = 2.0 * np.pi / BAND_SAMPLES
    grid = np.arange(BAND_SAMPLES) * step
    samples = value(np.broadcast_to(grid, (a.shape[0], BAND_SAMPLES)))
    local = (samples <= np.roll(samples, 1, axis=1)) & (samples <= np.roll(samples, -1, axis=1))
    best = grid[np.argsort(np.where(local, samples, np.inf), axis=1)[:, :BAND_MINIMA]]
    # Where the band passes near a pole, R√(1 − z²) dips in a cusp narrower than the
    # samples: start there too (the band's points nearest ±z, where G'' is large).
    pole = np.arctan2(delta, gamma)
    start = np.concatenate([best, pole, pole + np.pi], axis=1)
    theta = start.copy()
    # Newton's method on G' from those starts, kept within one sample of them. Its
    # kinks (z = 0: the band meets the equator; |z| = 1: a pole) are closed-form
    # candidates already, so only smooth minima are sought here.
    for _ in range(BAND_STEPS):
        c, s = np.cos(theta), np.sin(theta)
        z = c * gamma + s * delta
        dz = -s * gamma + c * delta
        w = np.sqrt(np.maximum(1.0 - z * z, 1e-24))  # w³ stays a float at a pole
        lean = h * np.sign(z) - r * z / w
        slope = -s * alpha + c * beta + dz * lean
        curve = -c * alpha - s * beta - z * lean - r * dz * dz / (w * w * w)
        move = np.where(
            curve > 0.0, -slope / np.where(curve > 0.0, curve, 1.0), -np.sign(slope) * step / 4
        )
        theta = np.clip(theta + move, start - step, start + step)
    theta = np.concatenate([theta, start], axis=1)
    return np.cos(theta)[..., None] * u[:, None, :] + np.sin(theta)[..., None] * v[:, None, :]


def segment_cylinder_distance(
    a: np.ndarray, b: np.ndarray, radius: np.ndarray, half_length: np.ndarray
) -> np.ndarray:
    """Signed distance of segments and centred cylinders along z, shape (N,).

    Parameters
    ----------
    a, b : ndarray, shape (N, 3)
        Segment ends in each cylinder's frame.
    radius, half_length : ndarray, shape (N,)
        The cylinders' radius and half their length (> 0).

    Returns
    -------
    ndarray, shape (N,)
        Distance when apart, ``−`` the penetration depth when they overlap.

    Examples
    --------
    >>> one = np.ones(2)
    >>> a = np.array([[3.0, 0, 0], [0.0, 0, -5]])
    >>> b = np.array([[3.0, 0, 5], [0.0, 0, 5]])
    >>> segment_cylinder_distance(a, b, one, one).round(12)  # beside; through the axis
    array([ 2., -1.])
    """
    candidates = np.concatenate(
        [
            _closed_form_directions(a, b, radius, half_length),
            _band_directions(a, b, radius, half_length),
        ],
        axis=1,
    )
    usable = dot(candidates, candidates) > 0.5
    values = np.where(usable, _support(candidates, a, b, radius, half_length), np.inf)
    return -np.min(values, axis=1)
