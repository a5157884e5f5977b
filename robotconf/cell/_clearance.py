"""``cell.clearance``: how far a robot is from touching anything, and what it nearly touches."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import one_line
from ._answers import Clearance
from ._pairs import PairDistances, measure_pairs

if TYPE_CHECKING:
    from ._cell import Cell

__all__ = ["clearance", "least"]


def least(pairs: PairDistances) -> tuple[np.ndarray, np.ndarray]:
    """Each sample's smallest distance and the column it is in."""
    if pairs.distance.shape[1] == 0:
        t = pairs.distance.shape[0]
        return np.full(t, np.inf), np.zeros(t, dtype=np.int64)
    column = np.argmin(pairs.distance, axis=1)
    return pairs.distance[np.arange(len(column)), column], column


def clearance(cell: Cell, robot: Any, q: Any, others: Any) -> Clearance:
    """The smallest signed distance of ``robot`` to the objects, itself and other robots.

    Parameters
    ----------
    cell : Cell
    robot : str or None
        The robot (may be left out when the cell has one).
    q : array-like, shape (n,) or (T, n), optional
        Its coordinates; default its own ``q``.
    others : dict, optional
        Other robots' coordinates, ``{name: q (n,) or (T, n)}``; default their own ``q``.

    Returns
    -------
    Clearance
        Scalars for one configuration, arrays of T for many; every distance exact
        (docs/cell.md, "Distances").

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> cell.add(rc.Sphere(5, pose=rc.pose([70, 0, 40]), name="ball"))
    'ball'
    >>> c = cell.clearance("arm", [0, 0, 0])
    >>> round(c.distance, 9), c.link, c.other   # 20 − 5 − 3.6 above the end effector
    (11.4, 'link 3', 'ball')
    >>> cell.clearance("arm", [[0, 0, 0], [0, -0.3, 0]]).distance.round(3)
    array([11.4  , -5.399])
    """
    entry = cell.robot_entry(robot)
    assert entry.robot is not None
    array = cell.coordinates(entry.name, entry.robot.q if q is None else q)
    samples = array.shape[0]
    given = {entry.name: array}
    if others is not None:
        if not isinstance(others, dict):
            raise InvalidInputError("others", one_line(others), "{robot name: q}")
        for name, value in others.items():
            other = cell.coordinates(cell.robot_entry(name).name, value)
            if other.shape[0] not in (1, samples):
                raise InvalidInputError(
                    f"others[{name!r}]", f"<{other.shape[0]} rows>", f"1 or {samples} rows"
                )
            given[name] = np.broadcast_to(other, (samples, other.shape[1]))
    obstacles, names = cell.obstacles()
    pairs = measure_pairs(
        cell._robot_entries(), cell._world(), obstacles, names, given, samples, focus=(entry.name,)
    )
    distance, column = least(pairs)
    if pairs.distance.shape[1] == 0:
        labels: tuple[tuple[str, ...], ...] = (("",) * samples,) * 3
    else:
        labels = tuple(
            tuple(np.array(x, dtype=object)[column]) for x in (pairs.link, pairs.other, pairs.kind)
        )
    if np.ndim(q) == 1 or q is None:
        return Clearance(
            float(distance[0]), labels[0][0], labels[1][0], labels[2][0], entry.name, cell.unit
        )
    return Clearance(distance, labels[0], labels[1], labels[2], entry.name, cell.unit)
