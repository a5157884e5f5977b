"""plot_robot: the paper's Figure 14, checked on the artists' data."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.plots import EE_COLOR, MODULE_COLOR, plot_robot


def _line(ax, label):
    (line,) = [line for line in ax.lines if line.get_label() == label]
    return line


def test_figure_14_markers_links_and_labels(paper_robot):
    from matplotlib.colors import to_rgba

    fig = plot_robot(paper_robot)
    ax = fig.axes[0]
    modules = np.array(_line(ax, "modules").get_data_3d()).T
    np.testing.assert_array_equal(modules, [[0, 0, 0], [0, 0, 20], [30, 0, 20]])
    ee = np.array(_line(ax, "end-effector").get_data_3d()).T
    np.testing.assert_array_equal(ee, [[70, 0, 20]])
    links = np.array(_line(ax, "links").get_data_3d()).T
    np.testing.assert_array_equal(
        links, [[0, 0, 0], [0, 0, 0], [0, 0, 20], [30, 0, 20], [70, 0, 20]]
    )
    assert to_rgba(_line(ax, "modules").get_color()) == to_rgba(MODULE_COLOR)
    assert to_rgba(_line(ax, "end-effector").get_color()) == to_rgba(EE_COLOR)
    assert [t.get_text() for t in ax.texts] == [
        "M1 (0.0, 0.0, 0.0)",
        "M2 (0.0, 0.0, 20.0)",
        "M3 (30.0, 0.0, 20.0)",
        "EE (70.0, 0.0, 20.0)",
    ]


def test_equal_axis_scaling(paper_robot):
    ax = plot_robot(paper_robot).axes[0]
    spans = [np.diff(get()) for get in (ax.get_xlim3d, ax.get_ylim3d, ax.get_zlim3d)]
    np.testing.assert_allclose(spans, [[70.0]] * 3)
    np.testing.assert_allclose(ax.get_xlim3d(), (0, 70))
    np.testing.assert_allclose(ax.get_zlim3d(), (-25, 45))


def test_markers_follow_q_from_the_core(paper_robot):
    q = [0.3, -0.4, 1.1]
    ax = plot_robot(paper_robot, q, labels=False).axes[0]
    np.testing.assert_allclose(
        np.array(_line(ax, "modules").get_data_3d()).T, paper_robot.frame_origins(q)
    )
    np.testing.assert_allclose(
        np.array(_line(ax, "end-effector").get_data_3d()).T[0], paper_robot.end_effector(q)
    )
    assert len(ax.texts) == 0


def test_frames_draw_each_module_axis(paper_robot):
    q = [np.pi / 2, 0.0, 0.0]
    ax = plot_robot(paper_robot, q, frames=True).axes[0]
    x_axis = np.array(_line(ax, "frame M1 x").get_data_3d()).T
    # M1 is turned a quarter about z: its x axis points along base y; length 15 % of 2·35.
    np.testing.assert_allclose(x_axis, [[0, 0, 0], [0, 10.5, 0]], atol=1e-12)
    labels = [line.get_label() for line in ax.lines]
    assert {"frame T0 z", "frame M3 y"} <= set(labels)


def test_draws_into_given_axes_and_labels_digits(paper_robot):
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.add_subplot(projection="3d")
    assert plot_robot(paper_robot, ax=ax, digits=2) is fig
    assert ax.texts[-1].get_text() == "EE (70.00, 0.00, 20.00)"


def test_rejects_2d_axes(paper_robot):
    from matplotlib.figure import Figure

    with pytest.raises(rc.InvalidInputError, match="ax: not 3D"):
        plot_robot(paper_robot, ax=Figure().add_subplot())


def test_rejects_non_flag(paper_robot):
    with pytest.raises(rc.InvalidInputError, match="frames: not True or False: 'yes'"):
        plot_robot(paper_robot, frames="yes")


def test_rejects_bad_q(paper_robot):
    with pytest.raises(rc.InvalidInputError, match="q: "):
        plot_robot(paper_robot, [0, np.nan, 0])


def test_points_at_one_place_share_a_label():
    robot = rc.Robot([rc.Module("Rz", a=(0, 0, 1)), rc.Module("Ry"), rc.Module("Tx")])
    ax = plot_robot(robot, digits=0).axes[0]
    assert [t.get_text() for t in ax.texts] == ["M1, M2, M3, EE (0, 0, 1)"]
    np.testing.assert_allclose(ax.get_zlim3d(), (0, 1))  # base (0, 0, 0) to the points
