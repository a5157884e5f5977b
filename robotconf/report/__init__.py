r"""Reports: every result of the paper's §3 for one robot, written to a folder.

:func:`write_report` writes the step-by-step matrices, the DVA table and statistics, the
figures, the 3D scene and ``report.md`` (a robot program's moves and check too, when one
is given). ``robotconf report`` (:mod:`robotconf.cli`) and the panel's report download
both call it, so they write the same files. Robot files come from students and
instructors and are treated as untrusted: every name, label and unit they carry is
escaped in ``report.md`` (:func:`markdown_text`) and drawn literally in the figures and
the 3D scene. Input a user can fix raises :class:`BadInput` (or the core's
``InvalidInputError``).

>>> markdown_text("*q1*")
'\\*q1\\*'
"""

from ._bad_input import BadInput
from ._steps import DPI, DVA_SIZE, MAX_MODULE_PLOTS, RESULT_COPIES, SYMBOLIC_OFF, SYMBOLIC_TOO_LONG
from ._text import MAX_MESSAGE_CHARS, markdown_text, one_line
from ._write import write_report

__all__ = [
    "write_report",
    "BadInput",
    "markdown_text",
    "one_line",
    "DPI",
    "DVA_SIZE",
    "MAX_MODULE_PLOTS",
    "MAX_MESSAGE_CHARS",
    "RESULT_COPIES",
    "SYMBOLIC_OFF",
    "SYMBOLIC_TOO_LONG",
]
