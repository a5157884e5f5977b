"""The cell designer: one state, every view drawn from it, every click one action.

:class:`CellDesigner` holds one immutable :class:`~robotconf.cell_designer.state.DesignerState`.
What the student does reaches it as one action (``designer.apply(SetPose("table", 2,
-5.0))``, see :mod:`robotconf.cell_designer.actions`); the action gives the next state,
the history records its document (the cell and the programs), every view draws itself
from it (the tables, the reach map, the programs, the 3D view) and the bound cell file
saves it. No widget holds truth: ``designer.cell`` is always the cell on screen.
"""

from __future__ import annotations

import os
import tempfile
import threading
from collections.abc import Callable, Hashable
from pathlib import Path
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..cell import Cell, CellRun, ReachMap
from ..io import cell_to_json, load_cell
from ..panel.files import file_stem, write_atomically
from ..panel.state import History
from ..panel.support import (
    LOGGER,
    ErrorLabel,
    failure_message,
    observe,
    stylesheet,
    view_column,
    workspace,
)
from ..presets import preset
from ..programs import Program
from . import actions as act
from ._binding import CellBinding, cell_path
from ._scene_slot import default_scene_factory
from ._view_sync import ViewSync
from .state import CellDescription, DesignerDocument, DesignerState, RobotProgram, target_of
from .views import (
    FilesView,
    HeaderView,
    Messages,
    ProgramsView,
    ReachView,
    RobotsView,
    TableView,
    length_step,
    mesh_from_upload,
)

__all__ = ["CellDesigner", "cell_designer", "TAB_TITLES", "DESIGNER_CLASS"]

#: The tabs of the designer's left column.
TAB_TITLES = ("Cell", "Reach map", "Programs", "Files")
#: The designer's outer box (browser tests and the stylesheet find it).
DESIGNER_CLASS = "robotconf-cell-designer"


def _starting_cell(
    source: Any, loaded: Any, length_unit: str | None
) -> tuple[Cell, dict[str, Any]]:
    if loaded is not None:
        return loaded
    if isinstance(source, Cell):
        return source, {}
    cell = Cell(unit=length_unit)  # a new (or unreadable) file starts as no file does:
    cell.add_robot("arm", preset("paper"))  # the paper's arm, something to start from
    return cell, {}


def _layout_key(state: DesignerState) -> Hashable:
    """What the controls' keys mean: the rows, the moves and their targets, the units."""
    moves = tuple(
        (robot, tuple((m.kind, target_of(m)) for m in program.moves))
        for robot, program in state.document.programs
    )
    return (state.cell.names, moves, state.units)


