"""Motion.plot: layout, labels, data and the kink annotation."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

import robotconf as rc  # noqa: E402
from robotconf.motion import simulate  # noqa: E402
from robotconf.plots import kink_note, plot_motion  # noqa: E402
from robotconf.signals import Quintic, RepeatingSequence  # noqa: E402


def paper_robot() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
        name="RzRyRy",
    )


def _text(fig) -> str:  # type: ignore[no-untyped-def]
    """Free text of the figure (the annotation), without the title, its line breaks
    (made to fit the figure's width) read as spaces."""
    return " ".join(" ".join(t.get_text().split()) for t in fig.texts if t is not fig._suptitle)


def test_layout_labels_and_data() -> None:
    motion = simulate(paper_robot(), {"q3": RepeatingSequence()}, t_end=4.0, dt=1e-2)
    fig = motion.plot("EE", length_unit="mm")
    axes = np.array(fig.axes).reshape(3, 3)
    assert [ax.get_title() for ax in axes[0]] == ["EE: x", "EE: y", "EE: z"]
    assert [ax.get_ylabel() for ax in axes[:, 0]] == [
        "position [mm]",
        "velocity [mm/s]",
        "acceleration [mm/s²]",
    ]
    assert all(ax.get_xlabel() == "time (s)" for ax in axes[2])
    assert axes[0, 0].get_shared_x_axes().joined(axes[0, 0], axes[2, 2])
    for r, quantity in enumerate(("position", "velocity", "acceleration")):
        for c in range(3):
            x, y = axes[r, c].lines[0].get_data()
            np.testing.assert_array_equal(x, motion.t)
            np.testing.assert_array_equal(y, motion.quantity(quantity)[:, 3, c])
    assert "RzRyRy: EE (analytic derivatives)" in fig._suptitle.get_text()
    assert "one-sided" in _text(fig)
    # Kink instants t = 0, 2, 4 marked on the acceleration row.
    assert len(axes[2, 0].lines) == 1 + 3


def test_numeric_plot_explains_the_spikes() -> None:
    motion = simulate(
        paper_robot(), {"q3": RepeatingSequence()}, t_end=5.0, dt=1e-2, method="numeric"
    )
    note = kink_note(motion)
    assert note is not None and "q3 at t = 0, 2, 4 s" in note and "impulse" in note
    assert "Δv/dt" in note
    fig = plot_motion(motion, "M3", displacement=True)
    assert note in _text(fig)
    assert fig.axes[0].get_ylabel() == "displacement [length]"
    np.testing.assert_array_equal(fig.axes[0].lines[0].get_data()[1], motion.displacement[:, 2, 0])


def test_smooth_input_has_no_annotation() -> None:
    motion = simulate(paper_robot(), {"q2": Quintic()}, t_end=1.0, dt=1e-2, method="numeric")
    assert kink_note(motion) is None
    assert _text(motion.plot()) == ""


def test_figure_is_not_registered_with_pyplot() -> None:
    import matplotlib.pyplot as plt

    before = plt.get_fignums()
    simulate(paper_robot(), {}, t_end=1.0, dt=0.1).plot()
    assert plt.get_fignums() == before


def test_point_is_resolved_by_the_robot() -> None:
    motion = simulate(paper_robot(), {"q2": Quintic()}, t_end=1.0, dt=0.1)
    by_name, by_coordinate, by_index = (plot_motion(motion, p) for p in ("M3", "q3", 2))
    for fig in (by_coordinate, by_index):
        assert fig.axes[0].get_title() == "M3: x"
        np.testing.assert_array_equal(
            fig.axes[2].lines[0].get_data()[1], by_name.axes[2].lines[0].get_data()[1]
        )
    np.testing.assert_array_equal(by_index.axes[2].lines[0].get_data()[1], motion.position[:, 2, 2])


def test_unknown_point() -> None:
    motion = simulate(paper_robot(), {}, t_end=1.0, dt=0.1)
    pattern = r"point: unknown module 'M4'; allowed: .*\(M1, M2, M3\).*or 'EE'"
    with pytest.raises(ValueError, match=pattern):
        motion.plot("M4")


def test_every_point_and_the_other_method_dashed() -> None:
    robot = paper_robot()
    exact = simulate(robot, {"q3": RepeatingSequence()}, t_end=4.0, dt=1e-2)
    approx = simulate(robot, {"q3": RepeatingSequence()}, t_end=4.0, dt=1e-2, method="numeric")
    fig = plot_motion(exact, "all", compare=approx, length_unit="mm")
    axes = np.array(fig.axes).reshape(3, 3)
    lines = axes[1, 0].lines[:8]  # 4 points × 2 methods, then the kink markers
    assert [line.get_linestyle() for line in lines] == ["-"] * 4 + ["--"] * 4
    for index, line in enumerate(lines[4:]):
        np.testing.assert_array_equal(line.get_ydata(), approx.velocity[:, index, 0])
    # The axes fit the analytic curves; the numeric spikes at the jumps run off them.
    low, high = axes[1, 0].get_ylim()
    assert high < np.abs(approx.velocity[:, -1, 0]).max()
    assert "numeric dashed, its spikes cut at the axes" in fig._suptitle.get_text()
    assert [t.get_text() for t in fig.legends[0].get_texts()] == ["M1", "M2", "M3", "EE"]


def test_compare_needs_the_same_robot_and_time_grid() -> None:
    motion = simulate(paper_robot(), {}, t_end=1.0, dt=0.1)
    other = simulate(paper_robot(), {}, t_end=1.0, dt=0.05)
    with pytest.raises(ValueError, match="compare: another robot or time grid"):
        plot_motion(motion, compare=other)


def test_backward_plot_says_it_is_simulinks_spike() -> None:
    motion = simulate(
        paper_robot(), {"q3": RepeatingSequence()}, t_end=5.0, dt=1e-2, method="backward"
    )
    note = kink_note(motion)
    assert note is not None and "Δv/dt" in note and "Simulink's Derivative block" in note
    numeric = simulate(
        paper_robot(), {"q3": RepeatingSequence()}, t_end=5.0, dt=1e-2, method="numeric"
    )
    assert "half as tall" in (kink_note(numeric) or "")
