"""The configurator panel: build, move and analyse a robot from widgets.

Presentation only: every number on screen comes from one core call (``rc.Robot``,
``rc.derivation``, ``rc.simulate``, the signals), and every bad input shows the core's
own message next to the control that caused it while the last valid robot stays.
"""

from __future__ import annotations

import html
import os
import re
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..kinematics import DHLink, Robot
from ..motion import Motion
from ..presets import preset
from ..programs import Program
from ._app_mode import app_mode
from ._atomic_file import write_atomically
from ._binding import FileBinding, bound_path
from ._callbacks import observe
from ._conversions import to_convention, to_modules
from ._dh_entry import DHEntry
from ._dh_table import DHTable
from ._errors_display import ErrorLabel, collect_errors
from ._exports import ExportsSection
from ._files_section import FilesSection
from ._layout import PANEL_CLASS, stylesheet, view_column, workspace
from ._matrices_view import MatricesView, end_effector_text
from ._module_list import ModuleList
from ._motion_section import MotionSection
from ._preset_menu import PresetMenu
from ._program_run import show_program_motion
from ._program_tab import ProgramTab
from ._ranges import joint_limits, length_scale
from ._reach_moves import show_coordinates
from ._reach_tab import ReachTab
from ._robot_extras import RobotExtras
from ._scene_slot import default_scene_factory
from ._setup_io import setup_parts as setup_from  # (robot, signals, simulation, program)
from ._setup_io import setup_to_json
from ._undo_buttons import UndoButtons
from ._units import LENGTH_UNITS, Units
from ._wizard import Wizard

__all__ = ["Configurator", "configurator"]

_MODES = (("Modules", "modules"), ("DH table", "dh"), ("Guided", "wizard"))
#: The result tabs under the editor and the 3D view (the view is no tab: it stays in
#: sight). Motion first: the matrices' symbolic view is computed only while it shows.
_MOTION_TAB, _MATRICES_TAB, _REACH_TAB, _PROGRAM_TAB, _FILES_TAB = range(5)


def _default_robot() -> Robot:
    return preset("paper")


def length_unit_dropdown(unit: str) -> widgets.Dropdown:
    """The length-unit choice of the header row, showing ``unit``.

    >>> length_unit_dropdown("mm").value, length_unit_dropdown("ft").options[-1]
    ('mm', 'ft')
    """
    # Letters, digits, spaces and dots only: the name goes into descriptions, which
    # MathJax would typeset ($…$), and into HTML.
    if not isinstance(unit, str) or not re.fullmatch(r"[\w µ.]{1,12}", unit):
        raise InvalidInputError(
            "length_unit", unit, f"a unit name of up to 12 letters, such as {LENGTH_UNITS[1:]}"
        )
    return widgets.Dropdown(
        options=tuple(dict.fromkeys((*LENGTH_UNITS, unit))),
        value=unit,
        description="length",
        tooltip=(
            "the unit of the robot's lengths, named in labels, tables and plots "
            "(lengths are not converted: robot files carry no unit)"
        ),
        style={"description_width": "44px"},
        layout=widgets.Layout(width="130px"),
    )


