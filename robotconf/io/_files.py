"""robotconf files: a robot, optional signals and simulation settings as versioned JSON.

Writing uses :mod:`json` with ``allow_nan=False`` (every float as its shortest exact
``repr``, so a round trip is exact). Reading is defensive: at most :data:`MAX_BYTES` of
strict UTF-8, JSON objects without duplicate keys, no NaN/Infinity, bounded nesting, and
the schema of :mod:`robotconf.io._schema`. Nothing read is ever evaluated. The format is
described in docs/file-format.md.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import InvalidInputError
from .._json_fields import Rejected, check_json_object
from .._validation import one_line
from ..motion import SimulationSettings
from ..programs import Program
from ..signals import Constant, Signal, signal_from_dict
from ._program_schema import program_from_dict, program_to_dict
from ._schema import (
    FORMAT,
    VERSION,
    JSONObject,
    check_simulation,
    robot_from_dict,
    robot_to_dict,
)

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = [
    "Setup",
    "load",
    "load_setup",
    "load_program",
    "program_to_json",
    "parse_json",
    "MAX_BYTES",
]

#: Largest file (or text) robotconf reads: 1 MB. 64 links with a signal each take ~50 kB.
MAX_BYTES = 1_000_000

# An indented list of numbers: json puts each on its own line. Raw newlines never occur
# inside JSON strings, so this cannot touch a name.
_NUMBER_LIST = re.compile(r"\[\n\s+(-?[\d.eE+-]+(?:,\n\s+-?[\d.eE+-]+)*)\n\s*\]")

_TOP_KEYS = {
    "format": True,
    "version": True,
    "robot": True,
    "signals": False,
    "simulation": False,
    "program": False,
}


def _pairs(pairs: list[tuple[str, Any]]) -> JSONObject:
    obj = JSONObject(pairs)
    if len(obj) != len(pairs):
        # json keeps the last of repeated keys silently; remember them to refuse the file.
        seen: set[str] = set()
        repeated = []
        for key, _ in pairs:
            if key in seen:
                repeated.append(key)
            seen.add(key)
        obj.duplicates = tuple(repeated)
    return obj


def _float(text: str) -> float | Rejected:
    value = float(text)
    return value if abs(value) != float("inf") else Rejected(text, "too large for a float")


def _int(text: str) -> int | Rejected:
    # Python refuses to parse ints of more than 4300 digits; no robot needs 30.
    if len(text) > 30:
        return Rejected(text[:20] + "…", "number with too many digits")
    return int(text)


def parse_json(text: Any, field: str = "file") -> Any:
    """Parse JSON text defensively (size, syntax, nesting; NaN/duplicates marked for later).

    >>> parse_json('{"a": [1, 2.5]}')
    {'a': [1, 2.5]}
    >>> parse_json('{"a": 1,')
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: file: not valid JSON (Expecting property name enclosed ...
    """
    if not isinstance(text, str):
        raise InvalidInputError(field, text, "JSON text (str)", problem="not text:")
    if len(text) > MAX_BYTES:
        raise InvalidInputError(
            field, f"<{len(text)} characters>", f"at most {MAX_BYTES} bytes", problem="too large:"
        )
    try:
        return json.loads(
            text,
            object_pairs_hook=_pairs,
            parse_constant=lambda name: Rejected(name, f"{name} is not allowed"),
            parse_float=_float,
            parse_int=_int,
        )
    except json.JSONDecodeError as error:
        where = f"line {error.lineno} column {error.colno}"
        raise InvalidInputError(
            field, where, "valid JSON", problem=f"not valid JSON ({error.msg}) at"
        ) from None
    except RecursionError:
        raise InvalidInputError(
            field, "<nested lists/objects>", "JSON nested a few levels deep", problem="too deep:"
        ) from None


def _check_signals(value: Any, robot: Robot, path: str = "signals") -> dict[str, Signal]:
    if not isinstance(value, Mapping):
        raise InvalidInputError(path, value, "an object mapping q1… to signals", problem="not:")
    duplicates = getattr(value, "duplicates", ())
    if duplicates:
        raise InvalidInputError(
            f"{path}.{duplicates[0]}", duplicates[0], "each key once", problem="duplicate key"
        )
    names = robot.coordinate_names
    out: dict[str, Signal] = {}
    for key, signal in value.items():
        label = names[robot.index(key, f"{path}.{key}")]
        if label in out:
            raise InvalidInputError(
                f"{path}.{key}", key, "each coordinate once", problem=f"{label} is given twice:"
            )
        if isinstance(signal, Signal):
            out[label] = signal
        elif isinstance(signal, (int, float)) and not isinstance(signal, bool):
            out[label] = Constant(signal)
        else:
            out[label] = signal_from_dict(signal, f"{path}.{key}")
    return out


def _simulation(value: Mapping[str, Any] | SimulationSettings) -> dict[str, Any]:
    if isinstance(value, SimulationSettings):
        return value.to_dict()
    return check_simulation(value)


@dataclass(frozen=True)
class Setup:
    """What a robotconf file holds: a robot, signals for some coordinates, run settings.

    Parameters
    ----------
    robot : Robot
    signals : dict, optional
        Maps coordinate names (``"q3"``) to :class:`~robotconf.signals.Signal` objects (a
        number means a constant), as for :func:`~robotconf.simulate`.
    simulation : dict or SimulationSettings, optional
        ``t_end`` (required), ``dt``, ``t0`` (s) and ``method``, checked by
        :class:`~robotconf.motion.SimulationSettings`. Kept as a dict of the keys given
        (all four for a SimulationSettings), so a file is written back as it was read;
        keys left out take the defaults. :attr:`settings` gives the settings object.
    program : Program, optional
        A robot program (PTP/LIN/CIRC/Wait moves, docs/programs.md) for this robot.

    Examples
    --------
    >>> import robotconf as rc
    >>> setup = Setup(rc.preset("paper"), {"q3": rc.signals.Ramp()}, {"t_end": 2.0})
    >>> Setup.from_json(setup.to_json()) == setup
    True
    >>> setup.simulate_kwargs()
    {'t_end': 2.0}
    >>> setup.settings.samples
    2001
    """

    robot: Robot
    signals: Mapping[str, Signal] = field(default_factory=dict)
    simulation: Mapping[str, Any] | SimulationSettings | None = None
    program: Program | None = None

    def __post_init__(self) -> None:
        from ..kinematics import Robot  # local: _robot imports this module

        if not isinstance(self.robot, Robot):
            raise InvalidInputError("robot", self.robot, "a Robot")
        if self.program is not None and (
            not isinstance(self.program, Program) or self.program.robot != self.robot
        ):
            raise InvalidInputError(
                "program", one_line(self.program), "a Program of this setup's robot, or None"
            )
        object.__setattr__(self, "signals", _check_signals(self.signals or {}, self.robot))
        if self.simulation is not None:
            object.__setattr__(self, "simulation", _simulation(self.simulation))

    @property
    def settings(self) -> SimulationSettings | None:
        """The simulation settings with defaults filled in, or ``None`` if there are none."""
        given = self.simulate_kwargs()
        return SimulationSettings(**given) if given else None

    def simulate_kwargs(self) -> dict[str, Any]:
        """The simulation settings given, as keyword arguments of :func:`~robotconf.simulate`."""
        return {} if self.simulation is None else _simulation(self.simulation)

    def to_dict(self) -> dict[str, Any]:
        """The file's content as plain data (see docs/file-format.md)."""
        data: dict[str, Any] = {
            "format": FORMAT,
            "version": VERSION,
            "robot": robot_to_dict(self.robot),
        }
        if self.signals:
            data["signals"] = {key: s.to_dict() for key, s in self.signals.items()}
        if self.simulation is not None:
            data["simulation"] = self.simulate_kwargs()
        if self.program is not None:
            data["program"] = program_to_dict(self.program)
        return data

    def to_json(self, indent: int | None = 2) -> str:
        """The file's text: JSON, UTF-8-ready, floats exact, number lists on one line."""
        text = json.dumps(self.to_dict(), indent=indent, ensure_ascii=False, allow_nan=False)
        return _NUMBER_LIST.sub(lambda m: "[" + re.sub(r",\s+", ", ", m.group(1)) + "]", text)

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write :meth:`to_json` to ``path`` (UTF-8); returns the path."""
        target = Path(path)
        target.write_text(self.to_json() + "\n", encoding="utf-8")
        return target

    @classmethod
    def from_dict(cls, data: Any) -> Setup:
        """Validate parsed file content (format, version, schema) into a Setup."""
        if not isinstance(data, Mapping):
            raise InvalidInputError(
                "file", data, "a JSON object at the top level", problem="expected an object, got"
            )
        if data.get("format") != FORMAT:
            raise InvalidInputError(
                "format", data.get("format"), f"'{FORMAT}'", problem="not a robotconf file:"
            )
        version = data.get("version")
        if isinstance(version, bool) or not isinstance(version, int) or version < 1:
            raise InvalidInputError("version", one_line(version), f"an integer 1…{VERSION}")
        if version > VERSION:
            raise InvalidInputError(
                "version",
                one_line(version),
                f"versions up to {VERSION}: update robotconf to read it",
                problem="written by a newer robotconf: file format version",
            )
        check_json_object(data, "file", _TOP_KEYS)
        robot = robot_from_dict(data["robot"])
        signals = _check_signals(data.get("signals", {}), robot)
        simulation = data.get("simulation")
        program = data.get("program")
        return cls(
            robot,
            signals,
            None if simulation is None else check_simulation(simulation),
            None if program is None else program_from_dict(program, robot),
        )

    @classmethod
    def from_json(cls, text: str) -> Setup:
        """Parse and validate file text (see :func:`load_setup`)."""
        return cls.from_dict(parse_json(text))


def _read(path: str | os.PathLike[str]) -> str:
    target = Path(path)
    try:
        with target.open("rb") as handle:
            raw = handle.read(MAX_BYTES + 1)
    except OSError as error:
        raise InvalidInputError(
            "file", str(target), "a readable file", problem=f"{error.strerror}:"
        ) from None
    if len(raw) > MAX_BYTES:
        raise InvalidInputError(
            "file", str(target), f"files of at most {MAX_BYTES} bytes", problem="too large:"
        )
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise InvalidInputError(
            "file", str(target), "UTF-8 text", problem=f"invalid UTF-8 at byte {error.start}:"
        ) from None


def load_setup(source: str | bytes | os.PathLike[str]) -> Setup:
    """Read a robotconf file (or its text) with its signals and simulation settings.

    Parameters
    ----------
    source : path, JSON text or bytes
        A :class:`~pathlib.Path`; a str whose first non-blank character (after a
        byte-order mark) is ``{``, ``[`` or ``"`` (JSON text) or else names a file; or the
        file's bytes (UTF-8, with or without a byte-order mark).

    Returns
    -------
    Setup

    Raises
    ------
    InvalidInputError
        Naming the JSON path of the first problem (e.g. ``robot.links[2].kind``), the
        value and what is allowed; see docs/file-format.md for every rule and limit.

    Examples
    --------
    >>> setup = load_setup('''{"format": "robotconf", "version": 1,
    ...   "robot": {"links": [{"type": "module", "kind": "Tz"}]},
    ...   "signals": {"q1": {"type": "Ramp", "slope": 2.0}}}''')
    >>> setup.signals["q1"].value(1.5)
    3.0
    >>> load_setup('{"format": "robotconf", "version": 2, "robot": {}}')
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: version: written by a newer robotconf: file format version 2; ...
    """
    if isinstance(source, bytes):
        if len(source) > MAX_BYTES:
            raise InvalidInputError(
                "file", f"<{len(source)} bytes>", f"at most {MAX_BYTES} bytes", problem="too large:"
            )
        try:
            text = source.decode("utf-8-sig")
        except UnicodeDecodeError as error:
            raise InvalidInputError(
                "file", source[:20], "UTF-8 text", problem=f"invalid UTF-8 at byte {error.start}:"
            ) from None
    elif isinstance(source, str) and source.lstrip("\ufeff").lstrip()[:1] in ("{", "[", '"'):
        # Text copied from a file saved "with BOM" starts with U+FEFF; json refuses it.
        text = source.lstrip("\ufeff")
    elif isinstance(source, (str, os.PathLike)):
        text = _read(source)
    else:
        raise InvalidInputError("source", source, "a path, JSON text or bytes", problem="not:")
    return Setup.from_json(text)


def program_to_json(program: Program, indent: int | None = 2) -> str:
    """A robotconf file's text holding a program's robot and the program.

    >>> import robotconf as rc
    >>> prog = rc.Program(rc.preset("paper"), [rc.PTP(q=[0, 0.3, -0.5])])
    >>> load_program(program_to_json(prog)) == prog
    True
    """
    if not isinstance(program, Program):
        raise InvalidInputError("program", one_line(program), "a Program", problem="not a program:")
    return Setup(program.robot, program=program).to_json(indent)


def load_program(source: str | bytes | os.PathLike[str]) -> Program:
    """The robot program of a robotconf file (a path, its text or bytes; its robot comes along).

    Raises
    ------
    InvalidInputError
        As :func:`load_setup`; ``program`` when the file holds none.

    Examples
    --------
    >>> import robotconf as rc
    >>> load_program(rc.preset("paper").to_json())
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: program: missing: None; allowed: a robotconf file with ...
    """
    program = load_setup(source).program
    if program is None:
        raise InvalidInputError(
            "program", None, 'a robotconf file with a "program" section', problem="missing:"
        )
    return program


def load(path: str | os.PathLike[str]) -> Robot:
    """Read the robot of a robotconf file (signals, settings, a program: validated, dropped).

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    Robot

    Examples
    --------
    >>> import tempfile, robotconf as rc
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = rc.preset("paper").save(folder + "/paper.json")
    ...     rc.load(path).end_effector([0, 0, 0])
    array([70.,  0., 20.])
    """
    return Setup.from_json(_read(path)).robot
