"""Lesson 13's exercises: the work cell — a table's point, reach, a base, a contact, a frame.

The cell is the paper's arm (lengths in mm: a 20 mm column, a 30 mm upper arm, a 40 mm
forearm, links as capsules of radius 3.6 mm) standing on a table. Each answer is the rule
a student works by hand; the cell is a layer above this folder, so the course's tests
hold each rule against what :class:`~robotconf.Cell` computes (``cell.pose_of``,
``cell.reach``, ``cell.place``, ``cell.check``) and against ``rc.locate_frame``. The
typical slips are a work-cell designer's: the table's offset or rotation left out, the
box's thickness forgotten (a box is centred at its pose), reach judged by distance
alone, the base moved the wrong way, a contact's time in samples or counted from the
move's start, the markers' centroid taken for the table's origin.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...calibration import locate_frame
from ._exercise import Exercise, checkers, register
from ._kinds import EXERCISE_SLIPS, name_slip, value_exercise

__all__ = ["NEAREST", "REACH", "SHOULDER", "RADIUS"]

LESSON = "13_work_cell"
#: The paper arm's reach from the shoulder (mm), its shoulder height, its links' radius.
REACH, SHOULDER, RADIUS = 70.0, 20.0, 3.6
#: The nearest a target may come to the shoulder: the elbow folds by at most 135°.
NEAREST = float(np.sqrt(30**2 + 40**2 - 2 * 30 * 40 * np.cos(np.radians(45))))
DT = 0.01  # s, cell.check's sampling step


EXERCISE_SLIPS.update(
    {
        "offset_left_out": "the point in the table's frame: the table's position left out",
        "rotation_left_out": "the table's position added, its rotation left out",
        "thickness_forgotten": "the box's centre taken for its top: half its thickness left out",
        "distance_only": "reach judged by the distance alone, the joint limits left aside",
        "shoulder_height_left_out": "the reach measured from the base, not from the shoulder",
        "height_left_out": "the reach laid along x, the target's height left aside",
        "in_samples": "the contact's time in samples, not in seconds",
        "wait_left_out": "the time counted from the LIN's start, the wait before it left out",
        "radius_left_out": "the tip's point where its capsule (radius 3.6 mm) meets the wall",
        "ramp_left_out": "the LIN at full speed from its start: the ramp left out",
        "centroid_origin": "the markers' centroid minus the nominal one: the rotation left out",
        "first_marker_origin": "the first marker taken for the table's origin",
        "inset_turned_back": "the markers' inset turned by −ψ instead of ψ",
    }
)


# -- exercise 1: a point on the table, in the cell's frame -------------------------------


def _table(variant: Any, _: Any) -> dict[str, Any]:
    thickness = variant.choice("table thickness", [8.0, 12.0, 16.0, 20.0])  # mm
    top = variant.choice("table top", [10.0, 20.0, 30.0])  # mm
    return {
        "table_xy": [
            variant.length("table x", 150, 300, step=10),
            variant.length("table y", -120, 120, step=20),
        ],
        "table_z": top - thickness / 2,  # the box is centred at its pose
        "table_size": [400.0, 300.0, thickness],
        "table_yaw": variant.angle("table yaw", [-60, -45, -30, 30, 45, 60, 120, 150]),
        "pick_ab": [
            variant.choice("pick a", [-120.0, -80.0, -40.0, 40.0, 80.0, 120.0]),
            variant.choice("pick b", [-90.0, -60.0, -30.0, 30.0, 60.0, 90.0]),
        ],
    }


def _rotation(yaw: float) -> np.ndarray:
    c, s = np.cos(yaw), np.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _pick_parts(n: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The table's centre, its rotation, and the pick point in its frame (mm)."""
    centre = np.array([*n["table_xy"], n["table_z"]])
    local = np.array([*n["pick_ab"], n["table_size"][2] / 2])
    return centre, _rotation(n["table_yaw"]), local


def _pick(n: Any) -> np.ndarray:
    centre, rotation, local = _pick_parts(n)
    return centre + rotation @ local


