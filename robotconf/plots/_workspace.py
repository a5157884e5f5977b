"""matplotlib figure of a workspace: a 3D scatter and the XY, XZ and YZ projections.

Only draws the points the core computed; matplotlib is imported inside the function.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._validation import check_integer
from ..kinematics import AXIS_NAMES
from ._plain_text import PLAIN

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..kinematics import Workspace

__all__ = ["plot_workspace", "PROJECTIONS"]

#: The three projections: (title, horizontal axis index, vertical axis index).
PROJECTIONS = (("XY (top view)", 0, 1), ("XZ (front view)", 0, 2), ("YZ (side view)", 1, 2))


def plot_workspace(
    ws: Workspace,
    *,
    max_points: int = 20_000,
    length_unit: str = "length",
    color: Any = "tab:blue",
    figsize: tuple[float, float] = (10.0, 9.0),
) -> Figure:
    """Plot a workspace: 3D scatter (top left) and three projections.

    Parameters
    ----------
    ws : Workspace
    max_points : int
        Draw at most this many points (every k-th one): matplotlib slows down beyond a
        few ten thousand markers and the shape is already clear.
    length_unit : str
        Unit label of the axes, e.g. ``"mm"`` or ``"m"``.
    color : matplotlib color
    figsize : (float, float)
        Inches.

    Returns
    -------
    matplotlib.figure.Figure
        Four axes: 3D, XY, XZ, YZ. Not registered with pyplot (displays itself in
        Jupyter; call ``fig.savefig(path)`` in a script).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 2, 0, "R"), (0, 0, 1, 0, "R")])
    >>> fig = rc.workspace(arm, 1000, ranges=[(-np.pi, np.pi)] * 2, seed=0).plot()
    >>> [ax.get_title() for ax in fig.axes][1:]
    ['XY (top view)', 'XZ (front view)', 'YZ (side view)']
    """
    from ._figures import new_figure

    max_points = check_integer(max_points, "max_points", 1)
    step = max(1, -(-len(ws) // max_points))
    shown = ws.points[::step]
    labels = [f"{axis} [{length_unit}]" for axis in AXIS_NAMES]
    fig = new_figure(figsize)
    ax3d = fig.add_subplot(2, 2, 1, projection="3d")
    ax3d.scatter(shown[:, 0], shown[:, 1], shown[:, 2], s=1, color=color, alpha=0.3)
    ax3d.set_xlabel(labels[0], **PLAIN)
    ax3d.set_ylabel(labels[1], **PLAIN)
    ax3d.set_zlabel(labels[2], **PLAIN)
    ax3d.set_title("3D")
    # Equal scaling, so a sphere looks like one.
    lo, hi = ws.bounds
    center, half = (lo + hi) / 2, max(float(np.max(hi - lo)) / 2, 1e-9)
    ax3d.set_xlim(center[0] - half, center[0] + half)
    ax3d.set_ylim(center[1] - half, center[1] + half)
    ax3d.set_zlim(center[2] - half, center[2] + half)
    ax3d.set_box_aspect((1, 1, 1))
    for k, (title, i, j) in enumerate(PROJECTIONS):
        ax = fig.add_subplot(2, 2, k + 2)
        ax.scatter(shown[:, i], shown[:, j], s=1, color=color, alpha=0.3, rasterized=True)
        ax.set_xlabel(labels[i], **PLAIN)
        ax.set_ylabel(labels[j], **PLAIN)
        ax.set_title(title)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
    what = f"{len(ws):,} samples ({ws.method})"
    if step > 1:
        what += f", every {step}th drawn"
    fig.suptitle(f"{ws.robot.name or 'Robot'}: end-effector workspace, {what}", **PLAIN)
    return fig
