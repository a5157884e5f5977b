"""``rc.view(robot)`` and ``rc.view(cell)``: a scene shown in the notebook, once per cell
(IPython's running cell tells which one)."""

from __future__ import annotations

import sys
from typing import Any

from ..cell import Cell
from ..kinematics import Robot
from ._scene import Scene
from .workcell import CellScene

__all__ = ["view", "execution_count"]


def view(
    robot: Robot | Cell, q: Any = None, *, display: bool = True, **options: Any
) -> Scene | CellScene:
    """Show a robot, or a work cell, in a 3D pane in the notebook.

    Parameters
    ----------
    robot : Robot or Cell
        A robot (a :class:`Scene`) or a cell (a :class:`CellScene`: its robots, objects
        and frames).
    q : array-like or dict, optional
        The robot's coordinates; for a cell, ``{robot name: q}``.
    display : bool
        Show the pane in the notebook now.
    **options
        The scene's options (see :class:`Scene` and :class:`CellScene`).

    Examples
    --------
    >>> import robotconf as rc
    >>> scene = rc.view(rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0)), display=False)
    >>> scene.labels()
    ['M1 (0.00, 0.00, 0.00)', 'EE (1.00, 0.00, 0.00)']
    >>> cell = rc.Cell(unit="mm"); cell.add_robot("arm", rc.preset("paper"))
    >>> rc.view(cell, {"arm": [0, 0, 0.5]}, display=False).labels()[-1]
    'EE (65.1, 0.0, 0.8) mm'
    """
    scene: Scene | CellScene = (
        CellScene(robot, q, **options) if isinstance(robot, Cell) else Scene(robot, q, **options)
    )
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


def display_once(scene: Any) -> None:
    """Display ``scene``'s pane, except the second time in the cell that
    :func:`view` displayed it in (IPython then displays the returned scene again).

    ``scene`` has ``_shown_in_cell`` (the cell :func:`view` displayed it in, or None)
    and ``_pane``.
    """
    from IPython.display import display

    if scene._shown_in_cell is not None and scene._shown_in_cell == execution_count():
        scene._shown_in_cell = None
        return
    display(scene._pane if scene._pane is not None else repr(scene))
