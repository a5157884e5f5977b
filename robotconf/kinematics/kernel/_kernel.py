"""The vectorized kernel that composes chains of links over many samples.

The pose ``[R | p]`` of a chain is held for a block of ``B`` samples as an array ``S`` of
shape (3, 4, B): ``S[r, k]`` is row ``r`` of column ``k`` (columns 0–2 are ``R``, column 3
is ``p``), contiguous over samples. Right-multiplying by an elementary rotation changes
just two columns and a translation just ``p``, so writing those few products out costs far
less than stacking 4×4 matrices and calling ``matmul``, and the constant last row is never
computed. Samples go in blocks small enough to stay in cache; each frame is written
straight into the caller's preallocated output with one copy.

Why cos and sin come from the tangent half-angle
------------------------------------------------
With ``t = tan(q/2)``: ``cos q = (1 − t²)/(1 + t²)`` and ``sin q = 2t/(1 + t²)``. numpy
vectorizes ``tan`` with SIMD on common CPUs while its float64 ``sin``/``cos`` run one
element at a time, so this is about three times faster for the same accuracy class: the
results stay within 3e-16 of the exact values (measured over |q| ≤ 1e4; ``np.cos`` is
within 6e-17), are exact at q = 0, and never overflow (``tan`` of a float never exceeds
about 1.6e16).

Why every block checks its positions
------------------------------------
Rotations only ever multiply by cosines and sines, so they stay finite; a position can
leave the float range only when a prismatic coordinate near ``1e308`` slides a frame
(link constants are at most ``1e150``, see :mod:`robotconf.kinematics.conventions._bounds`). Once a
position is inf or NaN, every later frame's position is too, so one check of the last
frame per block (3 numbers per sample, while they are still in cache) catches every
overflow. Only then is the culprit searched: the first frame of the first bad sample,
recomputed alone.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence

import numpy as np

from ..._errors import InvalidInputError
from ._geometry import LinkGeometry

__all__ = [
    "BLOCK_SIZE",
    "cos_sin",
    "chain_poses",
    "chain_origins",
    "chain_point",
    "chain_point_pose",
    "link_matrices",
    "kernel_bytes",
]

#: Samples per block: large enough to amortize numpy's per-call overhead, small enough
#: that state, scratch and cos/sin tables stay in a core's L2 cache.
BLOCK_SIZE = 4096

_LAST_ROW = np.array([0.0, 0.0, 0.0, 1.0])


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


def _blocks(total: int, size: int) -> Iterator[tuple[int, int]]:
    for start in range(0, total, size):
        yield start, min(start + size, total)


Emit = Callable[[int, int, int, np.ndarray], None]


def kernel_bytes(samples: int, n: int, floats: int) -> float:
    """Peak bytes a kernel call allocates for ``samples`` samples of an ``n``-link chain.

    The result (``floats`` numbers per sample), one block of scratch, and the validation
    of ``q`` before it (a boolean per coordinate). Calibrated with ``tracemalloc``
    against :meth:`Robot.frame_poses` and friends for 1 to 10⁶ samples and 3 or 6
    links: the estimate is never below the measured peak, and within 1 % of it for all
    poses of 10⁶ samples. A ``q`` that had to be converted to floats is not included.

    Parameters
    ----------
    samples, n : int
        Samples ``T`` and links ``n``.
    floats : int
        Result size per sample (``16 n`` for all poses, ``3`` for one point).

    Returns
    -------
    float
        Bytes (a float, so that huge products do not wrap).

    Examples
    --------
    >>> kernel_bytes(1_000_000, 6, 16 * 6) / 1e6  # all poses: about 768 MB of result
    775.78...
    """
    block = min(samples, BLOCK_SIZE)
    # Per-call objects (plan, views, the error-name list) take a few kB at any size.
    scratch = 8.0 * block * (30 + 4 * n) + 16384.0
    return 8.0 * samples * floats + 1.0 * samples * n + scratch


def _finite_positions(state: np.ndarray) -> bool:
    return bool(np.isfinite(state[:, 3]).all())


def _run(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    emit: Emit,
    *,
    restart: bool = False,
    block_size: int = BLOCK_SIZE,
    fields: Sequence[str] | None = None,
) -> None:
    """Compose the chain block by block, calling ``emit`` with the state after each link.

    ``emit(i, start, stop, state)`` gets the pose after link ``i`` and, with ``i = -1``,
    once more after the last link (an emitter may move the state to a point then). With
    ``restart`` every link starts from identity, so the states are the links' own
    transfer matrices. A position that overflows raises :class:`InvalidInputError`
    naming ``fields[i]`` (default ``q[i]``) of the coordinate that caused it.
    """
    plan = _Plan(links)
    total = q.shape[0]
    check = fields is not _UNCHECKED
    full = _Scratch(max(1, min(block_size, total)), len(plan.revolute))
    # An overflow is reported as an error below, not as numpy's warning first.
    with np.errstate(over="ignore", invalid="ignore"):
        _blocks_run(links, plan, full, q, emit, restart, block_size, check, fields)


def _blocks_run(
    links: Sequence[LinkGeometry | None],
    plan: _Plan,
    full: _Scratch,
    q: np.ndarray,
    emit: Emit,
    restart: bool,
    block_size: int,
    check: bool,
    fields: Sequence[str] | None,
) -> None:
    for start, stop in _blocks(q.shape[0], block_size):
        scratch = full.sized(stop - start)
        q_t = np.ascontiguousarray(q[start:stop].T)
        plan.trig(q_t, scratch.cos, scratch.sin)
        _reset(scratch.state)
        for i, g in enumerate(plan.links):
            if restart and i:
                _reset(scratch.state)
            if g is not None:
                _apply(g, i, plan, scratch, q_t)
                if restart and check and not _finite_positions(scratch.state):
                    raise _overflow(links, q, start + _first_bad(scratch.state), i, fields)
            emit(i, start, stop, scratch.state)
        emit(-1, start, stop, scratch.state)
        if check and not restart and not _finite_positions(scratch.state):
            sample = start + _first_bad(scratch.state)
            raise _overflow(links, q, sample, _first_bad_link(links, q[sample]), fields)


def _first_bad(state: np.ndarray) -> int:
    """The first sample (column) of a block whose position is not finite."""
    return int(np.flatnonzero(~np.isfinite(state[:, 3]).all(axis=0))[0])


def _first_bad_link(links: Sequence[LinkGeometry | None], q_row: np.ndarray) -> int:
    """The first link whose frame origin is not finite for one sample (n: none of them)."""
    origins = np.empty((len(links), 3))

    def emit(i: int, start: int, stop: int, state: np.ndarray) -> None:
        if i >= 0:
            origins[i] = state[:, 3, 0]

    _run(links, q_row[np.newaxis], emit, fields=_UNCHECKED)
    bad = np.flatnonzero(~np.isfinite(origins).all(axis=1))
    return int(bad[0]) if bad.size else len(links)


def _overflow(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    sample: int,
    link: int,
    fields: Sequence[str] | None,
) -> InvalidInputError:
    """The error for an overflow first seen at ``link`` (``n``: the point) in ``sample``."""
    problem = f"the frame positions overflow to inf or NaN at link {link}, sample {sample}, with"
    g = links[link] if link < len(links) else None
    if g is not None and g.joint == "P":
        field = fields[link] if fields is not None else f"q[{link}]"
        allowed = "coordinates that keep every frame position finite (|position| < 1.8e308)"
        return InvalidInputError(field, float(q[sample, link]), allowed, problem=problem)
    # Link constants are bounded, so only a prismatic coordinate can overflow a chain
    # built by robotconf; a hand-made LinkGeometry or point is named by its position.
    name, value = (f"links[{link}]", g) if link < len(links) else ("point", "the point")
    return InvalidInputError(name, value, "smaller constants (|values| well below 1e308)", problem)


# Passed as ``fields`` while the culprit is searched: no checks, so no recursion.
_UNCHECKED: list[str] = []


def _write_poses(out: np.ndarray) -> Emit:
    """An emitter that copies each link's state into ``out[:, i]`` of shape (T, n, 4, 4)."""

    def emit(i: int, start: int, stop: int, state: np.ndarray) -> None:
        block = out[start:stop]
        if i < 0:
            # The constant last row, once per block, as 4 long strided fills.
            rows = block.reshape(-1, 4, 4).transpose(1, 2, 0)[3]
            np.copyto(rows, _LAST_ROW[:, np.newaxis])
            return
        # (3, 4, B) destination view: the sample axis stays innermost for the copy.
        np.copyto(block.transpose(1, 2, 3, 0)[i, :3], state)

    return emit


