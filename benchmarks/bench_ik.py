"""Benchmark: numeric inverse kinematics for 1 and 1000 pose targets (PUMA 560, UR5).

The targets are forward kinematics of random configurations within the joint ranges, so
every one is reachable. Prints wall time and success rate of ``rc.ik(..., mode="pose")``
with its defaults (8 starts, 200 iterations each, tolerances 1e-9).

If Robotics Toolbox for Python (``roboticstoolbox``, a dev-only optional reference that is
not a dependency of robotconf) is importable, its C++ Levenberg–Marquardt solver
``ik_LM`` runs on the same targets in the same process, one call per target as it has no
batch form, and the ratios are printed. Both answers are checked with robotconf's own
forward kinematics against the same thresholds, since the two solvers stop on different
criteria (robotconf: position ≤ 1e-9 · L and angle ≤ 1e-9 rad; ``ik_LM``: ``½ eᵀe`` below
its ``tol``, set here to 1e-20 so that it aims as close).

Run: ``PYTHONPATH=. python benchmarks/bench_ik.py``; with the toolbox in another
environment: ``PYTHONPATH=. /path/to/venv/bin/python benchmarks/bench_ik.py``.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

import robotconf as rc
from robotconf.ik import ik

COUNTS = (1, 1000)
ROBOTS = ("puma560", "ur5")
# Thresholds both solvers' answers are judged by (metres and radians).
POSITION_CHECK = 1e-9
ANGLE_CHECK = 1e-8


def targets(robot: rc.Robot, count: int, seed: int = 0) -> np.ndarray:
    """Poses (count, 4, 4) of random configurations within the joint ranges."""
    limits = robot.joint_limits()
    rng = np.random.default_rng(seed)
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.random((count, robot.n))
    return robot.end_effector_pose(q)


def met(robot: rc.Robot, q: np.ndarray, goal: np.ndarray) -> np.ndarray:
    """Whether each answer (count, n) reaches its pose, by robotconf's own kinematics."""
    pose = robot.end_effector_pose(q)
    position = np.linalg.norm(pose[:, :3, 3] - goal[:, :3, 3], axis=-1)
    gap = np.linalg.norm(pose[:, :3, :3] - goal[:, :3, :3], axis=(-2, -1))
    angle = 2.0 * np.arcsin(np.minimum(gap / (2.0 * np.sqrt(2.0)), 1.0))
    size = rc.characteristic_length(robot)
    return (position <= POSITION_CHECK * size) & (angle <= ANGLE_CHECK)


def best_of(func: Any, repeat: int) -> float:
    """Best wall time in seconds over ``repeat`` runs (after one warm-up)."""
    func()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return min(times)


def toolbox_robot(robot: rc.Robot) -> Any:
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


def run_toolbox(model: Any, goals: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``ik_LM`` on each goal: answers (count, n) and its own success flags."""
    answers, flags = [], []
    for goal in goals:
        solution = model.ik_LM(goal, tol=1e-20, joint_limits=True)
        answers.append(solution.q)
        flags.append(bool(solution.success))
    return np.array(answers), np.array(flags)


def main() -> None:
    print("numeric IK, mode='pose', defaults (8 starts, tol 1e-9)")
    print(
        f"answers judged by robotconf FK: position ≤ {POSITION_CHECK:g}·L, angle ≤ {ANGLE_CHECK:g}"
    )
    for name in ROBOTS:
        robot = rc.preset(name)
        model = toolbox_robot(robot)
        if model is not None:
            q = np.array([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
            agree = np.allclose(model.fkine(q).A, robot.end_effector_pose(q), atol=1e-12)
            print(f"  {name}: toolbox model matches robotconf's forward kinematics: {agree}")
        for count in COUNTS:
            goals = targets(robot, count, seed=count)
            goal = goals[0] if count == 1 else goals
            repeat = 5 if count == 1 else 1
            ours = best_of(lambda robot=robot, goal=goal: ik(robot, goal, mode="pose"), repeat)
            result = ik(robot, goal, mode="pose")
            q = np.atleast_2d(result.q)
            rate = met(robot, q, goals).mean()
            line = (
                f"  {name:8s} {count:5d} target(s): robotconf {ours:8.4f} s "
                f"({ours / count * 1e3:7.3f} ms/target), success {rate:6.1%}"
            )
            if model is not None:
                theirs = best_of(lambda model=model, goals=goals: run_toolbox(model, goals), repeat)
                answers, flags = run_toolbox(model, goals)
                their_rate = met(robot, answers, goals).mean()
                line += (
                    f"  |  ik_LM {theirs:8.4f} s, success {their_rate:6.1%} "
                    f"(its own flag {flags.mean():6.1%})  |  time ratio robotconf/ik_LM "
                    f"{ours / theirs:6.2f}"
                )
            print(line)
    try:
        import roboticstoolbox  # noqa: F401
    except ImportError:
        print(
            "roboticstoolbox is not importable here: skipped the side-by-side comparison "
            "(pip install roboticstoolbox-python in a scratch environment to run it)"
        )


if __name__ == "__main__":
    main()
