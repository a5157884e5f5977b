"""The robotconf file schema (version 1): plain JSON data ⇄ robots, strictly validated.

Every reader here takes already-parsed JSON data (dicts, lists, str, int, float, None) and
a *path* such as ``robot.links[2]``; every error names that path, the value and what is
allowed. Nothing is ever evaluated. docs/file-format.md describes the schema.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from .._errors import InvalidInputError
from .._json_fields import check_json_number, check_json_object
from .._validation import one_line
from ..kinematics import MAX_MODULES, MAX_NAME_CHARS, MODULE_KINDS, DHLink, Module
from ..motion import SimulationSettings

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = [
    "FORMAT",
    "VERSION",
    "MAX_LINKS",
    "MAX_NAME_CHARS",
    "robot_to_dict",
    "robot_from_dict",
    "check_simulation",
]

#: The value of the top-level ``"format"`` key.
FORMAT = "robotconf"
#: The schema version this robotconf writes and the newest it reads.
VERSION = 1
#: Most links in a file: a teaching tool's robots have a handful; 64 is generous (and a
#: robot's own limit, :data:`~robotconf.kinematics.MAX_MODULES`).
MAX_LINKS = MAX_MODULES

_MODULE_KEYS = {"type": True, "kind": True, "a": False, "q": False, "name": False, "limits": False}
_DH_KEYS = {
    "type": True,
    "theta": True,
    "d": True,
    "a": True,
    "alpha": True,
    "joint": True,
    "convention": True,
    "q": False,
    "name": False,
    "limits": False,
}
_ROBOT_KEYS = {"links": True, "name": False, "end_effector": False, "active": False}


class JSONObject(dict):  # type: ignore[type-arg]
    """A parsed JSON object that remembers keys given twice (json keeps only the last)."""

    duplicates: tuple[str, ...] = ()


def numbers(value: Any, path: str, count: int) -> list[float]:
    """A JSON list of exactly ``count`` finite numbers."""
    if not isinstance(value, list) or len(value) != count:
        raise InvalidInputError(
            path,
            one_line(value),
            f"a list of {count} finite numbers",
            problem=f"expected {count} numbers:",
        )
    return [check_json_number(v, f"{path}[{i}]") for i, v in enumerate(value)]


def text(value: Any, path: str, choices: tuple[str, ...] | None = None) -> str:
    """A JSON string (optionally one of ``choices``), at most MAX_NAME_CHARS long."""
    allowed = " or ".join(repr(c) for c in choices) if choices else "text"
    if not isinstance(value, str):
        raise InvalidInputError(path, one_line(value), allowed, problem="expected text, got")
    if choices is not None and value not in choices:
        raise InvalidInputError(path, value, allowed, problem="unknown value")
    if len(value) > MAX_NAME_CHARS:
        raise InvalidInputError(
            path, value, f"text of at most {MAX_NAME_CHARS} characters", problem="too long:"
        )
    return value


def _optional_name(value: Any, path: str) -> str | None:
    return None if value is None else text(value, path)


def _limits(value: Any, path: str) -> list[float] | None:
    return None if value is None else numbers(value, path, 2)


def _build(factory: Any, path: str, **values: Any) -> Any:
    """Call a constructor; its own validation errors get the file path in front."""
    try:
        return factory(**values)
    except InvalidInputError as error:
        raise error.within(path) from None


def link_from_dict(value: Any, path: str) -> Module | DHLink:
    """One entry of ``robot.links``: a module or a DH row."""
    if not isinstance(value, Mapping) or value.get("type") not in ("module", "dh"):
        kind = value.get("type") if isinstance(value, Mapping) else value
        raise InvalidInputError(
            f"{path}.type" if isinstance(value, Mapping) else path,
            one_line(kind),
            'an object with "type": "module" or "dh"',
            problem="unknown link type",
        )
    if value["type"] == "module":
        check_json_object(value, path, _MODULE_KEYS)
        kinds = (*MODULE_KINDS, "null")
        return _build(
            Module,
            path,
            kind=text(value["kind"], f"{path}.kind", kinds),
            a=numbers(value.get("a", [0.0, 0.0, 0.0]), f"{path}.a", 3),
            q=check_json_number(value.get("q", 0.0), f"{path}.q"),
            name=_optional_name(value.get("name"), f"{path}.name"),
            limits=_limits(value.get("limits"), f"{path}.limits"),
        )
    check_json_object(value, path, _DH_KEYS)
    fields = {
        key: check_json_number(value[key], f"{path}.{key}") for key in ("theta", "d", "a", "alpha")
    }
    return _build(
        DHLink,
        path,
        **fields,
        joint=text(value["joint"], f"{path}.joint", ("R", "P")),
        convention=text(value["convention"], f"{path}.convention", ("standard", "modified")),
        q=check_json_number(value.get("q", 0.0), f"{path}.q"),
        name=_optional_name(value.get("name"), f"{path}.name"),
        limits=_limits(value.get("limits"), f"{path}.limits"),
    )


def robot_from_dict(value: Any, path: str = "robot") -> Robot:
    """The ``"robot"`` object of a file as a :class:`~robotconf.Robot`.

    >>> robot_from_dict({"links": [{"type": "module", "kind": "Rz"}], "end_effector": [1, 0, 0]})
    Robot([
        Module('Rz'),
    ], end_effector=(1.0, 0.0, 0.0))
    """
    from ..kinematics import Robot  # local: _robot imports the file methods

    check_json_object(value, path, _ROBOT_KEYS)
    links = value["links"]
    allowed = f"a list of 1 to {MAX_LINKS} links"
    if not isinstance(links, list) or not links:
        raise InvalidInputError(
            f"{path}.links", one_line(links), allowed, problem="not a non-empty list:"
        )
    if len(links) > MAX_LINKS:
        raise InvalidInputError(
            f"{path}.links", f"<{len(links)} links>", allowed, problem="too many links:"
        )
    active = value.get("active")
    if active is not None and (isinstance(active, bool) or not isinstance(active, int)):
        raise InvalidInputError(
            f"{path}.active", active, "an integer or null", problem="expected an integer, got"
        )
    return _build(
        Robot,
        path,
        modules=[link_from_dict(link, f"{path}.links[{i}]") for i, link in enumerate(links)],
        end_effector=numbers(value.get("end_effector", [0.0, 0.0, 0.0]), f"{path}.end_effector", 3),
        active=active,
        name=_optional_name(value.get("name"), f"{path}.name"),
    )


def _limits_out(limits: tuple[float, float] | None) -> list[float] | None:
    return None if limits is None else list(limits)


def robot_to_dict(robot: Robot) -> dict[str, Any]:
    """The ``"robot"`` object of a file: every key written, also defaults.

    >>> import robotconf as rc
    >>> robot_to_dict(rc.Robot([rc.Module("Rz")]))["links"]
    [{'type': 'module', 'kind': 'Rz', 'a': [0.0, 0.0, 0.0], 'q': 0.0, 'name': None, 'limits': None}]
    """
    links: list[dict[str, Any]] = []
    for i, link in enumerate(robot.modules):
        if isinstance(link, Module):
            links.append(
                {
                    "type": "module",
                    "kind": link.kind,
                    "a": list(link.a),
                    "q": link.q,
                    "name": link.name,
                    "limits": _limits_out(link.limits),
                }
            )
        elif isinstance(link, DHLink):
            entry: dict[str, Any] = {"type": "dh"}
            for key in ("theta", "d", "a", "alpha", "joint", "convention", "q", "name"):
                entry[key] = getattr(link, key)
            entry["limits"] = _limits_out(link.limits)
            links.append(entry)
        else:
            raise InvalidInputError(
                f"modules[{i}]", link, "Module or DHLink", problem="cannot be written to a file:"
            )
    active = None if robot.active == robot.n else robot.active
    return {
        "name": robot.name,
        "end_effector": list(robot.end_effector_point.tolist()),
        "active": active,
        "links": links,
    }


def check_simulation(value: Any, path: str = "simulation") -> dict[str, Any]:
    """Simulation settings: ``t_end`` (required), ``dt``, ``t0`` (s) and ``method``.

    :meth:`SimulationSettings.from_dict <robotconf.motion.SimulationSettings.from_dict>`
    checks them (at most :data:`~robotconf.motion.MAX_TIME_SAMPLES` samples, errors named
    ``simulation.dt`` etc.); the keys given come back normalized, the ones left out stay
    out so that a file is written back as it was read.

    >>> check_simulation({"t_end": 10, "dt": 0.01})
    {'t_end': 10.0, 'dt': 0.01}
    """
    written = SimulationSettings.from_dict(value, path).to_dict()
    return {key: written[key] for key in written if key in value}
