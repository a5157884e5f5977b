"""Workspace sampling: shapes of reachable sets with real numbers, methods, seeds, errors."""

from __future__ import annotations

import sys

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics import grid_size, workspace

FULL_TURN = (-np.pi, np.pi)


@pytest.fixture
def planar_2r() -> rc.Robot:
    """Links l1 = 2, l2 = 1 in the xy plane."""
    return rc.Robot([rc.Module("Rz"), rc.Module("Rz", a=(2, 0, 0))], end_effector=(1, 0, 0))


@pytest.fixture
def gantry() -> rc.Robot:
    """Cartesian TxTyTz; the Ty carriage sits 0.5 above the Tx rail."""
    return rc.Robot([rc.Module("Tx"), rc.Module("Ty", a=(0, 0, 0.5)), rc.Module("Tz")])


GANTRY_RANGES = [(0.0, 1.0), (-2.0, 2.0), (0.0, 0.3)]
GANTRY_BOX = np.array([[0.0, -2.0, 0.5], [1.0, 2.0, 0.8]])


def test_planar_2r_fills_the_annulus(planar_2r):
    ws = workspace(planar_2r, 20_000, ranges=[FULL_TURN, FULL_TURN], seed=7)
    r = np.hypot(ws.points[:, 0], ws.points[:, 1])
    assert ws.points.shape == (20_000, 3) and ws.q.shape == (20_000, 2)
    assert np.all(ws.points[:, 2] == 0.0)
    # |l1 − l2| ≤ r ≤ l1 + l2, and both rims are approached.
    assert r.min() >= 1.0 - 1e-12 and r.max() <= 3.0 + 1e-12
    assert r.min() < 1.01 and r.max() > 2.99
    np.testing.assert_allclose(ws.distances(), r)


def test_planar_2r_points_match_the_core(planar_2r):
    ws = workspace(planar_2r, 500, ranges=[FULL_TURN, FULL_TURN], seed=3)
    np.testing.assert_array_equal(ws.points, planar_2r.end_effector(ws.q))
    q1, q2 = ws.q.T
    expected = np.stack([2 * np.cos(q1) + np.cos(q1 + q2), 2 * np.sin(q1) + np.sin(q1 + q2)], 1)
    np.testing.assert_allclose(ws.points[:, :2], expected, atol=1e-12)


def test_gantry_random_points_fill_exactly_the_box(gantry):
    ws = workspace(gantry, 50_000, ranges=GANTRY_RANGES, seed=1)
    lo, hi = ws.bounds
    assert np.all(lo >= GANTRY_BOX[0]) and np.all(hi <= GANTRY_BOX[1])
    np.testing.assert_allclose(ws.bounds, GANTRY_BOX, atol=1e-3 * 4)
    # Uniform: each half of the box holds half of the points (±2 %).
    middle = GANTRY_BOX.mean(axis=0)
    np.testing.assert_allclose((ws.points < middle).mean(axis=0), 0.5, atol=0.02)


def test_gantry_grid_hits_the_corners_and_is_even(gantry):
    ws = workspace(gantry, 1000, ranges=GANTRY_RANGES, method="grid")
    assert len(ws) == 1000
    np.testing.assert_allclose(ws.bounds, GANTRY_BOX, rtol=0, atol=1e-15)
    np.testing.assert_allclose(np.unique(ws.points[:, 1]), np.linspace(-2, 2, 10), atol=1e-15)
    assert len({tuple(p) for p in ws.points.round(12)}) == 1000


def test_paper_robot_points_lie_on_a_shell(paper_robot):
    # q2 and q3 turn about parallel y axes through (0, 0, 20): the EE is
    # |l2 + l3·e^{i q3}| = sqrt(30² + 40² + 2·30·40·cos q3) ∈ [10, 70] from there.
    ranges = [FULL_TURN] * 3
    ws = workspace(paper_robot, 20_000, ranges=ranges, seed=11)
    d = ws.distances((0, 0, 20))
    assert d.min() >= 10 - 1e-9 and d.max() <= 70 + 1e-9
    assert d.min() < 11 and d.max() > 69.5
    np.testing.assert_allclose(d, np.sqrt(2500 + 2400 * np.cos(ws.q[:, 2])), atol=1e-9)


