"""robotconf's conventions as data: movement types, codes, axes, units, joints, DH orders.

Everything that names a movement type, a joint or a Denavit–Hartenberg factor reads it
from here: the modules and DH links, the kinematics kernel's link descriptions, the
symbolic chain, URDF export, the 3D scene and the configurator panel. The prose behind
these tables is docs/conventions.md.

>>> MODULE_KINDS[MODULE_CODES["Ry"]], kind_axis("Ry"), kind_joint_type("Ry")
('Ry', 1, 'revolute')
>>> dh_formula("modified")
'Rx(α)·Tx(a)·Rz(θ)·Tz(d)'

The derived tables agree with the factor products they summarize:

>>> [name for kind, name in DH_FACTORS["standard"] if kind in TRANSLATION_KINDS] == list(DH_LENGTHS)
True
>>> about_z = [(k, n) for k, n in DH_FACTORS["standard"] if kind_axis(k) == 2]
>>> {kind_joint_type(k): n for k, n in about_z} == DH_JOINT_PARAMETER
True
>>> MODULE_OFFSETS == tuple(f"a{axis}" for axis in AXIS_NAMES)
True
"""

from __future__ import annotations

__all__ = [
    "MODULE_KINDS",
    "MODULE_CODES",
    "KIND_ALIASES",
    "ROTATION_KINDS",
    "TRANSLATION_KINDS",
    "AXIS_NAMES",
    "JOINT_TYPES",
    "JOINT_LETTERS",
    "JOINT_OF_LETTER",
    "JOINT_UNITS",
    "DH_CONVENTIONS",
    "DH_PARAMETERS",
    "DH_FACTORS",
    "DH_SYMBOLS",
    "DH_LENGTHS",
    "DH_JOINT_PARAMETER",
    "MODULE_OFFSETS",
    "kind_joint_type",
    "kind_axis",
    "kind_label",
    "dh_formula",
]

#: Movement types in the paper's order of sub-systems, by code 0–6 (null block first, then
#: rotations about x, y, z, then translations along x, y, z), and the offset-only
#: ``fixed`` kind, which is not in the paper and so has no code.
MODULE_KINDS = ("none", "Rx", "Ry", "Rz", "Tx", "Ty", "Tz", "fixed")
#: The paper's code of each movement type (``fixed`` has none).
MODULE_CODES = {kind: code for code, kind in enumerate(MODULE_KINDS[:7])}
#: Other names a user may type for a movement type (matched without regard to case).
KIND_ALIASES = {"null": "none"}
#: Movement types whose coordinate is an angle (radians).
ROTATION_KINDS = ("Rx", "Ry", "Rz")
#: Movement types whose coordinate is a length.
TRANSLATION_KINDS = ("Tx", "Ty", "Tz")

#: Principal axes by index: the kernel's axis 0, 1, 2.
AXIS_NAMES = ("x", "y", "z")

#: Joint types a link reports: revolute (q in radians), prismatic (q in length units),
#: none (the paper's null module, identity) and fixed (a constant offset, no joint).
JOINT_TYPES = ("revolute", "prismatic", "none", "fixed")
#: The one-letter joint names of DH tables and of the kernel: ``R`` and ``P``.
JOINT_LETTERS = {"revolute": "R", "prismatic": "P"}
#: A joint letter (or the word, any case) to its joint type.
JOINT_OF_LETTER = {
    "R": "revolute",
    "P": "prismatic",
    "REVOLUTE": "revolute",
    "PRISMATIC": "prismatic",
}
#: Unit of a coordinate by joint type; links without a joint have none.
JOINT_UNITS = {"revolute": "rad", "prismatic": "length", "none": "", "fixed": ""}

#: The Denavit–Hartenberg conventions robotconf knows; it never guesses between them.
DH_CONVENTIONS = ("standard", "modified")
#: The four parameters of a DH row, in table order.
DH_PARAMETERS = ("theta", "d", "a", "alpha")
#: Each convention's elementary factors, left to right: (movement type, parameter).
#: Standard (the paper's eq. 9): ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)``; modified (Craig):
#: ``Rx(α)·Tx(a)·Rz(θ)·Tz(d)``.
DH_FACTORS = {
    "standard": (("Rz", "theta"), ("Tz", "d"), ("Tx", "a"), ("Rx", "alpha")),
    "modified": (("Rx", "alpha"), ("Tx", "a"), ("Rz", "theta"), ("Tz", "d")),
}
#: How a DH parameter is written in formulas.
DH_SYMBOLS = {"theta": "θ", "d": "d", "a": "a", "alpha": "α"}
#: The DH parameters that are lengths (those of the translation factors).
DH_LENGTHS = ("d", "a")
#: The DH parameter a joint's coordinate adds to: θ for revolute, d for prismatic (both
#: about or along z, the DH joint axis).
DH_JOINT_PARAMETER = {"revolute": "theta", "prismatic": "d"}
#: A module's offsets by name, one per axis.
MODULE_OFFSETS = ("ax", "ay", "az")


def kind_joint_type(kind: str) -> str:
    """The joint type of a canonical movement type.

    >>> kind_joint_type("Tz"), kind_joint_type("fixed")
    ('prismatic', 'fixed')
    """
    if kind in ROTATION_KINDS:
        return "revolute"
    if kind in TRANSLATION_KINDS:
        return "prismatic"
    return kind


def kind_axis(kind: str) -> int | None:
    """The axis index (0 = x, 1 = y, 2 = z) of a joint's movement type; None without joint.

    >>> kind_axis("Tz"), kind_axis("none")
    (2, None)
    """
    if kind in ROTATION_KINDS or kind in TRANSLATION_KINDS:
        return AXIS_NAMES.index(kind[1].lower())
    return None


def kind_label(kind: str) -> str:
    """A movement type as a person reads it in a list: the paper's code, then the name.

    >>> kind_label("Ry"), kind_label("fixed")
    ('2 Ry', 'fixed')
    """
    code = MODULE_CODES.get(kind)
    return kind if code is None else f"{code} {kind}"


def dh_formula(convention: str) -> str:
    """A convention's product of factors as text, e.g. ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)``.

    >>> dh_formula("standard")
    'Rz(θ)·Tz(d)·Tx(a)·Rx(α)'
    """
    return "·".join(f"{kind}({DH_SYMBOLS[name]})" for kind, name in DH_FACTORS[convention])
