"""The guided mode's draft: the paper's questionnaire (Figure 12) as answers so far.

The draft is not the panel's robot: **Finish** makes it so, **Cancel** drops it. While it
is open, the 3D view and the header show the robot built from the answers so far
(:meth:`WizardDraft.preview`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from ...kinematics import Module, Robot

__all__ = ["WizardDraft", "WizardModule", "MAX_WIZARD_MODULES", "STEP_PARTS"]

#: The questionnaire asks for at most this many modules.
MAX_WIZARD_MODULES = 12
#: The parts a step can be: the count, per module its type, offsets and coordinate, the
#: end effector, the summary.
STEP_PARTS = ("count", "type", "a", "q", "end_effector", "summary")


@dataclass(frozen=True)
class WizardModule:
    """The answers about one module (core units: length, radians)."""

    kind: str = "Rz"
    a: tuple[float, float, float] = (0.0, 0.0, 0.0)
    q: float = 0.0

    def module(self) -> Module:
        """The core's module for these answers."""
        return Module(self.kind, self.a, self.q)


@dataclass(frozen=True)
class WizardDraft:
    """Where the questionnaire is and what was answered.

    Attributes
    ----------
    step : int
        Index into :meth:`steps`.
    count : int
        How many modules, 1 … :data:`MAX_WIZARD_MODULES`.
    modules : tuple of WizardModule
        The answers, one per module (at least ``count``; answers beyond it are kept as
        defaults if the count grows again).
    end_effector : tuple of 3 floats
        The point P in the last module's frame.

    Examples
    --------
    >>> draft = WizardDraft(count=1, modules=(WizardModule("Tz", (0.0, 0.0, 20.0)),))
    >>> [part for part, _ in draft.steps()]
    ['count', 'type', 'a', 'q', 'end_effector', 'summary']
    >>> draft.go(3).part, draft.go(3).preview().modules
    ('q', (Module('Tz', a=(0.0, 0.0, 20.0)),))
    """

    step: int = 0
    count: int = 3
    modules: tuple[WizardModule, ...] = ()
    end_effector: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def steps(self) -> list[tuple[str, int]]:
        """``(part, module index)`` of every step, in order."""
        per_module = [(part, i) for i in range(self.count) for part in ("type", "a", "q")]
        return [("count", 0), *per_module, ("end_effector", 0), ("summary", 0)]

    @property
    def part(self) -> str:
        """What the current step asks: one of :data:`STEP_PARTS`."""
        return self.steps()[self.step][0]

    @property
    def index(self) -> int:
        """The module the current step is about (0 for the other steps)."""
        return self.steps()[self.step][1]

    def answers(self, i: int) -> WizardModule:
        """Module ``i``'s answers (the defaults until given)."""
        return self.modules[i] if i < len(self.modules) else WizardModule()

    def with_answers(self, i: int, **changes: Any) -> WizardDraft:
        """The draft with module ``i``'s answers changed."""
        modules = list(self.modules)
        while len(modules) <= i:
            modules.append(WizardModule())
        modules[i] = replace(modules[i], **changes)
        return replace(self, modules=tuple(modules))

    def go(self, step: int) -> WizardDraft:
        """The draft at another step (clamped to the steps there are)."""
        return replace(self, step=max(0, min(step, len(self.steps()) - 1)))

    def built(self, count: int | None = None, end_effector: bool = True) -> Robot:
        """The robot of the first ``count`` modules' answers (default all).

        Raises
        ------
        InvalidInputError
            The core's, for answers it refuses (two modules named alike cannot happen:
            the wizard names none).
        """
        count = self.count if count is None else count
        modules = [self.answers(i).module() for i in range(count)]
        point = self.end_effector if end_effector else (0.0, 0.0, 0.0)
        return Robot(modules, end_effector=point)

    def preview(self) -> Robot | None:
        """The robot built so far, as the 3D view shows it; ``None`` on the first step.

        On a module's steps, the modules up to this one (the end effector at the last
        frame's origin); from the end-effector step on, the whole robot.
        """
        part, i = self.steps()[self.step]
        if part == "count":
            return None
        if part in ("type", "a", "q"):
            return self.built(i + 1, end_effector=False)
        return self.built()