def test_seed_reproducibility_and_chunk_independence(paper_robot):
    ranges = [FULL_TURN] * 3
    first = workspace(paper_robot, 100_000, ranges=ranges, seed=5)
    again = workspace(paper_robot, 100_000, ranges=ranges, seed=5)
    other = workspace(paper_robot, 100_000, ranges=ranges, seed=6)
    np.testing.assert_array_equal(first.points, again.points)
    assert not np.array_equal(first.points, other.points)
    # 100 samples (one chunk) are the first 100 of 100 000 (two chunks): one stream.
    small = workspace(paper_robot, 100, ranges=ranges, seed=5)
    np.testing.assert_array_equal(small.q, first.q[:100])
    assert first.seed == 5 and first.method == "random"


def test_fixed_range_holds_a_coordinate(paper_robot):
    ws = workspace(paper_robot, 1000, ranges=[(0.5, 0.5), FULL_TURN, (0, 0)], seed=0)
    assert np.all(ws.q[:, 0] == 0.5) and np.all(ws.q[:, 2] == 0.0)
    # Only q2 moves, so the EE stays on a circle of radius 70 around (0, 0, 20).
    np.testing.assert_allclose(ws.distances((0, 0, 20)), 70.0)


def test_grid_of_six_joints_and_grid_size():
    assert [grid_size(s, 6) for s in (63, 64, 999_999, 1_000_000)] == [1, 2, 9, 10]
    assert grid_size(10, 0) == 1 and grid_size(100, 2) == 10 and grid_size(99, 2) == 9
    robot = rc.Robot([rc.Module(k) for k in ("Rz", "Ry", "Ry", "Rx", "Ry", "Rz")])
    ws = workspace(robot, 64, ranges=[FULL_TURN] * 6, method="grid")
    assert ws.q.shape == (64, 6)
    assert set(np.unique(ws.q)) == {-np.pi, np.pi}


def test_result_is_read_only(planar_2r):
    ws = workspace(planar_2r, 10, ranges=[FULL_TURN, FULL_TURN], seed=0)
    with pytest.raises(ValueError, match="read-only"):
        ws.points[0, 0] = 1.0
    with pytest.raises(AttributeError):
        ws.method = "grid"  # type: ignore[misc]


def test_table_columns_and_values(planar_2r):
    ws = workspace(planar_2r, 50, ranges=[FULL_TURN, FULL_TURN], seed=2)
    table = ws.table
    assert list(table.columns) == ["q1", "q2", "x", "y", "z"] and table.shape == (50, 5)
    np.testing.assert_array_equal(table[["x", "y", "z"]].to_numpy(), ws.points)
    np.testing.assert_array_equal(table[["q1", "q2"]].to_numpy(), ws.q)
    assert ws.table is table  # built once


def test_frame_is_a_deprecated_alias_of_table(planar_2r):
    ws = workspace(planar_2r, 5, ranges=[FULL_TURN, FULL_TURN], seed=2)
    with pytest.warns(
        DeprecationWarning, match=r"Workspace\.frame\(\) is now the property Workspace\.table"
    ):
        frame = ws.frame()
    assert frame.equals(ws.table)


def test_plot_has_3d_and_three_labelled_projections(gantry):
    ws = workspace(gantry, 30_000, ranges=GANTRY_RANGES, seed=4)
    fig = ws.plot(max_points=10_000, length_unit="m")
    ax3d, xy, xz, yz = fig.axes
    assert ax3d.name == "3d" and ax3d.get_zlabel() == "z [m]"
    assert [(a.get_xlabel(), a.get_ylabel()) for a in (xy, xz, yz)] == [
        ("x [m]", "y [m]"),
        ("x [m]", "z [m]"),
        ("y [m]", "z [m]"),
    ]
    drawn = xz.collections[0].get_offsets()
    assert len(drawn) == 10_000  # every 3rd of 30 000
    np.testing.assert_array_equal(drawn, ws.points[::3][:, [0, 2]])


class RecordingScene:
    """Stands in for the 3D scene: records add_point_cloud calls."""

    def __init__(self):
        self.calls = []

    def add_point_cloud(self, name, points, color=(0, 0, 1), size=None):
        self.calls.append((name, np.asarray(points), np.asarray(color), size))


def test_view_sends_the_points_to_the_scene(gantry):
    ws = workspace(gantry, 1000, ranges=GANTRY_RANGES, seed=4)
    scene = RecordingScene()
    assert ws.view(scene, color=(1.0, 0.5, 0.0), size=0.01) is scene
    name, points, color, size = scene.calls[0]
    assert name == "workspace" and size == 0.01
    np.testing.assert_array_equal(points, ws.points)
    np.testing.assert_array_equal(color, [1.0, 0.5, 0.0])
    ws.view(scene, name="half", max_points=500, color=np.ones((1000, 3)))
    assert scene.calls[1][1].shape == (500, 3) and scene.calls[1][2].shape == (500, 3)


