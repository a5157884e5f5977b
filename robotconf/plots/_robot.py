"""A static matplotlib picture of a robot, as the paper's Figure 14.

Links are straight lines between consecutive frame origins (base, M1 … Mn, EE), module
origins are green markers, the end-effector a red one, each labelled with its position.
Every number comes from the core (:func:`~robotconf.robot_points`,
:meth:`Robot.frame_poses`); matplotlib is imported inside the function.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_flag
from ..kinematics import AXIS_NAMES, format_point, robot_points
from ._plain_text import PLAIN
from ._robot_layout import fill_figure, keep_labels_inside

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..kinematics import Robot

__all__ = ["plot_robot", "MODULE_COLOR", "EE_COLOR"]

#: The paper's colours: green spheres for modules, red for the end-effector.
MODULE_COLOR = "tab:green"
EE_COLOR = "tab:red"
#: Frame triad colours for the x, y and z axes (the usual RGB convention).
TRIAD_COLORS = ("tab:red", "tab:green", "tab:blue")


def _coincident(points: list[Any], tolerance: float) -> list[tuple[list[str], np.ndarray]]:
    """Group points at the same place, so that one label reads ``M4, M5, EE (…)``."""
    groups: list[tuple[list[str], np.ndarray]] = []
    for name, xyz in points:
        for names, where in groups:
            if np.max(np.abs(where - xyz)) <= tolerance:
                names.append(name)
                break
        else:
            groups.append(([name], xyz))
    return groups


def plot_robot(
    robot: Robot,
    q: Any = None,
    *,
    ax: Any = None,
    labels: bool = True,
    frames: bool = False,
    digits: int = 1,
    length_unit: str = "length",
    figsize: tuple[float, float] = (7.0, 6.0),
) -> Figure:
    """Draw the robot at one configuration in 3D (the paper's Figure 14).

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Coordinates (radians / length); default: the modules' own ``q``.
    ax : mpl_toolkits.mplot3d.Axes3D, optional
        Draw into these axes; default: a new figure with one 3D axes.
    labels : bool
        Write ``M2 (0.0, 0.0, 20.0)``-style labels next to the markers; points at the
        same place share one label (``M4, M5, EE (…)``).
    frames : bool
        Draw each module frame's axes (x red, y green, z blue) and the base frame's,
        scaled to 15 % of the robot's size.
    digits : int
        Decimals in the labels.
    length_unit : str
        Axis label unit.
    figsize : (float, float)
        Size of a new figure (inches).

    Returns
    -------
    matplotlib.figure.Figure
        The figure holding the axes. Artists carry labels: the line ``"links"``, the
        markers ``"modules"`` and ``"end-effector"``, the triads ``"frame T0 x"``,
        ``"frame M<i> y"``… (``i`` = 1 … n by position, whatever the module's name).
        Names and units are drawn literally (no mathtext).

    Raises
    ------
    InvalidInputError
        For a bad ``q``, a non-3D ``ax`` or a non-boolean flag.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> fig = plot_robot(robot)
    >>> [text.get_text() for text in fig.axes[0].texts][-1]
    'EE (70.0, 0.0, 20.0)'
    """
    labels = check_flag(labels, "labels")
    frames = check_flag(frames, "frames")
    points = robot_points(robot, q)
    new = ax is None
    if new:
        from ._figures import new_figure

        fig = new_figure(figsize, layout="none")
        ax = fig.add_subplot(projection="3d")
    elif getattr(ax, "name", None) != "3d":
        raise InvalidInputError(
            "ax", ax, "a 3D axes (fig.add_subplot(projection='3d'))", problem="not 3D:"
        )
    modules = np.array([p.position for p in points[:-1]])
    ee = points[-1].position
    # The chain starts at the base frame [T0]'s origin.
    chain = np.vstack([np.zeros(3), modules, ee])
    ax.plot(*chain.T, color="0.35", lw=3, label="links", zorder=1)
    ax.plot(*modules.T, ls="", marker="o", ms=12, color=MODULE_COLOR, label="modules")
    ax.plot(*ee[:, np.newaxis], ls="", marker="o", ms=12, color=EE_COLOR, label="end-effector")
    lo, hi = chain.min(axis=0), chain.max(axis=0)
    span = float(np.max(hi - lo))
    half = span / 2 if span > 0 else 1.0
    offset = 0.04 * half
    if labels:
        for names, xyz in _coincident(points, 1e-9 * half):
            text = format_point(", ".join(names), xyz, digits)
            ax.text(*(xyz + offset), text, fontsize=9, **PLAIN)
    if frames:
        poses = robot.frame_poses(q)
        size = 0.15 * 2 * half
        # Keyed by position, not by name: two modules may share a name.
        named = [("T0", np.eye(4)), *((f"M{i + 1}", pose) for i, pose in enumerate(poses))]
        for name, pose in named:
            for k, axis in enumerate(AXIS_NAMES):
                tip = pose[:3, 3] + size * pose[:3, k]
                segment = np.array([pose[:3, 3], tip])
                ax.plot(*segment.T, color=TRIAD_COLORS[k], lw=1.5, label=f"frame {name} {axis}")
    # Equal scaling: a cube around the robot, so angles and lengths look true.
    center = (lo + hi) / 2
    ax.set_xlim(center[0] - half, center[0] + half)
    ax.set_ylim(center[1] - half, center[1] + half)
    ax.set_zlim(center[2] - half, center[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel(f"x [{length_unit}]", **PLAIN)
    ax.set_ylabel(f"y [{length_unit}]", **PLAIN)
    ax.set_zlabel(f"z [{length_unit}]", **PLAIN)
    title = ax.set_title(
        f"{robot.name or 'Robot'}: modules (green) and end-effector (red)", **PLAIN
    )
    if new:
        fill_figure(ax, title)
        if labels:
            keep_labels_inside(ax, ax.texts, lift=2 * offset)
    return ax.figure
