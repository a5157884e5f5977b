"""What a student does in the cell designer, one frozen value per action.

``action.apply(state)`` gives the next :class:`~robotconf.cell_designer.state.DesignerState`
or raises the core's :class:`~robotconf.InvalidInputError` (nothing changes). Actions
import no widget: each can be applied and tested alone, and
``designer.apply(action)`` does from a notebook cell what a control does.

The table
    :class:`AddObject`, :class:`AddFrame`, :class:`AddMesh`, :class:`RemoveEntry`,
    :class:`RenameEntry`, :class:`SetParent`, :class:`SetPose`, :class:`SetSize`,
    :class:`Select`, :data:`ADD_KINDS`
Robots
    :class:`AddRobot`, :class:`SetQ`, :func:`preset_name`
Programs and Run
    :class:`AddMove`, :class:`SetMoveKind`, :class:`SetMoveTarget`,
    :class:`SetMoveNumber`, :class:`SetMoveProfile`, :class:`TeachMove`,
    :class:`MoveRow`, :class:`RemoveMove`, :class:`SetProgramOption`,
    :class:`SetRunDt`, :class:`Run`
The reach map
    :class:`SetReachMap`, :class:`SetReachRobot`, :class:`SetReachCorner`,
    :class:`SetReachStep`, :class:`UpdateReachMap`, :func:`reach_region`,
    :data:`MAX_DESIGNER_VOXELS`
Units, view, files
    :class:`SetAngleUnit`, :class:`SetLengthUnit`, :class:`ShowCapsules`,
    :class:`LoadDocument`
Base
    :class:`Action`, helpers :func:`tcp_point`, :func:`frame_point`, :func:`end_point`

>>> from robotconf.cell_designer.state import DesignerState
>>> state = AddRobot("paper").apply(DesignerState())
>>> state = AddObject("box").apply(state)
>>> state = SetPose("box1", 0, 50.0).apply(state)
>>> state.cell.names, state.cell.build().pose_of("box1")[:3, 3].tolist()
(('paper', 'box1'), [50.0, 0.0, 5.0])
"""

from ._base import Action, cell_size, nice
from ._entries import (
    ADD_KINDS,
    AddFrame,
    AddMesh,
    AddObject,
    RemoveEntry,
    RenameEntry,
    Select,
    SetParent,
    SetPose,
    SetSize,
    fresh_name,
)
from ._moves import end_point, frame_point, tcp_point
from ._program import (
    MOVE_FIELDS,
    AddMove,
    MoveRow,
    RemoveMove,
    Run,
    SetMoveKind,
    SetMoveNumber,
    SetMoveProfile,
    SetMoveTarget,
    SetProgramOption,
    SetRunDt,
    TeachMove,
)
from ._reach import (
    MAX_DESIGNER_VOXELS,
    SetReachCorner,
    SetReachMap,
    SetReachRobot,
    SetReachStep,
    UpdateReachMap,
    reach_region,
    voxel_count,
)
from ._robots import AddRobot, SetQ, preset_name
from ._view import LoadDocument, SetAngleUnit, SetLengthUnit, ShowCapsules

__all__ = [
    "Action",
    # the table
    "AddObject",
    "AddFrame",
    "AddMesh",
    "RemoveEntry",
    "RenameEntry",
    "SetParent",
    "SetPose",
    "SetSize",
    "Select",
    "ADD_KINDS",
    "fresh_name",
    # robots
    "AddRobot",
    "SetQ",
    "preset_name",
    # programs
    "AddMove",
    "SetMoveKind",
    "SetMoveTarget",
    "SetMoveNumber",
    "SetMoveProfile",
    "TeachMove",
    "MoveRow",
    "RemoveMove",
    "SetProgramOption",
    "SetRunDt",
    "Run",
    "MOVE_FIELDS",
    # reach map
    "SetReachMap",
    "SetReachRobot",
    "SetReachCorner",
    "SetReachStep",
    "UpdateReachMap",
    "reach_region",
    "voxel_count",
    "MAX_DESIGNER_VOXELS",
    # units, view, files
    "SetAngleUnit",
    "SetLengthUnit",
    "ShowCapsules",
    "LoadDocument",
    # helpers
    "cell_size",
    "nice",
    "tcp_point",
    "frame_point",
    "end_point",
]
