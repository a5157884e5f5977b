"""The editor's rows as form specs: one per module or DH row, then the active count and
the end-effector point. Pure functions of the state (and the refused inputs to show).

Keys name the control as ``panel.errors`` does: ``modules[1].q``, ``modules[1].ax``,
``dh[0].alpha``, ``end_effector.Px``, ``active``; a row's buttons and type belong to the
row (``modules[1]``), the add button to the list (``modules`` / ``dh``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np

from ...kinematics import (
    DH_CONVENTIONS,
    DH_FACTORS,
    DH_PARAMETERS,
    DH_SYMBOLS,
    JOINT_LETTERS,
    MODULE_KINDS,
    MODULE_OFFSETS,
    ROTATION_KINDS,
    DHLink,
    Module,
    Robot,
    dh_formula,
    kind_label,
)
from .._feedback import Feedback
from .._ranges import length_scale, length_step, q_range
from ..form import button, message, row, select, text, toggle
from ..state import PanelState
from ._quantity import Quantity, Ranges, number_spec

__all__ = ["EditorContext", "module_rows", "dh_rows", "extras_rows", "KIND_OPTIONS", "POINT"]

#: Dropdown entries: the paper's codes 0–6 with names, then ``fixed`` (no code).
KIND_OPTIONS = tuple((kind_label(kind), kind) for kind in MODULE_KINDS)
#: The end-effector point's components.
POINT = ("Px", "Py", "Pz")
#: DH parameters that are angles (the rotation factors' θ and α).
DH_ANGLES = frozenset(name for kind, name in DH_FACTORS["standard"] if kind in ROTATION_KINDS)
_CONVENTION_SOURCES = {
    "standard": ("paper eq. 9", ""),
    "modified": ("Craig", "; row i holds α(i-1), a(i-1)"),
}
#: What each convention means, as the selector's tooltips and the note under it say.
CONVENTION_TIPS = {
    name: f"{name} ({source}): A = {dh_formula(name)}{reading}"
    for name, (source, reading) in _CONVENTION_SOURCES.items()
}


@dataclass
class EditorContext:
    """What every row needs: the state, the refused inputs, the ranges and the rev.

    ``memo`` keeps the rows of the last drawing: a row whose link and surroundings did not
    change is the same spec as before (a q drag rebuilds one row, not the table).
    """

    state: PanelState
    feedback: Feedback
    ranges: Ranges
    rev: str
    memo: dict[Hashable, dict[str, Any]] | None = None

    def __post_init__(self) -> None:
        # The robot's size does not depend on q: once per drawing, not once per box.
        self._scale = length_scale(self.state.robot)
        self._step = length_step(self._scale)
        self._common = (
            self.state.units,
            self._scale,
            self.rev,
            self.feedback.version,
            self.ranges.version,
            self.state.robot.n,
        )
        self._drawn: dict[Hashable, dict[str, Any]] = {}

    def cached(self, key: Hashable, build: Callable[[], dict[str, Any]]) -> dict[str, Any]:
        """The row ``build()`` makes, reused from the last drawing when ``key`` (with the
        units, the size, the rev, the messages and the ranges) is the same."""
        full = (key, self._common)
        found = None if self.memo is None else self.memo.get(full)
        spec = build() if found is None else found
        self._drawn[full] = spec
        return spec

    def keep(self) -> None:
        """Remember this drawing's rows (only these: the memo stays the size of one table)."""
        if self.memo is not None:
            self.memo.clear()
            self.memo.update(self._drawn)

    @property
    def robot(self) -> Robot:
        return self.state.robot

    def scale(self) -> float:
        return self._scale

    def length(self) -> Quantity:
        return Quantity("length", self.state.units, self._step)

    def coordinate(self, unit: str) -> Quantity:
        return Quantity(unit, self.state.units, self._step)

    def number(
        self, key: str, core: float, quantity: Quantity, default: tuple[float, float], **kw: Any
    ) -> dict[str, Any]:
        warning = kw.pop("warning", "")
        return number_spec(
            key,
            core,
            quantity,
            default,
            self.ranges,
            rev=self.rev,
            error=self.feedback.message(key),
            typed=self.feedback.typed(key),
            warning=warning,
            **kw,
        )

    def row_note(self, key: str) -> dict[str, str] | None:
        return message(self.feedback.message(key))


