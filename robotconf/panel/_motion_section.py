"""The Motion tab: a signal per coordinate, time settings, Run, and the results."""

from __future__ import annotations

import html
from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..kinematics import Robot
from ..motion import METHODS, Motion, SimulationSettings, simulate
from ..signals import Signal
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._motion_results import MotionResults
from ._units import Units

__all__ = ["MotionSection"]


def _unit(robot: Robot, i: int) -> str:
    return robot.modules[i].unit  # type: ignore[attr-defined,no-any-return]


class MotionSection:
    """Signals, t_end, dt, method and Run; ``motion`` is the last successful simulation.

    Run and save check the time settings with the core's
    :class:`~robotconf.motion.SimulationSettings`, so the panel refuses exactly what
    :func:`~robotconf.simulate`, files and the report command refuse. A start time ``t0``
    has no control: it comes from a loaded file (else 0) and is saved back with it.

    Parameters
    ----------
    robot : callable
        Returns the panel's current valid robot.
    animate : callable
        Plays a motion in the 3D pane.
    t_end, dt : float
        Initial time settings (s).
    method : {"analytic", "numeric"}
    app : bool
        The panel runs without cells around it (Voilà): no hint to type code in a cell.
    on_change : callable, optional
        Called after the user changed a signal or a time setting (the bound file saves).
    units : Units, optional
        The panel's units for signal parameters, tables and plots (default: the core's).

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Tz")], end_effector=(1, 0, 0))
    >>> section = MotionSection(lambda: robot, lambda motion: None, t_end=1.0, dt=0.5)
    >>> section.sync(robot)
    >>> section.editors[0].kind.value = "Ramp"
    >>> section.run_button.click()
    >>> section.motion.table[("EE", "position", "z")].tolist()
    [0.0, 0.5, 1.0]
    """

    def __init__(
        self,
        robot: Callable[[], Robot],
        animate: Callable[[Motion], None],
        *,
        t_end: float = 10.0,
        dt: float = 0.01,
        method: str = "analytic",
        app: bool = False,
        on_change: Callable[[], None] | None = None,
        units: Units | None = None,
    ):
        self._robot = robot
        self.units = units or Units(degrees=False)
        self._on_change = on_change or (lambda: None)
        self._t0 = 0.0
        self.motion: Motion | None = None
        self.editors: list[Any] = []
        self.t_end = widgets.FloatText(
            value=t_end, description="t_end [s]", layout=widgets.Layout(width="170px")
        )
        self.dt = widgets.FloatText(
            value=dt, description="dt [s]", layout=widgets.Layout(width="170px")
        )
        self.method = widgets.ToggleButtons(
            options=METHODS,
            value=method,
            tooltips=[
                "exact chain rule with the signals' own derivatives",
                "finite differences of sampled positions (Simulink's Derivative block)",
            ],
            style={"button_width": "80px"},
        )
        self.setting_errors = {name: ErrorLabel() for name in ("t_end", "dt", "method")}
        self.run_button = widgets.Button(description="Run", icon="play", button_style="primary")
        self.run_button.add_class("robotconf-run")  # browser tests find it by this
        self.status = widgets.HTML()
        self.run_error = ErrorLabel()
        self.results = MotionResults(animate, app=app, units=self.units)
        self._editors_box = widgets.VBox()
        self.signals_note = widgets.HTML()
        self._show_signals_note()
        self.widget = widgets.VBox(
            [
                self.signals_note,
                self._editors_box,
                widgets.HBox([self.t_end, self.setting_errors["t_end"].widget]),
                widgets.HBox([self.dt, self.setting_errors["dt"].widget]),
                widgets.HBox([self.method, self.setting_errors["method"].widget]),
                widgets.HBox([self.run_button, self.status, self.run_error.widget]),
                self.results.widget,
            ]
        )
        on_click(self.run_button, self.run_error, self.run)
        for name in ("t_end", "dt", "method"):
            observe(getattr(self, name), self.setting_errors[name], self._setting_changed)

    # -- editors ------------------------------------------------------------------------

    def sync(self, robot: Robot, order: Sequence[int | None] | None = None) -> None:
        """Match the editors to ``robot``'s coordinates.

        ``order`` gives, for each new coordinate, the index of the old one it came from
        (``None``: new), so a signal moves with its module when modules are reordered.
        """
        from ._signal_editor import SignalEditor

        old = self.editors
        if order is None:
            order = list(range(robot.n))
        editors = []
        for i in range(robot.n):
            source = order[i] if i < len(order) else None
            if source is not None and source < len(old):
                editor = old[source]
                editor.rename(f"q{i + 1}", _unit(robot, i))
            else:
                editor = SignalEditor(
                    f"q{i + 1}", _unit(robot, i), self._on_change, units=self.units
                )
            editors.append(editor)
        self.editors = editors
        self._editors_box.children = tuple(e.widget for e in editors)
        self.mark_stale(robot)

    def set_units(self, units: Units) -> None:
        """Show signals, tables and plots in ``units``; the signals themselves stay."""
        self.units = units
        for editor in self.editors:
            editor.set_units(units)
        self._show_signals_note()
        self.results.set_units(units)

    def _show_signals_note(self) -> None:
        self.signals_note.value = (
            f"<b>Signals</b> <small>(typed in {self.units.angle}, "
            f"{html.escape(self.units.length)} and s; the core signal under each is in "
            "radians. A held coordinate keeps its slider value.)</small>"
        )

    def signals(self) -> dict[str, Signal] | None:
        """Coordinate name → signal for the driven coordinates, or ``None`` if one is invalid."""
        chosen: dict[str, Signal] = {}
        valid = True
        for editor in self.editors:
            ok, signal = editor.build()
            valid = valid and ok
            if ok and signal is not None:
                chosen[editor.name] = signal
        return chosen if valid else None

    def load(self, signals: Mapping[str, Signal], simulation: Mapping[str, Any] | None) -> None:
        """Show saved signals (by coordinate name) and time settings."""
        for editor in self.editors:
            editor.load(signals.get(editor.name))
        if simulation:
            for name in ("t_end", "dt", "method"):
                if name in simulation:
                    getattr(self, name).value = simulation[name]
        # t0 has no control to show it, so a file without one must not inherit the last.
        self._t0 = float(simulation.get("t0", 0.0)) if simulation else 0.0

    def settings(self) -> dict[str, Any]:
        """``{"t_end", "dt", "method"}`` as typed, and ``t0`` when a file set one ≠ 0."""
        typed = {"t_end": self.t_end.value, "dt": self.dt.value, "method": self.method.value}
        return typed if self._t0 == 0.0 else {**typed, "t0": self._t0}

    def simulation_settings(self) -> SimulationSettings:
        """The typed settings checked by the core.

        Raises
        ------
        InvalidInputError
            Named after the setting (``t_end``, ``dt``, ``t0`` or ``method``).

        Examples
        --------
        >>> section = MotionSection(lambda: None, lambda motion: None, t_end=2.0, dt=0.5)
        >>> section.simulation_settings().samples
        5
        """
        return SimulationSettings(**self.settings())

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``t_end``, ``dt``, ``method``, ``run`` and ``signals.q…``."""
        yield from self.setting_errors.items()
        yield "run", self.run_error
        yield from self.results.error_items()
        for editor in self.editors:
            yield from editor.error_items(f"signals.{editor.name}")

    # -- running ------------------------------------------------------------------------

    def run(self) -> Motion | None:
        """Simulate the current robot; on bad input keep the last motion and show why."""
        for label in (*self.setting_errors.values(), self.run_error):
            label.clear()
        signals = self.signals()
        if signals is None:
            self.status.value = "<small>fix the signal marked in red</small>"
            return None
        self.status.value = ""
        robot = self._robot()
        try:
            settings = self.simulation_settings()
            motion = simulate(
                robot,
                dict(signals),  # type: ignore[arg-type]
                **settings.to_dict(),
            )
        except InvalidInputError as error:
            self.setting_errors.get(error.field, self.run_error).show(str(error))
            self.status.value = ""
            return None
        self.motion = motion
        self.status.value = _ran(motion)
        self.results.show(motion, settings)
        return motion

    def mark_stale(self, robot: Robot) -> None:
        """Say so when the robot changed since the last Run (the motion is kept); an
        equal robot (undo, the same file loaded again) takes the note back."""
        if self.motion is None:
            return
        if self.motion.robot != robot:
            self.status.value = "<small>the robot changed since this run: press Run</small>"
        else:
            self.status.value = _ran(self.motion)

    def _setting_changed(self, _: Any) -> None:
        # A message shown by Run for a setting goes as soon as the settings are valid
        # again, not at the next Run (the core names the first setting still wrong).
        try:
            self.simulation_settings()
            wrong = None
        except InvalidInputError as error:
            wrong = error.field
        for name, label in self.setting_errors.items():
            if name != wrong:
                label.clear()
        self._on_change()


def _ran(motion: Motion) -> str:
    """The status line after a run."""
    return f"<small>{motion.t.size} samples, {motion.method}</small>"
