"""The designer's views: each draws itself from the state with one form and turns what
the student does into one action.

:class:`HeaderView` (undo, redo, units, capsules), :class:`TableView` (objects and
frames), :class:`RobotsView`, :class:`ReachView`, :class:`ProgramsView` (the moves, Run
and its results), :class:`FilesView` (downloads), :func:`mesh_from_upload`;
:class:`Messages` (what is said beside a control) and the row keys' reader
:func:`parse_key`.
"""

from ._boxes import ANGLE, LENGTH, box, core_value, length_step, pose_boxes
from ._files import MESH_TYPES, FilesView, mesh_from_upload
from ._header import HeaderView
from ._messages import Messages
from ._moves import MOVE_CLASS, target_choices
from ._programs import ProgramsView
from ._reach import ReachView, reach_summary
from ._results import CONTACT_CLASS, move_notes, run_lines
from ._robots import RobotsView
from ._rows import CELL_PARENT, SELECTED_CLASS, parse_key
from ._table import TableView

__all__ = [
    "HeaderView",
    "TableView",
    "RobotsView",
    "ReachView",
    "ProgramsView",
    "FilesView",
    "Messages",
    "mesh_from_upload",
    "MESH_TYPES",
    "parse_key",
    "box",
    "pose_boxes",
    "core_value",
    "length_step",
    "target_choices",
    "reach_summary",
    "run_lines",
    "move_notes",
    "ANGLE",
    "LENGTH",
    "CELL_PARENT",
    "SELECTED_CLASS",
    "MOVE_CLASS",
    "CONTACT_CLASS",
]
