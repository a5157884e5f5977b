"""Speed of the kinematics kernel against simple references, in one process.

Run ``python benchmarks/bench_kinematics.py`` (``--quick`` for a short run). For a
6-module robot and T = 10⁴ … 10⁶ samples it reports, for ``frame_poses`` (all M_i),
``frame_origins`` and ``end_effector``:

- ns per sample-module and samples per second (best of several runs);
- the ratio to a per-sample Python loop over the same formulas (``transfer_matrix`` per
  module and ``@`` products; timed on a subset, because at 10⁶ samples it would take
  minutes) and to a naive vectorized chain of stacked 4×4 ``matmul`` calls;
- the floor: numpy's own ``cos`` + ``sin`` per element;
- peak memory of each call relative to its output (tracemalloc sees numpy's buffers).

The target, one core, pure numpy: ≤ 50 ns per sample-module for all frame poses.
"""

from __future__ import annotations

import argparse
import time
import tracemalloc

import numpy as np

import robotconf as rc


def six_module_robot() -> rc.Robot:
    """A 6-axis arm built from modules (RzRyRyRxRyRx), lengths in metres."""
    return rc.Robot(
        [
            rc.Module("Rz", a=(0, 0, 0.1)),
            rc.Module("Ry", a=(0, 0, 0.3)),
            rc.Module("Ry", a=(0.4, 0, 0)),
            rc.Module("Rx", a=(0.35, 0, 0.02)),
            rc.Module("Ry"),
            rc.Module("Rx", a=(0.08, 0, 0)),
        ],
        end_effector=(0.05, 0, 0),
    )


def best_time(function, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def python_loop_poses(robot: rc.Robot, q: np.ndarray) -> np.ndarray:
    """Reference: one sample at a time, one 4×4 product per module."""
    out = np.empty((len(q), robot.n, 4, 4))
    for t, row in enumerate(q):
        pose = np.eye(4)
        for i, (module, value) in enumerate(zip(robot.modules, row, strict=True)):
            pose = pose @ rc.transfer_matrix(module.kind, value, module.a)
            out[t, i] = pose
    return out


def stacked_matmul_poses(robot: rc.Robot, q: np.ndarray) -> np.ndarray:
    """Reference: build every A_i as a (T, 4, 4) stack with cos/sin, then chain matmul."""
    out = np.empty((len(q), robot.n, 4, 4))
    pose = np.broadcast_to(np.eye(4), (len(q), 4, 4))
    for i, module in enumerate(robot.modules):
        c, s = np.cos(q[:, i]), np.sin(q[:, i])
        a = np.zeros((len(q), 4, 4))
        a[:, 3, 3] = 1.0
        a[:, :3, 3] = module.a
        axis = "xyz".index(module.axis)
        j, k = (axis + 1) % 3, (axis + 2) % 3
        a[:, axis, axis] = 1.0
        a[:, j, j] = c
        a[:, k, k] = c
        a[:, k, j] = s
        a[:, j, k] = -s
        pose = pose @ a
        out[:, i] = pose
    return out


def peak_ratio(function, output_bytes: int) -> float:
    tracemalloc.start()
    tracemalloc.reset_peak()
    function()
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return peak / output_bytes


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="T up to 10⁵, fewer repeats")
    args = parser.parse_args()
    sizes = (10**4, 10**5) if args.quick else (10**4, 10**5, 10**6)
    repeats = 3 if args.quick else 5

    robot = six_module_robot()
    n = robot.n
    rng = np.random.default_rng(0)

    loop_q = rng.uniform(-np.pi, np.pi, (2000, n))
    loop_seconds = best_time(lambda: python_loop_poses(robot, loop_q), 2) / len(loop_q)
    np.testing.assert_allclose(
        python_loop_poses(robot, loop_q[:50]), robot.frame_poses(loop_q[:50]), atol=1e-12
    )

    print(f"6-module robot, numpy {np.__version__}; ns per sample-module (best of {repeats})")
    print(f"per-sample Python loop reference: {loop_seconds / n * 1e9:,.0f} ns per sample-module")
    header = (
        f"{'T':>9} {'call':<15} {'ns/s-m':>7} {'samples/s':>12} {'vs loop':>8} "
        f"{'vs matmul':>9} {'peak/out':>8}"
    )
    print(header)
    for samples in sizes:
        report(robot, rng.uniform(-np.pi, np.pi, (samples, n)), loop_seconds, repeats)


def report(robot: rc.Robot, q: np.ndarray, loop_seconds: float, repeats: int) -> None:
    """Print one block of rows for the trajectory ``q`` of shape (T, n)."""
    samples, n = q.shape
    floor = best_time(lambda: (np.cos(q), np.sin(q)), repeats) / q.size * 1e9
    matmul = best_time(lambda: stacked_matmul_poses(robot, q), max(2, repeats // 2))
    poses_out = np.empty((samples, n, 4, 4))
    cases = {
        "frame_poses": (lambda: robot.frame_poses(q), samples * n * 128, True),
        "  reused out=": (lambda: robot.frame_poses(q, out=poses_out), samples * n * 128, True),
        "frame_origins": (lambda: robot.frame_origins(q), samples * n * 24, False),
        "end_effector": (lambda: robot.end_effector(q), samples * 24, False),
    }
    for name, (call, output_bytes, all_poses) in cases.items():
        seconds = best_time(call, repeats)
        per = seconds / (samples * n) * 1e9
        ratio_loop = loop_seconds * samples / seconds
        ratio_matmul = f"{matmul / seconds:>8.1f}x" if all_poses else f"{'-':>9}"
        memory = peak_ratio(call, output_bytes)
        print(
            f"{samples:>9,} {name:<15} {per:>7.1f} {samples / seconds:>12,.0f} "
            f"{ratio_loop:>7,.0f}x {ratio_matmul} {memory:>8.2f}"
        )
    print(
        f"{'':>9} {'(floor cos+sin)':<15} {floor:>7.1f}   stacked matmul: "
        f"{matmul / (samples * n) * 1e9:.1f} ns/s-m"
    )


if __name__ == "__main__":
    main()
