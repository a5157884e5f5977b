"""Benchmark: a 10-move robot program for the PUMA 560, sampled at 1 kHz.

Target: planning (every target solved by ``rc.ik``) plus ``Program.simulate(dt=1e-3)``
(``rc.ik`` at every LIN/CIRC sample, analytic joint velocities and accelerations, and the
DVA of every frame) in ≤ 0.5 s. Prints the plan and simulate times, the sample counts
and what ``check`` found.

If Robotics Toolbox for Python (``roboticstoolbox``, a dev-only reference, not a
dependency of robotconf) is importable, the same Cartesian samples are solved the
toolbox's way: ``ctraj`` between the LIN end poses at the same path fractions
``s = u(t)`` (the toolbox has no circular interpolation, so CIRC samples take
robotconf's arc poses) and the C++ ``ik_LM`` once per sample, seeded from the previous
sample's answer; ``jtraj`` for the PTP moves. The toolbox computes no joint velocities
or frame DVA, so its figure covers less work. The two answers are compared by joint
values on the same samples (an independent check of the path and of the solutions).

Run: ``PYTHONPATH=. python benchmarks/bench_programs.py``; with the toolbox in another
environment: ``PYTHONPATH=/path/to/robotconf /path/to/venv/bin/python
benchmarks/bench_programs.py``.
"""

from __future__ import annotations

import time
import warnings
from typing import Any

import numpy as np

import robotconf as rc
from robotconf.programs import CIRC, LIN, PTP, Program, Wait

TARGET_S = 0.5
DT = 1e-3


def program_moves(robot: rc.Robot) -> list[Any]:
    """Ten moves around a comfortable PUMA configuration (lengths in metres)."""
    qa = np.array([0.2, 0.7, -2.6, 0.1, 0.8, 0.3])
    home = robot.end_effector_pose(qa)
    p = home[:3, 3]
    other = robot.end_effector_pose(np.array([0.0, 0.8, -2.4, 0.3, 0.6, -0.2]))
    return [
        PTP(q=qa),
        LIN(position=p + [-0.1, 0.0, 0.0]),
        LIN(position=p + [-0.1, 0.1, 0.05]),
        CIRC(via=p + [-0.05, 0.15, 0.05], end=p + [0.0, 0.1, 0.05]),
        Wait(0.2),
        PTP(pose=other),
        LIN(pose=home),
        CIRC(via=p + [-0.05, 0.05, 0.0], end=p + [-0.1, 0.0, 0.0]),
        PTP(q=qa, profile="quintic"),
        LIN(position=p + [-0.1, 0.0, 0.1]),
    ]


def build_and_run(robot: rc.Robot) -> tuple[float, float, Any, Any]:
    """Plan and simulate once: (plan s, simulate s, program, motion)."""
    start = time.perf_counter()
    prog = Program(robot, program_moves(robot), joint_speed=2.0, joint_accel=6.0)
    planned = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        motion = prog.simulate(dt=DT)
    return planned - start, time.perf_counter() - planned, prog, motion


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


def run_toolbox(model: Any, prog: Program, t: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """The program's samples the toolbox's way: (seconds, joint values, which rows)."""
    import roboticstoolbox as rtb
    from spatialmath import SE3

    start = time.perf_counter()
    q = np.zeros((t.size, prog.robot.n))
    done = np.zeros(t.size, dtype=bool)
    for segment in prog.segments:
        rows = np.flatnonzero((t >= segment.start) & (t < segment.end))
        if not rows.size:
            continue
        local = t[rows] - segment.start
        u, _, _ = segment.profile.evaluate(local)
        if segment.path is None:
            # jtraj's own quintic over the move's samples (its timing, not compared).
            q[rows] = segment.q_start
            if rows.size > 1 and segment.kind == "PTP":
                q[rows] = rtb.jtraj(segment.q_start, segment.q_end, local).q
        else:
            if segment.kind == "LIN":
                ends = segment.path.evaluate(np.array([0.0, 1.0]), np.zeros(2), np.zeros(2))[0]
                poses = rtb.ctraj(SE3(ends[0], check=False), SE3(ends[1], check=False), s=u)
                goals = [pose.A for pose in poses]
            else:
                goals = list(segment.path.evaluate(u, np.zeros_like(u), np.zeros_like(u))[0])
            seed = segment.q_start
            for row, goal in zip(rows, goals, strict=True):
                answer = model.ik_LM(goal, q0=seed, tol=1e-20, joint_limits=False)
                seed = answer.q
                q[row] = seed
            done[rows] = True
    return time.perf_counter() - start, q, done


def main() -> None:
    robot = rc.preset("puma560")
    build_and_run(robot)  # warm-up
    runs = [build_and_run(robot) for _ in range(3)]
    plan_s, sim_s, prog, motion = min(runs, key=lambda r: r[0] + r[1])
    cartesian = sum(
        int(np.sum((motion.t >= s.start) & (motion.t < s.end)))
        for s in prog.segments
        if s.path is not None
    )
    total = plan_s + sim_s
    print(
        f"PUMA 560, {len(prog.moves)} moves, {prog.duration:.3f} s at dt = {DT:g} s: "
        f"{motion.t.size} samples, {cartesian} of them on LIN/CIRC paths"
    )
    print(
        f"  robotconf: plan {plan_s * 1e3:6.1f} ms + simulate {sim_s * 1e3:6.1f} ms = "
        f"{total * 1e3:6.1f} ms (target ≤ {TARGET_S * 1e3:.0f} ms: "
        f"{'met' if total <= TARGET_S else 'MISSED'}); check: {motion.report!r}"
    )
    model = toolbox_robot(robot)
    if model is None:
        print(
            "  roboticstoolbox is not importable here: skipped the side-by-side comparison "
            "(pip install roboticstoolbox-python in a scratch environment to run it)"
        )
        return
    q_check = np.array([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
    agree = np.allclose(model.fkine(q_check).A, robot.end_effector_pose(q_check), atol=1e-12)
    theirs, q, done = min(
        (run_toolbox(model, prog, motion.t) for _ in range(2)), key=lambda r: r[0]
    )
    gap = float(np.abs(q[done] - motion.q[done]).max())
    print(f"  toolbox model matches robotconf's forward kinematics: {agree}")
    print(
        f"  toolbox:   ctraj + ik_LM per sample (+ jtraj) {theirs * 1e3:8.1f} ms "
        f"(no frame DVA); largest joint difference on the path samples {gap:.2e} rad; "
        f"time ratio robotconf/toolbox {total / theirs:5.2f}"
    )


if __name__ == "__main__":
    main()
