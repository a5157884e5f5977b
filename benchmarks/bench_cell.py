"""Benchmark: the work cell's contact check and reach map, side by side with coal.

1. ``cell.check`` of a 10 000-sample UR5 program (PTP moves at 1 kHz) with a tool:
   7 capsules against 20 objects (boxes, cylinders, spheres), plus the robot's own
   non-neighbouring link pairs, in two scenes: a work cell (a pick-and-place cycle over a
   table with fences, posts, fixtures, bins and sensors, one approach too low) and a
   stress scene (random sweeps through a ring of objects, about 40 % of the samples in
   contact). Targets: ≤ 50 ms, and ≥ 10× the reference.
   The reference is coal (dev-only, not a dependency of robotconf), run the way a
   per-sample loop runs it: the pairs' ``coal.ComputeDistance`` functors built once
   (the shape pair's dispatch resolved), then, per sample, the 7 capsule transforms set
   and one call per pair (the same pairs robotconf checks); GJK/EPA tolerances 1e-10.
   It measures every pair at every sample, which a per-sample loop must for each
   sample's least clearance; its answers are compared sample by sample with
   ``cell.clearance`` (robotconf's per-sample query). In the stress scene they differ
   only where coal's EPA fails on a penetrating cylinder (tests/test_cell_distance.py).
2. ``cell.reach_map`` of 8 000 voxels (20 × 20 × 20) for the paper arm with all
   closed-form branches, and the time of ``rc.ik_all`` alone on the same voxels (the
   reach map calls it once per voxel). Target: ≤ 2 s.

The CPU time is printed beside the wall time: on a shared machine the wall time also
counts other processes. Run: ``PYTHONPATH=. python benchmarks/bench_cell.py``.
"""

from __future__ import annotations

import time
import warnings

import numpy as np

import robotconf as rc
from robotconf.programs import PTP, Program

DT = 1e-3
CHECK_TARGET_S = 0.050
RATIO_TARGET = 10.0
MAP_TARGET_S = 2.0


def work_cell() -> rc.Cell:
    """A UR5 with a gripper on a table, fenced, with fixtures, bins, posts, sensors (m)."""
    cell = rc.Cell(unit="m")
    gripper = rc.Tool(tcp=rc.pose([0, 0, 0.12]), name="gripper")
    cell.add_robot("ur5", rc.preset("ur5"), tool=gripper, radius=0.04, mount="table")
    cell.add(rc.Box([2.2, 2.0, 0.04], pose=rc.pose([0.2, 0, -0.02]), name="table"))
    for k, (x, y) in enumerate([(1.3, 0), (-0.9, 0), (0.2, 1.0), (0.2, -1.0)]):
        size = [0.02, 2.0, 1.2] if k < 2 else [2.2, 0.02, 1.2]
        cell.add(rc.Box(size, pose=rc.pose([x, y, 0.6]), name=f"fence{k + 1}"))
    for k, (x, y) in enumerate([(1.2, 0.9), (1.2, -0.9), (-0.8, 0.9), (-0.8, -0.9)]):
        cell.add(rc.Cylinder(0.03, 1.2, pose=rc.pose([x, y, 0.6]), name=f"post{k + 1}"))
    spots = [(0.6, 0.35), (0.6, -0.35), (0.75, 0.0), (0.45, 0.45), (0.45, -0.45), (0.8, 0.3)]
    for k, (x, y) in enumerate(spots):
        cell.add(rc.Box([0.1, 0.1, 0.08], pose=rc.pose([x, y, 0.04]), name=f"fixture{k + 1}"))
    cell.add(rc.Box([0.3, 0.2, 0.15], pose=rc.pose([0.0, 0.45, 0.075]), name="bin1"))
    cell.add(rc.Box([0.3, 0.2, 0.15], pose=rc.pose([0.0, -0.45, 0.075]), name="bin2"))
    for k, (x, y, z) in enumerate([(1.2, 0.5, 1.1), (1.2, -0.5, 1.1), (-0.8, 0.0, 1.1)]):
        cell.add(rc.Sphere(0.05, pose=rc.pose([x, y, z]), name=f"sensor{k + 1}"))
    return cell


