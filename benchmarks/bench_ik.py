"""Benchmark: robotconf's numeric IK side by side with Robotics Toolbox's ik_LM and ikpy.

For the PUMA 560 and the UR5, ``--count`` (default 1000) random reachable pose targets —
forward kinematics of random configurations within the joint ranges, the same seed for
every solver — are solved

- by ``rc.ik`` in one batched call (time per target = total / count),
- by ``rc.ik`` one target at a time, cold (the default start ``q0``, the robot's ``q``),
- by ``rc.ik`` one target at a time, interactive: the target is the pose of a
  configuration moved by about 0.02 rad per joint and ``q0`` the configuration before the
  move, as when a student drags a target slider,
- by Robotics Toolbox for Python's C++ Levenberg–Marquardt ``ik_LM`` (``tol=1e-20`` so
  that it aims as close as robotconf, joint limits on), one call per target (it has no
  batch form), cold and interactive,
- by ikpy (SciPy least squares on the chain read from ``robot.to_urdf()``,
  ``tol=1e-15``), one call per target from the robot's ``q``,

all in this process. Every answer is judged by robotconf's own forward kinematics with
the same thresholds: position within 1e-9 · L (L = ``rc.characteristic_length``) and
orientation within 1e-8 rad. Each line gives the success rate and the median and 95th
percentile time per solve; the goals are checked at the end:

1. ``rc.ik`` batched succeeds at least as often as ``ik_LM``;
2. the batched call takes at most half the time of ``ik_LM``'s loop over the targets;
3. an interactive ``rc.ik`` solve takes at most 5 ms (median).

The references are dev-only (``pip install -e .[bench]``, see pyproject.toml); without
them their lines are skipped with a note. Run::

    PYTHONPATH=. python benchmarks/bench_ik.py [--count N]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np

import robotconf as rc
from robotconf.inverse_kinematics import ik

ROBOTS = ("puma560", "ur5")
# Thresholds every solver's answers are judged by (relative length, and radians).
POSITION_CHECK = 1e-9
ANGLE_CHECK = 1e-8
# The interactive case: how far (rad, per joint) the target moves between two solves.
DRAG = 0.02
INTERACTIVE_GOAL = 5e-3  # s
SPEEDUP_GOAL = 2.0


def workload(robot: rc.Robot, count: int, seed: int = 0) -> dict[str, np.ndarray]:
    """Targets (count, 4, 4), the configurations behind them, and nearby starts."""
    limits = robot.joint_limits()
    rng = np.random.default_rng(seed)
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.random((count, robot.n))
    moved = np.clip(q + rng.normal(scale=DRAG, size=q.shape), limits[:, 0], limits[:, 1])
    return {
        "cold": robot.end_effector_pose(q),
        "interactive": robot.end_effector_pose(moved),
        "before": q,
    }


def met(robot: rc.Robot, q: np.ndarray, goal: np.ndarray) -> np.ndarray:
    """Whether each answer (count, n) reaches its pose, by robotconf's own kinematics."""
    pose = robot.end_effector_pose(q)
    position = np.linalg.norm(pose[:, :3, 3] - goal[:, :3, 3], axis=-1)
    gap = np.linalg.norm(pose[:, :3, :3] - goal[:, :3, :3], axis=(-2, -1))
    angle = 2.0 * np.arcsin(np.minimum(gap / (2.0 * np.sqrt(2.0)), 1.0))
    size = rc.characteristic_length(robot)
    return (position <= POSITION_CHECK * size) & (angle <= ANGLE_CHECK)


class Row:
    """One solver on one workload: answers, per-solve times (s) and success."""

    def __init__(self, label: str, answers: np.ndarray, times: np.ndarray, ok: np.ndarray):
        self.label, self.answers, self.times, self.ok = label, answers, times, ok

    @property
    def total(self) -> float:
        return float(np.sum(self.times))

    def line(self) -> str:
        median, p95 = np.median(self.times) * 1e3, np.percentile(self.times, 95) * 1e3
        return (
            f"    {self.label:34s} success {self.ok.mean():7.1%}   median {median:7.3f} ms"
            f"   p95 {p95:7.3f} ms   total {self.total:7.3f} s"
        )


