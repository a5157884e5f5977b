"""A work cell in the 3D pane: its robots, objects and frames, its runs and reach maps.

:class:`CellScene` is what ``rc.view(cell)`` and ``cell.view()`` show. Like
:class:`~robotconf.scene.Scene` it is a hub of small parts, each given only the scene's
:class:`~robotconf.scene._commands.Outbox`: the robots (``_robots.py``, one robot layer
each, as the Scene draws its robot), the objects and frames with their labels
(``_entities.py``), the collision capsules (``_capsules.py``), the playback (the Scene's
``Playback``, fed one animation for every robot: ``_animation.py`` and
``_contacts.py``), the reach map (``_reach_map.py``) and the selection outline
(``_selection.py``). Positions are in the cell's frame, labels carry the cell's unit.

The interface (the cell designer builds on it):

``CellScene(cell, qs=None, *, height=480, labels=True, frames=False, capsules=False,
controls=True, channel=None, max_rate=60.0)``
    ``qs``: ``{robot name: q}`` (others at their own ``q``); ``labels``: ``True``
    (positions), ``False`` (off) or ``"off" | "names" | "positions"``.
``show(cell, qs=None)``
    Draw ``cell`` (the same object changed, or another one): only what changed is sent —
    a moved object, frame or robot base is one transform, a reshaped object or a new or
    removed entry rebuilds that entry alone, a new ``q`` moves that robot's items. A
    robot not in ``qs`` keeps the ``q`` it was shown at. A loaded run is dropped first.
``animate(cell_run, *, speed=1.0, play=True)``, ``play()``, ``pause()``, ``seek(t)``,
``set_speed(s)``, ``playback_state``, ``on_playback``, ``on_request``
    As :class:`~robotconf.scene.Scene`'s, for a :class:`~robotconf.cell.CellRun`: every
    robot's program on one clock, contacts red during their intervals, labelled at the
    contact point (``contact_labels``). ``on_request`` also gets ``{"kind":
    "capsules", "value": bool}`` from the bar's capsules button.
``show_reach_map(reach_map, *, color_by="branches")``, ``clear_reach_map()``
``show_capsules(visible=True)``, ``select(name or None)``, ``fit_view()``
``set_label_mode(mode)``, ``show_frames(visible)``, ``show_trace(visible)``
``export_html(path, title=None)``, ``widget``, ``receive_from_page(message)``,
``labels()``, ``close()``
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_flag, check_integer, one_line
from ...cell import Cell
from .._commands import Op, Outbox, options_op, scale_command
from .._drawing import SPHERE_RADIUS
from .._fit import camera_op, centring_ops, inside, view_sphere
from .._labels import check_label_mode, label_digits
from .._page import route_message
from .._playback import Playback, PlaybackState
from ._animation import CellAnimation, cell_animation, check_run
from ._capsules import CapsulesLayer
from ._entities import EntitiesLayer
from ._export import cell_bar_choices, names_visibility
from ._paths import CONTACTS, PathKeys
from ._reach_map import ReachMapLayer
from ._robots import RobotsLayer, read_qs
from ._selection import Selection

__all__ = ["CellScene", "TRIAD_SHARE", "RESIZE_FACTOR"]

#: A cell frame's triad length, as a share of the cell's size.
TRIAD_SHARE = 0.08
#: Scale the drawing again when the cell's size changes by more than this factor.
RESIZE_FACTOR = 2.0


class CellScene:
    """A work cell drawn in meshcat's three.js viewer inside the notebook.

    Parameters
    ----------
    cell : Cell
    qs : dict, optional
        ``{robot name: q}``; robots left out stand at their own ``q``.
    height : int
        Pane height in pixels (the bar sits above it).
    labels : {"positions", "names", "off"} or bool
        What the labels show (``True`` is ``"positions"``, ``False`` is ``"off"``).
    frames : bool
        Show the robots' module frames.
    capsules : bool
        Show the robots' collision capsules.
    controls : bool
        Draw the bar above the pane.
    channel : object, optional
        Where ops go (default: a notebook widget; tests pass a
        :class:`~robotconf.scene.RecordingChannel`).
    max_rate : float or None
        Messages per second to the notebook at most.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import CellScene, RecordingChannel
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> cell.add(rc.Box([20, 20, 20], pose=rc.pose([50, 0, 10]), name="fixture"))
    'fixture'
    >>> scene = CellScene(cell, channel=RecordingChannel())
    >>> scene.labels()
    ['M1 (0.0, 0.0, 0.0) mm', 'M2 (0.0, 0.0, 20.0) mm', 'M3 (30.0, 0.0, 20.0) mm', \
'EE (70.0, 0.0, 20.0) mm', 'fixture (50.0, 0.0, 10.0) mm']
    >>> cell.set_pose("fixture", rc.pose([45, 5, 10])); scene.channel.clear()
    >>> scene.show(cell)  # one transform and one label text
    >>> scene.channel.kinds()
    ['transforms', 'labels']
    """

    def __init__(
        self,
        cell: Cell,
        qs: Any = None,
        *,
        height: int = 480,
        labels: bool | str = True,
        frames: bool = False,
        capsules: bool = False,
        controls: bool = True,
        channel: Any = None,
        max_rate: float | None = 60.0,
    ) -> None:
        _check_cell(cell)
        self.height = check_integer(
            height, "height", 100, 4000, "an integer from 100 to 4000 (pixels)"
        )
        label_mode = check_label_mode(labels)
        self._controls_on = check_flag(controls, "controls")
        self.on_request: Callable[[dict[str, Any]], Any] | None = None
        self.on_playback: Callable[[PlaybackState], Any] | None = None
        self._pane: Any = None
        self._shown_in_cell: int | None = None
        if channel is None:
            from .._widget import SceneWidget, WidgetChannel, shared_code

            self._pane = SceneWidget(height=self.height, code=shared_code())
            channel = WidgetChannel(self._pane, self._replay, max_rate=max_rate)
            channel.on_event = self.receive_from_page
        self.channel = channel
        self._outbox = Outbox(channel)
        self._keys = PathKeys()
        self._robots = RobotsLayer(
            self._outbox, self._keys, label_mode, check_flag(frames, "frames")
        )
        self._entities = EntitiesLayer(self._outbox, self._keys)
        self._capsules = CapsulesLayer(self._outbox, self._keys)
        self._capsules.visible = check_flag(capsules, "capsules")
        self._playback = Playback(self._outbox)
        self._reach = ReachMapLayer(self._outbox)
        self._selection = Selection(self._outbox)
        self._animation: CellAnimation | None = None
        self._cell: Cell | None = None
        self._size = 0.0  # the drawing is scaled by 1 / size
        self._fitted = (np.zeros(3), 0.0)
        self._outbox.send([camera_op(), self._options_op(), *names_visibility(label_mode, False)])
        self.show(cell, qs)

    # -- the cell ---------------------------------------------------------------------------

    @property
    def cell(self) -> Cell:
        """The cell shown (as last given to :meth:`show`)."""
        assert self._cell is not None
        return self._cell

    @property
    def qs(self) -> dict[str, np.ndarray]:
        """Each robot's coordinates as shown, ``{name: q (n,)}``."""
        return {name: snap.q.copy() for name, snap in self._robots.snapshots.items()}

    def show(self, cell: Cell, qs: Any = None) -> None:
        """Draw ``cell`` with robots at ``qs`` (``{name: q}``), sending only what changed.

        Robots not in ``qs`` keep the ``q`` they were shown at (their own ``q`` when new).
        A loaded run is dropped first: the pane shows the cell, now and after a reload.

        Raises
        ------
        InvalidInputError
            ``cell`` not a Cell, ``qs`` not a dict of the cell's robots, or a bad ``q``
            (named ``qs['arm'].q``); nothing is drawn then.
        """
        _check_cell(cell)
        snapshots = self._robots.prepare(cell, read_qs(cell, qs))
        self._drop_animation()
        first = self._cell is None
        self._cell = cell
        rebuilt = self._robots.show(cell, snapshots)
        self._entities.show(cell, triad=self._triad(), mode=self.label_mode, digits=self._digits())
        size = self._cell_size()
        rescaled = first or not 1 / RESIZE_FACTOR <= size / self._size <= RESIZE_FACTOR
        if rescaled:
            self._size = size
            self._outbox.send([scale_command(size)])
            # The frames' triads and the labels' clearances follow the cell's size.
            self._entities.show(
                cell, triad=self._triad(), mode=self.label_mode, digits=self._digits()
            )
        self._capsules.follow(cell, snapshots)
        self._selection.follow(self._entities, self._robots, self._triad())
        if rescaled or rebuilt:
            self.fit_view()
        else:
            self._keep_in_view(np.vstack(self._extents()))

    def labels(self) -> list[str]:
        """Every label text shown: the robots' (robot by robot), then the objects' and
        frames' (in the cell's order); none with labels off."""
        texts = self._entities.texts(self.label_mode, self._digits())
        return self._robots.texts() + [text for text in texts if text]

    # -- view options -----------------------------------------------------------------------

    @property
    def label_mode(self) -> str:
        """What the labels show: ``"off"``, ``"names"`` or ``"positions"``."""
        return self._robots.label_mode

    @property
    def frames_shown(self) -> bool:
        """Whether the robots' module frames show."""
        return self._robots.frames

    @property
    def trace_shown(self) -> bool:
        """Whether each robot's TCP path is drawn while a run is loaded."""
        return self._playback.trace

    @property
    def capsules_shown(self) -> bool:
        """Whether the robots' collision capsules show."""
        return self._capsules.visible

    def set_label_mode(self, mode: str) -> None:
        """What every label shows: ``"off"``, ``"names"`` or ``"positions"``."""
        mode = check_label_mode(mode)
        self._robots.set_label_mode(mode)
        self._entities.relabel(mode, self._digits())
        visibility = names_visibility(mode, self._playback.loaded)
        self._outbox.send([*visibility, self._options_op()])

    def show_frames(self, visible: bool = True) -> None:
        """Show or hide the robots' module frames (the cell's frames always show)."""
        self._robots.set_frames(check_flag(visible, "visible"))
        self._outbox.send([self._options_op()])

    def show_trace(self, visible: bool = True) -> None:
        """Draw each robot's TCP path while a run is loaded."""
        self._playback.show_trace(check_flag(visible, "visible"))
        self._outbox.send([self._options_op()])

    def show_capsules(self, visible: bool = True) -> None:
        """Show the robots' collision capsules, see-through (as the checks measure the
        links), or hide them."""
        if visible := check_flag(visible, "visible"):
            self._capsules.catch_up()
        self._capsules.set_visible(visible)
        self._outbox.send([self._options_op()])

    def fit_view(self) -> None:
        """Centre everything drawn and zoom until it fills the pane: the robots, every
        object and frame, the reach map and where a loaded run takes the robots."""
        margin = 1.2 * SPHERE_RADIUS * max(self._robots.size, 0.2 * self._size)
        centre, radius = view_sphere(self._extents(), margin)
        self._fitted = (centre, radius)
        self._outbox.send(centring_ops(centre, radius, self._size))

    # -- selection and reach ----------------------------------------------------------------

    @property
    def selected(self) -> str | None:
        """The outlined entry's name (None: nothing)."""
        return self._selection.name

    def select(self, name: str | None) -> None:
        """Outline an object, a frame (full name) or a robot in amber; ``None`` clears."""
        self._selection.select(name, self._entities, self._robots, self._triad())

    @property
    def reach_map_legend(self) -> str:
        """What the reach map's colours mean (``""`` without a map)."""
        return self._reach.legend

    def show_reach_map(self, reach_map: Any, *, color_by: str = "branches") -> None:
        """Draw a reach map's voxels as points (replacing one shown): unreachable ones
        faint grey, the others from light to dark green by branches (``color_by=
        "manipulability"``: yellow to purple), with a legend; kept in view."""
        self._reach.show(reach_map, color_by, 0.02 * self._size, 1 / self._size)
        self._keep_in_view(self._reach.extent())

    def clear_reach_map(self) -> None:
        """Remove the reach map."""
        self._reach.clear()

    # -- playback ---------------------------------------------------------------------------

    @property
    def playback_state(self) -> PlaybackState:
        """Where the run's animation is: loaded, playing, time, speed, duration."""
        return self._playback.state()

    @property
    def contact_labels(self) -> list[str]:
        """The loaded run's contact labels, one per contact interval (in the check's
        order; the first :data:`~robotconf.scene.workcell._contacts.MAX_CONTACT_LABELS`
        are drawn)."""
        return [] if self._animation is None else [mark.text for mark in self._animation.marks]

    def animate(self, cell_run: Any, *, speed: float = 1.0, play: bool = True) -> None:
        """Play a run of the cell shown: every robot's program side by side on one clock.

        The page plays it to its end by itself; each contact interval of
        ``cell_run.check`` turns its link and the object (or the other link) red while
        the time is inside it, and a label at the contact point names it. Labels of the
        robots show names while the run is loaded; :meth:`show` drops it.

        Parameters
        ----------
        cell_run : CellRun
            From ``cell.run(programs)`` of this scene's cell.
        speed : float
            Playback speed (1 = real time).
        play : bool
            Start playing at once (else the bar's ▶ starts it).
        """
        run = check_run(self.cell, cell_run)
        animation = cell_animation(self.cell, run, self._robots, self._capsules, self._entities)
        self._drop_animation()
        self._outbox.send([*animation.build, *names_visibility(self.label_mode, True)])
        self._playback.load_animation(
            animation.command,
            animation.duration,
            animation.extent,
            animation.traces,
            speed=speed,
            play=play,
        )
        self._animation = animation
        self._robots.set_moving(True)
        self._outbox.send([self._options_op()])

    def play(self) -> None:
        """Play the loaded run (from the start once it has ended)."""
        self._playback.play()

    def pause(self) -> None:
        """Pause the loaded run where it is."""
        self._playback.pause()

    def seek(self, t: float) -> None:
        """Show the loaded run at time ``t`` (s), paused."""
        self._playback.seek(t)

    def set_speed(self, speed: float) -> None:
        """Playback speed: 1 is real time, 2 twice as fast."""
        self._playback.set_speed(speed)

    # -- the page ---------------------------------------------------------------------------

    @property
    def widget(self) -> Any:
        """The widget to place in a layout: the bar and the pane (``None`` with a custom
        channel)."""
        return self._pane

    def receive_from_page(self, message: Any) -> None:
        """Take a message a view sent (formats in :mod:`robotconf.scene._page`); a request
        goes to :attr:`on_request` when set, else the scene applies it."""
        route_message(message, self._playback, self._apply, self.on_request, self.on_playback)

    def export_html(self, path: str | Path, title: str | None = None) -> Path:
        """Write the cell (and a loaded run) as one self-contained HTML file that opens
        offline: the run plays, its contacts turn red, the bar works.

        Parameters
        ----------
        path : str or pathlib.Path
        title : str, optional
            The page's title (default: the cell's name, else ``"work cell"``).

        Returns
        -------
        pathlib.Path
        """
        from .._html import page_title, scene_html

        target = Path(path)
        title = page_title(title, self.cell.name or "work cell")
        ops = self._replay(from_start=True)
        target.write_text(scene_html(ops, self._bar_choices(), title=title), "utf-8")
        return target

    def close(self) -> None:
        """Close the widget (its views release their WebGL contexts)."""
        self.channel.close()

    def _ipython_display_(self) -> None:
        from .._view import display_once

        display_once(self)

    def __repr__(self) -> str:
        return f"<CellScene of {self.cell!r}>"

    # -- building blocks --------------------------------------------------------------------

    def _apply(self, request: dict[str, Any]) -> None:
        """A request from the bar, applied here (no :attr:`on_request`)."""
        kind = request["kind"]
        if kind == "labels":
            self.set_label_mode(request["mode"])
        elif kind == "frames":
            self.show_frames(request["value"])
        elif kind == "trace":
            self.show_trace(request["value"])
        elif kind == "capsules":
            self.show_capsules(request["value"])
        elif kind == "fit":
            self.fit_view()

    def _options_op(self, **changes: Any) -> Op:
        options = {
            "labels": self.label_mode,
            "frames": self.frames_shown,
            "trace": self.trace_shown,
            "controls": self._controls_on,
            "capsules": self.capsules_shown,
            **changes,
        }
        return options_op(**options)

    def _bar_choices(self) -> dict[str, Any]:
        return cell_bar_choices(
            self._robots,
            self._entities,
            self._capsules,
            self._playback,
            self._outbox.log,
            self._options_op,
            self._digits(),
        )

    def _replay(self, *, from_start: bool = False) -> list[Op]:
        self._capsules.catch_up()  # a new view (or a page) may switch them on
        return self._playback.replay(self._outbox.log.ops(), from_start=from_start)

    def _drop_animation(self) -> None:
        if not self._playback.loaded:
            return
        self._outbox.send_live(self._playback.drop())
        self._outbox.delete(CONTACTS)
        self._robots.set_moving(False)
        self._animation = None

    def _digits(self) -> int:
        return self._robots.digits if self._robots.layers else label_digits(self._size)

    def _triad(self) -> float:
        return TRIAD_SHARE * self._size

    def _cell_size(self) -> float:
        """The cell's size: its largest robot's, or the diagonal of the box around
        everything drawn, whichever is larger (1 for an empty cell)."""
        every = np.vstack([self._robots.extent(), self._entities.extent()])
        diagonal = float(np.linalg.norm(np.ptp(every, axis=0))) if len(every) else 0.0
        size = max(self._robots.size, diagonal)
        return size if size > 0 and np.isfinite(size) else 1.0

    def _extents(self) -> list[np.ndarray]:
        return [
            self._robots.extent(),
            self._entities.extent(),
            self._reach.extent(),
            self._playback.extent(),
        ]

    def _keep_in_view(self, points: np.ndarray) -> None:
        centre, radius = self._fitted
        if not inside(points, centre, radius):
            self.fit_view()


def _check_cell(cell: Any) -> None:
    if not isinstance(cell, Cell):
        raise InvalidInputError("cell", one_line(cell), "a robotconf Cell", problem="not a cell:")
