"""The exercises with per-student numbers of lessons 2 to 8: matrices and rates at numbers.

Each is the notebook's exercise, its numbers drawn as before (the same names and ranges,
so a draw that reveals every slip is the number a student had before screening), checked
as before.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...kinematics import DHLink, Module, Robot, jacobian
from ...motion import simulate
from ...signals import RepeatingSequence
from ._exercise import register
from ._kinds import EXERCISE_SLIPS, matrix_exercise, value_exercise

__all__ = ["PAPER", "paper_robot"]

PAPER = ((0, 0, 0), (0, 0, 20), (30, 0, 0))


def paper_robot(l1: float = 20, l2: float = 30, l3: float = 40, name: str = "RzRyRy") -> Robot:
    """The paper's R_zR_yR_y arm: R_z, R_y with a = (0, 0, l1), R_y with a = (l2, 0, 0),
    tool P = (l3, 0, 0)."""
    modules = [Module("Rz"), Module("Ry", a=(0, 0, l1)), Module("Ry", a=(l2, 0, 0))]
    return Robot(modules, end_effector=(l3, 0, 0), name=name)


def _degrees(angles: Any) -> str:
    return ", ".join(f"{np.degrees(a):g}°" for a in np.atleast_1d(angles))


# -- lesson 2 ---------------------------------------------------------------------------

_RZ = Robot([Module("Rz")])

register(
    matrix_exercise(
        "02_elementary_transforms",
        4,
        "R_z at q1 in numbers",
        lambda v, _: {"q1": v.length("q1", 0.4, 1.2, step=0.1), "module_rz": _RZ},
        lambda n: n["module_rz"],
        "A1",
        lambda n: [n["q1"]],
        shows=lambda n: f"$q_1 = {n['q1']:g}$ rad",
    )
)

# -- lesson 3 ---------------------------------------------------------------------------


def _pose_3(variant: Any, _: Any) -> dict[str, Any]:
    q_4 = [
        variant.angle("q1", [0, 30, 60, 90, 120, 150]),
        variant.angle("q2", [-60, -30, 0, 30, 60]),
        variant.angle("q3", [-120, -90, -60, -30, 30, 60, 90]),
    ]
    return {"q_4": q_4, "robot": paper_robot()}


def _pedestal(variant: Any, _: Any) -> dict[str, Any]:
    h = variant.length("h", 30, 90, step=10)
    modules = [Module("fixed", a=(0, 0, h)), *paper_robot().modules]
    return {"h": h, "on_pedestal": Robot(modules, end_effector=(40, 0, 0))}


register(
    matrix_exercise(
        "03_composing_a_chain",
        4,
        "the end-effector at your pose",
        _pose_3,
        lambda n: n["robot"],
        "p_EE",
        lambda n: n["q_4"],
        shows=lambda n: f"$q = ({_degrees(n['q_4'])})$",
    ),
    matrix_exercise(
        "03_composing_a_chain",
        5,
        "the robot on a pedestal",
        _pedestal,
        lambda n: n["on_pedestal"],
        "p_EE",
        lambda n: [0, 0, 0, 0],
        free=[],  # asked at q = 0: the exercise is the pedestal's offset
        shows=lambda n: f"$h = {n['h']:g}$ mm",
    ),
)

# -- lesson 4 ---------------------------------------------------------------------------

_SCARA = Robot(
    [Module("Rz", a=(0, 0, 40)), Module("Rz", a=(30, 0, 0)), Module("Tz", a=(20, 0, 0))],
    end_effector=(0, 0, -10),
)


def _scara_pose(variant: Any, _: Any) -> dict[str, Any]:
    q_4 = [
        variant.angle("q1", [30, 60, 90, 120, 150, 180]),
        variant.angle("q2", [-120, -90, -60, -30, 30, 60, 90, 120]),
        variant.length("q3", -25, 0, step=5),  # the slide, mm
    ]
    return {"q_4": q_4, "scara": _SCARA}


def _scara_shows(n: Any) -> str:
    q = n["q_4"]
    return f"$q_1 = {np.degrees(q[0]):g}°$, $q_2 = {np.degrees(q[1]):g}°$, $q_3 = {q[2]:g}$"


register(
    matrix_exercise(
        "04_module_method_classic_arms",
        4,
        "the SCARA at your pose",
        _scara_pose,
        lambda n: n["scara"],
        "p_EE",
        lambda n: n["q_4"],
        shows=_scara_shows,
    )
)

# -- lesson 5 ---------------------------------------------------------------------------

_PAPER_DH = Robot.from_dh(
    [(0, 20, 0, -np.pi / 2, "R"), (0, 0, 30, 0, "R"), (0, 0, 40, 0, "R")],
    convention="standard",
)


def _link_5(variant: Any, _: Any) -> dict[str, Any]:
    a_3 = variant.length("a", 1, 3.5, step=0.5)
    q1_3 = variant.angle("theta", [15, 30, 45, 60, 75, 90])
    link = Robot([DHLink(0.0, 0.0, a_3, 0.0, "R", "standard")])
    return {"a_3": a_3, "q1_3": q1_3, "link_3": link}


def _pose_5(variant: Any, _: Any) -> dict[str, Any]:
    q_5 = [
        variant.angle("q1", [-60, -30, 0, 30, 60, 90, 120, 150]),
        variant.angle("q2", [-60, -30, 0, 30]),
        variant.angle("q3", [-120, -90, -60, -30, 30, 60]),
    ]
    return {"q_5": q_5, "paper_dh": _PAPER_DH}


register(
    matrix_exercise(
        "05_denavit_hartenberg",
        3,
        "a DH matrix in numbers",
        _link_5,
        lambda n: n["link_3"],
        "A1",
        lambda n: [n["q1_3"]],
        shows=lambda n: f"$a = {n['a_3']:g}$, $q_1 = {np.degrees(n['q1_3']):g}°$",
    ),
    matrix_exercise(
        "05_denavit_hartenberg",
        5,
        "DH and modules: the end-effector at your pose",
        _pose_5,
        lambda n: n["paper_dh"],
        "p_EE",
        lambda n: n["q_5"],
        shows=lambda n: f"$q = ({_degrees(n['q_5'])})$",
    ),
)

# -- lesson 6 ---------------------------------------------------------------------------


def _puma(variant: Any, _: Any) -> dict[str, Any]:
    from ...presets import preset

    q2_1 = variant.angle("q2", [15, 30, 45, 60, 75, 90])
    return {"q2_1": q2_1, "q_1": [0, q2_1, 0, 0, 0, 0], "puma": preset("puma560")}


def _ur5(variant: Any, _: Any) -> dict[str, Any]:
    from ...presets import preset

    q1_2 = variant.angle("q1", [-120, -90, -60, -30, 0, 30, 60, 90])
    return {"q1_2": q1_2, "ur5": preset("ur5")}


register(
    matrix_exercise(
        "06_real_arms",
        1,
        "one PUMA link, in numbers",
        _puma,
        lambda n: n["puma"],
        "A2",
        lambda n: n["q_1"],
        free=[1],
        shows=lambda n: f"$q_2 = {np.degrees(n['q2_1']):g}°$",
    ),
    matrix_exercise(
        "06_real_arms",
        2,
        "the UR5's tool at your base angle",
        _ur5,
        lambda n: n["ur5"],
        "p_EE",
        lambda n: [n["q1_2"], 0, 0, 0, 0, 0],
        free=[0],
        shows=lambda n: f"$q_1 = {np.degrees(n['q1_2']):g}°$",
    ),
)

# -- lesson 7 ---------------------------------------------------------------------------


def _rates(variant: Any, _: Any) -> dict[str, Any]:
    qd_2 = [
        variant.choice("qd1", [0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]),
        0,
        variant.choice("qd3", [1.0, 1.5, 2.0, 2.5]),
    ]
    return {"qd_2": qd_2, "robot": paper_robot()}


EXERCISE_SLIPS.update(
    {
        "one_joint_only": "the velocity of one joint's motion, the other joint's left out",
        "rates_exchanged": "each joint's rate applied to the other joint's column",
        "ramp_slope": "the ramp's own slope where the difference across the jump is asked",
        "central_for_backward": "the central difference where the backward one is asked",
        "backward_for_central": "the backward difference where the central one is asked",
        "not_divided_by_dt": "a difference of samples not divided by dt (or 2 dt)",
        "elbow_for_shoulder": "the elbow singularity (the arm folded) for the shoulder one",
        "q2_left_out": "the shoulder angle q2 left out of the shoulder condition",
        "absolute_elbow": "q2 + q3 (the link's own angle) given for q3",
    }
)


def _velocity_named(n: Any) -> dict[str, tuple[Any, str]]:
    j = jacobian(n["robot"], [0, 0, 0])[:3]
    qd = np.asarray(n["qd_2"], dtype=float)
    both = "Both joints move: add the velocities, J·q̇ = Σ column j · q̇j."
    return {
        "one_joint_only": ((j[:, 0] * qd[0]).tolist(), "Only joint 1's part: " + both),
        "one_joint_only[q3]": ((j[:, 2] * qd[2]).tolist(), "Only joint 3's part: " + both),
        "rates_exchanged": (
            (j @ qd[::-1]).tolist(),
            "The rates are exchanged: q̇1 multiplies joint 1's column z × (p − o1), q̇3 "
            "joint 3's column y × (p − o3).",
        ),
    }


def _elbow(variant: Any, _: Any) -> dict[str, Any]:
    return {"q3_3": variant.angle("q3", [-120, -90, -60, -30, 30, 60]), "robot": paper_robot()}


def _spike(variant: Any, _: Any) -> dict[str, Any]:
    dt = variant.choice("dt", [0.002, 0.005, 0.01, 0.02, 0.05])
    return {"dt": dt, "robot": paper_robot(), "saw": RepeatingSequence()}


def _spike_rate(n: Any, method: str) -> float:
    """dq3/dt at t = 2 s of the default sawtooth, sampled every dt, by ``method``."""
    run = simulate(n["robot"], {"q3": n["saw"]}, t_end=2.5, dt=n["dt"], method=method)
    return float(run.qd[int(round(2 / n["dt"])), 2])


def _spike_named(n: Any, method: str) -> dict[str, tuple[Any, str]]:
    dt = n["dt"]
    ramp = (
        "1 rad/s is the ramp's own slope: across the jump the samples q[k-1] = 2 - dt, "
        "q[k] = 0, q[k+1] = dt give a large negative rate."
    )
    found = {"ramp_slope": (1.0, ramp)}
    if method == "numeric":
        found["backward_for_central"] = (
            -(2 - dt) / dt,
            "That is the backward difference (q[k] - q[k-1]) / dt; the numeric method "
            "takes the central one, (q[k+1] - q[k-1]) / (2 dt).",
        )
        found["not_divided_by_dt"] = (
            (2 * dt - 2) / 2,
            "Divide the difference by 2 dt: (q[k+1] - q[k-1]) / (2 dt) is a rate in rad/s.",
        )
    else:
        found["central_for_backward"] = (
            (2 * dt - 2) / (2 * dt),
            "That is the central difference (q[k+1] - q[k-1]) / (2 dt); Simulink's "
            "Derivative block takes the backward one, (q[k] - q[k-1]) / dt.",
        )
        found["not_divided_by_dt"] = (
            -(2 - dt),
            "Divide the difference by dt: (q[k] - q[k-1]) / dt is a rate in rad/s.",
        )
    return found


def _spike_options(hint: str) -> Any:
    return lambda n: {"name": "dq3/dt at t = 2 s", "unit": "rad/s", "hint": hint}


register(
    value_exercise(
        "07_velocity_acceleration",
        2,
        "a velocity by hand",
        _rates,
        lambda n: jacobian(n["robot"], [0, 0, 0])[:3] @ np.asarray(n["qd_2"], dtype=float),
        "check_vector",
        lambda n: {"name": "the end-effector velocity", "unit": "mm/s"},
        named=_velocity_named,
        shows=lambda n: (
            rf"$\dot q_1 = {n['qd_2'][0]:g}$ rad/s, $\dot q_3 = {n['qd_2'][2]:g}$ "
            "rad/s"
        ),
    ),
    matrix_exercise(
        "07_velocity_acceleration",
        3,
        "the linear Jacobian with the elbow bent",
        _elbow,
        lambda n: n["robot"],
        "J",
        lambda n: [0, 0, n["q3_3"]],
        free=[2],
    ),
    value_exercise(
        "07_velocity_acceleration",
        4,
        "the central difference across a jump",
        _spike,
        lambda n: _spike_rate(n, "numeric"),
        "check_value",
        _spike_options(
            "The numeric method uses the central difference (q[k+1] - q[k-1]) / (2 dt) "
            "across the jump, not the slope of the ramp."
        ),
        named=lambda n: _spike_named(n, "numeric"),
        length=False,
    ),
    value_exercise(
        "07_velocity_acceleration",
        5,
        "the backward difference Simulink shows",
        lambda v, earlier: {},
        lambda n: _spike_rate(n, "backward"),
        "check_value",
        _spike_options(
            "Simulink's Derivative block uses the backward difference (q[k] - q[k-1]) / dt: "
            "the change since the previous sample, over one step."
        ),
        named=lambda n: _spike_named(n, "backward"),
        length=False,
    ),
)

# -- lesson 8 ---------------------------------------------------------------------------

_UNIT_ARM = Robot.from_dh([(0, 0, 1, 0, "R"), (0, 0, 1, 0, "R")], convention="standard")


def _stretched(variant: Any, _: Any) -> dict[str, Any]:
    return {"q1_1": variant.angle("q1", [0, 30, 60, 90, 120, 150, 180]), "arm": _UNIT_ARM}


def _shoulder(variant: Any, _: Any) -> dict[str, Any]:
    return {"q2_4": variant.angle("q2", [-30, -15, 0, 15, 30, 45]), "robot": paper_robot()}


def _shoulder_q3(n: Any) -> float:
    """The q3 in (0, π) that puts the tip on the base z axis: 30 cos q2 + 40 cos(q2 + q3) = 0."""
    q2 = n["q2_4"]
    return float(np.arccos(-30 * np.cos(q2) / 40) - q2)


register(
    matrix_exercise(
        "08_workspace_singularities",
        1,
        "the Jacobian at a singularity",
        _stretched,
        lambda n: n["arm"],
        "J2",
        lambda n: [n["q1_1"], 0],
        free=[0],
        shows=lambda n: f"$q_1 = {np.degrees(n['q1_1']):g}°$",
    ),
    value_exercise(
        "08_workspace_singularities",
        4,
        "the shoulder singularity at your q2",
        _shoulder,
        _shoulder_q3,
        "check_angle",
        lambda n: {
            "name": "q3",
            "hint": "The tip is on the base z axis when l2 cos q2 + l3 cos(q2 + q3) = 0 (the "
            "shoulder factor of det J), with your q2. Give q3 in radians, between 0 and π.",
        },
        named=lambda n: {
            "q2_left_out": (
                float(np.arccos(-30 / 40)),
                "That q3 puts the tip on the axis with q2 = 0: keep your q2 in "
                "l2 cos q2 + l3 cos(q2 + q3) = 0.",
            ),
            "absolute_elbow": (
                float(np.arccos(-30 * np.cos(n["q2_4"]) / 40)),
                "That is q2 + q3, the forearm's own angle: subtract q2 to get the joint angle q3.",
            ),
        },
        angle=True,
        shows=lambda n: f"$q_2 = {np.degrees(n['q2_4']):g}°$",
    ),
)
