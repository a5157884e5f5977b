"""Benchmark: workspace of a 6-module robot, 10⁶ samples.

Target: 10⁶ samples of a 6-module robot in well under 5 s. Also prints the
ratio to a simple reference in the same process: a Python loop calling
``robot.end_effector`` on one configuration at a time, timed on a subset and
extrapolated to 10⁶ samples (running it in full would take minutes).

Run: ``PYTHONPATH=. python benchmarks/bench_workspace.py`` (pin one core with
``taskset -c 0`` and ``OMP_NUM_THREADS=1`` for a fair figure).
"""

from __future__ import annotations

import time

import numpy as np

import robotconf as rc

TARGET_S = 5.0
SAMPLES = 1_000_000
LOOP_SUBSET = 5_000


def ur5_like() -> rc.Robot:
    """Six revolute standard-DH rows with UR5-like dimensions (m)."""
    rows = [
        (0, 0.089159, 0, np.pi / 2, "R"),
        (0, 0, -0.425, 0, "R"),
        (0, 0, -0.39225, 0, "R"),
        (0, 0.10915, 0, np.pi / 2, "R"),
        (0, 0.09465, 0, -np.pi / 2, "R"),
        (0, 0.0823, 0, 0, "R"),
    ]
    return rc.Robot.from_dh(rows, name="UR5-like")


def six_modules() -> rc.Robot:
    kinds = ["Rz", "Ry", "Ry", "Rx", "Ty", "Rz"]
    modules = [rc.Module(k, a=(0.1 * (i % 3), 0.05, 0.2)) for i, k in enumerate(kinds)]
    return rc.Robot(modules, end_effector=(0.1, 0.0, 0.05), name="six modules")


def best_of(func, repeat: int = 5) -> float:  # type: ignore[no-untyped-def]
    """Best wall time in seconds over ``repeat`` runs (after one warm-up)."""
    func()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return min(times)


def reference_loop(robot: rc.Robot, ranges: np.ndarray, count: int) -> float:
    """Seconds per sample of the naive approach: one end_effector call per sample."""
    rng = np.random.default_rng(0)
    q = ranges[:, 0] + (ranges[:, 1] - ranges[:, 0]) * rng.random((count, robot.n))
    start = time.perf_counter()
    for row in q:
        robot.end_effector(row)
    return (time.perf_counter() - start) / count


def main() -> None:
    print(f"workspace, {SAMPLES:,} random samples (target < {TARGET_S:g} s)")
    for robot in (ur5_like(), six_modules()):
        ranges = np.array(
            [(-np.pi, np.pi) if t == "revolute" else (-0.5, 0.5) for t in robot.joint_types]
        )
        vectorized = best_of(
            lambda robot=robot, ranges=ranges: rc.workspace(
                robot, SAMPLES, ranges, seed=0, progress=False
            )
        )
        per_sample = reference_loop(robot, ranges, LOOP_SUBSET)
        loop = per_sample * SAMPLES
        print(
            f"  {robot.name:12s} {robot.n} modules: {vectorized:6.3f} s "
            f"({vectorized / SAMPLES * 1e9:5.0f} ns/sample)  |  Python loop of single-q "
            f"end_effector: {per_sample * 1e6:6.1f} µs/sample → {loop:6.1f} s extrapolated "
            f"→ {loop / vectorized:5.0f}× faster  |  " + ("OK" if vectorized < TARGET_S else "SLOW")
        )
    grid = best_of(
        lambda: rc.workspace(
            ur5_like(), SAMPLES, [(-np.pi, np.pi)] * 6, method="grid", progress=False
        )
    )
    print(f"  grid method, 10^6 points (10 per joint): {grid:.3f} s")


if __name__ == "__main__":
    main()
