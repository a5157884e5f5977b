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

The same robot in a work cell (``rc.view(cell)``, a :class:`CellScene`) with 20 boxes and
5 frames, through the recording fake: a q step (``show(cell, {"arm": q})``), a designer's
step (one box moved, ``show(cell)``), both against ``robot.at(q)``; and loading a run of
the same length (``animate(cell_run)``: the robot, its capsules, its contacts) against the
robot's own scene loading the run's motion.

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

CellScene = getattr(rc, "CellScene", None)  # an older checkout has none


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

    if CellScene is not None:
        rows += cell_rows(robot, qs, motion.t[-1], step[0])

    print(f"{'case':44s} {'p50 ms':>8s} {'p95 ms':>8s} {'× ref':>7s}")
    for name, (p50, p95), base in rows:
        print(f"{name:44s} {p50:8.3f} {p95:8.3f} {p50 / base:7.2f}")


def cell_rows(
    robot: rc.Robot, qs: np.ndarray, t_end: float, step: float
) -> list[tuple[str, tuple[float, float], float]]:
    """The robot in a cell of 20 boxes and 5 frames: a q step, a box moved, a run loaded."""
    rng = np.random.default_rng(1)
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", robot)
    for k in range(20):
        cell.add(rc.Box([4, 4, 4], pose=rc.pose(rng.uniform(-40, 40, 3)), name=f"box{k}"))
    for k in range(5):
        cell.add_frame(f"frame{k}", rc.pose(rng.uniform(-40, 40, 3)))
    scene = CellScene(cell, channel=RecordingChannel())
    rows = [
        (
            "cell: show(cell, {arm: q}), recording fake",
            percentiles(lambda q: scene.show(cell, {"arm": q}), list(qs)),
            step,
        )
    ]

    def move(k: int) -> None:
        cell.set_pose("box3", rc.pose([0.01 * k, 0.0, 0.0]))
        scene.show(cell)

    rows.append(("cell: a box moved, show(cell)", percentiles(move, list(range(300))), step))
    moves = [rc.PTP(q=q) for q in rng.uniform(-1, 1, (8, robot.n))]
    program = rc.Program(robot, moves)
    dt = float(t_end) / 2000 if os.environ.get("ROBOTCONF_FAST") else program.duration / 10_000
    run = cell.run({"arm": program}, dt=dt)
    plain = Scene(robot, channel=RecordingChannel())
    loads = [run.motions["arm"]] * 8
    reference = percentiles(plain.animate, loads, warm=2)
    samples = len(run.motions["arm"].t)
    rows.append((f"reference: Scene.animate, {samples} samples", reference, reference[0]))
    runs = [run] * 8
    rows.append(("cell: animate(cell_run)", percentiles(scene.animate, runs, warm=2), reference[0]))
    return rows


if __name__ == "__main__":
    main()
