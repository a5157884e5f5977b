"""The Motion tab: a signal per coordinate, the time settings, and Run.

Every value reaches the core as the core takes it (radians, length units, seconds): a
signal is replaced by the core signal class with the new parameter, which checks it; the
time settings pass through :class:`~robotconf.motion.SimulationSettings`; Run is
:func:`robotconf.simulate` of the state's robot and signals.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Hashable, Sequence
from dataclasses import dataclass

from ..._errors import InvalidInputError
from ...motion import simulate
from ...signals import SIGNAL_TYPES, RepeatingSequence
from ..state import PanelState, Playback
from ._base import Action

__all__ = [
    "SetSignalKind",
    "SetSignalParameter",
    "SetSignalTable",
    "SetTimeSetting",
    "Run",
    "HOLD",
    "EDITABLE_SIGNALS",
]

#: The signal choice that holds a coordinate at its slider value.
HOLD = "hold"
#: The signal types a coordinate can be given in the panel: the core's, without the
#: composites (a sum or a scaled signal comes only from a file and shows read-only).
EDITABLE_SIGNALS = {
    name: cls for name, cls in SIGNAL_TYPES.items() if name not in ("Affine", "Sum")
}


def _coordinate(state: PanelState, index: int) -> int:
    return state.robot.index(index, "index")


@dataclass(frozen=True)
class SetSignalKind(Action):
    """Drive coordinate ``index`` with a signal of type ``kind`` (its core defaults), or
    hold it (``"hold"``).

    >>> import robotconf as rc
    >>> state = SetSignalKind(2, "Sine").apply(PanelState.start(rc.preset("paper")))
    >>> state.document.motion.signals
    (None, None, Sine())
    """

    index: int
    kind: str

    def apply(self, state: PanelState) -> PanelState:
        i = _coordinate(state, self.index)
        current = state.document.motion.signals[i]
        if self.kind == HOLD:
            signal = None
        elif self.kind not in EDITABLE_SIGNALS:
            raise InvalidInputError("kind", self.kind, f"{HOLD}, " + ", ".join(EDITABLE_SIGNALS))
        elif type(current).__name__ == self.kind:
            return state
        else:
            signal = EDITABLE_SIGNALS[self.kind]()
        motion = state.document.motion.with_signal(i, signal)
        return state.with_document(motion=motion)


@dataclass(frozen=True)
class SetSignalParameter(Action):
    """Set parameter ``name`` of coordinate ``index``'s signal (core units)."""

    index: int
    name: str
    value: float

    def apply(self, state: PanelState) -> PanelState:
        i = _coordinate(state, self.index)
        signal = state.document.motion.signals[i]
        fields = () if signal is None else dataclasses.fields(signal)  # type: ignore[arg-type]
        names = [f.name for f in fields if f.init]
        if signal is None or self.name not in names:
            raise InvalidInputError(self.name, self.value, f"a parameter of {signal!r}")
        changed = dataclasses.replace(signal, **{self.name: self.value})  # type: ignore[type-var]
        return state.with_document(motion=state.document.motion.with_signal(i, changed))

    @property
    def gesture(self) -> Hashable:
        return ("signal", self.index, self.name)


@dataclass(frozen=True)
class SetSignalTable(Action):
    """Give coordinate ``index`` a repeating sequence of ``times`` (s) and ``values``
    (core units), as Simulink's Repeating Sequence block takes them."""

    index: int
    times: Sequence[float]
    values: Sequence[float]

    def apply(self, state: PanelState) -> PanelState:
        i = _coordinate(state, self.index)
        signal = RepeatingSequence(times=tuple(self.times), values=tuple(self.values))
        return state.with_document(motion=state.document.motion.with_signal(i, signal))

    @property
    def gesture(self) -> Hashable:
        return ("table", self.index)


@dataclass(frozen=True)
class SetTimeSetting(Action):
    """Set ``t_end`` or ``dt`` (s) or the ``method``, as the core's settings take them."""

    name: str
    value: object

    def apply(self, state: PanelState) -> PanelState:
        if self.name not in ("t_end", "dt", "method"):
            raise InvalidInputError("name", self.name, "t_end, dt or method")
        motion = state.document.motion.with_setting(self.name, self.value)
        return state.with_document(motion=motion)

    @property
    def gesture(self) -> Hashable:
        return ("time", self.name)


@dataclass(frozen=True)
class Run(Action):
    """Simulate the robot with its signals and settings (``rc.simulate``); the run
    becomes ``state.motion`` (an animation of an older run stops).

    >>> import robotconf as rc
    >>> state = SetSignalKind(0, "Ramp").apply(PanelState.start(rc.preset("paper")))
    >>> state = SetTimeSetting("t_end", 1.0).apply(state)
    >>> Run().apply(state).motion.t.size
    101
    """

    def apply(self, state: PanelState) -> PanelState:
        setup = state.document.motion
        signals = setup.driven(state.robot.coordinate_names)
        motion = simulate(state.robot, dict(signals), **setup.settings.to_dict())  # type: ignore[arg-type]
        playback = state.playback
        if playback.source is not None:
            playback = Playback(speed=playback.speed)
        return state.replace(motion=motion, run_settings=setup.settings, playback=playback)
