"""The panel's one state: an immutable value that every view renders and every action
replaces.

:class:`Document` is what a file holds and undo steps through (the robot with its q, the
signals and time settings, the program). :class:`PanelState` adds how the panel shows it
(units, the open question, the guided mode's draft, the Reach target, the view options,
the playback) and the results of the last runs. Nothing else in the panel holds truth: a
widget shows a part of the state and turns what the student does into an action.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

from ...kinematics import DHLink, Robot
from ...motion import Motion, SimulationSettings
from ._motion_setup import MotionSetup
from ._program_draft import ProgramDraft
from ._reach import ReachState
from ._units import Units
from ._view import Playback, ViewOptions
from ._wizard import WizardDraft

__all__ = ["Document", "PanelState", "Prompt", "ProgramRun", "PROMPTS", "EDITORS"]

#: The editors a robot can be shown in: its modules, or its DH rows.
EDITORS = ("modules", "dh")
#: The questions the panel asks before it converts: modules → DH table (convert, or a
#: new table), and standard ⇄ modified DH (convert the robot, or reinterpret the numbers).
PROMPTS = ("to_dh", "convention")


@dataclass(frozen=True)
class Document:
    """What the bound file holds and undo steps through.

    Attributes
    ----------
    robot : Robot
        The robot, its coordinates included.
    motion : MotionSetup
        A signal per coordinate and the time settings.
    program : ProgramDraft
        The Program tab's moves and limits.
    """

    robot: Robot
    motion: MotionSetup
    program: ProgramDraft = field(default_factory=ProgramDraft)


@dataclass(frozen=True)
class Prompt:
    """An open question under the header or the DH table's convention selector.

    Attributes
    ----------
    kind : str
        One of :data:`PROMPTS`.
    convention : str
        The convention the answer would use (``to_dh``: preselected, the student may pick
        the other; ``convention``: the one asked for).
    """

    kind: str
    convention: str


@dataclass(frozen=True, eq=False)
class ProgramRun:
    """The Program tab's last Run: the program it ran, its motion and its report."""

    program: Any
    motion: Any
    report: Any


@dataclass(frozen=True, eq=False)
class PanelState:
    """Everything the panel shows, as one value.

    Attributes
    ----------
    document : Document
        The robot, the signals and time settings, the program.
    units : Units
        The length unit's name and degrees or radians.
    wizard : WizardDraft or None
        The guided mode's draft while it is open.
    prompt : Prompt or None
        The question the panel is asking, if any.
    reach : ReachState
    view : ViewOptions
    playback : Playback
    motion : Motion or None
        The last simulation (the Motion tab's Run, or the Program tab's).
    run_settings : SimulationSettings or None
        The time settings the Motion tab's last Run used (``None`` for a program's run).
    program_run : ProgramRun or None
        The Program tab's last Run.
    program_dt : float
        The Program tab's sampling step (s; not saved with the setup).

    Examples
    --------
    >>> import robotconf as rc
    >>> state = PanelState.start(rc.preset("paper"))
    >>> state.robot.n, state.editor, state.document.motion.signals
    (3, 'modules', (None, None, None))
    """

    document: Document
    units: Units = Units()
    wizard: WizardDraft | None = None
    prompt: Prompt | None = None
    reach: ReachState = ReachState()
    view: ViewOptions = ViewOptions()
    playback: Playback = Playback()
    motion: Motion | None = None
    run_settings: SimulationSettings | None = None
    program_run: ProgramRun | None = None
    program_dt: float = 0.01

    @classmethod
    def start(cls, robot: Robot, **changes: Any) -> PanelState:
        """A state showing ``robot`` with nothing driven and the default settings."""
        document = Document(robot, MotionSetup((None,) * robot.n))
        return cls(document, **changes)

    @property
    def robot(self) -> Robot:
        """The robot: ``document.robot``."""
        return self.document.robot

    @property
    def editor(self) -> str:
        """The editor that shows the robot: ``"dh"`` for a robot of DH rows only, else
        ``"modules"`` (one of :data:`EDITORS`)."""
        return "dh" if all(isinstance(link, DHLink) for link in self.robot.modules) else "modules"

    @property
    def mode(self) -> str:
        """The header's editing mode: ``"wizard"`` while the guided mode is open, else
        :attr:`editor`."""
        return "wizard" if self.wizard is not None else self.editor

    @property
    def shown_robot(self) -> Robot:
        """The robot the 3D view and the header show: the guided mode's robot so far while
        it is open (when it has one), else the panel's robot."""
        if self.wizard is not None:
            try:
                preview = self.wizard.preview()
            except ValueError:
                preview = None
            if preview is not None:
                return preview
        return self.robot

    def with_document(self, **changes: Any) -> PanelState:
        """The state with parts of the document replaced."""
        return replace(self, document=replace(self.document, **changes))

    def replace(self, **changes: Any) -> PanelState:
        """The state with some fields replaced (a shorthand for :func:`dataclasses.replace`)."""
        return replace(self, **changes)
