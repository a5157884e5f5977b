"""Links: the paper's modules and Denavit–Hartenberg rows, one joint each, with ranges.

A link is what a robot chains: a :class:`Module` (``Trans(a)·Rot/Trans_axis(q)``) or a
:class:`DHLink` (a standard or modified DH row), both :class:`Link`\\ s that describe
themselves to the kernel. Joint ranges and the robot's size (the default stroke of a
prismatic joint) are read from the links.

Modules
    :class:`Module`, :func:`kind_name`, :func:`transfer_matrix`
DH rows
    :class:`DHLink`, :func:`dh_matrix`, :func:`check_convention`, :func:`dh_link_from_row`
Every link
    :class:`Link` (``matrix``, ``matrix_derivative``, ``geometry``)
Joint ranges and size
    :func:`check_limits`, :func:`chain_length`, :func:`chain_limits`, :func:`default_limits`

>>> float(transfer_matrix("Tz", 0.5)[2, 3]), float(DHLink(a=1.0).matrix()[0, 3])
(0.5, 1.0)
"""

from ._dh import DHLink, check_convention, dh_link_from_row, dh_matrix
from ._limits import chain_length, chain_limits, check_limits, default_limits
from ._link import Link
from ._module import Module, kind_name, transfer_matrix

__all__ = [
    "Link",
    "Module",
    "kind_name",
    "transfer_matrix",
    "DHLink",
    "dh_matrix",
    "check_convention",
    "dh_link_from_row",
    "check_limits",
    "chain_length",
    "chain_limits",
    "default_limits",
]