def loop(solve: Callable[[int], np.ndarray], count: int) -> tuple[np.ndarray, np.ndarray]:
    """Call ``solve(i)`` for every target (after one warm-up): answers and times."""
    solve(0)
    answers, times = [], np.empty(count)
    for i in range(count):
        start = time.perf_counter()
        answers.append(solve(i))
        times[i] = time.perf_counter() - start
    return np.array(answers), times


def robotconf_rows(robot: rc.Robot, work: dict[str, np.ndarray]) -> list[Row]:
    goals, count = work["cold"], len(work["cold"])
    ik(robot, goals[:8], mode="pose")  # warm-up (the robot's model is kept)
    totals = []
    for _ in range(3):
        start = time.perf_counter()
        batch = ik(robot, goals, mode="pose")
        totals.append(time.perf_counter() - start)
    rows = [
        Row(
            "rc.ik batched (total / count)",
            batch.q,
            np.full(count, np.median(totals) / count),
            met(robot, batch.q, goals),
        )
    ]
    answers, times = loop(lambda i: ik(robot, goals[i], mode="pose").q, count)
    rows.append(Row("rc.ik one at a time, cold", answers, times, met(robot, answers, goals)))
    moved, before = work["interactive"], work["before"]
    answers, times = loop(lambda i: ik(robot, moved[i], q0=before[i], mode="pose").q, count)
    rows.append(Row("rc.ik one at a time, interactive", answers, times, met(robot, answers, moved)))
    return rows


def toolbox_model(robot: rc.Robot) -> Any:
    """The same DH robot in Robotics Toolbox for Python (None when not installed)."""
    try:
        import roboticstoolbox as rtb
    except ImportError:
        return None
    links = []
    for link, (lo, hi) in zip(robot.modules, robot.joint_limits(), strict=True):
        kind = rtb.RevoluteDH if link.joint == "R" else rtb.PrismaticDH
        fixed = {"offset": link.theta, "d": link.d} if link.joint == "R" else {"theta": link.theta}
        links.append(kind(a=link.a, alpha=link.alpha, qlim=[lo, hi], **fixed))
    return rtb.DHRobot(links, name=robot.name)


def toolbox_rows(robot: rc.Robot, model: Any, work: dict[str, np.ndarray]) -> list[Row]:
    goals, moved, before = work["cold"], work["interactive"], work["before"]
    count = len(goals)
    answers, times = loop(lambda i: model.ik_LM(goals[i], tol=1e-20, joint_limits=True).q, count)
    rows = [Row("ik_LM loop, cold", answers, times, met(robot, answers, goals))]
    answers, times = loop(
        lambda i: model.ik_LM(moved[i], q0=before[i], tol=1e-20, joint_limits=True).q, count
    )
    rows.append(Row("ik_LM loop, interactive", answers, times, met(robot, answers, moved)))
    return rows


def ikpy_chain(robot: rc.Robot) -> tuple[Any, np.ndarray] | None:
    """ikpy's chain read from the robot's URDF, and where its joints sit in its links."""
    try:
        from ikpy.chain import Chain
    except ImportError:
        return None
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "robot.urdf")
        with open(path, "w", encoding="utf-8") as file:
            file.write(robot.to_urdf())
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # its notes on the fixed joints it reads
            chain = Chain.from_urdf_file(path, base_elements=["base_link"])
            active = [link.joint_type != "fixed" for link in chain.links]
            chain = Chain(chain.links, active_links_mask=active)
    return chain, np.flatnonzero(active)


