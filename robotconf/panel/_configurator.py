"""The configurator panel: one state, every view drawn from it, every click one action.

:class:`Configurator` holds a single immutable :class:`~robotconf.panel.state.PanelState`.
What the student does reaches it as one action (``panel.apply(SetQ(1, 0.5))``, see
:mod:`robotconf.panel.actions`); the action gives the next state, the history records the
document part of it, every view draws itself from it (the editors, the header, the 3D
view, the tabs), and the bound file saves it. No widget holds truth: what the screen
shows is always ``panel.state``, so ``panel.robot`` is the robot on screen.
"""

from __future__ import annotations

import dataclasses
import os
import threading
from collections.abc import Callable, Hashable
from pathlib import Path
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..kinematics import Robot
from ..motion import Motion, SimulationSettings
from ..presets import preset
from ..programs import Program
from . import actions as act
from ._feedback import Feedback
from .editor import EditorView
from .files import FileBinding, FilesView, bound_path, setup_parts, setup_to_json, write_atomically
from .header import HeaderView
from .matrices import MatricesView
from .motion import MotionTab
from .program import ProgramView
from .reach import ReachView
from .state import TABS, Document, History, MotionSetup, PanelState, Playback, Units
from .support import (
    LOGGER,
    PANEL_CLASS,
    ErrorLabel,
    app_mode,
    failure_message,
    observe,
    stylesheet,
    view_column,
    workspace,
)
from .viewport import EE_CLASS, NO_EXTRAS, ViewportView, default_scene_factory, end_effector_text
from .wizard import WizardView

__all__ = ["Configurator", "configurator"]

#: The result tabs' titles, in :data:`~robotconf.panel.state.TABS` order.
TAB_TITLES = ("Motion", "Matrices", "Reach", "Program", "Save / Load")
#: Actions that only move the robot's coordinates: a drag in flight stays current.
_Q_ONLY = (act.SetQ, act.SetReachTarget, act.PickSolution, act.Solve, act.SetReachMode)


