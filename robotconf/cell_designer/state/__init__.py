"""The cell designer's one state: immutable values, no widgets.

The designer never keeps a mutable :class:`~robotconf.Cell` in its state: it keeps a
:class:`CellDescription` (frozen copies of the entries) and builds the cell from it, once
per description. Equality is by value, so undo is going back to an older value and a
test can compare the table, the view and the file with ``==``.

The state
    :class:`DesignerState`, :class:`DesignerDocument`, :class:`ReachSetup`,
    :class:`ReachOutcome`, :class:`RunOutcome`
The cell
    :class:`CellDescription`, :class:`ObjectItem`, :class:`FrameItem`,
    :class:`RobotItem`, :data:`Item`, :data:`Pose`, :data:`POSE_FIELDS`,
    :func:`pose_of`, :func:`pose_numbers`, :func:`with_pose_number`, :func:`own_name`
Programs
    :class:`RobotProgram`, :data:`MOVE_KINDS`, :data:`OPTION_NAMES`, :func:`target_of`

>>> import robotconf as rc
>>> cell = rc.Cell(unit="mm")
>>> cell.add_robot("arm", rc.preset("paper"))
>>> state = DesignerState(DesignerDocument(CellDescription.from_cell(cell)))
>>> state.units, state.cell.robots
(Units(length='mm', degrees=True), ('arm',))
"""

from ._description import CellDescription, Renames
from ._items import (
    POSE_FIELDS,
    FrameItem,
    Item,
    ObjectItem,
    Pose,
    RobotItem,
    own_name,
    pose_numbers,
    pose_of,
    radius_value,
    with_pose_number,
)
from ._programs import MOVE_KINDS, OPTION_NAMES, RobotProgram, renamed_frames, target_of
from ._state import DesignerDocument, DesignerState, ReachOutcome, ReachSetup, RunOutcome

__all__ = [
    # the state
    "DesignerState",
    "DesignerDocument",
    "ReachSetup",
    "ReachOutcome",
    "RunOutcome",
    # the cell
    "CellDescription",
    "Renames",
    "ObjectItem",
    "FrameItem",
    "RobotItem",
    "Item",
    "Pose",
    "POSE_FIELDS",
    "pose_of",
    "pose_numbers",
    "with_pose_number",
    "own_name",
    "radius_value",
    # programs
    "RobotProgram",
    "MOVE_KINDS",
    "OPTION_NAMES",
    "target_of",
    "renamed_frames",
]