class RecordingBar:
    made: list[RecordingBar] = []

    def __init__(self, total, initial=0, **kwargs):
        self.total, self.done, self.closed = total, initial, False
        RecordingBar.made.append(self)

    def update(self, count):
        self.done += count

    def close(self):
        self.closed = True


@pytest.fixture
def bars(monkeypatch):
    import tqdm.auto

    RecordingBar.made = []
    monkeypatch.setattr(tqdm.auto, "tqdm", RecordingBar)
    return RecordingBar.made


def test_progress_true_forces_a_bar(planar_2r, bars):
    workspace(planar_2r, 1000, ranges=[FULL_TURN] * 2, progress=True)
    assert len(bars) == 1 and bars[0].done == bars[0].total == 1000 and bars[0].closed


def test_progress_auto_appears_for_long_runs_only(planar_2r, bars, monkeypatch):
    workspace(planar_2r, 200_000, ranges=[FULL_TURN] * 2)  # well under a second
    assert bars == []
    # every run looks "long" (the threshold is a global of the function's own module)
    monkeypatch.setattr(sys.modules[workspace.__module__], "PROGRESS_AFTER", 0.0)
    workspace(planar_2r, 200_000, ranges=[FULL_TURN] * 2)
    assert len(bars) == 1 and bars[0].done == 200_000
    workspace(planar_2r, 200_000, ranges=[FULL_TURN] * 2, progress=False)
    assert len(bars) == 1


def test_a_million_samples_of_six_modules_stay_within_reach():
    # Speed is measured in benchmarks/bench_workspace.py, not asserted here.
    robot = rc.Robot.from_dh(
        [(0, 0.089, 0, np.pi / 2, "R"), (0, 0, -0.425, 0, "R"), (0, 0, -0.392, 0, "R")]
        + [(0, 0.109, 0, np.pi / 2, "R"), (0, 0.095, 0, -np.pi / 2, "R"), (0, 0.082, 0, 0, "R")]
    )
    ws = workspace(robot, 1_000_000, ranges=[FULL_TURN] * 6, seed=0, progress=False)
    assert ws.points.shape == (1_000_000, 3)
    # Every point lies within the arm's reach: sum of link lengths and offsets.
    assert np.linalg.norm(ws.points - [0, 0, 0.089], axis=1).max() < 0.425 + 0.392 + 0.3


# -- errors ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"samples": 0}, "samples: out of range: 0"),
        ({"samples": -5}, "samples: out of range: -5"),
        ({"samples": 10.0}, "samples: not an integer"),
        ({"samples": True}, "samples: not an integer"),
        (
            {"samples": 11, "max_samples": 10},
            "samples: out of range: 11; allowed: an integer from 1 to 10",
        ),
        ({"max_samples": 0}, "max_samples: out of range"),
        ({"ranges": np.zeros((2, 3))}, r"ranges: expected shape \(3, 2\), got \(2, 3\)"),
        ({"ranges": [(0, 1), (0, 1)]}, r"expected shape \(3, 2\), got \(2, 2\)"),
        ({"ranges": [(0, 1), (2, 1), (0, 1)]}, "ranges: q2 has lo > hi"),
        ({"ranges": [(0, 1), (0, np.nan), (0, 1)]}, "ranges: q2 must be finite"),
        ({"ranges": [(0, 1), (0, 1), (-np.inf, 0)]}, "ranges: q3 must be finite"),
        ({"ranges": "0 1"}, "ranges: text is not a number"),
        ({"ranges": [(0, 1), (0, 1), ("a", 1)]}, "ranges: not numeric"),
        ({"method": "sobol"}, "method: unknown method 'sobol'"),
        ({"seed": -1}, "seed: out of range: -1; allowed: None or an integer ≥ 0"),
        ({"seed": 1.5}, "seed: not an integer"),
        ({"progress": "yes"}, "progress: not True or False: 'yes'"),
        (
            {"samples": 3, "method": "grid"},
            r"samples: too few for a grid: 3; allowed: at least 2\^3",
        ),
    ],
)
def test_bad_input(paper_robot, kwargs, match):
    kwargs = {"ranges": [FULL_TURN] * 3, **kwargs}
    with pytest.raises(rc.InvalidInputError, match=match):
        workspace(paper_robot, **kwargs)


