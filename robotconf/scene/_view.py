"""``rc.view(robot)``: a scene shown in the notebook, once per cell (IPython's running cell
tells which one)."""

from __future__ import annotations

import sys
from typing import Any

from ..kinematics import Robot
from ._scene import Scene

__all__ = ["view", "execution_count"]


def view(robot: Robot, q: Any = None, *, display: bool = True, **options: Any) -> Scene:
    """Show a robot in a 3D pane in the notebook (see :class:`Scene` for ``options``).

    Examples
    --------
    >>> import robotconf as rc
    >>> scene = rc.view(rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0)), display=False)
    >>> scene.labels()
    ['M1 (0.00, 0.00, 0.00)', 'EE (1.00, 0.00, 0.00)']
    """
    scene = Scene(robot, q, **options)
    if display:
        from IPython.display import display as show

        show(scene)
        # `rc.view(robot)` as a cell's last line displays the pane, then IPython displays
        # the returned scene again: the scene skips that second one (same cell).
        scene._shown_in_cell = execution_count()
    return scene


def execution_count() -> int | None:
    """The running cell's number in IPython, or None outside it.

    >>> execution_count() is None or isinstance(execution_count(), int)
    True
    """
    if "IPython" not in sys.modules:
        return None
    from IPython import get_ipython

    shell = get_ipython()
    return None if shell is None else int(shell.execution_count)
