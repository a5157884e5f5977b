"""Shared helpers for the cell designer's tests (no tests here).

A recording fake stands in for ``robotconf.scene.CellScene``: the designer talks to it
through the same members (``show(cell, qs)``, ``animate``, ``show_reach_map``,
``clear_reach_map``, ``show_capsules``, ``select``, ``fit_view``, ``export_html``,
``widget``, the playback), so a test sees exactly what the designer asked the view to
draw. ``use(designer, key)`` acts on any control as a student in the page would.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace
from typing import Any

import ipywidgets as widgets
import numpy as np

import robotconf as rc
from robotconf.cell_designer import CellDesigner
from robotconf.panel.form import Form


class FakeCellScene:
    """Records every call; ``cell`` is the last cell shown."""

    def __init__(self, cell: rc.Cell, *, height: int = 480, labels: bool = True) -> None:
        self.cell = cell
        self.height, self.labels = height, labels
        self.widget = widgets.HTML("fake cell scene")
        self.calls: list[tuple[str, Any]] = []
        self.reach_map: Any = None
        self.capsules = False
        self.selected: str | None = None
        self.animation: Any = None
        self.playback_state = SimpleNamespace(
            loaded=False, playing=False, time=0.0, speed=1.0, duration=0.0
        )
        self.on_playback: Any = None
        self.on_request: Any = None

    def _call(self, name: str, value: Any = None) -> None:
        self.calls.append((name, value))

    def show(self, cell: rc.Cell, qs: Any = None) -> None:
        self._call("show", cell)
        self.cell = cell
        self.animation = None
        self.playback_state.loaded = self.playback_state.playing = False

    def animate(self, cell_run: Any, *, speed: float = 1.0, play: bool = True) -> None:
        self._call("animate", cell_run)
        self.animation = cell_run
        state = self.playback_state
        state.loaded, state.playing, state.speed = True, play, speed
        state.duration, state.time = float(cell_run.cycle_time), 0.0

    def play(self) -> None:
        self._call("play")
        self.playback_state.playing = True

    def pause(self) -> None:
        self._call("pause")
        self.playback_state.playing = False

    def seek(self, t: float) -> None:
        self._call("seek", t)
        self.playback_state.time = t

    def set_speed(self, speed: float) -> None:
        self._call("set_speed", speed)
        self.playback_state.speed = speed

    def show_reach_map(self, reach_map: Any) -> None:
        self._call("show_reach_map", reach_map)
        self.reach_map = reach_map

    def clear_reach_map(self) -> None:
        self._call("clear_reach_map")
        self.reach_map = None

    def show_capsules(self, shown: bool) -> None:
        self._call("show_capsules", shown)
        self.capsules = bool(shown)

    def select(self, name: str | None) -> None:
        self._call("select", name)
        self.selected = name

    def fit_view(self) -> None:
        self._call("fit_view")

    def export_html(self, path: Any, title: str = "robotconf cell") -> Path:
        self._call("export_html", path)
        names = ", ".join(sorted(self.cell.entries))
        Path(path).write_text(f"<!doctype html><title>{title}</title><p>{names}</p>", "utf-8")
        return Path(path)

    def count(self, name: str) -> int:
        """How often the designer called ``name``."""
        return sum(1 for call, _ in self.calls if call == name)


class Clock:
    """A clock the test moves: edits of one box more than 1.5 s apart are two undo steps."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        self.now += 10.0  # every edit its own undo step unless a test says otherwise
        return self.now


def make_designer(source: Any = None, **options: Any) -> CellDesigner:
    """A designer drawing into a :class:`FakeCellScene`, each edit its own undo step."""
    designer = CellDesigner(source, scene_factory=FakeCellScene, **options)
    designer._history._clock = Clock()
    return designer


def forms(designer: CellDesigner) -> list[Form]:
    """Every form of the designer."""
    return [
        designer.header.form,
        designer.table.form,
        designer.robots.form,
        designer.reach.form,
        designer.programs_tab.form,
        designer.files.form,
    ]


def show_tab(designer: CellDesigner, title: str) -> None:
    """Click a tab as the student would (its form is drawn while it shows)."""
    from robotconf.cell_designer._designer import TAB_TITLES

    designer.tabs.selected_index = TAB_TITLES.index(title)


#: Which tab shows a control, by the start of its key (the header shows over every tab).
TABS = {
    "Cell": ("entry", "robot", "add."),
    "Reach map": ("reach",),
    "Programs": ("move", "program", "run"),
    "Files": ("save", "scene"),
}


def open_tab_of(designer: CellDesigner, key: str) -> None:
    """Show the tab that holds control ``key`` (its form is drawn while it shows)."""
    for title, prefixes in TABS.items():
        if key.startswith(prefixes):
            show_tab(designer, title)
            return


def use(designer: CellDesigner, key: str) -> Any:
    """Act on control ``key`` as a student in the page (the tab that shows it first)."""
    open_tab_of(designer, key)
    for form in forms(designer):
        if key in form.control_keys():
            return form.user(key)
    raise KeyError(key)


def row_of(designer: CellDesigner, name: str) -> str:
    """The key prefix of the table row showing entry ``name`` (``entry[2]``)."""
    index = designer.state.cell.names.index(name)
    table = "robot" if name in designer.state.cell.robots else "entry"
    return f"{table}[{index}]"


def paper_on_table(unit: str = "mm") -> rc.Cell:
    """The paper's arm on a table with a fixture and a pick point (docs/cell.md)."""
    cell = rc.Cell(unit=unit)
    cell.add(rc.Box([120, 80, 10], pose=rc.pose([40, 0, -5]), name="table"))
    cell.add_robot("arm", rc.preset("paper"), mount="table")
    cell.add(rc.Box([14, 14, 30], pose=rc.pose([5, -25, 20]), name="fixture"), parent="table")
    cell.add_frame("pick", rc.pose([15, 20, 15]), parent="table")
    return cell


def shown_value(designer: CellDesigner, key: str) -> Any:
    """The value control ``key`` shows (its tab opened first)."""
    open_tab_of(designer, key)
    for form in forms(designer):
        if key in form.control_keys():
            return form.control(key)["value"]
    raise KeyError(key)


def same_cell(a: rc.Cell, b: rc.Cell) -> bool:
    """Two cells with equal entries (names, kinds, parents, poses, shapes and robots)."""
    if sorted(a.entries) != sorted(b.entries) or a.unit != b.unit:
        return False
    for name, entry in a.entries.items():
        other = b.entries[name]
        if entry.kind != other.kind or entry.parent != other.parent:
            return False
        if not np.array_equal(entry.pose, other.pose) or entry.shape != other.shape:
            return False
        if entry.kind == "robot" and a.robot(name) != b.robot(name):
            return False
    return True
