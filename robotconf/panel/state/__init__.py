"""The panel's one state and its history: immutable values, no widgets.

Every view of the configurator renders a :class:`PanelState`; every user action replaces
it by the next one (``robotconf.panel.actions``). Undo and redo step through its
:class:`Document` (robot, signals and time settings, program), which is also what the
bound file holds.

The state
    :class:`PanelState`, :class:`Document`, :class:`Prompt`, :class:`ProgramRun`,
    :data:`EDITORS`, :data:`PROMPTS`
Its parts
    :class:`Units`, :class:`MotionSetup`, :class:`ProgramDraft`, :class:`ReachState`,
    :class:`ReachOutcome`, :class:`ViewOptions`, :class:`Playback`, :class:`WizardDraft`,
    :class:`WizardModule`
Undo and redo
    :class:`History`, :data:`HISTORY_LIMIT`, :data:`COALESCE_SECONDS`

>>> import robotconf as rc
>>> state = PanelState.start(rc.preset("paper"))
>>> state.mode, state.units
('modules', Units(length='units', degrees=True))
"""

from ._history import COALESCE_SECONDS, HISTORY_LIMIT, History
from ._motion_setup import MotionSetup, remap
from ._panel_state import EDITORS, PROMPTS, Document, PanelState, ProgramRun, Prompt
from ._program_draft import ProgramDraft
from ._reach import REACH_MODES, ReachOutcome, ReachState, target_numbers, target_of
from ._units import LENGTH_UNITS, Units
from ._units_text import in_units
from ._view import LABEL_MODES, RESULT_VIEWS, SOURCES, TABS, Playback, ViewOptions
from ._wizard import MAX_WIZARD_MODULES, WizardDraft, WizardModule

__all__ = [
    "in_units",
    # the state
    "PanelState",
    "Document",
    "Prompt",
    "ProgramRun",
    "EDITORS",
    "PROMPTS",
    # its parts
    "Units",
    "LENGTH_UNITS",
    "MotionSetup",
    "remap",
    "ProgramDraft",
    "ReachState",
    "ReachOutcome",
    "REACH_MODES",
    "target_numbers",
    "target_of",
    "ViewOptions",
    "Playback",
    "TABS",
    "LABEL_MODES",
    "RESULT_VIEWS",
    "SOURCES",
    "WizardDraft",
    "WizardModule",
    "MAX_WIZARD_MODULES",
    # undo and redo
    "History",
    "HISTORY_LIMIT",
    "COALESCE_SECONDS",
]
