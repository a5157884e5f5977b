"""Motion.table, stats, compare and export."""

from __future__ import annotations

import sys

import numpy as np
import pandas as pd
import pytest

import robotconf as rc
from robotconf.motion import (
    EXCEL_MAX_ROWS,
    QUANTITIES,
    STATS,
    TIE,
    compare_motions,
    motion_stats,
    simulate,
)
from robotconf.signals import RepeatingSequence, Sine


def paper_robot() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


@pytest.fixture(scope="module")
def motion():  # type: ignore[no-untyped-def]
    signals = {"q3": RepeatingSequence(), "q1": Sine(amplitude=0.3, frequency=0.2)}
    return simulate(paper_robot(), signals, t_end=10.0, dt=1e-3)


def test_table_layout(motion) -> None:  # type: ignore[no-untyped-def]
    table = motion.table
    assert table.shape == (10001, 4 * len(QUANTITIES) * 3)
    assert table.index.name == "time (s)"
    np.testing.assert_array_equal(table.index.to_numpy(), motion.t)
    assert table.columns.names == ["point", "quantity", "axis"]
    assert list(table.columns.levels[0]) == sorted(["M1", "M2", "M3", "EE"])
    assert table.columns[0] == ("M1", "position", "x")
    assert table.columns[-1] == ("EE", "angular_velocity", "z")
    for p, point in enumerate(motion.points):
        for quantity in QUANTITIES:
            for a, axis in enumerate("xyz"):
                column = table[(point, quantity, axis)].to_numpy()
                np.testing.assert_array_equal(column, motion.quantity(quantity)[:, p, a])
    np.testing.assert_allclose(
        table[("EE", "position", "x")],
        30 * np.cos(motion.q[:, 0]) + 40 * np.cos(motion.q[:, 2]) * np.cos(motion.q[:, 0]),
        atol=1e-10,
    )
    assert motion.table is table  # cached


def test_editing_the_table_does_not_touch_the_motion(motion) -> None:  # type: ignore[no-untyped-def]
    table = motion.table.copy()
    table.iloc[0, 0] = 123.0
    assert motion.position[0, 0, 0] == 0.0
    fresh = simulate(paper_robot(), {"q3": RepeatingSequence()}, t_end=1.0, dt=0.5)
    fresh.table.iloc[0, 0] = 7.0
    assert fresh.position[0, 0, 0] == 0.0


def test_stats_equal_numpy(motion) -> None:  # type: ignore[no-untyped-def]
    stats = motion.stats()
    assert list(stats.columns) == list(STATS)
    assert stats.index.equals(motion.table.columns)
    for column in [
        ("EE", "position", "z"),
        ("EE", "velocity", "z"),
        ("M1", "angular_velocity", "z"),
        ("EE", "acceleration", "x"),
    ]:
        x = motion.table[column].to_numpy()
        row = stats.loc[column]
        assert row["max"] == np.max(x) and row["min"] == np.min(x)
        tie = TIE * max(abs(np.max(x)), abs(np.min(x)))  # the first of equal peaks
        assert row["t_max"] == motion.t[np.flatnonzero(x >= np.max(x) - tie)[0]]
        assert row["t_min"] == motion.t[np.flatnonzero(x <= np.min(x) + tie)[0]]
        assert row["peak_to_peak"] == np.max(x) - np.min(x)
        assert row["mean"] == pytest.approx(np.mean(x), rel=1e-12, abs=1e-12)
        assert row["median"] == np.median(x)
        assert row["rms"] == pytest.approx(np.sqrt(np.mean(x**2)), rel=1e-12)
    # The paper's Figure 17: EE z swings between 20 (q3 = 0) and 20 − 40 = −20 (q3 = π/2).
    z = stats.loc[("EE", "position", "z")]
    assert z["max"] == pytest.approx(20.0) and z["min"] == pytest.approx(-20.0, abs=1e-5)
    assert z["t_min"] == pytest.approx(np.pi / 2, abs=1e-3)
    assert motion_stats(motion).equals(stats)


def test_a_periodic_motions_extremes_are_timed_in_its_first_period() -> None:
    # A 1 Hz sine on q1: every quantity repeats each second, but in floats a later period's
    # peak can be larger by an ulp (velocity x's minimum was reported at t = 2.118 s).
    motion = simulate(paper_robot(), {"q1": Sine(frequency=1.0)}, t_end=10.0, dt=1e-3)
    stats = motion.stats()
    assert stats["t_max"].max() < 1.0 and stats["t_min"].max() < 1.0
    # |v| of the EE peaks where q1 swings fastest; vx = −70·sin(q1)·q1' (r = 70, z = 20).
    vx = stats.loc[("EE", "velocity", "x")]
    assert vx["t_min"] == pytest.approx(0.118) and vx["t_max"] == pytest.approx(0.382)
    assert vx["max"] == pytest.approx(-vx["min"], rel=1e-12)


