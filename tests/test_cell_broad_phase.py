"""``cell.check``'s broad phase changes nothing: the same answer as measuring every pair.

The brute force measures every pair at every sample exactly (each object's own kernel,
segment–segment for capsule pairs) and is put in place of the pruned measurement, so
both answers come from the same contact and least-clearance code. Scenes are random:
boxes, cylinders, spheres and a mesh, one or two robots, margins of 0 and more, objects
placed to touch a link exactly, and motions that rest at their closest point (ties).
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.cell import _check
from robotconf.cell._pairs import PairDistances, cell_capsules, measure_pairs
from robotconf.cell.distance import segment_segment_distance
from robotconf.programs import PTP, Program, Wait

pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")


def _every_pair(robots, world, obstacles, object_names, q, samples, margin=-np.inf, **options):
    """``measure_pairs`` without pruning: every pair at every sample, exactly."""
    focus = options.get("focus") or tuple(robots)
    capsules = {}
    for name, entry in robots.items():
        caps = cell_capsules(entry, world[name], q.get(name, entry.robot.q[np.newaxis]))
        capsules[name] = np.broadcast_to(caps, (samples, *caps.shape[1:]))
    columns, labels = [], []
    for name in focus:
        entry, caps = robots[name], capsules[name]
        model = entry.links
        for i, link in enumerate(model.names):
            for k, obj in enumerate(object_names):
                column = np.full(samples, np.inf)
                if not (model.static[i] and obj in entry.mount):
                    index = np.full(samples, k)
                    radius = np.full(samples, model.radii[i])
                    column = obstacles.exact(caps[:, i, 0], caps[:, i, 1], radius, index)
                columns.append(column)
                labels.append((name, link, obj, "object"))
        for i, j in model.self_pairs:
            columns.append(_capsules_apart(caps[:, i], model.radii[i], caps[:, j], model.radii[j]))
            labels.append((name, model.names[i], model.names[j], "self"))
    names = list(robots)
    for x, first in enumerate(names):
        for second in names[x + 1 :]:
            m1, m2 = robots[first].links, robots[second].links
            for i, l1 in enumerate(m1.names):
                for j, l2 in enumerate(m2.names):
                    columns.append(
                        _capsules_apart(
                            capsules[first][:, i], m1.radii[i], capsules[second][:, j], m2.radii[j]
                        )
                    )
                    labels.append((first, l1, f"{second}/{l2}", "robot"))
    robot, link, other, kind = (tuple(x) for x in zip(*labels, strict=True))
    return PairDistances(np.stack(columns, axis=1), robot, link, other, kind)


def _capsules_apart(first, r1, second, r2):
    apart = segment_segment_distance(first[:, 0], first[:, 1], second[:, 0], second[:, 1])
    return apart - (r1 + r2)


def _tetrahedron(size, pose):
    vertices = size * np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    return rc.Mesh(vertices, faces, pose=pose)


def _random_cell(seed: int, two_robots: bool) -> rc.Cell:
    rng = np.random.default_rng(seed)
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", rc.preset("paper"), mount="table")
    cell.add(rc.Box([200, 200, 10], pose=rc.pose([0, 0, -5]), name="table"))
    if two_robots:
        cell.add_robot("other", rc.preset("paper"), base=rc.pose([110, 0, 0], [0, 0, np.pi]))
    for k in range(9):
        pose = rc.pose(rng.uniform([-70, -70, 0], [70, 70, 80]), rng.uniform(-1, 1, 3))
        kind = k % 4
        if kind == 0:
            cell.add(rc.Box(rng.uniform(4, 25, 3), pose=pose))
        elif kind == 1:
            cell.add(rc.Cylinder(rng.uniform(2, 8), rng.uniform(5, 30), pose=pose))
        elif kind == 2:
            cell.add(rc.Sphere(rng.uniform(2, 8), pose=pose))
        else:
            cell.add(_tetrahedron(rng.uniform(8, 20), pose))
    return cell


def _touching_sphere(cell: rc.Cell, q: np.ndarray, gap: float) -> None:
    """A sphere ``gap`` beyond the end of the arm's last capsule at ``q`` (0: touching)."""
    segments, radii = cell.link_capsules("arm", q[np.newaxis])
    a, b = segments[0, -1]
    direction = (b - a) / np.linalg.norm(b - a)
    radius = 3.0
    cell.add(rc.Sphere(radius, pose=rc.pose(b + direction * (radii[-1] + radius + gap))))


