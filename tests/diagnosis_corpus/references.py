"""The expected matrices of the course's exercises, built as the exercises build them.

Each key names a lesson and an exercise (``"L3.ex2"``), or a further step of the same
robot that a lesson derives (``"L3.M3"``); :func:`reference` builds it once.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np
import sympy

import robotconf as rc

__all__ = ["REFERENCES", "reference"]

HALF_PI = np.pi / 2


def _frame() -> rc.Robot:  # lesson 1: a frame turned about z, origin at (30, 0, 20)
    return rc.Robot([rc.Module("Rz", a=(30, 0, 20))], end_effector=(40, 0, 0))


def _paper() -> rc.Robot:  # lessons 3, 7, 8: the paper's RzRyRy robot
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def _pedestal() -> rc.Robot:
    return rc.Robot([rc.Module("fixed", a=(0, 0, 50)), *_paper().modules], end_effector=(40, 0, 0))


def _cartesian() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Tx"), rc.Module("Ty", a=(0, 0, 50)), rc.Module("Tz")], end_effector=(0, 0, -10)
    )


def _cylindrical() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Tz", a=(0, 0, 20)), rc.Module("Tx")], end_effector=(10, 0, 0)
    )


def _spherical() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 30)), rc.Module("Tx")], end_effector=(10, 0, 0)
    )


def _scara() -> rc.Robot:
    return rc.Robot(
        [
            rc.Module("Rz", a=(0, 0, 40)),
            rc.Module("Rz", a=(30, 0, 0)),
            rc.Module("Tz", a=(20, 0, 0)),
        ],
        end_effector=(0, 0, -10),
    )


def _dh(rows: list, convention: str = "standard") -> rc.Robot:
    return rc.Robot.from_dh(rows, convention=convention)


def _paper_dh() -> rc.Robot:
    return _dh([(0, 20, 0, -HALF_PI, "R"), (0, 0, 30, 0, "R"), (0, 0, 40, 0, "R")])


def _planar(l1: float = 1.0) -> rc.Robot:
    return _dh([(0, 0, l1, 0, "R"), (0, 0, 1, 0, "R")])


def _jacobian_2x2() -> sympy.Matrix:
    chain = rc.symbolic_chain(_planar())
    return chain.end_effector()[:2, :].jacobian(chain.q_symbols)


def _determinant() -> sympy.Matrix:
    chain = rc.symbolic_chain(_planar(2.0))
    return sympy.Matrix([[chain.end_effector()[:2, :].jacobian(chain.q_symbols).det()]])


def _axes_as_columns() -> np.ndarray:
    expected = np.eye(4)
    expected[:3, :3] = np.column_stack([(0, 0, 1), (1, 0, 0), (0, 1, 0)])
    expected[:3, 3] = (10, 20, 30)
    return expected


def _puma_q(q1: float = 0.0, q2: float = 0.0) -> list[float]:
    return [q1, q2, 0, 0, 0, 0]


E = rc.expected_matrix
REFERENCES: dict[str, Callable[[], Any]] = {
    # lesson 1: homogeneous transforms
    "L1.ex1": _axes_as_columns,
    "L1.ex2": lambda: E(_frame(), "A1", q=[HALF_PI]),
    "L1.ex3": lambda: E(_frame(), "p_EE", q=[HALF_PI]),
    "L1.ex4": lambda: E(_frame(), "A1"),
    # lesson 2: elementary transforms
    "L2.ex1": lambda: E(rc.Robot([rc.Module("Rx", a=(0, 0, 20))]), "A1"),
    "L2.ex2": lambda: E(rc.Robot([rc.Module("Ry", a=(30, 0, 0))]), "A1"),
    "L2.ex3": lambda: E(rc.Robot([rc.Module("Tz", a=(0, 0, 20))]), "A1"),
    "L2.ex4": lambda: E(rc.Robot([rc.Module("Rz")]), "A1", q=[0.5]),
    # lesson 3: the paper's robot
    "L3.ex1": lambda: E(_paper(), "A2", lengths=True),
    "L3.ex2": lambda: E(_paper(), "M2", lengths=True),
    "L3.ex3": lambda: E(_paper(), "p_EE", q=[0, 0, 0]),
    "L3.ex4": lambda: E(_paper(), "p_EE", q=[HALF_PI, 0, -HALF_PI]),
    "L3.ex5": lambda: E(_pedestal(), "p_EE", q=[0, 0, 0, 0]),
    "L3.M3": lambda: E(_paper(), "M3"),
    "L3.M3l": lambda: E(_paper(), "M3", lengths=True),
    "L3.pEE": lambda: E(_paper(), "p_EE"),
    "L3.pEE.q": lambda: E(_paper(), "p_EE", q=[0.3, -0.4, 0.7]),
    # lesson 4: classic arms
    "L4.ex1": lambda: E(_cartesian(), "M3"),
    "L4.ex2": lambda: E(_cylindrical(), "p_EE"),
    "L4.ex3": lambda: E(_spherical(), "p_EE"),
    "L4.ex4": lambda: E(_scara(), "p_EE", q=[HALF_PI, -HALF_PI, -5]),
    "L4.scara.M2": lambda: E(_scara(), "M2"),
    # lesson 5: Denavit-Hartenberg
    "L5.ex1": lambda: E(_dh([(0, 0.5, 1, HALF_PI, "R")]), "A1"),
    "L5.ex2": lambda: E(_dh([(0, 0.5, 1, HALF_PI, "R")], "modified"), "A1"),
    "L5.ex3": lambda: E(_dh([(0, 0, 2, 0, "R")]), "A1", q=[np.radians(30)]),
    "L5.ex4": lambda: E(_paper_dh(), "A1"),
    "L5.ex5": lambda: E(_paper_dh(), "p_EE", q=[HALF_PI, 0, -HALF_PI]),
    "L5.M3": lambda: E(_paper_dh(), "M3"),
    # lesson 6: real arms (metres)
    "L6.ex1": lambda: E(rc.preset("puma560"), "A2", q=_puma_q(q2=np.radians(30))),
    "L6.ex2": lambda: E(rc.preset("ur5"), "p_EE", q=np.zeros(6)),
    "L6.ex3": lambda: E(rc.preset("puma560"), "M2"),
    "L6.ex4": lambda: E(rc.preset("ur5"), "A1"),
    "L6.puma.A1": lambda: E(rc.preset("puma560"), "A1", q=_puma_q(q1=np.radians(30))),
    "L6.puma.M2": lambda: E(rc.preset("puma560"), "M2", q=_puma_q(np.radians(30), np.radians(45))),
    # lessons 7 and 8: Jacobians (bare matrices)
    "L7.ex1": _jacobian_2x2,
    "L7.ex2": lambda: rc.jacobian(_paper(), [0, 0, 0])[:3] @ [0.5, 0, 1],
    "L7.ex3": lambda: rc.jacobian(_paper(), [0, 0, -HALF_PI])[:3],
    "L7.pEE": lambda: E(_planar(), "p_EE"),
    "L8.ex1": lambda: rc.jacobian(_planar(), [0, 0])[:2],
    "L8.ex2": _determinant,
}


@functools.cache
def reference(key: str) -> Any:
    """The expected matrix named ``key`` (built once)."""
    return REFERENCES[key]()