def test_compare_analytic_with_numeric() -> None:
    robot = paper_robot()
    kwargs = {"signals": {"q2": Sine(frequency=0.5)}, "t_end": 2.0}
    exact = simulate(robot, **kwargs, dt=1e-3)
    approx = simulate(robot, **kwargs, dt=1e-3, method="numeric")
    diff = exact.compare(approx)
    assert diff.shape == exact.table.shape and diff.columns.equals(exact.table.columns)
    np.testing.assert_array_equal(diff.to_numpy(), exact.table.to_numpy() - approx.table.to_numpy())
    assert np.all(diff.xs("position", level="quantity", axis=1).to_numpy() == 0.0)
    worst = diff.abs().max()
    assert 0 < worst[("EE", "velocity", "x")] < 1e-3
    assert compare_motions(exact, approx).equals(diff)


@pytest.mark.parametrize(
    ("other", "match"),
    [
        (lambda: simulate(paper_robot(), {}, t_end=2.0, dt=2e-3), r"other: different time grids"),
        (
            lambda: simulate(paper_robot().with_end_effector((1, 0, 0)), {}, t_end=2.0),
            r"different robots",
        ),
        (lambda: "motion", r"other: invalid value 'motion'; allowed: a Motion"),
    ],
)
def test_compare_refuses_mismatched_motions(other, match) -> None:  # type: ignore[no-untyped-def]
    base = simulate(paper_robot(), {}, t_end=2.0, dt=1e-3)
    with pytest.raises(ValueError, match=match):
        base.compare(other())


def test_csv_round_trip(tmp_path) -> None:  # type: ignore[no-untyped-def]
    motion = simulate(paper_robot(), {"q3": RepeatingSequence()}, t_end=1.0, dt=0.01)
    path = tmp_path / "motion.csv"
    motion.to_csv(path)
    back = pd.read_csv(path, header=[0, 1, 2], index_col=0)
    np.testing.assert_allclose(back.to_numpy(), motion.table.to_numpy(), rtol=1e-15)
    assert list(back.columns) == list(motion.table.columns)
    flat = tmp_path / "flat.csv"
    motion.to_csv(flat, flat=True)
    header = flat.read_text().splitlines()[0].split(",")
    assert header[0] == "time (s)" and header[1] == "M1_position_x"
    assert "EE_velocity_z" in header


def test_excel_round_trip(tmp_path) -> None:  # type: ignore[no-untyped-def]
    pytest.importorskip("openpyxl")
    motion = simulate(paper_robot(), {"q3": RepeatingSequence()}, t_end=0.5, dt=0.1)
    path = tmp_path / "motion.xlsx"
    motion.to_excel(path)
    back = pd.read_excel(path, header=[0, 1, 2], index_col=0)
    np.testing.assert_allclose(back.to_numpy(), motion.table.to_numpy())


def test_excel_without_openpyxl_says_what_to_install(tmp_path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util, "find_spec", lambda name, *a: None if name == "openpyxl" else real(name, *a)
    )
    monkeypatch.setitem(sys.modules, "openpyxl", None)
    motion = simulate(paper_robot(), {}, t_end=0.5, dt=0.1)
    with pytest.raises(
        ModuleNotFoundError, match=r"needs the 'openpyxl' package.*pip install openpyxl"
    ):
        motion.to_excel(tmp_path / "x.xlsx")
    assert not (tmp_path / "x.xlsx").exists()


def test_excel_refuses_more_rows_than_a_sheet_holds(tmp_path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    import importlib.util

    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: object())
    # One slide keeps the million-sample run near 0.7 GB (the paper robot needs twice that).
    motion = simulate(rc.Robot([rc.Module("Tx")]), {}, t_end=EXCEL_MAX_ROWS * 1e-3, dt=1e-3)
    with pytest.raises(ValueError, match=r"samples do not fit in a sheet.*use to_csv"):
        motion.to_excel(tmp_path / "big.xlsx")


def test_pandas_is_not_imported_by_the_core() -> None:
    import subprocess

    code = (
        "import sys, robotconf, robotconf.signals, robotconf.motion, robotconf.kinematics;"
        "import robotconf.plots;"
        "print('pandas' in sys.modules, 'matplotlib' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "False"]