def _output(out: np.ndarray | None, shape: tuple[int, ...]) -> np.ndarray:
    if out is None:
        return np.empty(shape)
    if not isinstance(out, np.ndarray) or out.shape != shape or out.dtype != np.float64:
        described = (
            f"array of shape {out.shape} and dtype {out.dtype}"
            if isinstance(out, np.ndarray)
            else type(out).__name__
        )
        allowed = f"a writable float64 array of shape {shape} (or None)"
        raise InvalidInputError("out", described, allowed, problem="wrong output:")
    return out


def chain_poses(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    *,
    out: np.ndarray | None = None,
    block_size: int = BLOCK_SIZE,
    fields: Sequence[str] | None = None,
) -> np.ndarray:
    """Cumulative poses ``M_i = A_1 ⋯ A_i`` of every link frame.

    Parameters
    ----------
    links : sequence of LinkGeometry or None, length n
        ``None`` acts as identity (inactive or null module).
    q : ndarray, shape (T, n)
        Validated coordinates.
    out : ndarray, shape (T, n, 4, 4), optional
        Preallocated float64 output (reuse it to avoid page faults in loops).
    block_size : int
        Samples per block.
    fields : sequence of str, optional
        The name of each coordinate in errors (default ``q[i]``).

    Returns
    -------
    ndarray, shape (T, n, 4, 4)
    """
    result = _output(out, (q.shape[0], q.shape[1], 4, 4))
    _run(links, q, _write_poses(result), block_size=block_size, fields=fields)
    return result


