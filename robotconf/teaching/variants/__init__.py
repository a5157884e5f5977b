"""Per-student exercise numbers: the same student id gives the same numbers everywhere.

    :class:`Variant`

>>> Variant("demo", "lesson").length("l", 30, 30)
30.0
"""

from ._variant import Variant

__all__ = ["Variant"]
