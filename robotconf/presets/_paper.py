"""The paper's validation robot (Grosz & Borzan, §3, Figures 11–15)."""

from __future__ import annotations

import numpy as np

from .._validation import check_finite_number
from ..kinematics import Module, Robot

__all__ = ["paper"]


def paper(l1: float = 20.0, l2: float = 30.0, l3: float = 40.0) -> Robot:
    """The R_zR_yR_y robot of Grosz & Borzan, *Modular Robotics Configurator*, §3.

    Module 1 Rz at the base, module 2 Ry with ``a = (0, 0, l1)``, module 3 Ry with
    ``a = (l2, 0, 0)``, end-effector ``P = (l3, 0, 0)``; the paper uses l1 = 20, l2 = 30,
    l3 = 40 (plain length units, 70 long when stretched out). The paper gives no joint
    ranges; the base turns a full turn ``(−π, π)``, shoulder and elbow ``(−π/2, π/2)`` and
    ``(−3π/4, 3π/4)`` so the arm cannot fold into its own base.

    Parameters
    ----------
    l1, l2, l3 : float
        Column height, upper-arm length and forearm length (length units).

    Examples
    --------
    >>> paper().end_effector([0, 0, 0])
    array([70.,  0., 20.])
    """
    l1, l2, l3 = (check_finite_number(v, n) for v, n in ((l1, "l1"), (l2, "l2"), (l3, "l3")))
    return Robot(
        [
            Module("Rz", limits=(-np.pi, np.pi)),
            Module("Ry", a=(0.0, 0.0, l1), limits=(-np.pi / 2, np.pi / 2)),
            Module("Ry", a=(l2, 0.0, 0.0), limits=(-3 * np.pi / 4, 3 * np.pi / 4)),
        ],
        end_effector=(l3, 0.0, 0.0),
        name="paper (RzRyRy)",
    )
