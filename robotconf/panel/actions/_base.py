"""What every action is, and the one helper every robot change goes through.

An action is a small frozen value naming one thing a student does (``SetQ(1, 0.5)``).
``action.apply(state)`` gives the next :class:`~robotconf.panel.state.PanelState` in one
step, or raises the core's :class:`~robotconf.InvalidInputError` (the panel then shows it
beside the control and keeps the state). Actions never touch a widget.
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence

from ...kinematics import Robot
from ..state import PanelState, ReachState, remap
from ..state._program_draft import held, remapped

__all__ = ["Action", "with_robot", "Order"]

#: For each coordinate of a new robot, the index of the old coordinate it continues
#: (``None``: a new one); ``None`` for the whole list: coordinate i is coordinate i.
Order = Sequence[int | None] | None


class Action:
    """One user action on the panel's state.

    Subclasses are frozen dataclasses with an :meth:`apply`; :attr:`gesture` says which
    edits belong to one undo step (``None``: always its own).
    """

    def apply(self, state: PanelState) -> PanelState:  # pragma: no cover - abstract
        """The state after this action.

        Raises
        ------
        InvalidInputError
            The core refuses the result; the state stays as it was.
        """
        raise NotImplementedError

    @property
    def gesture(self) -> Hashable | None:
        """Edits of the same gesture shortly after each other are one undo step."""
        return None


def with_robot(
    state: PanelState, robot: Robot, order: Order = None, *, new_robot: bool = False
) -> PanelState:
    """``state`` showing ``robot``: signals and program coordinates follow their joints.

    Parameters
    ----------
    state : PanelState
    robot : Robot
    order : sequence or None
        For each coordinate of ``robot``, the coordinate of the old robot it continues
        (``None`` for the whole list: by position), as a row deleted or moved gives it.
    new_robot : bool
        Another robot altogether (a preset, a file, the guided mode): the Reach target
        starts again from its end effector, and the last run's marks go.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.signals import Sine
    >>> state = PanelState.start(rc.preset("paper"))
    >>> state = state.with_document(motion=state.document.motion.with_signal(2, Sine()))
    >>> moved = with_robot(state, state.robot.with_moved(2, 0), order=[2, 0, 1])
    >>> moved.document.motion.signals
    (Sine(), None, None)
    """
    document = state.document
    n = robot.n
    if order is not None or n != document.robot.n:
        signals = remap(document.motion.signals, n, order)
        motion = document.motion.__class__(signals, document.motion.settings)
    else:
        motion = document.motion
    program = document.program
    if program.moves and (order is not None or _misfits(program, n)):
        program = remapped(program, robot, order)
    if program.moves:
        program = held(program, robot)
    changes: dict[str, object] = {}
    if new_robot:
        changes["reach"] = ReachState(mode=state.reach.mode, show_all=state.reach.show_all)
    return state.replace(
        document=document.__class__(robot, motion, program), prompt=None, **changes
    )


def _misfits(program: object, n: int) -> bool:
    from ...programs import PTP

    moves = getattr(program, "moves", ())
    return any(isinstance(m, PTP) and m.q is not None and len(m.q) != n for m in moves)