class Configurator:
    """Widget panel: module list / DH table / guided wizard, 3D scene, matrices, motion.

    Parameters
    ----------
    robot : Robot or path-like, optional
        The robot to start with (default: the paper's preset when available), or a
        ``.json`` file to keep the work in: loaded when it exists (robot, signals, time
        settings), and every valid change is saved to it (see :class:`FileBinding`).
    scene_factory : callable, optional
        ``robot -> scene``; the scene needs ``widget``, ``set_robot(robot, q)`` and
        ``update(q)`` (``animate(motion)`` optional). Default: :class:`robotconf.scene.Scene`.
    degrees : bool
        Show angles in degrees (a toggle in the panel switches).
    length_unit : str
        The unit of the robot's lengths, named in every label, table and plot (``"mm"``,
        ``"cm"``, ``"m"``, ``"in"``; default ``"units"``, the paper's plain units). A
        dropdown in the panel switches; lengths are never converted (robot files carry
        no unit), so the core's numbers are the numbers shown.
    t_end, dt : float
        Initial simulation settings (s).
    method : {"analytic", "numeric"}
    scene_height : int
        Height of the default 3D scene (pixels).
    app : bool or None
        ``True`` when no notebook cells surround the panel (an app in Voilà): the panel then
        leaves out its hints to check things in a cell. ``None`` (default) detects Voilà.

    Attributes
    ----------
    robot : Robot
        Always the current valid robot.
    app : bool
        Whether the panel runs as an app (no code hints).
    binding : FileBinding
        The file the panel keeps its work in (``binding.path`` is ``None`` when unbound).
    history : UndoButtons
        The ↶ ↷ buttons and their history of robots (:meth:`undo`, :meth:`redo`).
    motion : Motion or None
        The last simulation (``None`` before Run).
    units : Units
        The length unit's name and degrees or radians, as the header row chooses them.
    view : ipywidgets.VBox
        The end-effector line and the 3D scene: beside the editor, or above it and
        pinned while the editor scrolls (``robotconf/panel/_layout.py``).
    reach : ReachTab
        The Reach tab: a target the robot follows by inverse kinematics.
    program_tab : ProgramTab
        The Program tab: PTP/LIN/CIRC/Wait moves taught, checked and run.
    errors : dict
        Control key → message of every input the core refused right now.

    Examples
    --------
    >>> import robotconf as rc
    >>> paper = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> panel = Configurator(paper)
    >>> panel.robot.end_effector()
    array([70.,  0., 20.])
    >>> panel.modules.rows[1].kind.value = "Rz"  # module 2 becomes a rotation about z
    >>> panel.robot.modules[1]
    Module('Rz', a=(0.0, 0.0, 20.0))
    >>> panel.undo()  # every change of the robot can be undone (and redone)
    >>> panel.robot.modules[1]
    Module('Ry', a=(0.0, 0.0, 20.0))
    >>> panel.motion_section.dt.value = 0.0
    >>> panel.motion_section.run_button.click()
    >>> panel.motion is None, panel.errors["dt"][:29]
    (True, 'dt: must be positive, got 0.0')
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
        saved = self.binding.load()  # (robot, signals, simulation) of the bound file
        if file is not None:
            robot = None if saved is None else saved[0]
        robot = _default_robot() if robot is None else robot
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", robot, "a robotconf Robot, a .json file or None")
        self._robot = robot
        # The editor that shows the robot: DH rows for an all-DH robot, else the modules.
        self._editor_mode = "modules"
        self._preview: Robot | None = None  # what the wizard shows in the scene, if anything
        self._loading = False
        self.title = widgets.HTML("<h3 style='margin:4px 0'>robotconf configurator</h3>")
        self.presets = PresetMenu(robot, self._load_robot, lambda: self._robot)
        self.preset, self.preset_error = self.presets.dropdown, self.presets.error
        self.history = UndoButtons(robot, self._restore)
        self.dh_entry = DHEntry(lambda: self._robot, self._load_converted)
        self.mode = widgets.ToggleButtons(options=_MODES, value="modules")
        self.mode_error = ErrorLabel()
        self.angle_unit = widgets.ToggleButtons(
            options=(("deg", True), ("rad", False)),
            value=degrees,
            tooltips=["angles in degrees", "angles in radians"],
            style={"button_width": "48px"},
        )
        self.angle_unit_error = ErrorLabel()
        self.length_unit = length_unit_dropdown(length_unit)
        self.length_unit.add_class("robotconf-length-unit")
        self.length_unit_error = ErrorLabel()
        self.modules = ModuleList(self._edited)
        self.dh = DHTable(self._edited, self._convert_convention)
        self.wizard = Wizard(
            self._wizard_finished,
            degrees,
            length_scale(robot),
            on_preview=self._wizard_preview,
            on_cancel=self._wizard_cancelled,
        )
        self.extras = RobotExtras(lambda: self._edited("link", None))
        self.matrices = MatricesView(app=self.app)
        self.motion_section = MotionSection(
            lambda: self._robot,
            self._animate,
            t_end=t_end,
            dt=dt,
            method=method,
            app=self.app,
            on_change=self.binding.changed,
            units=self.units,
        )
        self.exports = ExportsSection(
            lambda: self._robot,
            self.motion_section,
            source=lambda: self.binding.name or "configurator panel",
            app=self.app,
        )
        self.files = FilesSection(
            self.to_json, self._load_bytes, app=self.app, exports=self.exports
        )
        self.ee_label = widgets.HTML()
        self.ee_label.add_class("robotconf-ee")
        factory = scene_factory or default_scene_factory(scene_height)
        self.scene = factory(robot)
        # Inverse kinematics: moves the robot like an edit of its q (see _reach_to).
        self.reach = ReachTab(
            lambda: self._robot, self._reach_to, self.history, self.scene, self.units
        )
        self.program_tab = ProgramTab(
            lambda: self._robot,
            self.scene,
            self.units,
            show_motion=lambda m: show_program_motion(self.motion_section, self.scene, m),
            open_motion=lambda: setattr(self.results, "selected_index", _MOTION_TAB),
            on_change=self.binding.changed,
            dt=dt,
            app=self.app,
        )
        self.results = widgets.Tab(
            children=[
                self.motion_section.widget,
                self.matrices.widget,
                self.reach.widget,
                self.program_tab.widget,
                self.files.widget,
            ],
            titles=("Motion", "Matrices", "Reach", "Program", "Save / Load"),
        )
        self._editor_box = widgets.VBox()
        self.view = view_column([self.ee_label, self.scene.widget])
        self.matrices.widget.add_class("robotconf-matrices-tab")  # found by browser tests
        self.widget = widgets.VBox(
            [
                stylesheet(),
                self.title,
                widgets.HBox([self.binding.widget, self.binding.error.widget]),
                widgets.HBox(
                    [
                        self.history.widget,
                        self.preset,
                        self.preset_error.widget,
                        self.mode,
                        self.mode_error.widget,
                        self.angle_unit,
                        self.angle_unit_error.widget,
                        self.length_unit,
                        self.length_unit_error.widget,
                    ],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.dh_entry.widget,
                # The robot stays in sight while its sliders move: beside the editor, or
                # above it and pinned (robotconf/panel/_layout.py).
                workspace(self._editor_box, self.view),
                self.results,
            ],
            layout=widgets.Layout(overflow="visible"),
        )
        self.widget.add_class(PANEL_CLASS)
        self._mode_handler = observe(self.mode, self.mode_error, self._mode_changed)
        observe(self.angle_unit, self.angle_unit_error, lambda c: self._set_degrees(c["new"]))
        observe(self.length_unit, self.length_unit_error, lambda _: self._units_changed())
        # Showing the Matrices tab computes the symbolic view: its failures show there.
        observe(self.results, self.matrices.error, self._tab_changed, "selected_index")
        self.matrices.set_visible(False)
        self._load_robot(robot, first=True)
        if saved is not None and file is not None:  # a bound file: its setup, program too
            self.motion_section.load(saved[1], saved[2])
            self.program_tab.load(setup_from(file)[3])
        self.binding.start()

    # -- public -------------------------------------------------------------------------

    @property
    def robot(self) -> Robot:
        """The current valid robot (the last one every control agreed on)."""
        return self._robot

    @property
    def motion(self) -> Motion | None:
        """The last simulation, or ``None`` before the first successful Run."""
        return self.motion_section.motion

    @property
    def program(self) -> Program | None:
        """The Program tab's last valid program (``None`` while its table is empty)."""
        return self.program_tab.program

    @property
    def units(self) -> Units:
        """The units the panel shows: the length unit's name and degrees or radians."""
        return Units(str(self.length_unit.value), bool(self.angle_unit.value))

    @property
    def errors(self) -> dict[str, str]:
        """``{control key: message}`` for every input the core currently refuses."""
        return dict(collect_errors(self._error_items()))

    def set_robot(self, robot: Robot) -> None:
        """Show ``robot`` in the editors and make it the current robot."""
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", robot, "a robotconf Robot")
        self._load_robot(robot)

    def undo(self) -> None:
        """Go back to the robot before the last change (an edit, a load, a conversion)."""
        self.history.undo()

    def redo(self) -> None:
        """Bring back the robot the last :meth:`undo` left."""
        self.history.redo()

    def to_json(self) -> str:
        """The robot, the signals, the time settings and the program as the core's JSON."""
        signals = self.motion_section.signals()
        if signals is None:
            raise InvalidInputError(
                "signals", "invalid", "valid signals: fix the one marked in red first"
            )
        program = self.program_tab.saved_program(self._robot)
        return setup_to_json(self._robot, signals, self.motion_section.settings(), program)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write :meth:`to_json` to ``path`` (UTF-8, the file replaced in one step)."""
        text = self.to_json()  # an invalid setup is refused before any file is touched
        if self.binding.owns(path):
            self.binding.save_now()  # the binding keeps track of its file's versions
        else:
            write_atomically(path, text)

    def load(self, path: str | os.PathLike[str]) -> None:
        """Load a robot with its signals, time settings and program from a JSON file."""
        self._apply_setup(*setup_from(Path(path)))

    def _load_bytes(self, content: bytes) -> None:
        self._apply_setup(*setup_from(content))

    def _apply_setup(
        self, robot: Robot, signals: dict, simulation: dict | None, program: Program | None
    ) -> None:
        with self.binding.batch():  # the bound file gets the whole setup, once
            self.set_robot(robot)
            self.motion_section.load(signals, simulation)
            self.program_tab.load(program)

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        bundle = self.widget._repr_mimebundle_(**kwargs)
        if isinstance(bundle, dict):
            # A front end without widgets (a console, nbconvert's text) shows the panel's
            # own summary, not the repr of its outermost box.
            bundle = {**bundle, "text/plain": repr(self)}
        return bundle

    def __repr__(self) -> str:
        return f"<Configurator: {self._robot.n} modules, {end_effector_text(self._robot)}>"

    # -- loading ------------------------------------------------------------------------

    def _load_robot(
        self,
        robot: Robot,
        first: bool = False,
        order: Sequence[int | None] | None = None,
        record: bool = True,
    ) -> None:
        """Show ``robot`` in the editor that suits it and make it the current robot.

        ``order`` maps its coordinates to the old ones (a conversion); ``record=False``
        for a robot that comes from the history itself.
        """
        degrees = bool(self.angle_unit.value)
        scale = length_scale(robot)
        all_dh = all(isinstance(link, DHLink) for link in robot.modules)
        self._loading = True
        try:
            self.dh_entry.close()
            self.dh.convention_prompt.close()
            self.modules.load(robot.modules, scale, degrees, joint_limits(robot))
            if all_dh:
                self.dh.load(robot.modules, scale, degrees, joint_limits(robot))  # type: ignore[arg-type]
            self.extras.load(robot.n, robot.active, robot.end_effector_point, scale)
            self._editor_mode = "dh" if all_dh else "modules"
            self.mode.value = self._editor_mode
            self._show_editor()
        finally:
            self._loading = False
        self._accept(robot, order=order, rebuild=not first, first=first, record=record)

    def _load_converted(self, robot: Robot, order: Sequence[int | None]) -> None:
        self._load_robot(robot, order=order)

    def _restore(self, robot: Robot, order: Sequence[int | None] | None) -> None:
        self._load_robot(robot, order=order, record=False)

    def _show_editor(self) -> None:
        mode = self.mode.value
        editors: dict[str, Any] = {"modules": self.modules, "dh": self.dh, "wizard": self.wizard}
        editor = editors[mode]
        children: list[widgets.Widget] = [editor.widget]
        if mode != "wizard":
            children.append(self.extras.widget)
        self._editor_box.children = tuple(children)

    # -- editing ------------------------------------------------------------------------

    def _edited(self, reason: str, order: Sequence[int | None] | None) -> None:
        self._rebuild(reason, order)

    def _rebuild(self, reason: str, order: Sequence[int | None] | None) -> Robot | None:
        """Build and accept the robot the editor shows; ``None`` if the core refuses it."""
        if self._loading:
            return None
        mode = "dh" if self.mode.value == "dh" else "modules"
        editor = self.dh if mode == "dh" else self.modules
        links = editor.links()
        if reason == "structure" and links is not None:
            self.extras.set_count(len(links))
        extras = self.extras.values()
        if links is None or extras is None:
            return None
        active, point = extras
        try:
            robot = Robot(
                links,
                end_effector=point,
                active=None if active >= len(links) else active,
                # A moved joint is still the named robot; any other edit makes a new one.
                name=self._robot.name if reason == "q" else None,
            )
        except InvalidInputError as error:
            label = {"active": self.extras.active_error}.get(error.field, editor.error)
            label.show(str(error))
            return None
        self.extras.active_error.clear()
        structure = reason == "structure"
        # A drag or a burst of typing in one control is one undo step; a row added,
        # removed or moved is always its own.
        self._accept(robot, order=order if structure else None, coalesce=not structure)
        return robot

    def _accept(
        self,
        robot: Robot,
        order: Sequence[int | None] | None = None,
        rebuild: bool = False,
        first: bool = False,
        record: bool = True,
        coalesce: bool = False,
    ) -> None:
        old, self._robot = self._robot, robot
        self._preview = None  # the scene shows the panel's robot from here on
        if not first:
            if not rebuild and robot.n == old.n and robot.with_q(old.q) == old:
                self.scene.update(robot.q)  # only q changed: transforms, no rebuild
            else:
                self.scene.set_robot(robot, robot.q)  # the scene rebuilds if structure changed
        if first or rebuild or order is not None or robot.n != old.n:
            self.motion_section.sync(robot, order)
        elif robot.modules != old.modules:
            self.motion_section.sync(robot)  # units of q may have changed (Rz → Tz)
        else:
            self.motion_section.mark_stale(robot)
        self.matrices.show(robot)
        self.exports.show(robot)
        self.reach.show(robot)
        self.program_tab.show(robot, order)
        self._show_end_effector()
        if record:
            self.history.record(robot, coalesce, None if order is None else list(order))
        self.presets.show(robot)
        self.binding.changed()  # last: the file gets the state every view now shows

    # -- header controls ----------------------------------------------------------------

    def _mode_changed(self, change: dict[str, Any]) -> None:
        """Another editing mode: the same robot in it, or a question; never a silent swap."""
        if self._loading:
            return
        new, old = change["new"], change["old"]
        self.dh_entry.close()
        if old == "wizard":
            self._wizard_preview(None)  # the wizard was left unfinished: show the robot
        if new == "wizard":
            self._show_editor()
            self.wizard.restart()
            return
        if new == self._editor_mode:
            self._show_editor()
            return
        # The selector keeps showing the old mode until the robot is in the new one.
        with self._mode_handler.paused():
            self.mode.value = old
        if new == "modules":
            self._load_converted(*to_modules(self._robot))  # DH rows → modules: same robot
        else:
            self.dh_entry.ask(self.dh.convention.value)  # convert, or start a new table?

    def _convert_convention(self, convention: str) -> None:
        self._load_converted(*to_convention(self._robot, convention))

    def _set_degrees(self, degrees: bool) -> None:
        for editor in (self.modules, self.dh, self.wizard):
            editor.set_degrees(degrees)
        self._units_changed()

    def _units_changed(self) -> None:
        """Every view in the units now chosen; the robot and the signals stay as they are."""
        self.motion_section.set_units(self.units)
        self.reach.set_units(self.units)
        self.program_tab.set_units(self.units)
        self._show_end_effector()

    def _show_end_effector(self) -> None:
        unit = self.units.length
        self.ee_label.value = (
            f"<b>End-effector</b> <code>{html.escape(end_effector_text(self._robot))}</code> "
            f"<small>[{html.escape(unit)}]</small>"
        )

    def _reach_to(self, robot: Robot) -> None:
        """The Reach tab moved the robot: the q controls show it and every view follows;
        the tab records the undo step itself (one per drag)."""
        show_coordinates((self.modules, self.dh), robot.q)
        self._accept(robot, record=False)

    def _wizard_finished(self, robot: Robot) -> None:
        self._load_robot(robot)

    def _wizard_preview(self, robot: Robot | None) -> None:
        """Show the wizard's robot in the scene, or (``None``) the panel's robot again."""
        if robot is None:
            if self._preview is not None:
                self._preview = None
                self.scene.set_robot(self._robot, self._robot.q)
            return
        if robot != self._preview:
            self._preview = robot
            self.scene.set_robot(robot, robot.q)

    def _wizard_cancelled(self) -> None:
        self.mode.value = self._editor_mode

    def _tab_changed(self, change: dict[str, Any]) -> None:
        self.matrices.set_visible(change["new"] == _MATRICES_TAB)
        self.files.set_visible(change["new"] == _FILES_TAB)
        self.reach.set_visible(change["new"] == _REACH_TAB)
        self.program_tab.set_visible(change["new"] == _PROGRAM_TAB)

    def _animate(self, motion: Motion) -> None:
        animate = getattr(self.scene, "animate", None)
        if animate is not None:
            animate(motion)  # the view is always shown: no tab to switch to

    def _error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        yield "preset", self.preset_error
        yield "history", self.history.error
        yield "mode", self.mode_error
        yield "mode.dh", self.dh_entry.prompt.error
        yield "angle_unit", self.angle_unit_error
        yield "length_unit", self.length_unit_error
        yield from self.matrices.error_items()
        yield from self.modules.error_items()
        yield from self.dh.error_items()
        yield from self.extras.error_items()
        yield from self.wizard.error_items()
        yield from self.motion_section.error_items()
        yield from self.files.error_items()
        yield from self.reach.error_items()
        yield from self.program_tab.error_items()
        yield from self.binding.error_items()


def configurator(
    robot: Robot | str | os.PathLike[str] | None = None, **options: Any
) -> Configurator:
    """Build a :class:`Configurator` for ``robot``, display it, and return it.

    Parameters
    ----------
    robot : Robot or path-like, optional
        Default: the paper's R_zR_yR_y preset when available. A ``.json`` file name
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