def work_motion(cell: rc.Cell):
    """Pick and place over the fixtures and into the bins (PTP, 1 kHz, 10 000 samples);
    one approach goes too low and puts the gripper into fixture 3."""
    down = np.diag([1.0, -1.0, -1.0])
    points = [
        [0.6, 0.35, 0.25],
        [0.6, 0.35, 0.14],
        [0.6, 0.35, 0.25],
        [0.0, 0.45, 0.35],
        [0.75, 0.0, 0.3],
        [0.75, 0.0, 0.1],
        [0.75, 0.0, 0.3],
        [0.0, -0.45, 0.35],
        [0.6, -0.35, 0.2],
    ]
    robot = cell.robot("ur5")
    tcp_robot = robot.with_end_effector(robot.end_effector_point + [0, 0, 0.12])
    previous = None
    moves = []
    for point in points:
        target = np.eye(4)
        target[:3, :3], target[:3, 3] = down, point
        found = rc.ik_all(tcp_robot, target)
        rows = found.q[found.within_limits]
        q = rows[0] if previous is None else rows[np.argmin(np.abs(rows - previous).sum(axis=1))]
        moves.append(PTP(q=q))
        previous = q
    return _sampled(robot, moves[1:], start=moves[0].q)


def _sampled(robot: rc.Robot, moves, start=None):
    prog = Program(robot, moves, joint_speed=1.0, joint_accel=3.0, start=start)
    scale = prog.duration / (9999 * DT)  # stretch the program to exactly 10 000 samples
    prog = Program(robot, moves, joint_speed=scale, joint_accel=3.0 * scale**2, start=start)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return prog.simulate(DT)


def sweep_cell() -> rc.Cell:
    """Stress: 20 objects on a ring through the UR5's reach (m)."""
    cell = rc.Cell(unit="m")
    gripper = rc.Tool(tcp=rc.pose([0, 0, 0.12]), name="gripper")
    cell.add_robot("ur5", rc.preset("ur5"), tool=gripper, radius=0.04)
    rng = np.random.default_rng(7)
    for k in range(20):
        angle = 2 * np.pi * k / 20
        centre = [0.75 * np.cos(angle), 0.75 * np.sin(angle), rng.uniform(-0.1, 0.5)]
        pose = rc.pose(centre, rng.uniform(-0.5, 0.5, 3))
        kind = k % 3
        if kind == 0:
            cell.add(rc.Box(rng.uniform(0.05, 0.2, 3), pose=pose))
        elif kind == 1:
            cell.add(rc.Cylinder(rng.uniform(0.03, 0.08), rng.uniform(0.1, 0.3), pose=pose))
        else:
            cell.add(rc.Sphere(rng.uniform(0.03, 0.1), pose=pose))
    return cell


def sweep_motion(cell: rc.Cell):
    """Random PTP sweeps through the ring: about 40 % of the samples in contact."""
    rng = np.random.default_rng(3)
    return _sampled(cell.robot("ur5"), [PTP(q=rng.uniform(-1.5, 1.5, 6)) for _ in range(6)])


def ours(cell: rc.Cell, motion, repeats: int = 7):
    """Best and median wall time, the best CPU time (s), and the result."""
    times, cpu = [], []
    for _ in range(repeats):
        start, started = time.perf_counter(), time.process_time()
        result = cell.check(motion)
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - started)
    return min(times), float(np.median(times)), min(cpu), result


def _coal_shape(coal, shape):
    if shape.kind == "box":
        return coal.Box(*shape.size)
    if shape.kind == "cylinder":
        return coal.Cylinder(shape.radius, shape.length)
    return coal.Sphere(shape.radius)


def _capsule_transform(coal, a, b):
    axis = b - a
    length = float(np.linalg.norm(axis))
    z = axis / length if length > 0 else np.array([0.0, 0.0, 1.0])
    helper = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(z, helper)
    x /= np.linalg.norm(x)
    return coal.Transform3s(np.column_stack([x, np.cross(z, x), z]), 0.5 * (a + b)), length


