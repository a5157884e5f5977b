"""The robot in a 3D pane: Figure 14 of the paper, live in the notebook.

:class:`Scene` draws a :class:`~robotconf.kinematics.RobotSnapshot` (``robot.at(q)``, one
kernel pass): it builds the robot's objects once and, for each new snapshot, sends only
the transforms and label texts that changed. Every position it shows comes from the core,
so ``robot.end_effector(q)`` in a cell gives the number on the red sphere's label.

The scene is a hub of small parts, each given only the scene's :class:`Outbox` (and the
drawing's size where it needs it): the robot (``_robot_layer.py``), ghost robots
(``_ghosts.py``), the target marker (``_target.py``), a program's taught points
(``_taught_points.py``) and the animation's playback (``_playback.py``). The bar above the
pane and the animation's clock live in the page (``js/``); the page sends back the
student's requests and playback reports (``_page.py``).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_flag, check_integer, one_line
from ..kinematics import Robot, RobotSnapshot
from ._commands import Op, Outbox, options_op
from ._drawing import SPHERE_RADIUS, RobotDrawing
from ._fit import camera_op, centring_ops, inside, view_sphere
from ._ghosts import GhostsLayer
from ._labels import check_label_mode
from ._page import route_message
from ._playback import Playback, PlaybackState
from ._points import PointClouds
from ._robot_layer import RobotLayer
from ._target import TargetMarker
from ._taught_points import TaughtPointsLayer

__all__ = ["Scene"]


class Scene:
    """A robot drawn in meshcat's three.js viewer inside the notebook.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Initial coordinates; default: the modules' own ``q``.
    height : int
        Pane height in pixels (the bar sits above it).
    labels : {"positions", "names", "off"} or bool
        What the labels show: ``EE (70.0, 0.0, 20.0)``, ``EE``, or nothing (``True`` is
        ``"positions"``, ``False`` is ``"off"``).
    frames : bool
        Show an RGB triad (x red, y green, z blue) at every module frame.
    controls : bool
        Draw the bar above the pane (play, speed, time, fit, labels, frames, trace).
    channel : object, optional
        Where ops go: default a notebook widget; tests pass a
        :class:`~robotconf.scene.RecordingChannel` (and play the page with
        :meth:`receive_from_page`).
    max_rate : float or None
        Messages per second to the notebook at most (default 60).

    Attributes
    ----------
    on_request : callable or None
        Called with the student's requests from the bar (a dict, see
        :mod:`robotconf.scene._page`) instead of applying view options here: a panel turns
        them into its own actions and calls :meth:`set_label_mode`, :meth:`show_frames`,
        :meth:`show_trace` or :meth:`fit_view` back. Playback the student started in the
        bar is reported too (``"play"``, ``"pause"``, ``"seek"`` with ``"time"``,
        ``"speed"`` with ``"value"``), after the page has done it.
    on_playback : callable or None
        Called with the new :class:`PlaybackState` whenever the page reports a change
        (play, pause, seek, speed, end); never for the kernel's own commands.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, Scene
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> scene = Scene(robot, channel=RecordingChannel())
    >>> scene.labels()[-1]
    'EE (70.0, 0.0, 20.0)'
    >>> scene.show(robot.at([0, 0.5, 0]))
    >>> scene.channel.kinds()[-2:]
    ['transforms', 'labels']
    """

    def __init__(
        self,
        robot: Robot,
        q: Any = None,
        *,
        height: int = 420,
        labels: bool | str = True,
        frames: bool = False,
        controls: bool = True,
        channel: Any = None,
        max_rate: float | None = 60.0,
    ) -> None:
        _check_robot(robot)
        self.height = check_integer(
            height, "height", 100, 4000, "an integer from 100 to 4000 (pixels)"
        )
        label_mode = check_label_mode(labels)
        frames = check_flag(frames, "frames")
        self._controls_on = check_flag(controls, "controls")
        self.on_request: Callable[[dict[str, Any]], Any] | None = None
        self.on_playback: Callable[[PlaybackState], Any] | None = None
        self._pane: Any = None
        self._shown_in_cell: int | None = None
        if channel is None:
            from ._widget import SceneWidget, WidgetChannel, shared_code

            self._pane = SceneWidget(height=self.height, code=shared_code())
            channel = WidgetChannel(self._pane, self._replay, max_rate=max_rate)
            channel.on_event = self.receive_from_page
        self.channel = channel
        self._outbox = Outbox(channel)
        self._robot = RobotLayer(self._outbox, label_mode, frames)
        self._ghosts = GhostsLayer(self._outbox, self._size)
        self._target = TargetMarker(self._outbox, self._size)
        self._taught = TaughtPointsLayer(self._outbox, self._size, lambda: self._robot.digits)
        self._playback = Playback(self._outbox)
        self._clouds = PointClouds(self._outbox)
        self._fitted = (np.zeros(3), 0.0)  # the sphere the view was last fitted to
        self._outbox.send([camera_op(), self._options_op()])
        self.show(robot.at(q))

    # -- the robot --------------------------------------------------------------------------

    @property
    def snapshot(self) -> RobotSnapshot:
        """The snapshot shown (the robot at :attr:`q`)."""
        snapshot = self._robot.snapshot
        assert snapshot is not None
        return snapshot

    @property
    def robot(self) -> Robot:
        """The robot shown."""
        return self.snapshot.robot

    @property
    def q(self) -> np.ndarray:
        """The coordinates shown, shape (n,)."""
        return self.snapshot.q

    def show(self, snapshot: RobotSnapshot) -> None:
        """Draw ``snapshot.robot`` at ``snapshot.q`` from the snapshot's own numbers.

        Objects are rebuilt only when the robot's structure changes (or its size by more
        than a factor of 2; the view is then fitted again); otherwise one message carries
        the transforms and label texts that changed. A loaded animation is dropped first:
        the pane shows the snapshot, now and after a page reload.

        Parameters
        ----------
        snapshot : RobotSnapshot
            From :meth:`Robot.at <robotconf.Robot.at>`.
        """
        if not isinstance(snapshot, RobotSnapshot):
            raise InvalidInputError(
                "snapshot", one_line(snapshot), "a RobotSnapshot from robot.at(q)"
            )
        if self._playback.loaded:
            self._outbox.send_live(self._playback.drop())
            self._robot.set_moving(False)
        if self._robot.show(snapshot):
            self._playback.forget()  # its targets went with the old objects
            self.fit_view()

    def set_robot(self, robot: Robot, q: Any = None) -> None:
        """Show another robot: ``show(robot.at(q))`` (``q`` default: the robot's own)."""
        _check_robot(robot)
        self.show(robot.at(q))

    def update(self, q: Any) -> None:
        """Move the shown robot to ``q`` (n,): ``show(scene.robot.at(q))``.

        Raises
        ------
        InvalidInputError
            For a bad ``q``, or a trajectory of shape (T, n): :meth:`animate` plays a motion.
        """
        self.show(self.robot.at(q))

    def labels(self) -> list[str]:
        """The position labels of the robot shown: ``["M1 (…)", …, "EE (…)"]``."""
        return self._robot.labels()

    # -- view options -----------------------------------------------------------------------

    @property
    def label_mode(self) -> str:
        """What the labels show: ``"off"``, ``"names"`` or ``"positions"``."""
        return self._robot.label_mode

    @property
    def frames_shown(self) -> bool:
        """Whether the module frames' triads are shown."""
        return self._robot.frames

    @property
    def trace_shown(self) -> bool:
        """Whether the end-effector's path is drawn during an animation."""
        return self._playback.trace

    def set_label_mode(self, mode: str) -> None:
        """What the labels show: ``"off"``, ``"names"`` or ``"positions"`` (the taught
        points' labels hide with ``"off"`` too)."""
        mode = check_label_mode(mode)
        self._robot.set_label_mode(mode)
        self._taught.set_labels_visible(mode != "off")
        self._outbox.send([self._options_op()])

    def show_labels(self, visible: bool = True) -> None:
        """Show the position labels, or hide every label (see :meth:`set_label_mode`)."""
        self.set_label_mode("positions" if check_flag(visible, "visible") else "off")

    def show_frames(self, visible: bool = True) -> None:
        """Show or hide the RGB triads at the module frames (x red, y green, z blue)."""
        self._robot.set_frames(check_flag(visible, "visible"))
        self._outbox.send([self._options_op()])

    def show_trace(self, visible: bool = True) -> None:
        """Draw the end-effector's path (a line through the motion's EE positions) while
        an animation is loaded."""
        self._playback.show_trace(check_flag(visible, "visible"))
        self._outbox.send([self._options_op()])

    def fit_view(self) -> None:
        """Centre everything drawn and zoom until it fills the pane.

        The sphere holds the robot at its current ``q`` (base, frames, joint axes, end
        effector), the ghosts, the target marker, the taught points, the point clouds and
        where a loaded animation takes the robot.
        The camera keeps its direction; the scene's centre moves to the sphere's centre.
        """
        drawing = self._drawing()
        centre, radius = view_sphere(self._extents(), 1.2 * SPHERE_RADIUS * drawing.size)
        self._fitted = (centre, radius)
        self._outbox.send(centring_ops(centre, radius, drawing.size))

    # -- playback ---------------------------------------------------------------------------

    @property
    def playback_state(self) -> PlaybackState:
        """Where the animation is: loaded, playing, time (estimated while playing), speed,
        duration."""
        return self._playback.state()

    def animate(self, motion: Any, *, speed: float = 1.0, play: bool = True) -> None:
        """Play a simulated motion in the pane; the page plays it to its end by itself.

        Labels show names only while the animation is loaded: the page replays
        transforms, and a number that does not follow the robot would be wrong. The view
        stays (the student chose it); **fit** then takes in the whole motion.
        :meth:`show` (or ``update``) drops the animation and brings the numbers back.

        Parameters
        ----------
        motion : Motion
            From :func:`robotconf.simulate` with this scene's robot.
        speed : float
            Playback speed (1 = real time).
        play : bool
            Start playing at once (else the bar's ▶ starts it).
        """
        self._playback.load(self._drawing(), motion, speed=speed, play=play)
        self._robot.set_moving(True)
        self._outbox.send([self._options_op()])

    def play(self) -> None:
        """Play the loaded animation (from the start once it has ended)."""
        self._playback.play()

    def pause(self) -> None:
        """Pause the loaded animation where it is."""
        self._playback.pause()

    def seek(self, t: float) -> None:
        """Show the loaded animation at motion time ``t`` (s), paused."""
        self._playback.seek(t)

    def set_speed(self, speed: float) -> None:
        """Playback speed of the animation: 1 is real time, 2 twice as fast."""
        self._playback.set_speed(speed)

    # -- beside the robot -------------------------------------------------------------------

    @property
    def ghost_count(self) -> int:
        """How many ghost robots the pane shows."""
        return self._ghosts.count

    @property
    def target_shown(self) -> bool:
        """Whether the target marker is drawn."""
        return self._target.shown

    @property
    def taught_labels(self) -> list[str]:
        """The label of every taught point shown (``""`` where merged into another's)."""
        return self._taught.labels

    def show_ghosts(self, robot: Robot, qs: Any) -> None:
        """Draw faint copies of ``robot`` at each row of ``qs`` (k, n), replacing earlier
        ones (:meth:`GhostsLayer.show <robotconf.scene._ghosts.GhostsLayer.show>`); the
        view widens if one would be outside it."""
        self._ghosts.show(robot, qs)
        self._keep_in_view(self._ghosts.extent())

    def clear_ghosts(self) -> None:
        """Remove every ghost robot."""
        self._ghosts.clear()

    def show_target(self, point_or_pose: Any, reachable: bool = True) -> None:
        """Mark a target point (3,) or pose (4, 4): violet when ``reachable``, orange-red
        otherwise (:class:`~robotconf.scene._target.TargetMarker`); a target outside the
        view is brought into it."""
        self._target.show(point_or_pose, reachable)
        self._keep_in_view(self._target.extent())

    def clear_target(self) -> None:
        """Remove the target marker."""
        self._target.clear()

    def show_taught_points(
        self, points: Any, labels: Any = None, via: Any = None, via_labels: Any = None
    ) -> None:
        """Mark a program's taught points (k, 3) and CIRC via points (m, 3), labelled
        ``P1 …`` and ``via 1 …`` unless given
        (:meth:`TaughtPointsLayer.show <robotconf.scene._taught_points.TaughtPointsLayer.show>`);
        every marker is kept in view."""
        self._taught.show(points, labels, via=via, via_labels=via_labels)
        self._keep_in_view(self._taught.extent())

    def clear_taught_points(self) -> None:
        """Remove the taught points' markers."""
        self._taught.clear()

    def add_point_cloud(
        self, name: str, points: Any, color: Any = (0.2, 0.4, 0.9), size: float | None = None
    ) -> None:
        """Draw points (N, 3) in the base frame, e.g. a workspace, as cloud ``name``
        (replacing one of that name); RGB ``color`` (3,) or (N, 3) in 0…1, point ``size``
        in length units (default 1 % of the robot's size). The view widens to hold them."""
        # three.js sizes points in the viewer's units, which the drawing's scale never
        # reaches: the size is scaled here as every position is.
        self._clouds.add(name, points, color, (size or 0.01 * self._size()) / self._size())
        self._keep_in_view(self._clouds.extent())

    # -- the page ---------------------------------------------------------------------------

    @property
    def widget(self) -> Any:
        """The widget to place in a layout: the bar and the pane (``None`` with a custom
        channel)."""
        return self._pane

    @property
    def pane(self) -> Any:
        """The scene's widget (an anywidget), or ``None`` with a custom channel."""
        return self._pane

    def receive_from_page(self, message: Any) -> None:
        """Take a message a view sent (the bar's requests, the player's reports).

        The formats are in :mod:`robotconf.scene._page`; malformed messages are ignored.
        A request goes to :attr:`on_request` when set, else the scene applies it; a
        player report updates :attr:`playback_state` and goes to :attr:`on_playback`.

        Examples
        --------
        >>> import robotconf as rc
        >>> from robotconf.scene import RecordingChannel, Scene
        >>> scene = Scene(rc.preset("paper"), channel=RecordingChannel())
        >>> names = {"kind": "labels", "mode": "names"}
        >>> scene.receive_from_page({"kind": "request", "request": names})
        >>> scene.label_mode
        'names'
        """
        route_message(message, self._playback, self._apply, self.on_request, self.on_playback)

    def export_html(self, path: str | Path, title: str | None = None) -> Path:
        """Write the scene as one self-contained HTML file that opens offline.

        The viewer code is inlined (no CDN, no network); the bar works in the file too:
        an animation plays, pauses and scrubs, and labels, frames, trace and fit switch.

        Parameters
        ----------
        path : str or pathlib.Path
        title : str, optional
            The page's title (default: the robot's name, else ``"robot"``); escaped.

        Returns
        -------
        pathlib.Path
        """
        from ._html import bar_choices, page_title, scene_html

        choices = bar_choices(
            self._robot, self._taught, self._playback, self._outbox.log, self._options_op
        )
        target = Path(path)
        title = page_title(title, self.robot.name or "robot")
        ops = self._replay(from_start=True)
        target.write_text(scene_html(ops, choices, title=title), "utf-8")
        return target

    def close(self) -> None:
        """Close the widget (its views release their WebGL contexts)."""
        self.channel.close()

    def _ipython_display_(self) -> None:
        from ._view import display_once

        display_once(self)

    def __repr__(self) -> str:
        return f"<Scene of {self.robot.n} modules at q={np.round(self.q, 4).tolist()}>"

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
        elif kind == "fit":
            self.fit_view()

    def _options_op(self, **changes: Any) -> Op:
        options = {
            "labels": self.label_mode,
            "frames": self.frames_shown,
            "trace": self.trace_shown,
            "controls": self._controls_on,
            **changes,
        }
        return options_op(**options)

    def _replay(self, *, from_start: bool = False) -> list[Op]:
        """The log in replay order, then where the player stands (see
        :meth:`Playback.replay <robotconf.scene._playback.Playback.replay>`)."""
        return self._playback.replay(self._outbox.log.ops(), from_start=from_start)

    def _extents(self) -> list[np.ndarray]:
        return [
            self._robot.extent(),
            self._ghosts.extent(),
            self._target.extent(),
            self._taught.extent(),
            self._clouds.extent(),
            self._playback.extent(),
        ]

    def _keep_in_view(self, points: np.ndarray) -> None:
        centre, radius = self._fitted
        if not inside(points, centre, radius):
            self.fit_view()

    def _drawing(self) -> RobotDrawing:
        drawing = self._robot.drawing
        assert drawing is not None, "the scene has no robot yet"
        return drawing

    def _size(self) -> float:
        return self._drawing().size


def _check_robot(robot: Any) -> None:
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")