def _move_buttons(prefix: str, index: int, count: int, what: str) -> list[dict[str, Any]]:
    return [
        button(
            f"{prefix}.up",
            "↑",
            title=f"move this {what} up (towards the base)",
            disabled=index == 0,
            css_class="robotconf-row-up",
        ),
        button(
            f"{prefix}.down",
            "↓",
            title=f"move this {what} down (towards the tool)",
            disabled=index == count - 1,
            css_class="robotconf-row-down",
        ),
        button(
            f"{prefix}.delete",
            "✕",
            title=f"remove this {what} (↶ brings it back)",
            css_class="robotconf-module-delete",
        ),
    ]


def range_warning(q: float, limits: np.ndarray, quantity: Quantity, name: str) -> str:
    """A note when ``q`` lies beyond its joint's range: allowed, but never silent.

    >>> from robotconf.panel.state import Units
    >>> angle = Quantity("rad", Units(degrees=True), 1.0)
    >>> range_warning(4.0, np.array([-np.pi, np.pi]), angle, "q2")
    'q2 = 229.183 deg is beyond its range −180 … 180 deg (the panel allows it; a real joint stops)'
    """
    lo, hi = float(limits[0]), float(limits[1])
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo or lo <= q <= hi:
        return ""
    unit = f" {quantity.label}" if quantity.label else ""
    return (
        f"{name} = {_minus(quantity.shown(q))}{unit} is beyond its range "
        f"{_minus(quantity.shown(lo))} … {_minus(quantity.shown(hi))}{unit} "
        "(the panel allows it; a real joint stops)"
    )


def _minus(value: float) -> str:
    return f"{value:.6g}".replace("-", "−")


def _q_control(ctx: EditorContext, key: str, i: int, link: Any, limits: np.ndarray) -> dict:
    unit = link.unit
    quantity = ctx.coordinate(unit)
    default = q_range(unit, ctx.scale(), limits, ctx.state.units.degrees)
    name = f"q{i + 1}"
    warning = range_warning(link.q, limits, quantity, name) if link.is_joint else ""
    return ctx.number(
        key,
        link.q,
        quantity,
        default,
        label="q",
        disabled=not link.is_joint,
        warning=warning,
        label_width="20px",
        css_class="robotconf-module-q",
        title=f"{name}: the generalized coordinate",
    )


def _module_row(
    ctx: EditorContext, i: int, link: Any, limits: np.ndarray, scale: float
) -> dict[str, Any]:
    prefix = f"modules[{i}]"
    head: list[dict[str, Any]] = [text(f"M{i + 1}", tone="title")]
    name = link.name
    if isinstance(link, Module):
        head.append(
            select(
                f"{prefix}.kind",
                link.kind,
                KIND_OPTIONS,
                label="type",
                rev=ctx.rev,
                width="96px",
                css_class="robotconf-module-kind",
            )
        )
    else:
        head.append(text(repr(link), tone="note"))  # a DH row: its q only
        name = None
    if name:
        head.append(text(name, tone="note"))
    head += _move_buttons(prefix, i, ctx.robot.n, "module")
    controls: list[dict[str, Any]] = []
    if isinstance(link, Module):
        for axis, field in enumerate(MODULE_OFFSETS):
            controls.append(
                ctx.number(
                    f"{prefix}.{field}",
                    link.a[axis],
                    ctx.length(),
                    (-scale, scale),
                    label=field,
                    disabled=link.kind == "none",
                    label_width="20px",
                    css_class="robotconf-module-offset",
                )
            )
    controls.append(_q_control(ctx, f"{prefix}.q", i, link, limits))
    return row(
        prefix,
        head,
        controls,
        box=True,
        note=ctx.row_note(prefix),
        css_class="robotconf-module-row",
    )


def module_rows(ctx: EditorContext) -> list[dict[str, Any]]:
    """One row per link of a module robot (a DH link in it shows read-only with its q),
    then the add button."""
    robot = ctx.robot
    limits = robot.joint_limits()
    scale = ctx.scale()
    rows = [
        ctx.cached(
            ("module", i, link, tuple(limits[i])),
            partial(_module_row, ctx, i, link, limits[i], scale),
        )
        for i, link in enumerate(robot.modules)
    ]
    rows.append(
        row(
            "modules",
            [
                button(
                    "modules.add",
                    "+ add module",
                    title="append a module at the tool end",
                    css_class="robotconf-add-module",
                )
            ],
            note=ctx.row_note("modules"),
        )
    )
    return rows


