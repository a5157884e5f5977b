"""How the panel shows things: units, the tab in front, the scene's options, the result
views, and the playback of an animation. None of these changes a number of the robot.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ..state import (
    LABEL_MODES,
    LENGTH_UNITS,
    RESULT_VIEWS,
    SOURCES,
    TABS,
    PanelState,
    Playback,
    Units,
)
from ._base import Action

__all__ = [
    "SetAngleUnit",
    "SetLengthUnit",
    "SelectTab",
    "SetViewOption",
    "Animate",
    "Play",
    "Pause",
    "Seek",
    "SetSpeed",
    "PlaybackReported",
    "check_length_unit",
]

_FLAGS = ("frames", "trace", "symbolic", "lengths", "latex", "overlay", "displacement")


def check_length_unit(unit: object) -> str:
    """A length unit's name: letters, digits, spaces and dots, at most 12 characters
    (it goes into labels, which MathJax would typeset, and into HTML).

    >>> check_length_unit("mm")
    'mm'
    >>> check_length_unit("$x$")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: length_unit: invalid value '$x$'; allowed: a unit name of up to ...
    """
    if not isinstance(unit, str) or not re.fullmatch(r"[\w µ.]{1,12}", unit):
        raise InvalidInputError(
            "length_unit", unit, f"a unit name of up to 12 letters, such as {LENGTH_UNITS[1:]}"
        )
    return unit


@dataclass(frozen=True)
class SetAngleUnit(Action):
    """Show angles in degrees (``True``) or radians; the robot and signals stay."""

    degrees: bool

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(units=Units(state.units.length, bool(self.degrees)))


@dataclass(frozen=True)
class SetLengthUnit(Action):
    """Name the robot's length unit (``"mm"``, ``"m"`` …); lengths are not converted."""

    unit: str

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(units=Units(check_length_unit(self.unit), state.units.degrees))


@dataclass(frozen=True)
class SelectTab(Action):
    """Bring a result tab to the front (one of ``motion``, ``matrices``, ``reach``,
    ``program``, ``files``)."""

    tab: str

    def apply(self, state: PanelState) -> PanelState:
        if self.tab not in TABS:
            raise InvalidInputError("tab", self.tab, ", ".join(TABS))
        return state.replace(view=replace(state.view, tab=self.tab))


@dataclass(frozen=True)
class SetViewOption(Action):
    """Set one view option: ``labels`` (off, names, positions), a flag (``frames``,
    ``trace``, ``symbolic``, ``lengths``, ``latex``, ``overlay``), ``result_point`` or
    ``result_view`` (table, statistics, plot)."""

    name: str
    value: object

    def apply(self, state: PanelState) -> PanelState:
        value = self.value
        if self.name == "labels":
            _check_choice(value, LABEL_MODES, "labels")
        elif self.name == "result_view":
            _check_choice(value, RESULT_VIEWS, "result_view")
        elif self.name == "result_point":
            names = (*state.robot.module_names, "EE", "all")
            _check_choice(value, names, "result_point")
        elif self.name in _FLAGS:
            value = bool(value)
        else:
            allowed = "labels, result_view, result_point, " + ", ".join(_FLAGS)
            raise InvalidInputError("name", self.name, allowed)
        return state.replace(view=replace(state.view, **{self.name: value}))  # type: ignore[arg-type]


def _check_choice(value: object, choices: tuple[str, ...], field: str) -> None:
    if value not in choices:
        raise InvalidInputError(field, value, ", ".join(choices))


@dataclass(frozen=True)
class Animate(Action):
    """Play a run in the 3D view: the Motion tab's (``"motion"``) or the Program tab's."""

    source: str = "motion"

    def apply(self, state: PanelState) -> PanelState:
        if self.source not in SOURCES:
            raise InvalidInputError("source", self.source, ", ".join(SOURCES))
        run = state.motion if self.source == "motion" else state.program_run
        if run is None:
            raise InvalidInputError("animate", self.source, "a run first: press Run")
        playback = Playback(source=self.source, playing=True, speed=state.playback.speed)
        return state.replace(playback=playback)


def _loaded(state: PanelState) -> Playback:
    if state.playback.source is None:
        raise InvalidInputError("playback", "nothing loaded", "a run animated in the 3D view")
    return state.playback


@dataclass(frozen=True)
class Play(Action):
    """Play the loaded animation (from the start once it has ended)."""

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(playback=replace(_loaded(state), playing=True))


@dataclass(frozen=True)
class Pause(Action):
    """Pause the loaded animation where it is."""

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(playback=replace(_loaded(state), playing=False))


@dataclass(frozen=True)
class Seek(Action):
    """Show the loaded animation at motion time ``time`` (s), paused (a user's scrub)."""

    time: float

    def apply(self, state: PanelState) -> PanelState:
        time = max(check_finite_number(self.time, "time"), 0.0)
        return state.replace(playback=replace(_loaded(state), playing=False, time=time))


@dataclass(frozen=True)
class SetSpeed(Action):
    """Playback speed: 1 is real time."""

    speed: float

    def apply(self, state: PanelState) -> PanelState:
        speed = check_finite_number(self.speed, "speed")
        if not speed > 0 or not math.isfinite(speed):
            raise InvalidInputError("speed", speed, "a number > 0", problem="must be positive:")
        return state.replace(playback=replace(state.playback, speed=speed))


@dataclass(frozen=True)
class PlaybackReported(Action):
    """What the page says its animation does now (it plays by itself): no command goes
    back, the state only follows."""

    playing: bool
    time: float
    speed: float

    def apply(self, state: PanelState) -> PanelState:
        if state.playback.source is None:
            return state
        playback = replace(
            state.playback,
            playing=bool(self.playing),
            time=max(float(self.time), 0.0),
            speed=float(self.speed) if self.speed > 0 else state.playback.speed,
        )
        return state.replace(playback=playback)
