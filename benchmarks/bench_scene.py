"""Python-side cost of one 3D-scene update (6 modules, labels on).

Reports p50/p95 of ``scene.update(q)`` through the notebook widget channel (message built,
JSON-encoded as the comm would, buffers attached) and through a recording fake, against a
simple reference in the same process: the bare core calls the scene needs
(``frame_poses`` + ``end_effector``). Target: ≤ 5 ms, so a slider drives 30+ updates/s.

Run: ``python benchmarks/bench_scene.py``
"""

from __future__ import annotations

import json
import time

import numpy as np

import robotconf as rc
from robotconf.scene import RecordingChannel, Scene


def six_modules() -> rc.Robot:
    kinds = ["Rz", "Ry", "Ry", "Tx", "Rz", "Rx"]
    modules = [
        rc.Module(kind, a=(0.0, 0.0, 10.0) if i else (0, 0, 0)) for i, kind in enumerate(kinds)
    ]
    return rc.Robot(modules, end_effector=(5.0, 0.0, 0.0))


def percentiles(call, qs: np.ndarray) -> tuple[float, float]:  # type: ignore[no-untyped-def]
    times = []
    for q in qs:
        start = time.perf_counter()
        call(q)
        times.append(time.perf_counter() - start)
    ms = 1e3 * np.array(times[20:])  # drop warm-up
    return float(np.percentile(ms, 50)), float(np.percentile(ms, 95))


def main() -> None:
    robot = six_modules()
    qs = np.random.default_rng(0).uniform(-1, 1, (1000, robot.n))

    def reference(q: np.ndarray) -> None:
        robot.frame_poses(q)
        robot.end_effector(q)

    widget_scene = rc.view(robot, display=False, max_rate=None)
    sent = widget_scene.widget.send

    def encode(content, buffers=None):  # type: ignore[no-untyped-def]
        json.dumps(content)  # what ipykernel does to the message body
        sent(content, buffers)

    widget_scene.widget.send = encode
    fake_scene = Scene(robot, channel=RecordingChannel())

    rows = [
        ("reference: frame_poses + end_effector", percentiles(reference, qs)),
        ("scene.update, recording fake", percentiles(fake_scene.update, qs)),
        ("scene.update, notebook widget + JSON", percentiles(widget_scene.update, qs)),
    ]
    base = rows[0][1][0]
    print(f"{'case':42s} {'p50 ms':>8s} {'p95 ms':>8s} {'× ref':>7s}")
    for name, (p50, p95) in rows:
        print(f"{name:42s} {p50:8.3f} {p95:8.3f} {p50 / base:7.1f}")


if __name__ == "__main__":
    main()
