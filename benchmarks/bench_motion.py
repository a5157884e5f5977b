"""Benchmark: analytic DVA of every frame of a 6-module robot plus the DataFrame.

Target: 10 s at 1 kHz (10 001 samples), analytic DVA for all frames and the EE
plus ``Motion.table`` in ≤ 50 ms on one core. Also prints the scaling in T and in n and the
ratio to a per-sample Python loop (the same code called once per sample).

Run: ``PYTHONPATH=. python benchmarks/bench_motion.py`` (pin one core with
``taskset -c 0`` and ``OMP_NUM_THREADS=1`` for a fair figure).
"""

from __future__ import annotations

import time

import numpy as np

import robotconf as rc
from robotconf.motion import analytic_dva, simulate
from robotconf.signals import RepeatingSequence, Sine

TARGET_MS = 50.0


def six_module_robot(n: int = 6) -> rc.Robot:
    kinds = ["Rz", "Ry", "Ry", "Rx", "Ty", "Rz"]
    modules = [rc.Module(kinds[i % 6], a=(0.1 * (i % 3), 0.05, 0.2)) for i in range(n)]
    return rc.Robot(modules, end_effector=(0.1, 0.0, 0.05))


def drive(robot: rc.Robot) -> dict[str, object]:
    signals: dict[str, object] = {
        name: Sine(amplitude=0.5, frequency=0.2 + 0.1 * i)
        for i, name in enumerate(robot.coordinate_names)
    }
    signals["q2"] = RepeatingSequence(times=[0, 1, 2], values=[0, 1, 0])
    return signals


def best_of(func, repeat: int = 7) -> float:  # type: ignore[no-untyped-def]
    """Best wall time in seconds over ``repeat`` runs (after one warm-up)."""
    func()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return min(times)


def run(robot: rc.Robot, t_end: float, dt: float = 1e-3) -> float:
    signals = drive(robot)

    def once() -> None:
        motion = simulate(robot, signals, t_end=t_end, dt=dt)  # type: ignore[arg-type]
        _ = motion.table

    return best_of(once)


def main() -> None:
    robot = six_module_robot()
    headline = run(robot, 10.0)
    status = "OK" if headline * 1e3 <= TARGET_MS else "OVER TARGET"
    print(
        f"6 modules, 10 s at 1 kHz (10001 samples), analytic DVA + DataFrame: "
        f"{headline * 1e3:.1f} ms (target ≤ {TARGET_MS:.0f} ms) {status}"
    )

    print("\nScaling in T (6 modules):")
    for t_end in (1.0, 10.0, 100.0):
        seconds = run(robot, t_end)
        samples = int(round(t_end * 1000)) + 1
        print(
            f"  T = {samples:>6}: {seconds * 1e3:7.1f} ms"
            f"  ({seconds / samples * 1e9:6.0f} ns/sample)"
        )

    print("\nScaling in n (10 s at 1 kHz):")
    for n in (3, 6, 12, 24):
        seconds = run(six_module_robot(n), 10.0)
        print(
            f"  n = {n:>2}: {seconds * 1e3:7.1f} ms"
            f"  ({seconds / (n + 1) / 10001 * 1e9:5.0f} ns per sample-point)"
        )

    # Reference: the same analytic kernel called once per sample from a Python loop.
    motion = simulate(robot, drive(robot), t_end=10.0, dt=1e-3)  # type: ignore[arg-type]
    q, qd, qdd = motion.q, motion.qd, motion.qdd
    subset = 500
    start = time.perf_counter()
    for k in range(subset):
        analytic_dva(robot, q[k : k + 1], qd[k : k + 1], qdd[k : k + 1])
    loop = (time.perf_counter() - start) / subset * q.shape[0]
    vector = best_of(lambda: analytic_dva(robot, q, qd, qdd))
    print(
        f"\nPer-sample Python loop (extrapolated from {subset} samples): {loop * 1e3:.0f} ms "
        f"for 10001 samples; vectorized DVA alone {vector * 1e3:.1f} ms → "
        f"{loop / vector:.0f}× faster (full pipeline incl. table: {loop / headline:.0f}×)"
    )
    full = np.allclose(
        analytic_dva(robot, q[:1], qd[:1], qdd[:1])[..., 0],
        motion.columns().reshape(robot.n + 1, 5, 3, -1)[..., 0],
    )
    print(f"Loop and vectorized results agree at sample 0: {full}")


if __name__ == "__main__":
    main()