def test_bad_robot():
    with pytest.raises(rc.InvalidInputError, match="robot: not a robot"):
        workspace([rc.Module("Rz")], 10)


def test_bad_view_max_points(planar_2r):
    ws = workspace(planar_2r, 10, ranges=[FULL_TURN] * 2, seed=0)
    with pytest.raises(rc.InvalidInputError, match="max_points: out of range: 0"):
        ws.view(RecordingScene(), max_points=0)


def test_bad_view_color(planar_2r):
    ws = workspace(planar_2r, 10, ranges=[FULL_TURN] * 2, seed=0)
    with pytest.raises(rc.InvalidInputError, match=r"color: expected shape \(3,\) or \(10, 3\)"):
        ws.view(RecordingScene(), color=(1, 0))
    with pytest.raises(rc.InvalidInputError, match="color: text is not a color"):
        ws.view(RecordingScene(), color="red")


def test_bad_distance_center(planar_2r):
    ws = workspace(planar_2r, 10, ranges=[FULL_TURN] * 2, seed=0)
    with pytest.raises(rc.InvalidInputError, match=r"center: expected shape \(3,\)"):
        ws.distances((0, 0))


# -- default ranges: the robot's joint limits -----------------------------------------


def test_default_ranges_are_the_joint_limits():
    robot = rc.preset("paper")
    ws = workspace(robot, 20_000, seed=9)
    np.testing.assert_array_equal(ws.ranges, robot.joint_limits())
    assert np.all(ws.q >= ws.ranges[:, 0]) and np.all(ws.q <= ws.ranges[:, 1])
    # |q3| ≤ 3π/4 keeps the EE between sqrt(30² + 40² + 2400 cos 135°) and 70 of the shoulder.
    d = ws.distances((0, 0, 20))
    inner = np.sqrt(2500 + 2400 * np.cos(3 * np.pi / 4))
    assert inner == pytest.approx(28.336, abs=1e-3)
    assert d.min() >= inner - 1e-9 and d.min() < inner + 0.5 and d.max() > 69.5


def test_cartesian_preset_fills_the_box_of_its_limits():
    robot = rc.preset("cartesian")
    limits = robot.joint_limits()
    ws = workspace(robot, 8000, method="grid")  # 20 values per axis
    np.testing.assert_allclose(ws.bounds, limits.T + robot.end_effector(np.zeros(3)), atol=1e-12)
    assert len(ws) == 8000 and len(np.unique(ws.points[:, 0])) == 20


def test_dict_ranges_override_by_coordinate_or_module_name():
    robot = rc.preset("paper")
    ws = workspace(robot, 500, {"q1": (0, 0), "M3": (0.5, 0.5)}, seed=1)
    assert np.all(ws.q[:, 0] == 0) and np.all(ws.q[:, 2] == 0.5)
    by_index = workspace(robot, 500, {0: (0, 0), 2: (0.5, 0.5)}, seed=1)
    np.testing.assert_array_equal(by_index.points, ws.points)
    np.testing.assert_array_equal(ws.ranges[1], robot.joint_limits()[1])
    assert np.all(ws.points[:, 1] == 0.0)  # q1 = 0: the arm stays in the xz plane


def test_dict_ranges_errors():
    robot = rc.preset("paper")
    with pytest.raises(
        rc.InvalidInputError, match="ranges: unknown module 'q7'; allowed: an index"
    ):
        workspace(robot, 10, {"q7": (0, 1)})
    with pytest.raises(rc.InvalidInputError, match="ranges: out of range: 3; allowed: an index"):
        workspace(robot, 10, {3: (0, 1)})
    with pytest.raises(rc.InvalidInputError, match=r"ranges\['q2'\]: expected 2 numbers"):
        workspace(robot, 10, {"q2": (0, 1, 2)})
    with pytest.raises(rc.InvalidInputError, match="ranges: q2 has lo > hi"):
        workspace(robot, 10, {"q2": (1, 0)})


def test_view_in_the_real_scene(planar_2r, tmp_path):
    ws = workspace(planar_2r, 2000, ranges=[FULL_TURN] * 2, seed=0)
    scene = rc.view(planar_2r, display=False)
    assert ws.view(scene, name="reach") is scene
    html = scene.export_html(tmp_path / "ws.html").read_text(encoding="utf-8")
    assert "clouds/reach" in html