def ikpy_rows(robot: rc.Robot, found: tuple[Any, np.ndarray], work: dict[str, np.ndarray]) -> Row:
    chain, joints = found
    goals = work["cold"]
    start = np.zeros(len(chain.links))
    start[joints] = robot.q

    def solve(i: int) -> np.ndarray:
        goal = goals[i]
        full = chain.inverse_kinematics(
            goal[:3, 3], goal[:3, :3], orientation_mode="all", initial_position=start, tol=1e-15
        )
        return full[joints]

    answers, times = loop(solve, len(goals))
    return Row("ikpy loop, cold", answers, times, met(robot, answers, goals))


def agree(robot: rc.Robot, pose: Callable[[np.ndarray], np.ndarray]) -> bool:
    """Whether a reference's forward kinematics matches robotconf's."""
    q = np.array([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
    return bool(np.allclose(pose(q), robot.end_effector_pose(q), atol=1e-12))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=1000, help="pose targets per robot")
    count = parser.parse_args().count
    print(f"numeric IK, mode='pose', {count} random reachable targets per robot, rc.ik defaults")
    print(
        f"answers judged by robotconf FK: position ≤ {POSITION_CHECK:g}·L, angle ≤ {ANGLE_CHECK:g}"
    )
    verdicts = []
    for name in ROBOTS:
        robot = rc.preset(name)
        work = workload(robot, count)
        print(f"  {name}:")
        rows = robotconf_rows(robot, work)
        model = toolbox_model(robot)
        found = ikpy_chain(robot)
        if model is not None:
            same = agree(robot, lambda q, model=model: model.fkine(q).A)
            print(f"    (toolbox FK agrees with robotconf's: {same})")
            rows += toolbox_rows(robot, model, work)
        if found is not None:
            chain, joints = found

            def ikpy_pose(q: np.ndarray, chain: Any = chain, joints: np.ndarray = joints) -> Any:
                full = np.zeros(len(chain.links))
                full[joints] = q
                return chain.forward_kinematics(full)

            print(f"    (ikpy FK agrees with robotconf's: {agree(robot, ikpy_pose)})")
            rows.append(ikpy_rows(robot, found, work))
        for row in rows:
            print(row.line())
        verdicts += check_goals(name, rows, model is not None)
    if toolbox_model(rc.preset("ur5")) is None:
        print(
            "roboticstoolbox is not importable: skipped ik_LM (pip install -e .[bench], "
            "or run this file with the Python of an environment that has it)"
        )
    if ikpy_chain(rc.preset("ur5")) is None:
        print("ikpy is not importable: skipped ikpy (pip install -e .[bench])")
    print("goals:")
    for verdict in verdicts:
        print("  " + verdict)


def check_goals(name: str, rows: list[Row], toolbox: bool) -> list[str]:
    """The three goals for one robot, as lines ending in 'met' or 'MISSED'."""
    by_label = {row.label: row for row in rows}
    batch = by_label["rc.ik batched (total / count)"]
    interactive = by_label["rc.ik one at a time, interactive"]
    median = float(np.median(interactive.times))
    out = [
        f"{name}: interactive median {median * 1e3:.2f} ms ≤ {INTERACTIVE_GOAL * 1e3:.0f} ms: "
        + ("met" if median <= INTERACTIVE_GOAL else "MISSED")
    ]
    if toolbox:
        loop_ = by_label["ik_LM loop, cold"]
        speedup = loop_.total / batch.total
        out.append(
            f"{name}: success rc.ik {batch.ok.mean():.1%} ≥ ik_LM {loop_.ok.mean():.1%}: "
            + ("met" if batch.ok.mean() >= loop_.ok.mean() else "MISSED")
        )
        out.append(
            f"{name}: batched {batch.total:.3f} s vs ik_LM loop {loop_.total:.3f} s, "
            f"{speedup:.2f}× ≥ {SPEEDUP_GOAL:g}×: "
            + ("met" if speedup >= SPEEDUP_GOAL else "MISSED")
        )
    return out


if __name__ == "__main__":
    main()
