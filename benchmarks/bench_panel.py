"""Responsiveness of the configurator: one q-slider change on a 6-module robot.

Run: ``PYTHONPATH=. python benchmarks/bench_panel.py``. Target: the new robot,
the matrices printout and the scene update together in ≤ 20 ms (p95, in-process).

Measured: setting a q slider's value, which runs the whole callback chain (validate every
control with the core, build the Robot, ``rc.derivation`` and its text, the EE line, and
``scene.update(q)``). Reference: the bare core calls for the same work
(``robot.frame_poses(q)`` + ``rc.derivation(robot, q)`` + its text), in the same process.
The scene is ``robotconf.scene.Scene`` when it is installed (its Python side, widget
messages included, without a browser), else a no-op stand-in (reported).
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

import robotconf as rc
from robotconf.panel import Configurator

TARGET_P95_MS = 20.0
SAMPLES = 400


def six_module_robot() -> rc.Robot:
    """Six modules of mixed kinds, as a lab exercise would use."""
    return rc.Robot(
        [
            rc.Module("Rz"),
            rc.Module("Ry", a=(0, 0, 20)),
            rc.Module("Ry", a=(30, 0, 0)),
            rc.Module("Rx", a=(10, 0, 0)),
            rc.Module("Ry", a=(5, 0, 0)),
            rc.Module("Tz", a=(0, 0, 3)),
        ],
        end_effector=(4, 0, 0),
    )


def percentiles(run: Callable[[int], object], samples: int = SAMPLES) -> tuple[float, float]:
    """p50 and p95 of ``run(i)`` in milliseconds (after 20 warm-up calls)."""
    for i in range(20):
        run(i)
    times = np.empty(samples)
    for i in range(samples):
        start = time.perf_counter()
        run(i)
        times[i] = time.perf_counter() - start
    return float(np.percentile(times, 50) * 1e3), float(np.percentile(times, 95) * 1e3)


def main() -> None:
    robot = six_module_robot()
    panel = Configurator(robot)  # the real 3D scene, as in a notebook
    scene = type(panel.scene).__name__
    angles = np.linspace(-170.0, 170.0, 97)
    control = panel.modules.rows[2].q

    def slider(i: int) -> None:
        control.slider.value = float(angles[i % angles.size])

    def reference(i: int) -> None:
        q = robot.q.copy()
        q[2] = np.deg2rad(angles[i % angles.size])
        robot.frame_poses(q)
        str(rc.derivation(robot, q))

    p50, p95 = percentiles(slider)
    r50, r95 = percentiles(reference)
    assert panel.errors == {}
    print(f"scene: {scene}")
    print(f"panel slider change (6 modules): p50 {p50:.2f} ms, p95 {p95:.2f} ms")
    print(f"bare core reference:             p50 {r50:.2f} ms, p95 {r95:.2f} ms")
    verdict = "OK" if p95 <= TARGET_P95_MS else "TOO SLOW"
    print(f"target p95 ≤ {TARGET_P95_MS:.0f} ms: {verdict}")


if __name__ == "__main__":
    main()
