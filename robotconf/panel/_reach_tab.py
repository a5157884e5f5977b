"""The "Reach" tab: inverse kinematics in the panel.

Type or drag a target (x, y, z, and roll, pitch, yaw for a pose) and the robot follows:
each change solves :func:`robotconf.ik` seeded from the current q, and a solution
moves the robot through the panel's usual path (undo, bound file, p_EE, scene). When the
target cannot be reached the core's reason is shown beside the controls, the robot stays
where it was and the target marker turns orange-red. Robots of a classic geometry also
list every closed-form solution (:func:`robotconf.ik_all`) as buttons and, while the
tab shows, as faint ghost robots in the 3D pane. Dragging the marker in the pane is not
offered: the sliders move the target.
"""

from __future__ import annotations

import html
import time
import warnings
from collections.abc import Callable, Hashable, Iterator
from typing import Any

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..inverse_kinematics import IKResult, ik
from ..kinematics import Robot, characteristic_length
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._ranges import length_scale
from ._reach_moves import GestureHistory
from ._reach_solutions import ClosedForm, SolutionList, closed_form
from ._reach_target import TargetControls
from ._undo_buttons import UndoButtons
from ._units import ANGLE_UNIT, Units

__all__ = ["ReachTab"]

_OK = "color:#1b7a1b"
#: Within this (relative to the robot's size, and in radians) a moved robot still meets
#: the target: the numeric solver's default ``tol`` and ``orientation_tol``.
TOLERANCE = 1e-9
_FAIL = "color:#c2410c"