class Configurator:
    """The configurator: module list / DH table / guided mode, 3D view, and the tabs.

    Parameters
    ----------
    robot : Robot or path-like, optional
        The robot to start with (default: the paper's), or a ``.json`` file to keep the
        work in: loaded when it exists, and every valid change saved to it.
    scene_factory : callable, optional
        ``robot -> scene`` (default: :class:`robotconf.scene.Scene`); a scene needs
        ``widget`` and ``show(snapshot)`` (see ``viewport/_scene_slot.py``).
    degrees : bool
        Show angles in degrees (the header switches).
    length_unit : str
        The name of the robot's length unit (``"mm"``, ``"m"`` …; lengths are never
        converted: robot files carry no unit).
    t_end, dt : float
        Initial time settings (s).
    method : {"analytic", "numeric", "backward"}
    scene_height : int
        Height of the default 3D scene (pixels).
    app : bool or None
        ``True`` when no notebook cells surround the panel (an app in Voilà): no hints to
        type code. ``None`` (default) detects Voilà.

    Attributes
    ----------
    state : PanelState
        Everything the panel shows, as one value (see :mod:`robotconf.panel.state`).
    robot : Robot
        ``state.robot``: the robot on screen.
    motion : Motion or None
        The last simulation (``None`` before Run).
    errors : dict
        Control key → message of every input the panel refused right now.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.panel.actions import SetModuleKind, SetTimeSetting
    >>> panel = Configurator(rc.preset("paper"))
    >>> panel.robot.end_effector()
    array([70.,  0., 20.])
    >>> panel.apply(SetModuleKind(1, "Rz"))  # module 2 becomes a rotation about z
    >>> panel.robot.modules[1].kind, panel.robot.modules[1].a
    ('Rz', (0.0, 0.0, 20.0))
    >>> panel.undo()  # every change of the document can be undone (and redone)
    >>> panel.robot.modules[1].kind
    'Ry'
    >>> panel.editor.form.user("modules[1].q").type("-90")  # as a student types it
    >>> panel.robot.end_effector().round(9) + 0.0
    array([ 0.,  0., 90.])
    >>> panel.motion_tab.form.user("dt").type("0")
    >>> panel.errors["dt"][:29], panel.state.document.motion.settings.dt
    ('dt: must be positive, got 0.0', 0.01)
    """

    def __init__(
        self,
        robot: Robot | str | os.PathLike[str] | None = None,
        *,
        scene_factory: Callable[[Robot], Any] | None = None,
        degrees: bool = True,
        length_unit: str = "units",
        t_end: float = 10.0,
        dt: float = 0.01,
        method: str = "analytic",
        scene_height: int = 420,
        app: bool | None = None,
    ):
        file = bound_path(robot)
        self.app = app_mode(app)
        self.binding = FileBinding(file, self.to_json, app=self.app)
        saved = self.binding.load() if file is not None else None
        if file is not None:
            robot = None if saved is None else saved[0]
        robot = preset("paper") if robot is None else robot
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", robot, "a robotconf Robot, a .json file or None")
        units = Units(act.check_length_unit(length_unit), bool(degrees))
        settings = SimulationSettings(t_end, dt=dt, method=method)
        state = PanelState(
            Document(robot, MotionSetup((None,) * robot.n, settings)),
            units=units,
            program_dt=float(dt),
        )
        if saved is not None:
            state = act.LoadSetup(*saved).apply(state)
        self._state = state
        self._history: History[Document] = History(state.document)
        self._layout = 0  # bumped when what a control means changes (rows, units)
        self.feedback = Feedback()
        self.feedback.show_in(state.units)
        self._rendering = False
        # JupyterLab may send the forms' events to a kernel subshell (another thread) while
        # the tabs' clicks arrive on the main one: one action at a time, in arrival order.
        self._lock = threading.RLock()
        # -- the views --------------------------------------------------------------
        self.title = widgets.HTML("<h3 style='margin:4px 0'>robotconf configurator</h3>")
        self.header = HeaderView(self._dispatch, self._can, self.undo, self.redo)
        self.editor = EditorView(self._dispatch)
        self.wizard = WizardView(self._dispatch)
        self.ee_label = widgets.HTML()
        self.ee_label.add_class(EE_CLASS)
        factory = scene_factory or default_scene_factory(scene_height)
        self.scene = factory(robot)
        self.viewport = ViewportView(self.scene, self.ee_label, self._dispatch)
        self.motion_tab = MotionTab(self._dispatch, app=self.app)
        self.matrices = MatricesView(self._dispatch, app=self.app)
        self.reach = ReachView(self._dispatch)
        self.program_tab = ProgramView(self._dispatch, self.undo, self.redo, self._can, self.app)
        self.files = FilesView(
            self._dispatch,
            self.to_json,
            source=lambda: self.binding.name or "configurator panel",
            figure=self.motion_tab.results.figure,
            app=self.app,
        )
        self.results = widgets.Tab(
            children=[
                self.motion_tab.widget,
                self.matrices.widget,
                self.reach.widget,
                self.program_tab.widget,
                self.files.widget,
            ],
            titles=TAB_TITLES,
        )
        self.results.add_class("robotconf-tabs")
        self._tab_error = ErrorLabel()
        observe(self.results, self._tab_error, self._tab_clicked, "selected_index")
        self._editor_box = widgets.VBox()
        self.view = view_column([self.ee_label, self.scene.widget])
        self.widget = widgets.VBox(
            [
                stylesheet(),
                self.title,
                self.binding.widget,
                self.binding.error.widget,
                self.header.form,
                # The robot stays in sight while its sliders move: beside the editor, or
                # above it and pinned (support/_layout.py).
                workspace(self._editor_box, self.view),
                self.results,
                self._tab_error.widget,
            ],
            layout=widgets.Layout(overflow="visible"),
        )
        self.widget.add_class(PANEL_CLASS)
        self._render(None)
        self.binding.start()

    # -- the state ----------------------------------------------------------------------

    @property
    def state(self) -> PanelState:
        """Everything the panel shows, as one immutable value."""
        return self._state

    @property
    def robot(self) -> Robot:
        """The robot on screen (``state.robot``)."""
        return self._state.robot

    @property
    def motion(self) -> Motion | None:
        """The last simulation, or ``None`` before the first Run."""
        return self._state.motion

    @property
    def program(self) -> Program | None:
        """The Program tab's program for the robot (``None`` while empty or refused)."""
        return self.program_tab.program(self._state)

    @property
    def units(self) -> Units:
        """The units the panel shows: the length unit's name and degrees or radians."""
        return self._state.units

    @property
    def errors(self) -> dict[str, str]:
        """``{control key: message}`` for every input the panel refused right now, and
        the bound file's trouble (``"file"``)."""
        found = dict(self.feedback.items())
        refused = self.program_tab.refusal(self._state)
        if refused is not None:  # the core's word on the Program tab's table
            found.setdefault(*refused)
        if self.binding.error.message:
            found["file"] = self.binding.error.message
        if self.files.upload_error.message:
            found["load"] = self.files.upload_error.message
        if self._tab_error.message:  # a view that could not draw itself
            found["panel"] = self._tab_error.message
        return found

    @property
    def can_undo(self) -> bool:
        """Whether there is a change to undo."""
        return self._history.can_undo

    @property
    def can_redo(self) -> bool:
        """Whether an undo can be redone."""
        return self._history.can_redo

    def apply(self, action: act.Action) -> None:
        """Apply one action (see :mod:`robotconf.panel.actions`) and show the result.

        Raises
        ------
        InvalidInputError
            The core refuses the result; the panel keeps its state.
        """
        with self._lock:
            self._commit(action.apply(self._state), action)

    def undo(self) -> None:
        """Go back to the document before the last change (robot, signals, program)."""
        with self._lock:
            self._go(self._history.undo())

    def redo(self) -> None:
        """Bring back the document the last :meth:`undo` left."""
        with self._lock:
            self._go(self._history.redo())

    def set_robot(self, robot: Robot) -> None:
        """Show ``robot`` and make it the panel's robot (one undo step)."""
        self.apply(act.LoadRobot(robot))

    # -- files --------------------------------------------------------------------------

    def to_json(self) -> str:
        """The robot, the signals, the time settings and the program as the core's JSON.

        Raises
        ------
        InvalidInputError
            While the program does not fit the robot (the Program tab says which move):
            the core would refuse to load such a file.
        """
        state = self._state
        document = state.document
        program = self.program_tab._build(state)
        if isinstance(program, InvalidInputError):
            raise program.within("program")
        signals = document.motion.driven(state.robot.coordinate_names)
        settings = document.motion.settings.to_dict()
        if settings.get("t0") == 0.0:
            del settings["t0"]
        return setup_to_json(state.robot, signals, settings, program)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write :meth:`to_json` to ``path`` (UTF-8, the file replaced in one step)."""
        text = self.to_json()  # an invalid setup is refused before any file is touched
        if self.binding.owns(path):
            self.binding.save_now()  # the binding keeps track of its file's versions
        else:
            write_atomically(path, text)

    def load(self, path: str | os.PathLike[str]) -> None:
        """Load a robot with its signals, time settings and program from a JSON file."""
        self.apply(act.LoadSetup(*setup_parts(Path(path))))

    # -- the one flow -------------------------------------------------------------------

    def _dispatch(
        self, action: Any, key: str, typed: str | None = None, quiet: bool = False
    ) -> None:
        """What a view asks for: an action (applied), a refusal (shown beside ``key``), or
        ``None`` (draw again). Nothing a student does raises out of a widget callback."""
        with self._lock:
            self._dispatch_now(action, key, typed, quiet)

    def _dispatch_now(self, action: Any, key: str, typed: str | None, quiet: bool) -> None:
        if action is None:
            self._render(self._state)
            return
        if isinstance(action, BaseException):
            if not quiet:
                self.feedback.refused(key, failure_message(action), typed)
            self._render(self._state)
            return
        try:
            new = action.apply(self._state)
        except Exception as error:  # every failure is shown; the kernel never sees one
            if not isinstance(error, InvalidInputError):
                LOGGER.exception("panel action %r failed", action)
            if not quiet:
                self.feedback.refused(key, failure_message(error), typed)
                self._render(self._state)
            return
        self.feedback.accepted(key)
        self._commit(new, action)

    def _commit(self, new: PanelState, action: act.Action) -> None:
        old = self._state
        moved = new.shown_robot is not old.shown_robot
        if moved and new.playback.source is not None and new.playback is old.playback:
            # A robot that moves or changes ends the animation of the old one.
            new = dataclasses.replace(new, playback=Playback(speed=new.playback.speed))
        gesture: Hashable | None = action.gesture
        if new.document is not old.document:
            self._history.record(new.document, gesture)
        moved_only = isinstance(action, _Q_ONLY)
        if new.units != old.units or (new.robot is not old.robot and not moved_only):
            self._layout += 1
        if new.robot is not old.robot and not moved_only and new.robot.n != old.robot.n:
            self.editor.ranges.forget()
        self._state = new
        self.feedback.show_in(new.units)
        self._render(old)
        if new.document is not old.document:
            self.binding.changed()

    def _go(self, document: Document | None) -> None:
        if document is None:
            return
        old = self._state
        self.feedback.clear()  # the editors show the document again: old refusals go
        self._state = dataclasses.replace(old, document=document, prompt=None)
        self._layout += 1
        self._render(old)
        self.binding.changed()

    def _can(self) -> tuple[bool, bool]:
        return self._history.can_undo, self._history.can_redo

    # -- drawing ------------------------------------------------------------------------

    def _render(self, old: PanelState | None) -> None:
        """Every view draws itself from the state (each skips what did not change). A view
        that fails says so under the tabs; the others still draw."""
        if self._rendering:
            return
        self._rendering = True
        failures: list[str] = []
        try:
            state, feedback, rev = self._state, self.feedback, str(self._layout)
            tab = state.view.tab

            def draw(name: str, render: Callable[..., None], *args: Any) -> None:
                try:
                    render(*args)
                except Exception as error:  # one view's bug must not stop the others
                    LOGGER.exception("drawing the %s failed", name)
                    failures.append(f"{name}: {failure_message(error)}")

            draw("header", self.header.render, state, feedback, rev)
            if state.wizard is not None:
                draw("guided mode", self.wizard.render, state, feedback, rev)
                editor = self.wizard.widget
            else:
                draw("editor", self.editor.render, state, feedback, rev)
                editor = self.editor.form
            if self._editor_box.children != (editor,):
                self._editor_box.children = (editor,)
            for name, view in (
                ("motion", self.motion_tab),
                ("matrices", self.matrices),
                ("reach", self.reach),
                ("program", self.program_tab),
                ("files", self.files),
            ):
                draw(f"{name} tab", view.render, state, feedback, rev, tab == name)
            extras = NO_EXTRAS
            if state.wizard is None and tab in ("reach", "program"):
                view = self.reach if tab == "reach" else self.program_tab
                try:
                    extras = view.scene_extras(state)
                except Exception as error:
                    LOGGER.exception("drawing the %s tab's points failed", tab)
                    failures.append(f"{tab} tab: {failure_message(error)}")
            draw("3D view", self.viewport.render, state, extras)
            index = TABS.index(tab)
            if self.results.selected_index != index:
                self.results.selected_index = index
        finally:
            self._rendering = False
        if failures:
            self._tab_error.show("; ".join(failures))
        else:
            self._tab_error.clear()

    def _tab_clicked(self, change: dict[str, Any]) -> None:
        if change["new"] is None:
            return
        with self._lock:  # a click made while another thread works waits for it
            if self._rendering:  # this thread's own render set the index: no click
                return
            self._dispatch_now(act.SelectTab(TABS[int(change["new"])]), "tab", None, False)

    # -- display ------------------------------------------------------------------------

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        bundle = self.widget._repr_mimebundle_(**kwargs)
        if isinstance(bundle, dict):
            # A front end without widgets (a console, nbconvert's text) shows the panel's
            # own summary, not the repr of its outermost box.
            bundle = {**bundle, "text/plain": repr(self)}
        return bundle

    def __repr__(self) -> str:
        robot = self._state.robot
        return f"<Configurator: {robot.n} modules, {end_effector_text(robot.at().end_effector)}>"


def configurator(
    robot: Robot | str | os.PathLike[str] | None = None, **options: Any
) -> Configurator:
    """Build a :class:`Configurator` for ``robot``, display it, and return it.

    Parameters
    ----------
    robot : Robot or path-like, optional
        Default: the paper's R_zR_yR_y robot. A ``.json`` file name
        (``rc.configurator("my_robot.json")``) keeps the work in that file: the panel
        loads it when it exists and saves every valid change to it.
    **options
        Passed to :class:`Configurator` (``scene_factory``, ``degrees``, ``length_unit``,
        ``t_end``, ``dt``, ``method``, ``scene_height``, ``app``).

    Returns
    -------
    Configurator
        ``panel.robot`` is the current robot, ``panel.motion`` the last simulation.
    """
    panel = Configurator(robot, **options)
    from IPython.display import display

    display(panel)
    return panel
