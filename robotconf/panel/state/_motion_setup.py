"""The Motion tab's part of the state: a signal per coordinate and the time settings.

Signals are kept as the core's own :class:`~robotconf.signals.Signal` objects, one per
coordinate of the robot (``None`` holds the coordinate at its slider value), so what the
panel simulates and saves is exactly what a cell would pass to :func:`robotconf.simulate`.
The time settings pass through :class:`~robotconf.motion.SimulationSettings` whenever one
changes, so the state never holds a setting the core would refuse.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from ...motion import SimulationSettings
from ...signals import Signal

__all__ = ["MotionSetup", "remap"]


@dataclass(frozen=True)
class MotionSetup:
    """Signals and time settings.

    Parameters
    ----------
    signals : tuple of Signal or None
        One per coordinate of the robot, base first; ``None`` holds the coordinate.
    settings : SimulationSettings
        ``t_end``, ``dt``, ``t0`` and the method, as the core checked them.

    Examples
    --------
    >>> from robotconf.signals import Sine
    >>> setup = MotionSetup((None, Sine(), None), SimulationSettings(2.0, dt=0.5))
    >>> setup.driven(["q1", "q2", "q3"])
    {'q2': Sine()}
    >>> setup.with_setting("dt", 0.25).settings.samples
    9
    """

    signals: tuple[Signal | None, ...] = ()
    settings: SimulationSettings = SimulationSettings(10.0, dt=0.01)

    def driven(self, names: Sequence[str]) -> dict[str, Signal]:
        """``{coordinate name: signal}`` for the driven coordinates (what ``simulate`` takes)."""
        return {
            name: signal
            for name, signal in zip(names, self.signals, strict=True)
            if signal is not None
        }

    def with_signal(self, index: int, signal: Signal | None) -> MotionSetup:
        """The same setup with coordinate ``index``'s signal replaced."""
        signals = list(self.signals)
        signals[index] = signal
        return replace(self, signals=tuple(signals))

    def with_setting(self, name: str, value: Any) -> MotionSetup:
        """The same setup with one time setting changed, as the core checks it.

        Raises
        ------
        InvalidInputError
            The core's, naming the setting (``dt: must be positive, …``).
        """
        values = {**self.settings.to_dict(), name: value}
        return replace(self, settings=SimulationSettings(**values))

    @classmethod
    def loaded(
        cls, names: Sequence[str], signals: Mapping[str, Signal], simulation: Mapping[str, Any]
    ) -> MotionSetup:
        """A setup from a file's parts: signals by coordinate name, settings as saved."""
        return cls(
            tuple(signals.get(name) for name in names), SimulationSettings(**dict(simulation))
        )


def remap(
    signals: tuple[Signal | None, ...], n: int, order: Sequence[int | None] | None
) -> tuple[Signal | None, ...]:
    """Signals following their coordinates to a robot of ``n`` coordinates.

    ``order[i]`` is the old coordinate that new coordinate ``i`` continues (``None``: a
    new one, held); ``order`` ``None`` keeps them by position.

    >>> from robotconf.signals import Sine, Step
    >>> remap((Sine(), Step()), 3, [1, None, 0])
    (Step(), None, Sine())
    >>> remap((Sine(),), 2, None)
    (Sine(), None)
    """
    source = list(order) if order is not None else list(range(n))
    out: list[Signal | None] = []
    for i in range(n):
        j = source[i] if i < len(source) else None
        out.append(signals[j] if j is not None and 0 <= j < len(signals) else None)
    return tuple(out)