def link_matrices(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    *,
    out: np.ndarray | None = None,
    block_size: int = BLOCK_SIZE,
    fields: Sequence[str] | None = None,
) -> np.ndarray:
    """Each link's own transfer matrix ``A_i(q_i)``.

    Parameters
    ----------
    links : sequence of LinkGeometry or None, length n
    q : ndarray, shape (T, n)
    out : ndarray, shape (T, n, 4, 4), optional
    fields : sequence of str, optional
        The name of each coordinate in errors (default ``q[i]``).

    Returns
    -------
    ndarray, shape (T, n, 4, 4)
    """
    result = _output(out, (q.shape[0], q.shape[1], 4, 4))
    _run(links, q, _write_poses(result), restart=True, block_size=block_size, fields=fields)
    return result


def chain_origins(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    *,
    out: np.ndarray | None = None,
    block_size: int = BLOCK_SIZE,
    fields: Sequence[str] | None = None,
) -> np.ndarray:
    """Origins of every link frame, without building 4×4 stacks.

    Parameters
    ----------
    links : sequence of LinkGeometry or None, length n
    q : ndarray, shape (T, n)
    out : ndarray, shape (T, n, 3), optional
    fields : sequence of str, optional
        The name of each coordinate in errors (default ``q[i]``).

    Returns
    -------
    ndarray, shape (T, n, 3)
    """
    result = _output(out, (q.shape[0], q.shape[1], 3))

    def emit(i: int, start: int, stop: int, state: np.ndarray) -> None:
        if i >= 0:
            np.copyto(result[start:stop, i].T, state[:, 3])

    _run(links, q, emit, block_size=block_size, fields=fields)
    return result


def chain_point(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    point: np.ndarray,
    *,
    out: np.ndarray | None = None,
    block_size: int = BLOCK_SIZE,
    fields: Sequence[str] | None = None,
) -> np.ndarray:
    """Position of a point fixed in the last frame: ``M_n · [point, 1]``.

    Parameters
    ----------
    links : sequence of LinkGeometry or None, length n
    q : ndarray, shape (T, n)
    point : ndarray, shape (3,)
    out : ndarray, shape (T, 3), optional
    fields : sequence of str, optional
        The name of each coordinate in errors (default ``q[i]``).

    Returns
    -------
    ndarray, shape (T, 3)
    """
    result = _output(out, (q.shape[0], 3))

    def emit(i: int, start: int, stop: int, state: np.ndarray) -> None:
        if i < 0:
            _translate(state, np.empty_like(state[:, 3]), point)
            np.copyto(result[start:stop].T, state[:, 3])

    _run(links, q, emit, block_size=block_size, fields=fields)
    return result


def chain_point_pose(
    links: Sequence[LinkGeometry | None],
    q: np.ndarray,
    point: np.ndarray,
    *,
    out: np.ndarray | None = None,
    block_size: int = BLOCK_SIZE,
    fields: Sequence[str] | None = None,
) -> np.ndarray:
    """Pose of the last frame moved to a point fixed in it: ``M_n · Trans(point)``.

    Parameters
    ----------
    links : sequence of LinkGeometry or None, length n
    q : ndarray, shape (T, n)
    point : ndarray, shape (3,)
    out : ndarray, shape (T, 4, 4), optional
    fields : sequence of str, optional
        The name of each coordinate in errors (default ``q[i]``).

    Returns
    -------
    ndarray, shape (T, 4, 4)
    """
    result = _output(out, (q.shape[0], 4, 4))

    def emit(i: int, start: int, stop: int, state: np.ndarray) -> None:
        if i < 0:
            _translate(state, np.empty_like(state[:, 3]), point)
            np.copyto(result[start:stop].transpose(1, 2, 0)[:3], state)
            np.copyto(result[start:stop].transpose(1, 2, 0)[3], _LAST_ROW[:, np.newaxis])

    _run(links, q, emit, block_size=block_size, fields=fields)
    return result
