"""The robot editor: the module list or the DH table, the active count, the end effector.

A form rendered from the state (:func:`module_rows`, :func:`dh_rows`,
:func:`extras_rows`); what the student does becomes an action (:class:`EditorView`).
Numbers are shown and read back through :class:`Quantity`.
"""

from ._editor import Dispatch, EditorView
from ._quantity import Quantity, Ranges, number_spec, read_number
from ._rows import CONVENTION_TIPS, KIND_OPTIONS, EditorContext, dh_rows, extras_rows, module_rows

__all__ = [
    "EditorView",
    "Dispatch",
    "Quantity",
    "Ranges",
    "number_spec",
    "read_number",
    "EditorContext",
    "module_rows",
    "dh_rows",
    "extras_rows",
    "KIND_OPTIONS",
    "CONVENTION_TIPS",
]