def reference_loop(cell: rc.Cell, motion):
    """coal, one ComputeDistance call per pair per sample: (seconds, least clearance (T,))."""
    import coal

    segments, radii = cell.link_capsules("ur5", motion.q)  # the same capsules as ours
    lengths = np.linalg.norm(segments[0, :, 1] - segments[0, :, 0], axis=1)
    capsules = [
        coal.Capsule(r, max(length, 1e-12)) for r, length in zip(radii, lengths, strict=True)
    ]
    request = coal.DistanceRequest()
    request.gjk_tolerance = request.epa_tolerance = 1e-10
    objects = [
        (_coal_shape(coal, s), coal.Transform3s(cell.pose_of(n)[:3, :3], cell.pose_of(n)[:3, 3]))
        for n, s in cell.objects.items()
    ]
    self_pairs = cell.robot_entry("ur5").links.self_pairs
    entry = cell.robot_entry("ur5")
    mounted = [name in entry.mount for name in cell.objects]
    env = [
        (i, coal.ComputeDistance(capsules[i], shape), placed)
        for i in range(len(capsules))
        for (shape, placed), on in zip(objects, mounted, strict=True)
        if not (on and entry.links.static[i])  # a base link on what it stands on
    ]
    own = [(i, j, coal.ComputeDistance(capsules[i], capsules[j])) for i, j in self_pairs]
    result = coal.DistanceResult()
    least = np.empty(len(motion.t))
    start = time.perf_counter()
    for k in range(len(motion.t)):
        placed = [_capsule_transform(coal, a, b)[0] for a, b in segments[k]]
        best = np.inf
        for i, functor, where in env:
            result.clear()
            best = min(best, functor(placed[i], where, request, result))
        for i, j, functor in own:
            result.clear()
            best = min(best, functor(placed[i], placed[j], request, result))
        least[k] = best
    return time.perf_counter() - start, least


def reach_map_timing():
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", rc.preset("paper"), mount="table")
    cell.add(rc.Box([200, 200, 10], pose=rc.pose([0, 0, -5]), name="table"))
    cell.add(rc.Box([20, 20, 40], pose=rc.pose([40, 30, 20]), name="fixture"))
    region = [(-76, -76, -56), (76, 76, 96)]  # 20 × 20 × 20 voxels, 8 mm apart
    start = time.perf_counter()
    rmap = cell.reach_map("arm", region, 8)
    total = time.perf_counter() - start
    start = time.perf_counter()
    for point in rmap.points:
        rc.ik_all(cell.robot("arm"), point)
    alone = time.perf_counter() - start
    return total, alone, rmap


def check_scene(title: str, cell: rc.Cell, motion) -> None:
    links = len(cell.link_names("ur5"))
    pairs = len(cell.robot_entry("ur5").links.self_pairs)
    print(
        f"cell.check, {title}: UR5 + gripper, {links} capsules, {len(cell.objects)} objects, "
        f"{pairs} self pairs, {motion.t.size} samples"
    )
    best, median, cpu, result = ours(cell, motion)
    print(
        f"  robotconf cell.check: best {best * 1e3:.1f} ms, median {median * 1e3:.1f} ms, "
        f"CPU {cpu * 1e3:.1f} ms (target ≤ {CHECK_TARGET_S * 1e3:.0f} ms); "
        f"{len(result)} contact intervals, least clearance {result.min_clearance:.4f} m"
    )
    try:
        seconds, least = reference_loop(cell, motion)
    except ImportError:
        print("  coal is not installed (pip install -e '.[bench]'): no reference")
        return
    per_sample = cell.clearance("ur5", motion.q).distance
    gap = np.abs(least - per_sample)
    print(
        f"  coal per-sample loop (ComputeDistance per pair): {seconds:.2f} s; "
        f"ratio {seconds / best:.0f}× (target ≥ {RATIO_TARGET:.0f}×)"
    )
    print(
        f"  least clearance per sample, robotconf vs coal: max difference {gap.max():.2e} m "
        f"({np.count_nonzero(gap > 1e-9)} of {gap.size} samples differ by more than 1e-9)"
    )


def main() -> None:
    cell = work_cell()
    check_scene("a work cell", cell, work_motion(cell))
    cell = sweep_cell()
    check_scene("stress, sweeping through 20 objects", cell, sweep_motion(cell))
    total, alone, rmap = reach_map_timing()
    print(
        f"cell.reach_map: {len(rmap.points)} voxels, all branches: {total:.2f} s "
        f"(target ≤ {MAP_TARGET_S:.0f} s); rc.ik_all alone on the voxels: {alone:.2f} s; "
        f"{int(rmap.reachable.sum())} voxels reachable"
    )


if __name__ == "__main__":
    main()
