"""One block of samples: the pose state ``S`` (3, 4, B) and the products that move it.

The layout of ``S`` and why the products are written out are in
:mod:`robotconf.kinematics.kernel._kernel`, which runs a chain block by block through
these: :func:`cos_sin` for the joint angles, then for each link :func:`_apply` (constant
translations and rotations, a turn about or a slide along its axis), in place.

Why cos and sin come from the tangent half-angle
------------------------------------------------
With ``t = tan(q/2)``: ``cos q = (1 − t²)/(1 + t²)`` and ``sin q = 2t/(1 + t²)``. numpy
vectorizes ``tan`` with SIMD on common CPUs while its float64 ``sin``/``cos`` run one
element at a time, so this is about three times faster for the same accuracy class: the
results stay within 3e-16 of the exact values (measured over |q| ≤ 1e4; ``np.cos`` is
within 6e-17), are exact at q = 0, and never overflow (``tan`` of a float never exceeds
about 1.6e16).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ._geometry import LinkGeometry

__all__ = ["cos_sin"]


def cos_sin(
    angle: np.ndarray, cos: np.ndarray | None = None, sin: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """cos and sin of an array through the tangent half-angle (see module notes).

    Parameters
    ----------
    angle : ndarray
        Angles (radians), finite.
    cos, sin : ndarray, optional
        Outputs of the same shape; allocated when omitted.

    Returns
    -------
    cos, sin : ndarray

    Examples
    --------
    >>> c, s = cos_sin(np.array([0.0, np.pi / 3]))
    >>> bool(np.allclose(c, [1, 0.5], rtol=0, atol=1e-15)), bool(s[0] == 0.0)
    (True, True)
    """
    cos = np.empty_like(angle) if cos is None else cos
    sin = np.empty_like(angle) if sin is None else sin
    np.multiply(angle, 0.5, out=sin)
    np.tan(sin, out=sin)  # sin holds t
    np.multiply(sin, sin, out=cos)  # cos holds t²
    scale = np.add(cos, 1.0)  # 1 + t²
    np.reciprocal(scale, out=scale)
    np.subtract(1.0, cos, out=cos)
    cos *= scale
    sin *= scale
    sin *= 2.0
    return cos, sin


class _Plan:
    """Per-chain precomputation shared by every block."""

    def __init__(self, links: Sequence[LinkGeometry | None]):
        self.links = [None if (g is None or g.is_identity) else g for g in links]
        self.revolute = [i for i, g in enumerate(self.links) if g is not None and g.joint == "R"]
        self.row = {link: r for r, link in enumerate(self.revolute)}
        self.angles = np.array([self.links[i].angle for i in self.revolute])  # type: ignore[union-attr]
        self.has_angles = bool(np.any(self.angles != 0.0))
        # A constant screw angle (a prismatic DH joint's θ) needs cos/sin only once.
        self.constant_cs: dict[int, tuple[float, float]] = {}
        for i, g in enumerate(self.links):
            if g is not None and g.axis is not None and g.joint != "R" and g.angle != 0.0:
                self.constant_cs[i] = (float(np.cos(g.angle)), float(np.sin(g.angle)))

    def trig(self, q_t: np.ndarray, cos: np.ndarray, sin: np.ndarray) -> None:
        """Fill cos, sin (shape (m, B)) for every revolute link of one block."""
        if not self.revolute:
            return
        # Gather the angles into ``sin``; cos_sin works in place element by element.
        np.take(q_t, self.revolute, axis=0, out=sin)
        if self.has_angles:
            sin += self.angles[:, np.newaxis]
        cos_sin(sin, cos, sin)


class _Scratch:
    """Memory for one block of samples, allocated once per call."""

    def __init__(self, size: int, revolute: int):
        self.state = np.empty((3, 4, size))
        self.t1 = np.empty((3, size))
        self.t2 = np.empty((3, size))
        self.cos = np.empty((revolute, size))
        self.sin = np.empty((revolute, size))

    def sized(self, size: int) -> _Scratch:
        if size == self.state.shape[-1]:
            return self
        view = object.__new__(_Scratch)
        view.state = self.state[..., :size]
        view.t1, view.t2 = self.t1[:, :size], self.t2[:, :size]
        view.cos, view.sin = self.cos[:, :size], self.sin[:, :size]
        return view


def _reset(state: np.ndarray) -> None:
    state.fill(0.0)
    state[0, 0] = 1.0
    state[1, 1] = 1.0
    state[2, 2] = 1.0


def _translate(state: np.ndarray, t1: np.ndarray, vector: np.ndarray) -> None:
    """p += R · vector for a constant 3-vector (zero entries cost nothing)."""
    p = state[:, 3]
    for k in range(3):
        if vector[k] == 1.0:
            p += state[:, k]
        elif vector[k] != 0.0:
            np.multiply(state[:, k], vector[k], out=t1)
            p += t1


def _rotate_constant(state: np.ndarray, t1: np.ndarray, rotation: np.ndarray) -> None:
    """R ← R · rotation for a constant 3×3 rotation."""
    old = state[:, :3].copy()
    for k in range(3):
        col = state[:, k]
        col.fill(0.0)
        for j in range(3):
            factor = rotation[j, k]
            if factor == 1.0:
                col += old[:, j]
            elif factor != 0.0:
                np.multiply(old[:, j], factor, out=t1)
                col += t1


def _rotate_axis(
    state: np.ndarray,
    t1: np.ndarray,
    t2: np.ndarray,
    axis: int,
    c: np.ndarray | float,
    s: np.ndarray | float,
) -> None:
    """R ← R · Rot_axis(c, s): only the two columns orthogonal to the axis change.

    With (i, j) the cyclic successors of the axis, ``Rot`` maps e_i → c e_i + s e_j and
    e_j → −s e_i + c e_j, so column i becomes ``c R_i + s R_j`` and column j
    ``c R_j − s R_i``.
    """
    i, j = (axis + 1) % 3, (axis + 2) % 3
    col_i, col_j = state[:, i], state[:, j]
    np.multiply(col_i, s, out=t1)
    col_i *= c
    np.multiply(col_j, s, out=t2)
    col_i += t2
    col_j *= c
    col_j -= t1


def _slide_axis(state: np.ndarray, t1: np.ndarray, axis: int, d: np.ndarray | float) -> None:
    """p += d · R[:, axis]."""
    np.multiply(state[:, axis], d, out=t1)
    state[:, 3] += t1


def _apply(g: LinkGeometry, index: int, plan: _Plan, scratch: _Scratch, q_t: np.ndarray) -> None:
    """state ← state · A(q) for one link over one block."""
    state, t1, t2 = scratch.state, scratch.t1, scratch.t2
    if g.pre_translation is not None:
        _translate(state, t1, g.pre_translation)
    if g.pre_rotation is not None:
        _rotate_constant(state, t1, g.pre_rotation)
    if g.axis is not None:
        if g.joint == "R":
            r = plan.row[index]
            _rotate_axis(state, t1, t2, g.axis, scratch.cos[r], scratch.sin[r])
        elif index in plan.constant_cs:
            _rotate_axis(state, t1, t2, g.axis, *plan.constant_cs[index])
        if g.joint == "P":
            slide = q_t[index] + g.offset if g.offset != 0.0 else q_t[index]
            _slide_axis(state, t1, g.axis, slide)
        elif g.offset != 0.0:
            _slide_axis(state, t1, g.axis, g.offset)
    if g.post_translation is not None:
        _translate(state, t1, g.post_translation)
    if g.post_rotation is not None:
        _rotate_constant(state, t1, g.post_rotation)
