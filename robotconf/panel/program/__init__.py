"""The Program tab: PTP, LIN, CIRC and Wait moves taught, edited, checked and run."""

from ._limits import LIMIT_FIELDS, default_limits, joint_setting, limit_controls, limit_value
from ._rows import move_rows, short_number
from ._view import ProgramView, run_summary, violations_by_move

__all__ = [
    "ProgramView",
    "move_rows",
    "short_number",
    "run_summary",
    "violations_by_move",
    "LIMIT_FIELDS",
    "default_limits",
    "joint_setting",
    "limit_controls",
    "limit_value",
]