def dh_rows(ctx: EditorContext) -> list[dict[str, Any]]:
    """The convention selector (and its question), one row per DH link, the add button."""
    robot = ctx.robot
    state = ctx.state
    convention = getattr(robot.modules[0], "convention", DH_CONVENTIONS[0])
    options = [(name, name, CONVENTION_TIPS[name]) for name in DH_CONVENTIONS]
    head = [
        toggle(
            "dh.convention",
            convention,
            options,
            label="convention",
            rev=ctx.rev,
            css_class="robotconf-dh-convention",
        )
    ]
    rows = [
        row(
            "dh.head",
            head,
            [text(CONVENTION_TIPS[convention], tone="note")],
            note=ctx.row_note("dh.convention"),
        )
    ]
    prompt = state.prompt
    if prompt is not None and prompt.kind == "convention":
        rows.append(
            row(
                "dh.prompt",
                [
                    text(f"Switch the table to {prompt.convention} DH:"),
                    button(
                        "dh.prompt.convert",
                        "convert (same robot)",
                        title="rewrite the rows so that every frame and the end-effector stay put",
                    ),
                    button(
                        "dh.prompt.reinterpret",
                        "reinterpret (same numbers)",
                        title="keep every number and read the rows in the other convention",
                    ),
                    button("dh.prompt.cancel", "cancel", title="change nothing"),
                ],
                box=True,
                note=ctx.row_note("dh.prompt"),
                css_class="robotconf-prompt",
            )
        )
    limits = robot.joint_limits()
    scale = ctx.scale()
    rows += [
        ctx.cached(
            ("dh", i, link, tuple(limits[i])), partial(_dh_row, ctx, i, link, limits[i], scale)
        )
        for i, link in enumerate(robot.modules)
    ]
    rows.append(
        row(
            "dh",
            [button("dh.add", "+ add row", title="append a revolute row")],
            note=ctx.row_note("dh"),
        )
    )
    return rows


def _dh_row(
    ctx: EditorContext, i: int, link: Any, limits: np.ndarray, scale: float
) -> dict[str, Any]:
    assert isinstance(link, DHLink)
    prefix = f"dh[{i}]"
    cells: list[dict[str, Any]] = [text(str(i + 1), tone="title")]
    for name in DH_PARAMETERS:
        angle = name in DH_ANGLES
        quantity = ctx.coordinate("rad") if angle else ctx.length()
        default = q_range("rad", scale, None, ctx.state.units.degrees) if angle else (-scale, scale)
        cells.append(
            ctx.number(
                f"{prefix}.{name}",
                getattr(link, name),
                quantity,
                default,
                label=DH_SYMBOLS[name],
                slider=False,
                width="70px",
                css_class=f"robotconf-dh-{name}",
            )
        )
    letters = [(letter, letter) for letter in JOINT_LETTERS.values()]
    cells.append(
        select(
            f"{prefix}.joint",
            link.joint,
            letters,
            rev=ctx.rev,
            width="52px",
            title="R: q adds to θ (revolute); P: q adds to d (prismatic)",
        )
    )
    cells += _move_buttons(prefix, i, ctx.robot.n, "row")
    q = _q_control(ctx, f"{prefix}.q", i, link, limits)
    return row(
        prefix,
        cells,
        [q],
        box=True,
        note=ctx.row_note(prefix),
        css_class="robotconf-dh-row",
    )


def extras_rows(ctx: EditorContext) -> list[dict[str, Any]]:
    """The active-module count (paper §2.3.3) and the end-effector point P."""
    robot = ctx.robot
    return [
        ctx.cached(("active", robot.active), partial(_active_row, ctx)),
        ctx.cached(("end_effector", *robot.end_effector_point.tolist()), partial(_point_row, ctx)),
    ]


def _active_row(ctx: EditorContext) -> dict[str, Any]:
    robot = ctx.robot
    count = ctx.number(
        "active",
        float(robot.active),
        Quantity("", ctx.state.units, 1.0),
        (1.0, float(robot.n)),
        label="active modules",
        slider=False,
        width="60px",
        title=f"the paper's number of active modules, 1 to {robot.n}",
    )
    return row("active", [count])


def _point_row(ctx: EditorContext) -> dict[str, Any]:
    robot = ctx.robot
    scale = ctx.scale()
    point = [
        ctx.number(
            f"end_effector.{name}",
            float(value),
            ctx.length(),
            (-scale, scale),
            label=name,
            label_width="24px",
            css_class="robotconf-end-effector",
        )
        for name, value in zip(POINT, robot.end_effector_point, strict=True)
    ]
    return row(
        "end_effector", [text("End-effector P in the last module's frame", tone="title")], point
    )