def _pick_named(n: Any) -> dict[str, tuple[Any, str]]:
    centre, rotation, local = _pick_parts(n)
    flat = np.array([local[0], local[1], 0.0])
    return {
        "offset_left_out": (
            (rotation @ local).tolist(),
            "That is the point in the table's frame, turned: add the table's position.",
        ),
        "rotation_left_out": (
            (centre + local).tolist(),
            "The table is turned by ψ about z: turn (a, b, h/2) by Rz(ψ) before adding "
            "its position.",
        ),
        "thickness_forgotten": (
            (centre + rotation @ flat).tolist(),
            "A box is centred at its pose: its top lies half its thickness above it.",
        ),
    }


register(
    value_exercise(
        LESSON,
        1,
        "a point on the table, in the cell's frame",
        _table,
        _pick,
        "check_vector",
        lambda n: {
            "name": "the pick point in the cell's frame",
            "unit": "mm",
            "hint": "p = t + Rz(ψ)·(a, b, h/2): the table's pose is its box's centre.",
        },
        named=_pick_named,
        shows=lambda n: (
            f"table centre $t = ({n['table_xy'][0]:g}, {n['table_xy'][1]:g}, "
            f"{n['table_z']:g})$ mm, turned by $\\psi = {np.degrees(n['table_yaw']):g}°$ "
            f"about $z$, thickness $h = {n['table_size'][2]:g}$ mm; pick point "
            f"$(a, b) = ({n['pick_ab'][0]:g}, {n['pick_ab'][1]:g})$ mm on its top"
        ),
    )
)

# -- exercise 2: which targets does the arm reach? ---------------------------------------

#: (distance from the shoulder, mm) by kind: within reach, too near, too far.
_DISTANCES = {
    "inside": [35.0, 40.0, 45.0, 50.0, 55.0, 60.0, 65.0],
    "near": [14.0, 17.0, 20.0, 23.0, 25.0],
    "far": [74.0, 78.0, 82.0, 86.0],
}
_KINDS = [
    ("inside", "near", "far", "inside"),
    ("near", "inside", "inside", "far"),
    ("far", "inside", "near", "inside"),
    ("inside", "far", "inside", "near"),
    ("near", "far", "inside", "near"),
    ("inside", "near", "far", "far"),
]


def _targets(variant: Any, _: Any) -> dict[str, Any]:
    kinds = variant.choice("target kinds", _KINDS)
    points = []
    for k, kind in enumerate(kinds):
        distance = variant.choice(f"target {k} distance", _DISTANCES[kind])
        azimuth = variant.angle(f"target {k} azimuth", [-150, -90, -40, 0, 40, 90, 150])
        up = variant.angle(f"target {k} elevation", [0, 10, 20, 30])
        radial = distance * np.cos(up)
        points.append(
            [
                round(float(radial * np.cos(azimuth)), 1),
                round(float(radial * np.sin(azimuth)), 1),
                round(float(SHOULDER + distance * np.sin(up)), 1),
            ]
        )
    return {"targets_2": points}


def _distances(n: Any) -> np.ndarray:
    points = np.asarray(n["targets_2"], dtype=float)
    return np.linalg.norm(points - [0.0, 0.0, SHOULDER], axis=1)


def _reached(n: Any) -> list[int]:
    """The targets within reach and joint limits (the drawn targets are above the table,
    clear of it, so this is what ``cell.reach`` finds: the course's tests check it)."""
    return [k for k, d in enumerate(_distances(n)) if NEAREST <= d <= REACH]


def _reach_named(n: Any) -> dict[str, tuple[Any, str]]:
    reached = _reached(n)
    by_distance = [k for k, d in enumerate(_distances(n)) if d <= REACH]
    return {
        "distance_only": (
            by_distance,
            "Within 70 mm of the shoulder is not enough: the elbow folds by at most 135°, "
            "so a target nearer than √(30² + 40² − 2·30·40·cos 45°) ≈ 28.3 mm is out of "
            "the joint limits.",
        ),
        "counted_from_1": (
            [k + 1 for k in reached],
            "Give indices from 0, like the list: targets_2[0] is index 0.",
        ),
    }


def _same_set(values: Any, answer: Any) -> bool:
    return sorted(np.asarray(values, dtype=float).reshape(-1).tolist()) == sorted(answer)