class CellDesigner:
    """The cell designer: tables of objects, frames and robots, the reach map, programs
    and Run, beside the cell's 3D view (docs/cell.md, "Designer").

    Parameters
    ----------
    cell_or_path : Cell or path-like, optional
        The cell to start with (default: the paper's arm alone), or a ``.json`` cell file
        to keep the work in: loaded when it exists (with its programs), else created
        with the paper's arm, and every valid change saved to it.
    length_unit : str, optional
        The cell's length unit (a name: no number changes); default the cell's own.
    degrees : bool
        Show angles in degrees (the header switches).
    scene_factory : callable, optional
        ``cell -> view`` (default :class:`robotconf.scene.CellScene`); see
        ``robotconf/cell_designer/_scene_slot.py`` for the members it needs.
    scene_height : int
        Height of the 3D view (pixels).

    Examples
    --------
    >>> from robotconf.cell_designer import actions as act
    >>> designer = CellDesigner(scene_factory=lambda cell: _Quiet())
    >>> designer.apply(act.AddObject("box"))
    >>> designer.apply(act.SetPose("box1", 0, 50.0))
    >>> designer.cell.pose_of("box1")[:3, 3]
    array([50.,  0.,  5.])
    >>> designer.undo(); designer.cell.pose_of("box1")[:3, 3]
    array([25.,  0.,  5.])
    >>> designer.table.form.user("entry[1].size0").type("abc")
    >>> designer.errors["entry[1].size0"]
    "box1.size[0]: not a number: 'abc'; allowed: a number such as 12, -0.5 or 1e-3"
    """

    def __init__(
        self,
        cell_or_path: Cell | str | os.PathLike[str] | None = None,
        *,
        length_unit: str | None = None,
        degrees: bool = True,
        scene_factory: Callable[[Any], Any] | None = None,
        scene_height: int = 480,
    ):
        path = cell_path(cell_or_path)
        self.binding = CellBinding(path, self.to_json)
        loaded = self.binding.load()
        start, programs = _starting_cell(cell_or_path, loaded, length_unit)
        description = CellDescription.from_cell(start)
        if length_unit is not None:
            description = (
                act.SetLengthUnit(length_unit)
                .apply(DesignerState(DesignerDocument(description)))
                .cell
            )
        document = DesignerDocument(description).with_cell(description)
        for robot, (moves, options) in programs.items():
            document = document.with_program(robot, RobotProgram.of(moves, options))
        self._state = DesignerState(document, degrees=bool(degrees))
        self._history: History[DesignerDocument] = History(document)
        self._layout = 0
        self._tab = 0
        self._rendering = False
        # The forms' events may run on a kernel subshell's thread and the tabs' clicks on
        # the main one: one change at a time, in arrival order.
        self._lock = threading.RLock()
        self.messages = Messages()
        # -- the views --------------------------------------------------------------
        self.title = widgets.HTML("<h3 style='margin:4px 0'>robotconf cell designer</h3>")
        self.header = HeaderView(self._dispatch, self.undo, self.redo, self._can)
        self.table = TableView(self._dispatch)
        self.robots = RobotsView(self._dispatch)
        self.reach = ReachView(self._dispatch)
        self.programs_tab = ProgramsView(self._dispatch)
        self.files = FilesView(self._dispatch, self.to_json, self._scene_page, self._stem)
        self.mesh_upload = widgets.FileUpload(
            accept=".stl,.obj", multiple=False, description="mesh"
        )
        self.mesh_error = ErrorLabel()
        self._uploaded = observe(self.mesh_upload, self.mesh_error, self._mesh_uploaded)
        cell_tab = widgets.VBox(
            [
                widgets.HTML("<b>Objects and frames</b> (poses in the parent's frame)"),
                self.table.form,
                widgets.HBox(
                    [
                        widgets.HTML("load a mesh (STL or OBJ):"),
                        self.mesh_upload,
                        self.mesh_error.widget,
                    ]
                ),
                widgets.HTML("<b>Robots</b> (base poses in the parent's frame)"),
                self.robots.form,
            ]
        )
        self.tabs = widgets.Tab(
            children=[cell_tab, self.reach.form, self.programs_tab.form, self.files.form],
            titles=TAB_TITLES,
        )
        self._view_error = ErrorLabel()
        observe(self.tabs, self._view_error, self._tab_clicked, "selected_index")
        factory = scene_factory or default_scene_factory(scene_height)
        self.scene = factory(description.cell)
        self._view = ViewSync(self.scene, description)
        self.widget = widgets.VBox(
            [
                stylesheet(),
                self.title,
                self.binding.widget,
                self.binding.error.widget,
                self.header.form,
                workspace(self.tabs, view_column([self.scene.widget])),
                self._view_error.widget,
            ],
            layout=widgets.Layout(overflow="visible"),
        )
        self.widget.add_class(DESIGNER_CLASS)
        self._render()
        self.binding.start()

    # -- the state ----------------------------------------------------------------------

    @property
    def state(self) -> DesignerState:
        """Everything the designer shows, as one immutable value."""
        return self._state

    @property
    def cell(self) -> Cell:
        """A new :class:`~robotconf.Cell` equal to the one on screen (yours to change)."""
        return self._state.cell.build()

    @property
    def programs(self) -> dict[str, tuple[Any, dict[str, Any]]]:
        """``{robot: (moves, options)}``: each robot's program as the cell file keeps it."""
        return self._state.document.file_programs()

    def program(self, robot: str) -> Program:
        """The :class:`~robotconf.programs.Program` Run plans for ``robot``
        (``cell.program(robot, moves, **options)``; refused as Run refuses it)."""
        moves, options = self.programs.get(robot, ((), {}))
        return self._state.cell.cell.program(robot, list(moves), **options)

    @property
    def run(self) -> CellRun | None:
        """The last Run's result (``cell.run(…)``), ``None`` before one."""
        return None if self._state.run is None else self._state.run.run

    @property
    def reach_map(self) -> ReachMap | None:
        """The reach map on screen (``cell.reach_map(…)``), ``None`` while it is off."""
        outcome = self._state.reach_map
        return outcome.result if self._state.reach.on and outcome is not None else None

    @property
    def errors(self) -> dict[str, str]:
        """``{control key: message}`` for every input refused right now, and the file's."""
        found = dict(self.messages.items())
        for key, label in (
            ("file", self.binding.error),
            ("mesh", self.mesh_error),
            ("view", self._view_error),
        ):
            if label.message:
                found[key] = label.message
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
        """Apply one action (see :mod:`robotconf.cell_designer.actions`) and show it.

        Raises
        ------
        InvalidInputError
            The core refuses the result; the designer keeps its state.
        """
        with self._lock:
            self._commit(action.apply(self._state), action)

    def undo(self) -> None:
        """Go back to the document before the last change (the cell and the programs)."""
        with self._lock:
            self._go(self._history.undo())

    def redo(self) -> None:
        """Bring back the document the last :meth:`undo` left."""
        with self._lock:
            self._go(self._history.redo())

    # -- files --------------------------------------------------------------------------

    def to_json(self, path: str | os.PathLike[str] | None = None) -> str:
        """The cell file's text with every robot's program; mesh paths relative to
        ``path``'s folder (default: the bound file's)."""
        where = self.binding.path if path is None else path
        document = self._state.document
        return cell_to_json(document.cell.cell, where, programs=document.file_programs())

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write the cell file to ``path`` (replaced in one step)."""
        if self.binding.owns(path):
            self.binding.save_now()
        else:
            write_atomically(path, self.to_json(path) + "\n")

    def load(self, path: str | os.PathLike[str]) -> None:
        """Load a cell file with its programs (one undo step)."""
        cell, programs = load_cell(path, with_programs=True)
        description = CellDescription.from_cell(cell)
        document = DesignerDocument(description)
        for robot, (moves, options) in programs.items():
            document = document.with_program(robot, RobotProgram.of(moves, options))
        self.apply(act.LoadDocument(document))

    def export_html(self, path: str | os.PathLike[str], title: str | None = None) -> Any:
        """The 3D view as one HTML page that opens offline (the last run animated)."""
        return self.scene.export_html(path, title=title or self._stem())

    def _scene_page(self, title: str) -> str:
        with tempfile.TemporaryDirectory() as folder:
            page = Path(folder, "scene.html")
            self.scene.export_html(page, title=title)
            return page.read_text("utf-8")

    def _stem(self) -> str:
        if self.binding.path is not None:
            return file_stem(self.binding.path.stem, "cell")
        return file_stem(self._state.cell.name, "cell")

    # -- the one flow -------------------------------------------------------------------

    def _dispatch(self, action: Any, key: str, typed: str | None = None) -> None:
        """What a view asks for: an action (applied), a refusal (shown beside ``key``),
        or ``None`` (draw again). Nothing a student does raises out of a widget."""
        with self._lock:
            self._dispatch_now(action, key, typed)

    def _dispatch_now(self, action: Any, key: str, typed: str | None) -> None:
        if action is None:
            self.messages.accepted(key)
            self._render()
            return
        if isinstance(action, BaseException):
            self.messages.refused(key, failure_message(action), typed)
            self._render()
            return
        try:
            new = action.apply(self._state)
        except Exception as error:  # every failure is shown; the kernel never sees one
            if not isinstance(error, InvalidInputError):
                LOGGER.exception("cell designer action %r failed", action)
            self.messages.refused(key, failure_message(error), typed)
            self._render()
            return
        self.messages.accepted(key)
        self._commit(new, action)

    def _commit(self, new: DesignerState, action: act.Action) -> None:
        old = self._state
        changed = new.document is not old.document
        if changed:
            self._history.record(new.document, action.gesture)
            self.messages.accepted("run")  # Run's refusal was about the old document
        if _layout_key(new) != _layout_key(old):
            self._layout += 1
        self._state = new
        fit = isinstance(action, (act.AddRobot, act.LoadDocument))
        self._render(play=isinstance(action, act.Run), fit=fit)
        if changed:
            self.binding.changed()

    def _go(self, document: DesignerDocument | None) -> None:
        if document is None:
            return
        self.messages.clear()  # the tables show the document again: old refusals go
        self._state = self._state.with_document(document)
        self._layout += 1
        self._render()
        self.binding.changed()

    def _can(self) -> tuple[bool, bool]:
        return self._history.can_undo, self._history.can_redo

    # -- drawing ------------------------------------------------------------------------

    def _render(self, *, play: bool = False, fit: bool = False) -> None:
        """Every view draws itself from the state (the hidden tabs when shown); a view
        that fails says so, and the others still draw."""
        if self._rendering:
            return
        self._rendering = True
        failures: list[str] = []
        try:
            state, messages, rev = self._state, self.messages, str(self._layout)
            messages.units = state.units
            step = length_step(act.cell_size(state))
            views: list[tuple[str, Callable[[], None]]] = [
                ("header", lambda: self.header.render(state, messages, rev))
            ]
            if self._tab == 0:
                views.append(("table", lambda: self.table.render(state, messages, rev, step)))
                views.append(("robots", lambda: self.robots.render(state, messages, rev, step)))
            elif self._tab == 1:
                views.append(("reach map", lambda: self.reach.render(state, messages, rev, step)))
            elif self._tab == 2:
                views.append(
                    ("programs", lambda: self.programs_tab.render(state, messages, rev, step))
                )
            else:
                views.append(("files", lambda: self.files.render(state, messages, rev)))
            views.append(("3D view", lambda: self._view.follow(state, play=play, fit=fit)))
            for name, draw in views:
                try:
                    draw()
                except Exception as error:  # one view's bug must not stop the others
                    LOGGER.exception("drawing the designer's %s failed", name)
                    failures.append(f"{name}: {failure_message(error)}")
        finally:
            self._rendering = False
        if failures:
            self._view_error.show("; ".join(failures))
        else:
            self._view_error.clear()

    def _tab_clicked(self, change: dict[str, Any]) -> None:
        if change["new"] is None:
            return
        with self._lock:  # a click made while another thread works waits for it
            self._tab = int(change["new"])
            self._render()

    def _mesh_uploaded(self, change: dict[str, Any]) -> None:
        files = change["new"]
        if not files:
            return
        upload = files[0]
        folder = None
        if self.binding.path is not None and not self.binding.refused:
            folder = self.binding.path.resolve().parent
        try:
            mesh, label = mesh_from_upload(bytes(upload["content"]), str(upload["name"]), folder)
        finally:
            with self._uploaded.paused():
                self.mesh_upload.value = ()  # the same file may be uploaded again
        self._dispatch(act.AddMesh(mesh, label), "mesh")

    # -- display ------------------------------------------------------------------------

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        bundle = self.widget._repr_mimebundle_(**kwargs)
        if isinstance(bundle, dict):
            bundle = {**bundle, "text/plain": repr(self)}
        return bundle

    def __repr__(self) -> str:
        return f"<CellDesigner: {self._state.cell.cell!r}>"


class _Quiet:
    """A view that draws nothing (the docstring's example runs without a browser)."""

    widget = widgets.HTML()

    def __getattr__(self, name: str) -> Callable[..., None]:
        return lambda *args, **kwargs: None


def cell_designer(
    cell_or_path: Cell | str | os.PathLike[str] | None = None, **options: Any
) -> CellDesigner:
    """Build a :class:`CellDesigner`, display it, and return it.

    Parameters
    ----------
    cell_or_path : Cell or path-like, optional
        Default: the paper's arm alone. A ``.json`` file name
        (``rc.cell_designer("my_cell.json")``) keeps the work in that cell file: loaded
        when it exists, created otherwise, every valid change saved to it.
    **options
        Passed to :class:`CellDesigner` (``length_unit``, ``degrees``, ``scene_factory``,
        ``scene_height``).
    """
    designer = CellDesigner(cell_or_path, **options)
    from IPython.display import display

    display(designer)
    return designer
