"""The configurator panel: build, move and analyse a robot from widgets.

Presentation only: every number on screen comes from one core call (``rc.Robot``,
``rc.derivation``, ``rc.simulate``, the signals), and every bad input shows the core's
own message next to the control that caused it while the last valid robot stays.
"""

from __future__ import annotations

import html
import os
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..kinematics import DHLink, Robot
from ..motion import Motion
from ..presets import preset, preset_names
from ._callbacks import observe
from ._dh_table import DHTable
from ._errors_display import ErrorLabel, collect_errors
from ._files_section import FilesSection
from ._matrices_view import MatricesView, end_effector_text
from ._module_list import ModuleList
from ._motion_section import MotionSection
from ._ranges import joint_limits, length_scale
from ._robot_extras import RobotExtras
from ._scene_slot import default_scene_factory
from ._setup_io import setup_from, setup_to_json
from ._wizard import Wizard

__all__ = ["Configurator", "configurator"]

_MODES = (("Modules", "modules"), ("DH table", "dh"), ("Guided", "wizard"))
_SCENE_TAB, _MATRICES_TAB, _MOTION_TAB, _FILES_TAB = range(4)


def _default_robot() -> Robot:
    return preset("paper")


class Configurator:
    """Widget panel: module list / DH table / guided wizard, 3D scene, matrices, motion.

    Parameters
    ----------
    robot : Robot, optional
        The robot to start with (default: the paper's preset when available).
    scene_factory : callable, optional
        ``robot -> scene``; the scene needs ``widget``, ``set_robot(robot, q)`` and
        ``update(q)`` (``animate(motion)`` optional). Default: :class:`robotconf.scene.Scene`.
    degrees : bool
        Show angles in degrees (a toggle in the panel switches).
    t_end, dt : float
        Initial simulation settings (s).
    method : {"analytic", "numeric"}
    scene_height : int
        Height of the default 3D scene (pixels).

    Attributes
    ----------
    robot : Robot
        Always the current valid robot.
    motion : Motion or None
        The last simulation (``None`` before Run).
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
    >>> panel.motion_section.dt.value = 0.0
    >>> panel.motion_section.run_button.click()
    >>> panel.motion is None, panel.errors["dt"][:29]
    (True, 'dt: must be positive, got 0.0')
    """

    def __init__(
        self,
        robot: Robot | None = None,
        *,
        scene_factory: Callable[[Robot], Any] | None = None,
        degrees: bool = True,
        t_end: float = 10.0,
        dt: float = 0.01,
        method: str = "analytic",
        scene_height: int = 420,
    ):
        robot = _default_robot() if robot is None else robot
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", robot, "a robotconf Robot or None")
        self._robot = robot
        # The last robot each editor described, for a mode switch onto a pending bad value.
        self._last_valid: dict[str, Robot] = {}
        self._loading = False
        self.title = widgets.HTML("<h3 style='margin:4px 0'>robotconf configurator</h3>")
        names = preset_names()
        self.preset = widgets.Dropdown(
            options=[("— preset —", ""), *((n, n) for n in names)],
            value=robot.name if robot.name in names else "",
            description="preset",
            disabled=not names,
            layout=widgets.Layout(width="220px"),
        )
        self.preset_error = ErrorLabel()
        self.mode = widgets.ToggleButtons(options=_MODES, value="modules")
        self.mode_error = ErrorLabel()
        self.angle_unit = widgets.ToggleButtons(
            options=(("deg", True), ("rad", False)),
            value=degrees,
            tooltips=["angles in degrees", "angles in radians"],
            style={"button_width": "48px"},
        )
        self.angle_unit_error = ErrorLabel()
        self.modules = ModuleList(self._edited)
        self.dh = DHTable(self._edited)
        self.wizard = Wizard(self._wizard_finished, degrees, length_scale(robot))
        self.extras = RobotExtras(lambda: self._edited("link", None))
        self.matrices = MatricesView()
        self.motion_section = MotionSection(
            lambda: self._robot, self._animate, t_end=t_end, dt=dt, method=method
        )
        self.files = FilesSection(self.to_json, self._load_bytes)
        self.ee_label = widgets.HTML()
        self.ee_label.add_class("robotconf-ee")
        factory = scene_factory or default_scene_factory(scene_height)
        self.scene = factory(robot)
        self.results = widgets.Tab(
            children=[
                self.scene.widget,
                self.matrices.widget,
                self.motion_section.widget,
                self.files.widget,
            ],
            titles=("3D scene", "Matrices", "Motion", "Save / Load"),
        )
        self._editor_box = widgets.VBox()
        self.widget = widgets.VBox(
            [
                self.title,
                widgets.HBox(
                    [
                        self.preset,
                        self.preset_error.widget,
                        self.mode,
                        self.mode_error.widget,
                        self.angle_unit,
                        self.angle_unit_error.widget,
                    ],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                widgets.HBox(
                    [
                        widgets.Box(
                            [self._editor_box],
                            layout=widgets.Layout(min_width="560px", flex="1 1 560px"),
                        ),
                        widgets.VBox(
                            [self.ee_label, self.results],
                            layout=widgets.Layout(min_width="420px", flex="1 1 520px"),
                        ),
                    ],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="flex-start"),
                ),
            ]
        )
        observe(self.preset, self.preset_error, self._preset_chosen)
        observe(self.mode, self.mode_error, lambda _: self._mode_changed())
        observe(self.angle_unit, self.angle_unit_error, lambda c: self._set_degrees(c["new"]))
        # Showing the Matrices tab computes the symbolic view: its failures show there.
        observe(self.results, self.matrices.error, self._tab_changed, "selected_index")
        self.matrices.set_visible(False)
        self._load_robot(robot, first=True)

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
    def errors(self) -> dict[str, str]:
        """``{control key: message}`` for every input the core currently refuses."""
        return dict(collect_errors(self._error_items()))

    def set_robot(self, robot: Robot) -> None:
        """Show ``robot`` in the editors and make it the current robot."""
        if not isinstance(robot, Robot):
            raise InvalidInputError("robot", robot, "a robotconf Robot")
        self._load_robot(robot)
        if self.preset.value:
            self._loading = True  # a robot from elsewhere is not the preset shown
            try:
                self.preset.value = ""
            finally:
                self._loading = False

    def to_json(self) -> str:
        """The robot, the signals and the time settings as the core's JSON text."""
        signals = self.motion_section.signals()
        if signals is None:
            raise InvalidInputError(
                "signals", "invalid", "valid signals: fix the one marked in red first"
            )
        return setup_to_json(self._robot, signals, self.motion_section.settings())

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write :meth:`to_json` to ``path`` (UTF-8)."""
        Path(path).write_text(self.to_json(), encoding="utf-8")

    def load(self, path: str | os.PathLike[str]) -> None:
        """Load a robot with its signals and time settings from a JSON file."""
        self._apply_setup(*setup_from(Path(path)))

    def _load_bytes(self, content: bytes) -> None:
        self._apply_setup(*setup_from(content))

    def _apply_setup(self, robot: Robot, signals: dict, simulation: dict | None) -> None:
        self.set_robot(robot)
        self.motion_section.load(signals, simulation)

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        return self.widget._repr_mimebundle_(**kwargs)

    def __repr__(self) -> str:
        return f"<Configurator: {self._robot.n} modules, {end_effector_text(self._robot)}>"

    # -- loading ------------------------------------------------------------------------

    def _load_robot(self, robot: Robot, first: bool = False) -> None:
        degrees = bool(self.angle_unit.value)
        scale = length_scale(robot)
        all_dh = all(isinstance(link, DHLink) for link in robot.modules)
        self._loading = True
        try:
            self.modules.load(robot.modules, scale, degrees, joint_limits(robot))
            if all_dh:
                self.dh.load(robot.modules, scale, degrees, joint_limits(robot))  # type: ignore[arg-type]
            self.extras.load(robot.n, robot.active, robot.end_effector_point, scale)
            self.mode.value = "dh" if all_dh else "modules"
            self._show_editor()
        finally:
            self._loading = False
        self._last_valid = {"modules": robot, **({"dh": robot} if all_dh else {})}
        self._accept(robot, rebuild=not first, first=first)

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
        self._leave_preset(robot)
        self._last_valid[mode] = robot
        self._accept(robot, order=order if reason == "structure" else None)
        return robot

    def _leave_preset(self, robot: Robot) -> None:
        if self.preset.value and robot != self._robot:
            self._loading = True  # the robot was edited: it is no longer the preset
            try:
                self.preset.value = ""
            finally:
                self._loading = False

    def _accept(
        self,
        robot: Robot,
        order: Sequence[int | None] | None = None,
        rebuild: bool = False,
        first: bool = False,
    ) -> None:
        old, self._robot = self._robot, robot
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
        self.ee_label.value = (
            f"<b>End-effector</b> <code>{html.escape(end_effector_text(robot))}</code>"
        )

    # -- header controls ----------------------------------------------------------------

    def _preset_chosen(self, change: dict[str, Any]) -> None:
        name = change["new"]
        if not name or self._loading:
            return
        self.preset_error.clear()
        try:
            robot = preset(name)
        except InvalidInputError as error:
            self.preset_error.show(str(error))
            return
        self._load_robot(robot)

    def _mode_changed(self) -> None:
        if self._loading:
            return
        self._show_editor()
        if self.mode.value == "wizard":
            self.wizard.restart()
            return
        if self.mode.value == "dh" and not self.dh.rows:
            self.dh.load([DHLink(a=length_scale(self._robot) / 10.0)], length_scale(self._robot))
        if self._rebuild("structure", None) is not None:
            return
        # The editor holds a value the core refuses (a NaN being typed, say): the panel
        # shows the last robot this editor described, not the other mode's robot.
        last = self._last_valid.get(self.mode.value)
        if last is not None and last != self._robot:
            self.extras.set_count(last.n)
            self._leave_preset(last)
            self._accept(last, rebuild=True)

    def _set_degrees(self, degrees: bool) -> None:
        for editor in (self.modules, self.dh, self.wizard):
            editor.set_degrees(degrees)

    def _wizard_finished(self, robot: Robot) -> None:
        self._load_robot(robot)

    def _tab_changed(self, change: dict[str, Any]) -> None:
        self.matrices.set_visible(change["new"] == _MATRICES_TAB)

    def _animate(self, motion: Motion) -> None:
        animate = getattr(self.scene, "animate", None)
        if animate is not None:
            self.results.selected_index = _SCENE_TAB
            animate(motion)

    def _error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        yield "preset", self.preset_error
        yield "mode", self.mode_error
        yield "angle_unit", self.angle_unit_error
        yield from self.matrices.error_items()
        yield from self.modules.error_items()
        yield from self.dh.error_items()
        yield from self.extras.error_items()
        yield from self.wizard.error_items()
        yield from self.motion_section.error_items()
        yield from self.files.error_items()


def configurator(robot: Robot | None = None, **options: Any) -> Configurator:
    """Build a :class:`Configurator` for ``robot``, display it, and return it.

    Parameters
    ----------
    robot : Robot, optional
        Default: the paper's R_zR_yR_y preset when available.
    **options
        Passed to :class:`Configurator` (``scene_factory``, ``degrees``, ``t_end``, ``dt``,
        ``method``, ``scene_height``).

    Returns
    -------
    Configurator
        ``panel.robot`` is the current robot, ``panel.motion`` the last simulation.
    """
    panel = Configurator(robot, **options)
    from IPython.display import display

    display(panel)
    return panel