def _program(cell: rc.Cell, seed: int) -> Program:
    rng = np.random.default_rng(seed)
    moves = [PTP(q=rng.uniform(-1.5, 1.5, 3)) for _ in range(3)]
    rest = moves[1].q
    moves.insert(2, Wait(0.05))  # resting at one configuration: the least distance ties
    return Program(cell.robot("arm"), moves, joint_speed=2.0, joint_accel=6.0), rest


def _both(cell, motion, monkeypatch, **options):
    pruned = cell.check(motion, "arm", **options)
    with monkeypatch.context() as patched:
        patched.setattr(_check, "measure_pairs", _every_pair)
        brute = cell.check(motion, "arm", **options)
    return pruned, brute


def _same(pruned, brute):
    assert pruned.contacts == brute.contacts
    assert pruned.more == brute.more
    assert pruned.min_clearance == brute.min_clearance
    assert pruned.min_time == brute.min_time
    assert pruned.min_pair == brute.min_pair


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("margin", [0.0, 2.0, 40.0])
def test_the_broad_phase_gives_the_brute_force_answer(seed, margin, monkeypatch):
    cell = _random_cell(seed, two_robots=seed % 2 == 1)
    program, rest = _program(cell, 100 + seed)
    _touching_sphere(cell, rest, gap=[0.0, 1e-9, -1e-9][seed % 3])
    pruned, brute = _both(cell, program, monkeypatch, margin=margin, dt=0.002)
    _same(pruned, brute)


def _ur5_cell(seed: int) -> rc.Cell:
    """A UR5 with a gripper (7 capsules, 14 own pairs) among objects that may be far."""
    rng = np.random.default_rng(seed)
    cell = rc.Cell(unit="m")
    gripper = rc.Tool(tcp=rc.pose([0, 0, 0.12]), name="gripper")
    cell.add_robot("arm", rc.preset("ur5"), tool=gripper, radius=0.04)
    for k in range(8):
        angle = rng.uniform(0, 2 * np.pi)
        far = rng.uniform(0.5, 1.2)
        pose = rc.pose([far * np.cos(angle), far * np.sin(angle), rng.uniform(-0.2, 0.6)])
        kind = k % 4
        if kind == 0:
            cell.add(rc.Box(rng.uniform(0.05, 0.2, 3), pose=pose))
        elif kind == 1:
            cell.add(rc.Cylinder(rng.uniform(0.02, 0.08), rng.uniform(0.1, 0.3), pose=pose))
        elif kind == 2:
            cell.add(rc.Sphere(rng.uniform(0.02, 0.1), pose=pose))
        else:
            cell.add(_tetrahedron(rng.uniform(0.05, 0.2), pose))
    return cell


@pytest.mark.parametrize("seed", range(8))
def test_own_links_and_objects_compete_for_the_least_clearance(seed, monkeypatch):
    cell = _ur5_cell(seed)
    rng = np.random.default_rng(200 + seed)
    moves = [PTP(q=rng.uniform(-2.5, 2.5, 6)) for _ in range(3)]
    program = Program(cell.robot("arm"), moves, joint_speed=2.0, joint_accel=6.0)
    pruned, brute = _both(cell, program, monkeypatch, margin=[0.0, 0.01][seed % 2], dt=0.004)
    _same(pruned, brute)


def test_a_clear_motion_keeps_its_least_pair(monkeypatch):
    cell = _random_cell(11, two_robots=False)
    robot = cell.robot("arm")
    rest = np.array([0.4, -0.2, 0.3])
    _touching_sphere(cell, rest, gap=5.0)
    motion = Program(robot, [PTP(q=rest), Wait(0.1), PTP(q=[-0.4, 0.1, -0.3])], start=rest)
    pruned, brute = _both(cell, motion, monkeypatch, dt=0.002)
    _same(pruned, brute)
    assert pruned.min_clearance > -np.inf


def test_the_brute_force_measures_what_clearance_measures():
    """The stand-in is itself right: each sample's least distance as ``cell.clearance``."""
    cell = _random_cell(3, two_robots=True)
    program, _ = _program(cell, 5)
    motion = program.simulate(0.01)
    obstacles, names = cell.obstacles()
    given = (cell._robot_entries(), cell._world(), obstacles, names, {"arm": motion.q})
    brute = _every_pair(*given, len(motion.t), focus=("arm",))
    pruned = measure_pairs(*given, len(motion.t), focus=("arm",))
    assert brute.distance.shape == pruned.distance.shape
    assert np.array_equal(brute.distance.min(axis=1), cell.clearance("arm", motion.q).distance)
    finite = np.isfinite(pruned.distance)
    assert np.array_equal(pruned.distance[finite], brute.distance[finite])
