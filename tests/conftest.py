"""Shared fixtures and independent reference formulas for the tests.

The references below are written out literally from docs/conventions.md, "Modules" (the
paper's eq. 11–16), the paper's eq. 10 and Craig's modified-DH matrix, one sample at a
time with plain 4×4 products: deliberately the simplest possible code, independent of the
numpy kernel.
"""

from __future__ import annotations

import os

import numpy as np
import pytest

import robotconf as rc

os.environ.setdefault("MPLBACKEND", "Agg")

L1, L2, L3 = 20.0, 30.0, 40.0


def reference_matrix(kind: str, q: float, a=(0.0, 0.0, 0.0)) -> np.ndarray:
    """The module table of docs/conventions.md, entry by entry."""
    c, s = np.cos(q), np.sin(q)
    ax, ay, az = a
    table = {
        "none": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "Rx": [[1, 0, 0, ax], [0, c, -s, ay], [0, s, c, az], [0, 0, 0, 1]],
        "Ry": [[c, 0, s, ax], [0, 1, 0, ay], [-s, 0, c, az], [0, 0, 0, 1]],
        "Rz": [[c, -s, 0, ax], [s, c, 0, ay], [0, 0, 1, az], [0, 0, 0, 1]],
        "Tx": [[1, 0, 0, q + ax], [0, 1, 0, ay], [0, 0, 1, az], [0, 0, 0, 1]],
        "Ty": [[1, 0, 0, ax], [0, 1, 0, q + ay], [0, 0, 1, az], [0, 0, 0, 1]],
        "Tz": [[1, 0, 0, ax], [0, 1, 0, ay], [0, 0, 1, q + az], [0, 0, 0, 1]],
        "fixed": [[1, 0, 0, ax], [0, 1, 0, ay], [0, 0, 1, az], [0, 0, 0, 1]],
    }
    return np.array(table[kind], dtype=float)


def reference_dh(theta: float, d: float, a: float, alpha: float, convention: str) -> np.ndarray:
    """Paper eq. 10 (standard) and Craig's eq. 3.6 (modified), written out."""
    ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha)
    if convention == "standard":
        rows = [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ]
    else:
        rows = [
            [ct, -st, 0, a],
            [st * ca, ct * ca, -sa, -sa * d],
            [st * sa, ct * sa, ca, ca * d],
            [0, 0, 0, 1],
        ]
    return np.array(rows, dtype=float)


def reference_link(link, q: float) -> np.ndarray:
    """Reference transfer matrix of a Module or DHLink at coordinate q."""
    if isinstance(link, rc.Module):
        return reference_matrix(link.kind, q, link.a)
    theta = link.theta + (q if link.joint == "R" else 0.0)
    d = link.d + (q if link.joint == "P" else 0.0)
    return reference_dh(theta, d, link.a, link.alpha, link.convention)


def reference_poses(robot: rc.Robot, q) -> np.ndarray:
    """M_1 … M_n by a Python loop of 4×4 products (inactive modules are identity)."""
    poses, pose = [], np.eye(4)
    for i, (link, qi) in enumerate(zip(robot.modules, q, strict=True)):
        if i < robot.active:
            pose = pose @ reference_link(link, float(qi))
        poses.append(pose)
    return np.array(poses)


def assert_transform_close(actual, expected, atol: float = 1e-12) -> None:
    """Homogeneous transforms agree entry by entry (absolute tolerance, length units)."""
    actual, expected = np.asarray(actual), np.asarray(expected)
    assert actual.shape == expected.shape, f"shape {actual.shape} != {expected.shape}"
    np.testing.assert_allclose(actual, expected, rtol=0, atol=atol)


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20261123)


@pytest.fixture
def paper_robot() -> rc.Robot:
    """The paper's R_zR_yR_y validation robot (§3): l1 = 20, l2 = 30, l3 = 40."""
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, L1)), rc.Module("Ry", a=(L2, 0, 0))],
        end_effector=(L3, 0, 0),
    )
