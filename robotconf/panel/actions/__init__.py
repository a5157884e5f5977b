"""Every user action on the configurator, as a value: ``panel.apply(SetQ(1, 0.5))``.

Each action is a small frozen dataclass; ``action.apply(state)`` gives the next
:class:`~robotconf.panel.state.PanelState` in one step or raises the core's
:class:`~robotconf.InvalidInputError` (the panel shows it beside the control and keeps
its state). Widgets only ever turn what the student does into one of these.

The robot
    :class:`SetQ`, :class:`SetModuleKind`, :class:`SetModuleOffset`,
    :class:`SetDHParameter`, :class:`SetDHJoint`, :class:`SetEndEffector`,
    :class:`SetActive`, :class:`AddModule`, :class:`RemoveModule`, :class:`MoveModule`
Another robot
    :class:`LoadPreset`, :class:`LoadRobot`, :class:`LoadSetup`
Editing modes and conversions
    :class:`ChooseMode`, :class:`ChooseConvention`, :class:`SetPromptConvention`,
    :class:`AnswerPrompt`
The guided mode
    :class:`WizardSetCount`, :class:`WizardSetKind`, :class:`WizardSetOffset`,
    :class:`WizardSetQ`, :class:`WizardSetPoint`, :class:`WizardNext`,
    :class:`WizardBack`, :class:`WizardCancel`
Motion
    :class:`SetSignalKind`, :class:`SetSignalParameter`, :class:`SetSignalTable`,
    :class:`SetTimeSetting`, :class:`Run`
Program
    :class:`AddMove`, :class:`ClearProgram`, :class:`EditMove`, :class:`MoveRow`,
    :class:`SetProgramSetting`, :class:`SetProgramDt`, :class:`RunProgram`
Reach
    :class:`SetReachMode`, :class:`SetReachTarget`, :class:`ReachFromCurrent`,
    :class:`Solve`, :class:`PickSolution`, :class:`SetShowAll`; the closed-form branches
    of a target (:func:`solutions_for`, :class:`ClosedForm`)
Units, view and playback
    :class:`SetAngleUnit`, :class:`SetLengthUnit`, :class:`SelectTab`,
    :class:`SetViewOption`, :class:`Animate`, :class:`Play`, :class:`Pause`,
    :class:`Seek`, :class:`SetSpeed`, :class:`PlaybackReported`

>>> import robotconf as rc
>>> from robotconf.panel.state import PanelState
>>> state = PanelState.start(rc.preset("paper"))
>>> state = SetAngleUnit(False).apply(SetQ(0, 0.25).apply(state))
>>> state.robot.q, state.units.angle
(array([0.25, 0.  , 0.  ]), 'rad')
"""

from ._base import Action, with_robot
from ._closed_form import ClosedForm, closed_form, q_text, same_configuration
from ._conversions import CONSTANT_MARK, held_modules, to_convention, to_dh, to_modules
from ._editors import MODES, AnswerPrompt, ChooseConvention, ChooseMode, SetPromptConvention
from ._loads import LoadPreset, LoadRobot, LoadSetup
from ._motion import (
    EDITABLE_SIGNALS,
    HOLD,
    Run,
    SetSignalKind,
    SetSignalParameter,
    SetSignalTable,
    SetTimeSetting,
)
from ._program import (
    ROW_ACTIONS,
    AddMove,
    ClearProgram,
    EditMove,
    MoveRow,
    RunProgram,
    SetProgramDt,
    SetProgramSetting,
    run_program,
)
from ._program_edits import edit_move, row_action, taught_markers
from ._reach import (
    TARGET_FIELDS,
    PickSolution,
    ReachFromCurrent,
    SetReachMode,
    SetReachTarget,
    SetShowAll,
    Solve,
    solutions_for,
)
from ._robot_edits import (
    AddModule,
    MoveModule,
    RemoveModule,
    SetActive,
    SetDHJoint,
    SetDHParameter,
    SetEndEffector,
    SetModuleKind,
    SetModuleOffset,
    SetQ,
)
from ._view import (
    Animate,
    Pause,
    Play,
    PlaybackReported,
    Seek,
    SelectTab,
    SetAngleUnit,
    SetLengthUnit,
    SetSpeed,
    SetViewOption,
    check_length_unit,
)
from ._wizard import (
    WizardBack,
    WizardCancel,
    WizardNext,
    WizardSetCount,
    WizardSetKind,
    WizardSetOffset,
    WizardSetPoint,
    WizardSetQ,
)

__all__ = [
    "Action",
    "with_robot",
    "to_modules",
    "to_dh",
    "to_convention",
    "held_modules",
    "CONSTANT_MARK",
    # the robot
    "SetQ",
    "SetModuleKind",
    "SetModuleOffset",
    "SetDHParameter",
    "SetDHJoint",
    "SetEndEffector",
    "SetActive",
    "AddModule",
    "RemoveModule",
    "MoveModule",
    # another robot
    "LoadPreset",
    "LoadRobot",
    "LoadSetup",
    # editing modes and conversions
    "ChooseMode",
    "ChooseConvention",
    "SetPromptConvention",
    "AnswerPrompt",
    "MODES",
    # the guided mode
    "WizardSetCount",
    "WizardSetKind",
    "WizardSetOffset",
    "WizardSetQ",
    "WizardSetPoint",
    "WizardNext",
    "WizardBack",
    "WizardCancel",
    # motion
    "SetSignalKind",
    "SetSignalParameter",
    "SetSignalTable",
    "SetTimeSetting",
    "Run",
    "HOLD",
    "EDITABLE_SIGNALS",
    # program
    "AddMove",
    "ClearProgram",
    "EditMove",
    "MoveRow",
    "SetProgramSetting",
    "SetProgramDt",
    "RunProgram",
    "ROW_ACTIONS",
    "run_program",
    "edit_move",
    "row_action",
    "taught_markers",
    # reach
    "SetReachMode",
    "SetReachTarget",
    "ReachFromCurrent",
    "Solve",
    "PickSolution",
    "SetShowAll",
    "TARGET_FIELDS",
    "solutions_for",
    "ClosedForm",
    "closed_form",
    "same_configuration",
    "q_text",
    # units, view and playback
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
