"""The answer of :func:`~robotconf.ik`: joint values, and why the solver stopped."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["IKResult", "REASONS"]

#: Every reason a solve can end with.
REASONS = ("converged", "unreachable", "singular", "joint limit", "iteration limit")


@dataclass(frozen=True, repr=False, eq=False)
class IKResult:
    """The joint values found for one target or for T targets, and why the solver stopped.

    For one target every field is a single value; for T targets (``target`` of shape
    (T, 3) or (T, 4, 4)) each is an array (or a tuple of text) with a leading T axis, and
    ``result[i]`` is the single result of target i.

    Attributes
    ----------
    q : ndarray, shape (n,) or (T, n)
        The best coordinates found (radians or length units): a solution where
        ``success``, else the closest configuration found.
    success : bool or ndarray of bool, shape (T,)
        Whether ``q`` meets the tolerances.
    position_error : float or ndarray, shape (T,)
        Distance from the end effector to the target point (length units), over the
        position rows the mask keeps; NaN when it keeps none.
    orientation_error : float or ndarray, shape (T,)
        Angle still to turn (rad): the length of the rotation vector of
        ``R_target·Rᵀ`` over the turn rows the mask keeps; NaN when it keeps none (mode
        ``"position"``).
    iterations : int or ndarray of int, shape (T,)
        Steps taken, summed over the runs tried for the target: its starts within the
        ranges up to the first that converges and, where all of them fail on a robot
        with clipped joints, the same starts without them (so up to
        ``2 · seeds · max_iterations``).
    reason : str or tuple of str
        One of ``"converged"``, ``"unreachable"``, ``"singular"``, ``"joint limit"``,
        ``"iteration limit"``.
    message : str or tuple of str
        The reason in a sentence, with its numbers.
    distance_to_reach : float or ndarray, shape (T,)
        0 unless ``reason`` is ``"unreachable"``; then how far the target lies outside
        the reach shell (proved), or, when the search only failed to get closer, the
        position error left at the closest configuration found (see docs/ik.md).
    """

    q: np.ndarray
    success: Any
    position_error: Any
    orientation_error: Any
    iterations: Any
    reason: Any
    message: Any
    distance_to_reach: Any

    @property
    def batched(self) -> bool:
        """Whether this holds T targets."""
        return np.ndim(self.q) == 2

    def __len__(self) -> int:
        if not self.batched:
            raise TypeError("a single IK result has no length; index only T results")
        return int(self.q.shape[0])

    def __getitem__(self, i: int) -> IKResult:
        """The result of target ``i`` alone (only for T targets)."""
        if not self.batched:
            raise TypeError("a single IK result cannot be indexed")
        return IKResult(
            q=self.q[i].copy(),
            success=bool(self.success[i]),
            position_error=float(self.position_error[i]),
            orientation_error=float(self.orientation_error[i]),
            iterations=int(self.iterations[i]),
            reason=self.reason[i],
            message=self.message[i],
            distance_to_reach=float(self.distance_to_reach[i]),
        )

    def __repr__(self) -> str:
        if self.batched:
            counts = {r: self.reason.count(r) for r in REASONS if r in self.reason}
            summary = ", ".join(f"{count} {name}" for name, count in counts.items())
            return f"IKResult({len(self)} targets: {summary})"
        q = np.array2string(np.asarray(self.q), precision=6, separator=", ")
        return f"IKResult({self.reason!r}, q={q}, message={self.message!r})"

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text(repr(self))


def single_or_batch(batched: bool, **fields: Any) -> IKResult:
    """An :class:`IKResult` from (T,)-arrays: kept for T targets, unwrapped for one."""
    if batched:
        fields["reason"] = tuple(fields["reason"])
        fields["message"] = tuple(fields["message"])
        return IKResult(**fields)
    return IKResult(
        q=fields["q"][0],
        success=bool(fields["success"][0]),
        position_error=float(fields["position_error"][0]),
        orientation_error=float(fields["orientation_error"][0]),
        iterations=int(fields["iterations"][0]),
        reason=fields["reason"][0],
        message=fields["message"][0],
        distance_to_reach=float(fields["distance_to_reach"][0]),
    )
