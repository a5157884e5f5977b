"""Which chains the symbolic derivation handles in interactive time.

The symbolic matrices M_i = A_1 ⋯ A_i multiply the sines and cosines of every rotation
in the chain and simplify after each product, so their size, and the time sympy needs,
roughly doubles with every rotation. A plain link count is a poor guide: six revolute
joints whose axes are multiples of 90° apart (PUMA 560, UR5) take 0.3 s, while five DH
links with twists such as 0.3 rad take 16 s. :func:`symbolic_cost` therefore counts what
grows: the rotations (revolute joints, and DH twists or fixed angles that are not a
multiple of 90°) and weighs every link by 2 ** (rotations up to and including it), the
number of terms its position picks up.

:data:`SYMBOLIC_COST_LIMIT` keeps ``derivation(robot, symbolic=True, lengths=True)``
under about 3 s. Measured on the development machine (2 shared cores, sympy 1.14;
derivation only, printing adds 0.1-1 s):

=================================  =====  =====  ========
chain (module kinds cycled)        links  cost   time (s)
=================================  =====  =====  ========
Rz Ry Tx Rx Ty Ry Tz Rz            1-8    ≤ 90   0.2-1.5
Rz Ry Rx                           5      62     0.3
Rz Ry Rx                           6      126    1.3-1.6
Rz Ry Rx                           7      254    3.5-4.3
Rz Ry Rx                           8      510    8-12
Rz Tx Ry Ty Rx Tz                  10     124    2.9
Rz Tx Ry Ty Rx Tz                  12     252    9.4
Rz Ry Rx Tx                        8      198    3.1
Rz Ry Rx Rz Ry, then 5 fixed       10     222    7.2
Tx Ty Tz                           64     64     0.1
DH R, twists 0.3, 0.5, 0.7 …       3      84     0.7
DH R, twists 0.3, 0.5, 0.7 …       4      340    3.0
DH R, twists 0.3, 0.5, 0.7 …       5      1364   16
DH RRPRR, twists π/2 0.3 −π/2 0.7  5      218    2.0-3.4
PUMA 560, UR5 presets              6      126    0.3
Stanford preset                    6      66     0.3
=================================  =====  =====  ========

:func:`~robotconf.teaching.derivation` refuses a chain over the limit with
:data:`SYMBOLIC_TOO_LONG` (the sentence ``robotconf report`` and the panel show too);
``allow_slow=True`` still builds it, taking longer (exponentially so).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ...kinematics import Link, Robot

__all__ = ["SYMBOLIC_COST_LIMIT", "SYMBOLIC_TOO_LONG", "symbolic_cost", "symbolic_fits"]

#: The largest :func:`symbolic_cost` whose symbolic derivation is built by default.
SYMBOLIC_COST_LIMIT = 128

#: Why a chain over the limit gets no symbolic matrices, and how to get them anyway.
SYMBOLIC_TOO_LONG = (
    "this chain is too long for them by default, as sympy's time grows exponentially "
    "with the rotations in the chain, from seconds to many minutes "
    "(robotconf.teaching.symbolic_fits). To get them anyway, run "
    "rc.derivation(robot, symbolic=True, allow_slow=True) in a notebook and accept the wait."
)


def _is_quarter_turn(angle: float) -> bool:
    # sin and cos of a multiple of 90° are 0 or ±1, so such a rotation only permutes
    # entries and adds no terms.
    return math.isclose(math.remainder(angle, math.pi / 2), 0.0, abs_tol=1e-12)


def _rotations(link: Link) -> int:
    """How many rotations that add terms one link contributes (0, 1 or 2)."""
    parameters = link.parameters()
    count = 0
    if link.joint_type == "revolute":
        count += 1
    elif not _is_quarter_turn(parameters.get("theta", 0.0)):
        count += 1  # a DH prismatic joint's fixed θ still rotates
    if not _is_quarter_turn(parameters.get("alpha", 0.0)):
        count += 1
    return count


def symbolic_cost(robot: Robot) -> int:
    """An estimate of the size of the symbolic derivation: Σ 2 ** (rotations so far).

    Parameters
    ----------
    robot : Robot
        The robot to derive.

    Returns
    -------
    int
        Each link adds 2 ** r, r being the number of term-adding rotations from the base
        up to and including that link (see the module notes).

    Examples
    --------
    >>> from robotconf.kinematics import Module, Robot
    >>> symbolic_cost(Robot([Module("Rz"), Module("Tx"), Module("Ry", a=(1, 0, 0))]))
    8
    """
    cost = 0
    rotations = 0
    for link in robot.modules:
        rotations += _rotations(link)
        cost += 2**rotations
    return cost


def symbolic_fits(robot: Robot) -> bool:
    """Whether the symbolic derivation of ``robot`` is quick enough to build by default.

    Parameters
    ----------
    robot : Robot
        The robot to derive.

    Returns
    -------
    bool
        ``True`` when :func:`symbolic_cost` is at most :data:`SYMBOLIC_COST_LIMIT`
        (about 3 s or less for ``derivation(robot, symbolic=True, lengths=True)``).

    Examples
    --------
    >>> from robotconf.kinematics import Module, Robot
    >>> symbolic_fits(Robot([Module("Rz"), Module("Ry", a=(1, 0, 0))]))
    True
    >>> symbolic_fits(Robot([Module(kind, a=(1, 0, 0)) for kind in ["Rz", "Ry", "Rx"] * 4]))
    False
    """
    return symbolic_cost(robot) <= SYMBOLIC_COST_LIMIT
