"""Which preset a robot is: the header's dropdown names it, or shows "— preset —"."""

from __future__ import annotations

from functools import cache

from ...kinematics import Robot
from ...presets import preset, preset_names

__all__ = ["preset_of", "NO_PRESET", "PRESET_OPTIONS"]

#: The entry shown when the robot is no preset.
NO_PRESET = ("— preset —", "")


@cache
def _presets() -> dict[str, Robot]:
    return {name: preset(name) for name in preset_names()}


#: The dropdown's entries: "— preset —", then every preset's name.
PRESET_OPTIONS = (NO_PRESET, *((name, name) for name in preset_names()))


def preset_of(robot: Robot) -> str:
    """The name of the preset ``robot`` is (equal as robots, however it was made), or ``""``.

    >>> import robotconf as rc
    >>> preset_of(rc.preset("puma560")), preset_of(rc.preset("puma560").with_q([0.1] * 6))
    ('puma560', '')
    """
    for name, candidate in _presets().items():
        # The name first: most robots are no preset, and comparing names is cheap.
        if candidate.name == robot.name and candidate == robot:
            return name
    return ""
