"""The vectorized kernel that composes chains of links over many samples.

The pose ``[R | p]`` of a chain is held for a block of ``B`` samples as an array ``S`` of
shape (3, 4, B): ``S[r, k]`` is row ``r`` of column ``k`` (columns 0–2 are ``R``, column 3
is ``p``), contiguous over samples. Right-multiplying by an elementary rotation changes
just two columns and a translation just ``p``, so writing those few products out costs far
less than stacking 4×4 matrices and calling ``matmul``, and the constant last row is never
computed. Samples go in blocks small enough to stay in cache; each frame is written
straight into the caller's preallocated output with one copy.

Why every block checks its positions
------------------------------------
Rotations only ever multiply by cosines and sines, so they stay finite; a position can
leave the float range only when a prismatic coordinate near ``1e308`` slides a frame
(link constants are at most ``1e150``, see
:mod:`robotconf.kinematics.conventions._bounds`). Once a position is inf or NaN, every
later frame's position is too, so one check of the last frame per block (3 numbers per
sample, while they are still in cache) catches every overflow. Only then is the culprit
searched: the first frame of the first bad sample, recomputed alone.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence

import numpy as np

from ..._errors import InvalidInputError
from ._block import _apply, _Plan, _reset, _Scratch, _translate, cos_sin
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
