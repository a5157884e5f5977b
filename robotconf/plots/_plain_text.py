"""Text properties that draw user-provided strings literally in matplotlib.

Robot, module and point names, units and signal descriptions come from students' and
instructors' files. matplotlib reads ``$…$`` in any text as mathtext (and everything as
LaTeX when ``text.usetex`` is on), so a name such as ``$\\frac{a}{b}$`` would be typeset,
and ``$x$$`` would make drawing the figure raise. Every title, label and annotation
that can hold such a string passes ``**PLAIN`` to matplotlib.

>>> from matplotlib.figure import Figure
>>> Figure().suptitle("$x$$", **PLAIN).get_text()
'$x$$'
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Any

__all__ = ["PLAIN"]

#: Keyword arguments for ``set_title``, ``set_xlabel``, ``text``, ``suptitle`` …: no
#: mathtext, no LaTeX, whatever the user's rcParams say.
PLAIN: MappingProxyType[str, Any] = MappingProxyType({"parse_math": False, "usetex": False})
