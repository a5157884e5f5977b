"""Robot programs: PTP, LIN, CIRC and Wait moves between taught positions (docs/programs.md).

As a robot controller runs them (KUKA KRL PTP/LIN/CIRC, UR MoveJ/MoveL/MoveP, ABB
MoveJ/MoveL/MoveC): a PTP move interpolates the joints, synchronized, with a trapezoidal
or quintic profile; LIN and CIRC move the end effector along an exact line or circular
arc at a trapezoidal path speed, solved by ``rc.ik`` at every sample.

Programs
    :class:`Program` (``check``, ``simulate``; files: :mod:`robotconf.io`),
    :class:`PTP`, :class:`LIN`, :class:`CIRC`, :class:`Wait`, :class:`Move`
Results
    :class:`ProgramMotion` (a :class:`~robotconf.motion.Motion` with its moves),
    :class:`ProgramReport`, :class:`Violation`, :data:`VIOLATIONS`, :class:`Segment`,
    :func:`moving_joints` (which coordinates a program moves)
Profiles and paths
    :class:`Profile`, :func:`trapezoidal`, :func:`quintic`, :data:`PROFILES`,
    :class:`CartesianPath`, :func:`line_path`, :func:`arc_path`, :class:`Limits`

The largest joint step, 0.5 rad at the default 1 rad/s and 2 rad/s², takes
0.5/1 + 1/2 = 1 s; then the program waits 0.5 s:

>>> import robotconf as rc
>>> prog = Program(rc.preset("paper"), [PTP(q=[0, 0.3, -0.5]), Wait(0.5)])
>>> prog.duration
1.5
"""

from ._chain import moving_joints
from ._limits import LIMIT_NAMES, Limits, resolve_limits
from ._motion import ProgramMotion
from ._moves import CIRC, LIN, MOVE_TYPES, ORIENTATIONS, PTP, Move, Wait
from ._paths import CartesianPath, arc_path, line_path
from ._plan import PATH_TOL, Segment
from ._profiles import PROFILES, Profile, quintic, trapezoidal
from ._program import MAX_MOVES, SINGULARITY_TOL, Program
from ._report import VIOLATIONS, ProgramReport, Violation

__all__ = [
    # programs
    "Program",
    "Move",
    "PTP",
    "LIN",
    "CIRC",
    "Wait",
    "MOVE_TYPES",
    "ORIENTATIONS",
    "MAX_MOVES",
    "SINGULARITY_TOL",
    "PATH_TOL",
    "LIMIT_NAMES",
    # results
    "ProgramMotion",
    "ProgramReport",
    "Violation",
    "VIOLATIONS",
    "Segment",
    "moving_joints",
    # profiles and paths
    "Profile",
    "PROFILES",
    "trapezoidal",
    "quintic",
    "CartesianPath",
    "line_path",
    "arc_path",
    "Limits",
    "resolve_limits",
]