class ReachTab:
    """Target controls, the numeric solve, closed-form solutions and their ghosts.

    Parameters
    ----------
    robot : callable
        Returns the panel's current robot.
    move : callable
        ``move(robot)`` shows a robot whose q changed and makes it the panel's robot,
        without recording it for undo (:class:`GestureHistory` does).
    history : UndoButtons
        The panel's undo buttons.
    scene : object
        The panel's 3D scene; ``show_ghosts``/``clear_ghosts`` and
        ``show_target``/``clear_target`` are used when it has them.
    units : Units
        The panel's units.
    clock : callable
        Seconds, for what counts as one drag (a test passes its own).

    Attributes
    ----------
    target : TargetControls
        x, y, z, roll, pitch, yaw and the position/pose toggle.
    solutions : SolutionList
        The closed-form branches as buttons.
    result : IKResult or None
        The last numeric solve (``None`` before the first).
    status : ipywidgets.HTML
        The last solve's outcome in a sentence (the core's ``message``).
    show_all : ipywidgets.Checkbox
        Draw every closed-form solution as a ghost robot.
    moves : GestureHistory
        Records this tab's moves for undo, one step per drag of a control.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> state = {"robot": arm}
    >>> tab = ReachTab(
    ...     lambda: state["robot"],
    ...     lambda robot: state.update(robot=robot),
    ...     UndoButtons(arm, lambda robot, order: None),
    ...     scene=None,
    ...     units=Units(),
    ... )
    >>> tab.target.controls["x"].box.value = 1.0
    >>> tab.target.controls["y"].box.value = 1.0
    >>> tab.result.reason, state["robot"].end_effector().round(9) + 0.0
    ('converged', array([1., 1., 0.]))
    >>> [button.description for button in tab.solutions.buttons]
    ['elbow down', 'elbow up']
    """

    def __init__(
        self,
        robot: Callable[[], Robot],
        move: Callable[[Robot], None],
        history: UndoButtons,
        scene: Any,
        units: Units,
        clock: Callable[[], float] = time.monotonic,
    ):
        self._robot = robot
        self._move = move
        self.moves = GestureHistory(history, clock=clock)
        self._scene = scene
        self.units = units
        current = robot()
        self._scale = length_scale(current)
        self.target = TargetControls(self._target_changed, self._scale, units)
        self.from_current = widgets.Button(
            description="from current pose",
            icon="crosshairs",
            tooltip="set the target to where the end effector is now",
            layout=widgets.Layout(width="auto"),
        )
        self.reach_button = widgets.Button(
            description="reach",
            icon="bullseye",
            tooltip="solve again from the robot's current q",
            layout=widgets.Layout(width="auto"),
        )
        self.from_current.add_class("robotconf-reach-from-current")
        self.reach_button.add_class("robotconf-reach-solve")
        self.error = ErrorLabel()
        self.status = widgets.HTML()
        self.status.add_class("robotconf-reach-status")
        self.show_all = widgets.Checkbox(value=True, description="show all solutions", indent=False)
        self.show_all.add_class("robotconf-reach-ghosts")
        self.solutions = SolutionList(self._pick)
        self.result: IKResult | None = None
        self._picked: str | None = None  # the branch last clicked, while nothing was solved
        self._warning = ""  # what the solver warned about (a planar arm asked for a pose)
        self._reached: Robot | None = None  # the robot the last solve or click produced
        self._found: ClosedForm | None = None
        self._found_for: tuple[Robot, bytes] | None = None  # geometry and target of _found
        self._touched = False  # whether the user set a target (else it follows the robot)
        self._visible = False
        self._moving = False  # this tab is moving the robot: the panel's echo is no news
        self._drawn: tuple[Any, ...] | None = None  # what the 3D view shows for this tab
        on_click(self.from_current, self.error, self.set_from_current)
        on_click(self.reach_button, self.error, lambda: self._solve(None))
        observe(self.show_all, self.error, lambda _: self._redraw())
        self.widget = widgets.VBox(
            [
                widgets.HBox(
                    [self.target.mode, self.from_current, self.reach_button, self.error.widget],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.target.widget,
                self.status,
                self.show_all,
                self.solutions.widget,
            ]
        )
        self.widget.add_class("robotconf-reach-tab")
        self.target.set_pose(current.end_effector_pose())
        self._show_status()

    # -- what the panel calls -----------------------------------------------------------

    def show(self, robot: Robot) -> None:
        """The panel's robot changed (an edit, undo, a load): follow it while the tab
        shows, else catch up when it shows again (a q drag elsewhere costs nothing)."""
        if self._moving:
            return
        if self._visible:
            self._follow(robot)

    def set_visible(self, visible: bool) -> None:
        """Draw the target and the ghosts while the tab shows; take them away when not."""
        self._visible = bool(visible)
        if self._visible:
            self._follow(self._robot())
        else:
            self._call("clear_ghosts")
            self._call("clear_target")
            self._drawn = None

    def set_units(self, units: Units) -> None:
        """Show the target and the solutions' q in ``units``; nothing is solved again."""
        self.units = units
        self.target.set_units(units)
        if self._found is not None:
            self.solutions.show(self._robot(), self._found, units)
            self.solutions.mark(self._robot())

    def set_from_current(self) -> None:
        """Make the target the end-effector's current pose (the robot does not move)."""
        robot = self._robot()
        self.target.set_pose(robot.end_effector_pose())
        self._touched = False
        self.result, self._picked, self._reached = None, None, robot
        self._refresh(robot)
        self._show_status()

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` for every error label of the tab."""
        yield "reach", self.error
        yield "reach.solutions", self.solutions.error
        yield from self.target.error_items()

    # -- solving ------------------------------------------------------------------------

    def _follow(self, robot: Robot) -> None:
        scale = length_scale(robot)
        if scale != self._scale:  # another robot: its own ranges, and a target it reaches
            self._scale = scale
            self.target.set_scale(scale)
            self._touched = False
        if not self._touched:
            self.target.set_pose(robot.end_effector_pose())
        self._refresh(robot)
        self._show_status()

    def _target_changed(self, field: str) -> None:
        self._touched = True
        if field == "mode" and self.target.is_pose:
            # The orientation starts as the tool's own: asking for a pose moves nothing yet.
            self.target.set_orientation(self._robot().end_effector_pose())
        self._solve(None if field == "mode" else field)

    def _solve(self, gesture: Hashable | None) -> None:
        """Solve for the target from the current q; move the robot when it converged."""
        target = self.target.target()
        robot = self._robot()
        mode = "pose" if self.target.is_pose else "position"
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = ik(robot, target, q0=robot.q, mode=mode)
        self._warning = "; ".join(str(w.message) for w in caught)
        self.result, self._picked = result, None
        if result.success:
            moved = robot.with_q(result.q)
            if moved != robot:
                self._go(moved, gesture)
            self._reached = moved
        self._refresh(self._robot())
        self._show_status()

    def _pick(self, index: int) -> None:
        """Move the robot to closed-form branch ``index`` (its own undo step)."""
        found = self._found
        if found is None or found.solutions is None:
            return
        robot = self._robot()
        moved = robot.with_q(found.solutions.q[index])
        if moved != robot:
            self._go(moved, None)
        self.result, self._picked, self._reached = None, found.solutions.labels[index], moved
        self._refresh(moved)
        self._show_status()

    def _go(self, robot: Robot, gesture: Hashable | None) -> None:
        self._moving = True
        try:
            self._move(robot)
        finally:
            self._moving = False
        self.moves.record(robot, None if gesture is None else ("reach", gesture))

    # -- showing ------------------------------------------------------------------------

    def _shown_target(self) -> np.ndarray | None:
        """The target the controls hold, or ``None`` while one of them is refused."""
        try:
            return self.target.target()
        except InvalidInputError:
            return None  # the control says why; the last drawing stays

    def _refresh(self, robot: Robot) -> None:
        """Closed-form solutions for the target (recomputed only when the robot's
        geometry or the target changed), the highlighted branch, and the drawing."""
        target = self._shown_target()
        if target is None:
            return
        key = (robot.with_q(np.zeros(robot.n)), target.tobytes())
        if self._found_for is None or self._found_for[1] != key[1] or self._found_for[0] != key[0]:
            self._found = closed_form(robot, target)
            self._found_for = key
            self.solutions.show(robot, self._found, self.units)
        self.solutions.mark(robot)
        if self._visible:
            self._draw(robot, target)

    def _draw(self, robot: Robot, target: np.ndarray) -> None:
        reachable = self.result is None or bool(self.result.success)
        drawn = (self._found_for, bool(self.show_all.value), reachable)
        if drawn == self._drawn:
            return  # a q drag elsewhere: the ghosts and the marker stay as they are
        self._drawn = drawn
        solutions = None if self._found is None else self._found.solutions
        if self.show_all.value and solutions is not None and len(solutions):
            self._call("show_ghosts", robot, solutions.q)
        else:
            self._call("clear_ghosts")
        self._call("show_target", target, reachable)

    def _redraw(self) -> None:
        target = self._shown_target()
        if self._visible and target is not None:
            self._draw(self._robot(), target)

    def _show_status(self) -> None:
        result, robot = self.result, self._robot()
        style = ""
        if result is not None and not result.success:
            text = f"✗ {result.reason}: {result.message}; the robot stays where it was"
            style = _FAIL
        elif self._reached is not None and robot != self._reached:
            text, style = self._gap_text(robot)
        elif result is not None:
            text, style = f"✓ reached: {result.message}", _OK
        elif self._picked is not None:
            text, style = f"✓ closed-form solution: {self._picked}", _OK
        else:
            text = "target: the end effector's current pose"
        note = self._warning if result is not None else ""
        extra = f"<br><small>{html.escape(note)}</small>" if note else ""
        self.status.value = f'<span style="{style}">{html.escape(text)}</span>{extra}'

    def _gap_text(self, robot: Robot) -> tuple[str, str]:
        """Whether the moved robot (an edit, an undo) still meets the target, or how far
        its end effector is from it; and the text's style."""
        target = self._shown_target()
        if target is None:
            return "the robot moved since", ""
        pose = robot.end_effector_pose()
        point = target if target.shape == (3,) else target[:3, 3]
        gap = float(np.linalg.norm(pose[:3, 3] - point))
        turn = 0.0
        if target.shape == (4, 4):
            cos = (np.trace(target[:3, :3].T @ pose[:3, :3]) - 1.0) / 2.0
            turn = float(np.arccos(np.clip(cos, -1.0, 1.0)))
        # The numeric solver's own default tolerances.
        if gap <= TOLERANCE * characteristic_length(robot) and turn <= TOLERANCE:
            return "✓ the end effector is on the target", _OK
        text = f"{gap:.4g} {self.units.length}"
        if target.shape == (4, 4):
            text += f" and {self.units.to_shown(turn, ANGLE_UNIT):.4g} {self.units.angle}"
        return f"the robot moved: its end effector is {text} from the target; press reach", ""

    def _call(self, name: str, *args: Any) -> None:
        method = getattr(self._scene, name, None)
        if method is not None:
            method(*args)
