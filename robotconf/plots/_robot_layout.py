"""Placing the robot figure's 3D axes and its point labels, once, when it is built.

A 3D axes draws its ticks and axis labels inside its own box, so giving it the whole
figure below the title is what constrained layout does too, without measuring the 3D
ticks at every draw. Point labels are written to the right of their points; one that
would run past the 3D box into the z axis' numbers or out of the figure (the end
effector of an arm reaching along x, with a long label) is written to the left instead,
above its point.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from ._drawing import renderer_of, text_width
from ._grid_layout import PAD

__all__ = ["fill_figure", "keep_labels_inside"]

#: Room below the 3D box for the x and y axis labels drawn at its lower edge, in inches.
BOTTOM = 0.25


def fill_figure(ax: Any, title: Any) -> None:
    """Give the 3D axes ``ax`` its whole figure below its ``title`` (a Text)."""
    fig = ax.figure
    width, height = fig.bbox.width, fig.bbox.height
    pad, bottom = PAD * fig.dpi, BOTTOM * fig.dpi
    # The title and the gap matplotlib leaves between it and the axes.
    above = title.get_window_extent(renderer_of(fig)).height
    above += ax.titleOffsetTrans.get_matrix()[1, 2]
    top = height - 2 * pad - above
    ax.set_position((pad / width, bottom / height, 1 - 2 * pad / width, (top - bottom) / height))


def keep_labels_inside(ax: Any, texts: Iterable[Any], lift: float) -> None:
    """Write a label that would cross the 3D box's right edge to the left of its point,
    ``lift`` (data units) above it."""
    import itertools

    import numpy as np
    from mpl_toolkits.mplot3d import proj3d

    renderer = renderer_of(ax.figure)
    ax.apply_aspect()  # the 3D box's final place on the figure
    projection = ax.get_proj()

    def screen_x(x: Any, y: Any, z: Any) -> np.ndarray:
        flat_x, flat_y, _ = proj3d.proj_transform(x, y, z, projection)
        return ax.transData.transform(np.column_stack([flat_x, flat_y]))[:, 0]

    corners = np.array(list(itertools.product(ax.get_xlim(), ax.get_ylim(), ax.get_zlim())))
    right = float(screen_x(*corners.T).max())
    for text in texts:
        x, y, z = text.get_position_3d()
        start = float(screen_x(np.array([x]), np.array([y]), np.array([z]))[0])
        if start + text_width(renderer, text, text.get_text()) > right:
            text.set_position_3d((x, y, z + lift))
            text.set_horizontalalignment("right")
            text.set_verticalalignment("bottom")