def _reach_check(given: Any, n: Any) -> Any:
    result = checkers().check_set(
        given,
        _reached(n),
        name="the targets the arm reaches",
        hint="Measure each target's distance from the shoulder (0, 0, 20) and compare it "
        "with what the arm spans: at most 30 + 40, at least what a 135° fold leaves.",
    )
    return name_slip(result, n, _reach_named, _same_set)


register(
    Exercise(
        LESSON,
        2,
        "which targets the arm reaches",
        _targets,
        _reached,
        _reach_check,
        lambda n: {k: v for k, (v, _) in _reach_named(n).items()},
        lambda n: "\n".join(
            f"- `targets_2[{k}]` = ({p[0]:g}, {p[1]:g}, {p[2]:g}) mm"
            for k, p in enumerate(n["targets_2"])
        ),
        lambda given, n: _same_set(given, _reached(n)),
    )
)

# -- exercise 3: where must the base go? -------------------------------------------------


def _far_target(variant: Any, _: Any) -> dict[str, Any]:
    side = variant.choice("target side", [-1.0, 1.0])
    return {
        "target_3": [
            side * variant.length("target x", 90, 140, step=5),
            0.0,
            variant.choice("target z", [30.0, 40.0, 50.0, 60.0, 65.0]),
        ]
    }


def _base_x(n: Any, *, height: float = SHOULDER, reach: float = REACH) -> float:
    x, _, z = n["target_3"]
    across = np.sqrt(reach**2 - (z - height) ** 2) if abs(z - height) < reach else 0.0
    return float(x - np.sign(x) * across)


def _base_named(n: Any) -> dict[str, tuple[Any, str]]:
    x, _, z = n["target_3"]
    # the base moved the wrong way is the component slip "sign_error", named by the check
    return {
        "shoulder_height_left_out": (
            _base_x(n, height=0.0),
            "The arm reaches 70 mm from its shoulder, which stands 20 mm above the base.",
        ),
        "height_left_out": (
            float(x - np.sign(x) * REACH),
            "The target is not at the shoulder's height: only √(70² − Δz²) of the reach "
            "lies along x.",
        ),
    }


register(
    value_exercise(
        LESSON,
        3,
        "the nearest base position",
        _far_target,
        _base_x,
        "check_value",
        lambda n: {
            "name": "the base's x",
            "unit": "mm",
            "hint": "From the base at (x_b, 0, 0) the shoulder is at (x_b, 0, 20); the "
            "target must lie within 70 mm of it.",
        },
        named=_base_named,
        shows=lambda n: (
            f"target $({n['target_3'][0]:g}, 0, {n['target_3'][2]:g})$ mm; the base "
            "stands at $(0, 0, 0)$"
        ),
    )
)

# -- exercise 4: when does the LIN hit the wall? -----------------------------------------

#: (speed mm/s, acceleration mm/s²): ramps of at most 2.5 mm, so the contact is at cruise.
_LIMITS = [(5.0, 10.0), (8.0, 20.0), (10.0, 20.0), (10.0, 40.0), (12.0, 40.0)]


def _wall(variant: Any, _: Any) -> dict[str, Any]:
    speed, accel = variant.choice("LIN limits", _LIMITS)
    return {
        "x0_4": variant.length("x0", 30, 40, step=2),
        "wall_x": variant.length("wall x", 52, 60, step=2),
        "v_4": speed,
        "a_4": accel,
        "wait_4": variant.choice("wait", [0.5, 1.0, 1.5, 2.0]),
    }


def _contact(n: Any, *, radius: float = RADIUS, ramp: bool = True, wait: bool = True) -> float:
    travel = n["wall_x"] - radius - n["x0_4"]
    time = travel / n["v_4"] + (n["v_4"] / (2 * n["a_4"]) if ramp else 0.0)
    return float(time + (n["wait_4"] if wait else 0.0))


def _contact_named(n: Any) -> dict[str, tuple[Any, str]]:
    return {
        "in_samples": (
            _contact(n) / DT,
            "That is a sample count: cell.check samples every 0.01 s; give seconds.",
        ),
        "wait_left_out": (
            _contact(n, wait=False),
            "Time runs from the program's start: the wait before the LIN counts.",
        ),
        "radius_left_out": (
            _contact(n, radius=0.0),
            "The forearm is a capsule: its surface meets the wall 3.6 mm before its axis.",
        ),
        "ramp_left_out": (
            _contact(n, ramp=False),
            "The LIN starts from rest: its ramp up costs v/(2a) beyond the cruise.",
        ),
    }


