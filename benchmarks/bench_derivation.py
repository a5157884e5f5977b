"""Time to build and print the symbolic derivation of a 6-module robot (target ≤ 2 s).

Run: ``PYTHONPATH=. python benchmarks/bench_derivation.py``. Each run is cold for the
robot (a fresh derivation, nothing cached by robotconf); the first run also pays for
importing sympy, so it is reported apart.
"""

from __future__ import annotations

import time

import numpy as np

from robotconf import Module, Robot
from robotconf.teaching import derivation

TARGET_SECONDS = 2.0


def six_module_robot() -> Robot:
    """Six modules of mixed kinds, as a lab exercise would use."""
    return Robot(
        [
            Module("Rz"),
            Module("Ry", a=(0, 0, 20)),
            Module("Ry", a=(30, 0, 0)),
            Module("Rx", a=(10, 0, 0)),
            Module("Ry", a=(5, 0, 0)),
            Module("Tz", a=(0, 0, 3)),
        ],
        end_effector=(4, 0, 0),
        name="six-module arm",
    )


def puma_like() -> Robot:
    """A PUMA-560-like standard DH table (six revolute joints)."""
    pi = np.pi
    rows = [
        (0, 0, 0, pi / 2, "R"),
        (0, 0, 0.4318, 0, "R"),
        (0, 0.15, 0.0203, -pi / 2, "R"),
        (0, 0.4318, 0, pi / 2, "R"),
        (0, 0, 0, -pi / 2, "R"),
        (0, 0, 0, 0, "R"),
    ]
    return Robot.from_dh(rows, end_effector=(0, 0, 0.1), name="PUMA-like")


def time_once(robot: Robot, lengths: bool) -> float:
    start = time.perf_counter()
    steps = derivation(robot, symbolic=True, lengths=lengths)
    text = str(steps)
    source = steps.latex()
    elapsed = time.perf_counter() - start
    assert len(text) > 1000 and len(source) > 1000
    return elapsed


def main() -> None:
    start = time.perf_counter()
    import sympy  # noqa: F401  (import cost reported apart)

    print(f"import sympy: {time.perf_counter() - start:.3f} s")
    worst = 0.0
    for robot in (six_module_robot(), puma_like()):
        for lengths in (False, True):
            runs = [time_once(robot, lengths) for _ in range(3)]
            worst = max(worst, max(runs))
            print(
                f"{robot.name:>15}, lengths={lengths!s:5}: build + str + latex "
                f"min {min(runs):.3f} s, max {max(runs):.3f} s"
            )
    verdict = "OK" if worst <= TARGET_SECONDS else "TOO SLOW"
    print(f"worst: {worst:.3f} s (target ≤ {TARGET_SECONDS} s): {verdict}")


if __name__ == "__main__":
    main()
