"""DH tables and conversions: the same chain written as modules or as DH rows of either kind.

A DH row becomes the paper's modules and back (:func:`dh_to_modules`,
:func:`modules_to_dh`, using exact identities only); a standard table becomes the
modified table of the same robot, or the same numbers are read in the other convention.

DH ⇄ modules
    :func:`dh_to_modules`, :func:`modules_to_dh`
Standard ⇄ modified DH
    :func:`convert_dh` (the same robot), :func:`reinterpret_dh` (the same numbers)

>>> [m.kind for m in dh_to_modules((0.0, 0.5, 1.0, 0.0, "R"))]
['Rz', 'fixed']
"""

from ._convention_change import convert_dh, reinterpret_dh
from ._from_modules import modules_to_dh
from ._to_modules import dh_to_modules

__all__ = ["dh_to_modules", "modules_to_dh", "convert_dh", "reinterpret_dh"]