register(
    value_exercise(
        LESSON,
        4,
        "when the LIN hits the wall",
        _wall,
        _contact,
        "check_value",
        lambda n: {
            "name": "the time the forearm meets the wall",
            "unit": "s",
            "hint": "The forearm's outermost point is the tip's ball; after the ramp "
            "(v²/(2a) of distance, v/a of time) the tip cruises at v.",
        },
        named=_contact_named,
        length=False,
        shows=lambda n: (
            f"start $x_0 = {n['x0_4']:g}$ mm, wall at $x_w = {n['wall_x']:g}$ mm, "
            f"$v = {n['v_4']:g}$ mm/s, $a = {n['a_4']:g}$ mm/s², wait "
            f"{n['wait_4']:g} s"
        ),
    )
)

# -- exercise 5: the table's origin from three markers -----------------------------------

_INSET = 20.0  # mm: each marker 20 mm in from the table's edges


def _markers(variant: Any, _: Any) -> dict[str, Any]:
    length = variant.choice("marker length", [200.0, 250.0, 300.0])
    width = variant.choice("marker width", [150.0, 200.0])
    nominal = np.array(
        [[_INSET, _INSET, 0.0], [_INSET + length, _INSET, 0.0], [_INSET, _INSET + width, 0.0]]
    )
    origin = np.array(
        [
            variant.length("origin x", 200, 400, step=20),
            variant.choice("origin y", [-160.0, -120.0, -80.0, 80.0, 120.0, 160.0]),
            variant.choice("origin z", [5.0, 10.0, 15.0]),
        ]
    )
    yaw = variant.angle("markers yaw", [-70, -50, -20, 20, 35, 50, 70, 110])
    measured = origin + nominal @ _rotation(yaw).T
    return {"nominal_5": nominal.tolist(), "measured_5": measured.tolist()}


def _origin(n: Any) -> np.ndarray:
    return np.asarray(locate_frame(n["measured_5"], n["nominal_5"]).pose[:3, 3])


def _origin_named(n: Any) -> dict[str, tuple[Any, str]]:
    measured, nominal = np.asarray(n["measured_5"]), np.asarray(n["nominal_5"])
    x_axis = (measured[1] - measured[0]) / np.linalg.norm(measured[1] - measured[0])
    y_axis = (measured[2] - measured[0]) / np.linalg.norm(measured[2] - measured[0])
    return {
        "centroid_origin": (
            (measured.mean(axis=0) - nominal.mean(axis=0)).tolist(),
            "The centroids match only after the rotation: t = c_measured − R·c_nominal.",
        ),
        "first_marker_origin": (
            measured[0].tolist(),
            "The first marker sits 20 mm in from both edges: step back along the "
            "table's x and y axes.",
        ),
        "inset_turned_back": (
            (measured[0] - _INSET * (x_axis * [1, -1, 1] + y_axis * [-1, 1, 1])).tolist(),
            "The table's axes are turned by +ψ: x̂ = (cos ψ, sin ψ, 0), ŷ = (−sin ψ, cos ψ, 0).",
        ),
    }


register(
    value_exercise(
        LESSON,
        5,
        "the table's origin from three markers",
        _markers,
        _origin,
        "check_vector",
        lambda n: {
            "name": "the table's origin in the cell's frame",
            "unit": "mm",
            "hint": "The table's x axis points from marker 1 to marker 2, its y axis from "
            "marker 1 to marker 3; marker 1 is 20 mm in along both.",
        },
        named=_origin_named,
        shows=lambda n: (
            "| marker | nominal (mm) | measured (mm) |\n|---|---|---|\n"
            + "".join(
                f"| {k + 1} | ({', '.join(f'{v:g}' for v in m)}) | "
                f"({', '.join(f'{v:.2f}' for v in p)}) |\n"
                for k, (m, p) in enumerate(zip(n["nominal_5"], n["measured_5"], strict=True))
            )
        ),
    )
)
