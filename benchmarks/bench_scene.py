"""Kernel-side cost of the 3D scene: one q step, and loading an animation.

A q step of a 6-module robot (labels on), p50/p95 over 1000 random q:

- ``scene.show(snapshot)`` with the snapshot made beforehand (what a panel does: its state
  holds ``robot.at(q)`` for the header too), through a recording fake and through the
  notebook widget's channel (message built, JSON-encoded as the comm would, buffers
  attached);
- ``scene.update(q)``, the same plus the snapshot (``robot.at(q)``, one kernel pass).

Loading a 10 s motion sampled at 1 ms (10 001 samples, thinned to 1500 keyframes):
``scene.animate(motion)``, through the fake and the widget + JSON.

References in the same process, so the ratios hold on a loaded machine: ``robot.at(q)``
(one kernel pass, the least a picture of the robot needs) for the q step, and the
motion's batch of frame poses (``robot.frame_poses(motion.q)``) for the animation.

Run: ``python benchmarks/bench_scene.py``. Pointed at an older checkout of the package
(``PYTHONPATH=old/ python benchmarks/bench_scene.py``), the rows its scene lacks are left
out, so before and after print side by side with the same references.
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import robotconf as rc
from robotconf.scene import RecordingChannel, Scene


def six_modules() -> rc.Robot:
    kinds = ["Rz", "Ry", "Ry", "Tx", "Rz", "Rx"]
    modules = [
        rc.Module(kind, a=(0.0, 0.0, 10.0) if i else (0, 0, 0)) for i, kind in enumerate(kinds)
    ]
    return rc.Robot(modules, end_effector=(5.0, 0.0, 0.0))


def percentiles(
    call: Callable[[Any], Any], inputs: list[Any], warm: int = 20
) -> tuple[float, float]:
    times = []
    for value in inputs:
        start = time.perf_counter()
        call(value)
        times.append(time.perf_counter() - start)
    ms = 1e3 * np.array(times[warm:])
    return float(np.percentile(ms, 50)), float(np.percentile(ms, 95))


def widget_scene(robot: rc.Robot) -> Any:
    scene = rc.view(robot, display=False, max_rate=None)
    sent = scene.pane.send

    def encode(content: Any, buffers: Any = None) -> None:
        json.dumps(content)  # what ipykernel does to the message body
        sent(content, buffers)

    scene.pane.send = encode
    return scene


def main() -> None:
    robot = six_modules()
    qs = np.random.default_rng(0).uniform(-1, 1, (1000, robot.n))
    robots = [robot.with_q(q) for q in qs]  # a new robot object per step, as a panel's state
    snapshots = [r.at() for r in robots]
    has_show = hasattr(Scene, "show")

    fake, widget = Scene(robot, channel=RecordingChannel()), widget_scene(robot)
    rows: list[tuple[str, tuple[float, float], float]] = []
    step = percentiles(lambda q: robot.at(q), list(qs))
    rows.append(("reference: robot.at(q), one kernel pass", step, step[0]))
    if has_show:
        rows.append(
            ("scene.show(snapshot), recording fake", percentiles(fake.show, snapshots), step[0])
        )
        rows.append(
            ("scene.show(snapshot), widget + JSON", percentiles(widget.show, snapshots), step[0])
        )
    rows.append(("scene.update(q), recording fake", percentiles(fake.update, list(qs)), step[0]))
    rows.append(("scene.update(q), widget + JSON", percentiles(widget.update, list(qs)), step[0]))

    t_end = 2.0 if os.environ.get("ROBOTCONF_FAST") else 10.0
    signals = {name: rc.signals.Sine(amplitude=0.5) for name in robot.coordinate_names}
    motion = rc.simulate(robot, signals, t_end=t_end, dt=1e-3)
    repeats = [motion] * 8
    poses = percentiles(lambda m: robot.frame_poses(m.q), repeats, warm=2)
    rows.append((f"reference: frame_poses of {len(motion.t)} samples", poses, poses[0]))
    rows.append(
        ("scene.animate, recording fake", percentiles(fake.animate, repeats, warm=2), poses[0])
    )
    rows.append(
        ("scene.animate, widget + JSON", percentiles(widget.animate, repeats, warm=2), poses[0])
    )

    print(f"{'case':44s} {'p50 ms':>8s} {'p95 ms':>8s} {'× ref':>7s}")
    for name, (p50, p95), base in rows:
        print(f"{name:44s} {p50:8.3f} {p95:8.3f} {p50 / base:7.2f}")


if __name__ == "__main__":
    main()
