"""Every pair that can collide in a cell, measured over time in one vectorized pass.

The pairs: each robot's links against every object (a robot's base links — those no
joint moves — not against the objects it is mounted on), each robot's links against its
own non-neighbouring links (:class:`~robotconf.cell._links.LinkModel`), and every two
robots' links. Robots without given coordinates stand at their own ``q``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._budget import check_memory
from ._entries import RobotEntry
from .distance import Obstacles, capsule_obstacle_distances, capsule_pair_distances

__all__ = ["PairDistances", "measure_pairs", "cell_capsules"]


@dataclass
class PairDistances:
    """Signed distances of every pair at every sample.

    Attributes
    ----------
    distance : ndarray, shape (T, K)
        ``inf`` where a pair is farther than the cutoff (see
        :func:`robotconf.cell.distance.capsule_obstacle_distances`).
    robot, link, other, kind : tuple of str, length K
        Column labels: the robot and its link, what it meets (an object's name, the same
        robot's link, or ``"robot/link k"``) and the kind (``"object"``, ``"self"`` or
        ``"robot"``).
    """

    distance: np.ndarray
    robot: tuple[str, ...]
    link: tuple[str, ...]
    other: tuple[str, ...]
    kind: tuple[str, ...]


def cell_capsules(entry: RobotEntry, world: np.ndarray, q: np.ndarray) -> np.ndarray:
    """A robot's capsules in the cell's frame, (T, L, 2, 3), for q (T, n)."""
    assert entry.links is not None
    local = entry.links.capsules(q)
    turned = local.reshape(-1, 3) @ world[:3, :3].T  # one (N, 3)·(3, 3) product
    return (turned + world[:3, 3]).reshape(local.shape)


def measure_pairs(
    robots: dict[str, RobotEntry],
    world: dict[str, np.ndarray],
    obstacles: Obstacles,
    object_names: tuple[str, ...],
    q: dict[str, np.ndarray],
    samples: int,
    margin: float = -np.inf,
    focus: tuple[str, ...] | None = None,
    per_sample: bool = True,
) -> PairDistances:
    """Distances of every pair at ``samples`` samples (q per robot: (T, n), or its own).

    ``focus`` keeps only the pairs that involve these robots; ``per_sample`` False
    measures exactly only the motion's least distance and the pairs closer than
    ``margin`` (see :func:`~robotconf.cell.distance.capsule_obstacle_distances`).
    """
    chosen = tuple(robots) if focus is None else focus
    links_total = sum(len(e.links.names) for e in robots.values() if e.links is not None)
    check_memory(
        "samples",
        samples,
        8.0 * samples * links_total * (len(object_names) + links_total) * 6,
        "fewer samples (a larger dt) or fewer objects",
    )
    capsules = {}
    for name, entry in robots.items():
        assert entry.robot is not None
        given = q.get(name, entry.robot.q[np.newaxis])
        caps = cell_capsules(entry, world[name], given)
        capsules[name] = (
            np.broadcast_to(caps, (samples, *caps.shape[1:])) if len(caps) == 1 else caps
        )
    columns: list[np.ndarray] = []
    labels: list[tuple[str, str, str, str]] = []
    names = list(robots)
    for name in chosen:
        entry = robots[name]
        model = entry.links
        assert model is not None
        if len(object_names):
            skip = np.zeros((len(model.names), len(object_names)), dtype=bool)
            for k, obj in enumerate(object_names):
                skip[:, k] = model.static & (obj in entry.mount)
            env = capsule_obstacle_distances(
                capsules[name], model.radii, obstacles, margin, per_sample, skip
            )
            columns.append(env.reshape(samples, -1))
            labels += [(name, link, obj, "object") for link in model.names for obj in object_names]
        if model.self_pairs:
            pairs = np.array(model.self_pairs)
            own = capsule_pair_distances(
                capsules[name], model.radii, capsules[name], model.radii, pairs, margin, per_sample
            )
            columns.append(own)
            labels += [(name, model.names[i], model.names[j], "self") for i, j in model.self_pairs]
    for x, first in enumerate(names):
        for second in names[x + 1 :]:
            if first not in chosen and second not in chosen:
                continue
            m1, m2 = robots[first].links, robots[second].links
            assert m1 is not None and m2 is not None
            both = capsule_pair_distances(
                capsules[first], m1.radii, capsules[second], m2.radii, None, margin, per_sample
            )
            columns.append(both.reshape(samples, -1))
            labels += [(first, l1, f"{second}/{l2}", "robot") for l1 in m1.names for l2 in m2.names]
    distance = np.concatenate(columns, axis=1) if columns else np.full((samples, 0), np.inf)
    robot, link, other, kind = (
        (tuple(x) for x in zip(*labels, strict=True)) if labels else ((), (), (), ())
    )
    return PairDistances(distance, robot, link, other, kind)
