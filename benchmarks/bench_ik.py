"""Benchmark: robotconf's numeric IK side by side with Robotics Toolbox's ik_LM and ikpy.

For the PUMA 560 and the UR5, ``--count`` (default 1000) random reachable pose targets —
forward kinematics of random configurations within the joint ranges, the same seed for
every solver — are solved

- by ``rc.ik`` in one batched call (time per target = total / count),
- by ``rc.ik`` one target at a time, cold (the default start ``q0``, the robot's ``q``),
- by ``rc.ik`` one target at a time, interactive: the target is the pose of a
  configuration moved by about 0.02 rad per joint and ``q0`` the configuration before the
  move, as when a student drags a target slider,
- by Robotics Toolbox for Python's fastest path, ``robot.ets().ik_LM``: its C++
  Levenberg–Marquardt (``IK_LM_c``, method ``"chan"``, up to 30 iterations per search and
  100 searches from random starts, joint limits on) on the robot's elementary transform
  sequence, with ``tol=1e-18`` on its residual ``E = ½ eᵀe`` so that it aims as close as
  ``rc.ik`` (|e| ≈ 1.4e-9, against ``rc.ik``'s 1e-9 · L and 1e-9 rad), one call per
  target (it has no batch form), cold (its own random start) and interactive. Not
  ``DHRobot.ik_LM``: that Python wrapper is slower, and in RTB 1.5 applies a tool twice.
- by ikpy (SciPy least squares on the chain read from ``robot.to_urdf()``,
  ``tol=1e-15``), one call per target from the robot's ``q``,

all in this process. Every answer is judged by robotconf's own forward kinematics with
the same thresholds: position within 1e-9 · L (L = ``rc.characteristic_length``) and
orientation within 1e-8 rad. Each line gives the success rate and the median and 95th
percentile time per solve.

The batched call and the toolbox's loop are then timed side by side, interleaved, best
of ``--repeats`` (default 5) each, and their ratio per target is printed. The goals,
checked at the end:

1. ``rc.ik`` batched succeeds at least as often as ``ets().ik_LM``;
2. ``rc.ik`` batched takes at most the time of ``ets().ik_LM`` per target (ratio ≤ 1);
3. an interactive ``rc.ik`` solve takes at most 5 ms (median).

The references are dev-only (``pip install -e .[bench]``, see pyproject.toml); without
them their lines are skipped with a note. Run::

    PYTHONPATH=. python benchmarks/bench_ik.py [--count N] [--repeats K]
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
RATIO_GOAL = 1.0  # rc.ik batched time per target / ets().ik_LM's
#: The toolbox's tolerance on its residual E = ½ eᵀe (about |e| = 1.4e-9).
TOOLBOX_TOL = 1e-18


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
    """The same DH robot as the toolbox's elementary transform sequence (ETS), whose
    ``ik_LM`` is its C++ solver (None when the toolbox is not installed)."""
    try:
        import roboticstoolbox as rtb
    except ImportError:
        return None
    links = []
    for link, (lo, hi) in zip(robot.modules, robot.joint_limits(), strict=True):
        kind = rtb.RevoluteDH if link.joint == "R" else rtb.PrismaticDH
        fixed = {"offset": link.theta, "d": link.d} if link.joint == "R" else {"theta": link.theta}
        links.append(kind(a=link.a, alpha=link.alpha, qlim=[lo, hi], **fixed))
    return rtb.DHRobot(links, name=robot.name).ets()


def toolbox_path() -> str:
    """Which reference path runs, in words."""
    import roboticstoolbox as rtb

    return (
        f"roboticstoolbox-python {rtb.__version__}: robot.ets().ik_LM (C++ IK_LM_c, method "
        f"'chan', ilimit 30, slimit 100, tol {TOOLBOX_TOL:g} on E = ½ eᵀe, joint_limits=True), "
        "one call per target"
    )


def toolbox_solve(ets: Any, goal: np.ndarray, q0: np.ndarray | None = None) -> np.ndarray:
    return ets.ik_LM(goal, q0=q0, tol=TOOLBOX_TOL, joint_limits=True).q


def toolbox_rows(robot: rc.Robot, ets: Any, work: dict[str, np.ndarray]) -> list[Row]:
    goals, moved, before = work["cold"], work["interactive"], work["before"]
    count = len(goals)
    answers, times = loop(lambda i: toolbox_solve(ets, goals[i]), count)
    rows = [Row("ets().ik_LM loop, cold", answers, times, met(robot, answers, goals))]
    answers, times = loop(lambda i: toolbox_solve(ets, moved[i], before[i]), count)
    rows.append(Row("ets().ik_LM loop, interactive", answers, times, met(robot, answers, moved)))
    return rows


def side_by_side(robot: rc.Robot, ets: Any, goals: np.ndarray, repeats: int) -> dict[str, float]:
    """The batched call and the toolbox's loop, interleaved, best of ``repeats`` each:
    seconds per target and success, for both."""
    batched, looped = [], []
    answers = {}
    for _ in range(repeats):
        start = time.perf_counter()
        answers["rc"] = ik(robot, goals, mode="pose").q
        batched.append(time.perf_counter() - start)
        start = time.perf_counter()
        answers["tb"] = np.array([toolbox_solve(ets, goal) for goal in goals])
        looped.append(time.perf_counter() - start)
    count = len(goals)
    return {
        "rc": min(batched) / count,
        "tb": min(looped) / count,
        "rc_ok": float(met(robot, answers["rc"], goals).mean()),
        "tb_ok": float(met(robot, answers["tb"], goals).mean()),
    }


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
    parser.add_argument("--repeats", type=int, default=5, help="timings side by side")
    arguments = parser.parse_args()
    count = arguments.count
    print(f"numeric IK, mode='pose', {count} random reachable targets per robot, rc.ik defaults")
    print(
        f"answers judged by robotconf FK: position ≤ {POSITION_CHECK:g}·L, angle ≤ {ANGLE_CHECK:g}"
    )
    if toolbox_model(rc.preset("ur5")) is not None:
        print(f"reference: {toolbox_path()}")
    verdicts = []
    for name in ROBOTS:
        robot = rc.preset(name)
        work = workload(robot, count)
        print(f"  {name}:")
        rows = robotconf_rows(robot, work)
        ets = toolbox_model(robot)
        found = ikpy_chain(robot)
        timing = None
        if ets is not None:
            same = agree(robot, lambda q, ets=ets: ets.fkine(q).A)
            print(f"    (toolbox FK agrees with robotconf's: {same})")
            rows += toolbox_rows(robot, ets, work)
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
        if ets is not None:
            timing = side_by_side(robot, ets, work["cold"], arguments.repeats)
            print(
                f"    side by side, best of {arguments.repeats}: rc.ik batched "
                f"{timing['rc'] * 1e3:.3f} ms/target ({timing['rc_ok']:.1%} met), "
                f"ets().ik_LM {timing['tb'] * 1e3:.3f} ms/target ({timing['tb_ok']:.1%} met): "
                f"ratio {timing['rc'] / timing['tb']:.2f}"
            )
        verdicts += check_goals(name, rows, timing)
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


def check_goals(name: str, rows: list[Row], timing: dict[str, float] | None) -> list[str]:
    """The three goals for one robot, as lines ending in 'met' or 'MISSED'."""
    by_label = {row.label: row for row in rows}
    interactive = by_label["rc.ik one at a time, interactive"]
    median = float(np.median(interactive.times))
    out = [
        f"{name}: interactive median {median * 1e3:.2f} ms ≤ {INTERACTIVE_GOAL * 1e3:.0f} ms: "
        + ("met" if median <= INTERACTIVE_GOAL else "MISSED")
    ]
    if timing is not None:
        out.append(
            f"{name}: success rc.ik {timing['rc_ok']:.1%} ≥ ets().ik_LM {timing['tb_ok']:.1%}: "
            + ("met" if timing["rc_ok"] >= timing["tb_ok"] else "MISSED")
        )
        ratio = timing["rc"] / timing["tb"]
        out.append(
            f"{name}: batched {timing['rc'] * 1e3:.3f} vs ets().ik_LM {timing['tb'] * 1e3:.3f} "
            f"ms/target, ratio {ratio:.2f} ≤ {RATIO_GOAL:g}: "
            + ("met" if ratio <= RATIO_GOAL else "MISSED")
        )
    return out


if __name__ == "__main__":
    main()
