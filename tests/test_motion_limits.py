"""Limits of a motion: time-grid bounds, memory budgets, overflow and strict types.

Every failure must end quickly in an ``InvalidInputError`` naming its field. Inputs that
once allocated gigabytes, hung or overflowed run in a forked child under an address-space
limit and a hard timeout (``tests/hostile_harness.py``), so a regression fails its test
instead of taking the suite down.
"""

from __future__ import annotations

import datetime
import io
import re
import tracemalloc
from dataclasses import dataclass

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.motion import (
    MAX_TIME,
    MAX_TIME_SAMPLES,
    MIN_TIME_STEP,
    TIME_RESOLUTION,
    SimulationSettings,
    simulate,
)
from robotconf.motion._memory import (
    csv_bytes,
    kink_count,
    simulation_bytes,
    table_bytes,
)
from robotconf.signals import Ramp, RepeatingSequence, Signal, Sine

from .hostile_harness import Case, Refused, run_case


@pytest.fixture(autouse=True)
def _default_budget():  # type: ignore[no-untyped-def]
    yield
    rc.set_memory_budget(None)


def one_joint() -> rc.Robot:
    return rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))


def refused(case: Case) -> None:
    """Run a risky case in a child (≤ 1.5 GiB more address space, 20 s) and judge it."""
    kind, name, text, ok, seconds = run_case(case)
    assert ok, f"{case.id}: {kind} {name}: {text}"
    assert seconds < case.seconds


# -- the documented limits ---------------------------------------------------------------


def test_limits_are_the_documented_numbers() -> None:
    assert (MIN_TIME_STEP, MAX_TIME, TIME_RESOLUTION) == (1e-9, 1e9, 1e-10)
    assert MAX_TIME_SAMPLES == 10_000_000
    # The extremes themselves are allowed.
    assert SimulationSettings(t_end=MAX_TIME, t0=MAX_TIME - 1.0, dt=0.1).samples == 11
    assert SimulationSettings(t_end=1e-3, dt=MIN_TIME_STEP).samples == 1_000_001
    assert SimulationSettings(t_end=-MAX_TIME + 10, t0=-MAX_TIME, dt=1.0).samples == 11


@pytest.mark.parametrize(
    ("kwargs", "field", "match"),
    [
        ({"dt": 5e-324}, "dt", r"dt: below the smallest time step: 5e-324; allowed: a time step"),
        ({"dt": 1e-12}, "dt", r"dt: below the smallest time step: 1e-12"),
        ({"dt": 1e10}, "dt", r"dt: above the largest time step: 10000000000\.0"),
        ({"t0": -1e308, "t_end": 1e308}, "t_end", r"t_end: out of range: 1e\+308"),
        ({"t0": -1e308}, "t0", r"t0: out of range: -1e\+308; allowed: a time from -1e\+09"),
        ({"t_end": 1.5e9}, "t_end", r"t_end: out of range: 1500000000\.0"),
        (
            {"t0": MAX_TIME - 1.0, "t_end": MAX_TIME, "dt": 1e-9},
            "dt",
            r"dt: too fine for times as large as 1e\+09 s: 1e-09; allowed: dt ≥ 1e-10 × "
            r"max\(\|t0\|, \|t_end\|\) = 0\.1 s",
        ),
        ({"t_end": 1e7, "dt": 1e-3}, "dt", r"dt: too many samples at 0.001"),
    ],
)
def test_time_grid_arithmetic_never_overflows(kwargs, field, match) -> None:  # type: ignore[no-untyped-def]
    arguments = {"t_end": 1.0, **kwargs}
    with pytest.raises(InvalidInputError, match=match) as caught:
        SimulationSettings(**arguments)
    assert caught.value.field == field
    # simulate reports exactly the same, before allocating anything
    with pytest.raises(InvalidInputError) as again:
        simulate(one_joint(), {"q1": Sine()}, **arguments)
    assert (again.value.field, str(again.value)) == (caught.value.field, str(caught.value))


def test_a_denormal_t_end_is_one_sample_not_an_error() -> None:
    # 5e-324 s after t0 = 0 is a valid, if silly, run: one sample at t = 0.
    assert SimulationSettings(t_end=5e-324).samples == 1


def test_denormal_and_huge_settings_in_a_child_end_in_named_errors() -> None:
    cases = [
        ("dt 5e-324", lambda: simulate(one_joint(), {}, t_end=1.0, dt=5e-324), "dt"),
        (
            "±1e308 span",
            lambda: simulate(one_joint(), {}, t_end=1e308, t0=-1e308, dt=1e300),
            "t_end",
        ),
        ("dt 1e-308 to 1e308", lambda: simulate(one_joint(), {}, t_end=1e308, dt=1e-308), "t_end"),
    ]
    for name, call, field in cases:
        refused(Case("simulate", name, call, Refused(field), risky=True))


# -- strict types ------------------------------------------------------------------------

_NOT_SECONDS = [
    (1 + 0j, "a complex number is not a time"),
    (np.complex128(1.0), "a complex number is not a time"),
    (np.array(1.0 + 0j), "a complex number is not a time"),
    (True, "a boolean is not a number"),
    (np.True_, "a boolean is not a number"),
    (np.array(True), "a boolean is not a number"),
    (datetime.datetime(2024, 1, 1), "a date or duration is not a number of seconds"),
    (datetime.date(2024, 1, 1), "a date or duration is not a number of seconds"),
    (datetime.timedelta(seconds=1), "a date or duration is not a number of seconds"),
    (np.datetime64("2024-01-01"), "a date or duration is not a number of seconds"),
    (np.timedelta64(1, "s"), "a date or duration is not a number of seconds"),
    (np.str_("1.0"), "text is not a number"),
    (np.bytes_(b"1.0"), "text is not a number"),
    (np.array("1.0"), "text is not a number"),
    ("1.0", "text is not a number"),
    (np.array([1.0]), "expected one number"),
]


@pytest.mark.parametrize("field", ["t_end", "dt", "t0"])
@pytest.mark.parametrize(("value", "problem"), _NOT_SECONDS, ids=lambda v: repr(v)[:30])
def test_time_settings_must_be_real_seconds(field, value, problem) -> None:  # type: ignore[no-untyped-def]
    arguments = {"t_end": 1.0, "dt": 0.1, "t0": 0.0, field: value}
    with pytest.raises(InvalidInputError) as caught:
        SimulationSettings(**arguments)
    assert caught.value.field == field
    assert problem in str(caught.value)


def test_numpy_numbers_are_still_welcome() -> None:
    settings = SimulationSettings(np.float32(2.0), dt=np.float64(0.5), t0=np.int8(0))
    assert settings == SimulationSettings(2.0, 0.5, 0.0)
    assert SimulationSettings(np.array(2.0)).t_end == 2.0


@pytest.mark.parametrize("method", [True, 1, b"analytic", np.array("analytic"), ["numeric"]])
def test_method_must_be_text(method) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InvalidInputError, match=r"method: expected text, got") as caught:
        SimulationSettings(1.0, method=method)
    assert caught.value.field == "method"


def test_numpy_text_method_becomes_plain_text() -> None:
    settings = SimulationSettings(1.0, method=np.str_(" Numeric"))
    assert settings.method == "numeric" and type(settings.method) is str


# -- the memory budget for simulate ------------------------------------------------------


def test_small_budget_refuses_simulate_naming_dt_and_what_fits() -> None:
    robot = rc.preset("paper")
    rc.set_memory_budget("100M")
    with pytest.raises(InvalidInputError) as caught:
        simulate(robot, {"q3": RepeatingSequence()}, t_end=100.0, dt=1e-4)
    error = caught.value
    assert error.field == "dt" and error.value == 1e-4
    assert "needs about 1.29 GiB of memory (budget 100 MiB)" in str(error)
    assert "1,000,001 samples × 4 points" in str(error)
    # The suggested dt does fit, and runs.
    suggested = float(re.search(r"dt ≥ (\S+) s", error.allowed).group(1))  # type: ignore[union-attr]
    motion = simulate(robot, {"q3": RepeatingSequence()}, t_end=100.0, dt=suggested)
    assert 50_000 < motion.t.size < 100_000


def test_a_long_run_at_the_default_step_names_t_end() -> None:
    rc.set_memory_budget("100M")
    with pytest.raises(InvalidInputError, match=r"t_end: needs about .* with 1000\.0; allowed: "):
        simulate(rc.preset("paper"), {}, t_end=1000.0)


def test_everyday_runs_never_consult_the_budget() -> None:
    rc.set_memory_budget(1)  # one byte: only estimates under 64 MiB can pass
    motion = simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=10.0)
    assert motion.t.size == 10_001


def test_ten_million_samples_are_refused_in_a_child_not_allocated() -> None:
    # Within MAX_TIME_SAMPLES, but ~7 GB; the child could not even hold half of it.
    def setup() -> None:
        rc.set_memory_budget("1G")

    for name, kwargs, field in [
        ("1 ms for 10⁴ s", {"t_end": 9_999.999}, "t_end"),
        ("0.1 ms for 10³ s", {"t_end": 999.9999, "dt": 1e-4}, "dt"),
        ("numeric, 10⁷ samples", {"t_end": 9_999.999, "method": "numeric"}, "t_end"),
    ]:
        case = Case(
            "simulate",
            name,
            lambda kwargs=kwargs: simulate(one_joint(), {"q1": Sine()}, **kwargs),
            Refused(field, "of memory (budget 1 GiB)"),
            risky=True,
            setup=setup,
        )
        refused(case)


@pytest.mark.parametrize("method", ["analytic", "numeric"])
@pytest.mark.parametrize("robot_name", ["paper", "ur5"])
def test_estimate_is_at_least_the_measured_peak(method: str, robot_name: str) -> None:
    robot = rc.preset(robot_name)
    signals = {i: Sine(frequency=1.0 + i) + Ramp() for i in range(robot.n)}
    samples = 50_001
    simulate(robot, signals, t_end=0.01, method=method)  # warm up imports and caches
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        motion = simulate(robot, signals, t_end=(samples - 1) * 1e-3, method=method)
        peak = tracemalloc.get_traced_memory()[1] - start
    finally:
        tracemalloc.stop()
    assert motion.t.size == samples
    estimate = simulation_bytes(robot.n, samples, method, signals.values())
    assert peak <= estimate, f"measured {peak} > estimated {estimate:.0f}"
    assert estimate < 1.5 * peak + 8 * 1024**2  # and not wildly pessimistic
    assert peak > 30 * 1024**2  # real numbers: tens of MiB


# -- overflow from finite input ----------------------------------------------------------


@dataclass(frozen=True)
class Sampled(Signal):
    """A test signal with fixed value, velocity and acceleration (the real signals refuse
    parameters this extreme, so only a hand-made one reaches simulate's own checks)."""

    level: float = 0.0
    rate: float = 0.0
    curvature: float = 0.0
    alternate: bool = False  # flip the sign of the value every 0.5 s

    def _value(self, t: np.ndarray) -> np.ndarray:
        if self.alternate:
            return np.where(np.mod(t, 1.0) < 0.5, -self.level, self.level)
        return np.full(t.shape, self.level)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return np.full(t.shape, self.rate)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.full(t.shape, self.curvature) * 1e10  # 1e300 becomes inf here


def test_overflowing_accelerations_name_the_signal() -> None:
    with pytest.raises(InvalidInputError) as caught:
        simulate(one_joint(), {"q1": Sampled(curvature=1e300)}, t_end=1.0)
    # The signal itself may name its parameter; simulate adds the coordinate.
    assert caught.value.field in ("signals[q1]", "signals[q1].curvature")
    assert "accelerations" in str(caught.value)
    assert "overflow to inf or NaN" in str(caught.value)


def test_a_huge_fast_sine_is_refused_not_returned_as_inf() -> None:
    # Amplitude 1e300 at 1e10 Hz: accelerations ~ 4e320. The signal may refuse it itself.
    with pytest.raises(InvalidInputError) as caught:
        sine = Sine(amplitude=1e300, frequency=1e10)
        simulate(one_joint(), {"q1": sine}, t_end=1e-6, dt=1e-9)
    assert caught.value.field in ("signals[q1]", "amplitude", "frequency") or (
        caught.value.field.startswith("signals[q1].")
    )
    assert "\n" not in str(caught.value)


def test_numeric_finite_differences_that_overflow_name_the_signal() -> None:
    jumping = Sampled(level=1.5e308, alternate=True)  # ±1.5e308: differences of 3e308
    robot = rc.Robot([rc.Module("Tx")])
    with pytest.raises(InvalidInputError) as caught:
        simulate(robot, {"q1": jumping}, t_end=2.0, dt=0.5, method="numeric")
    assert caught.value.field == "signals[q1]"
    assert "the finite-difference velocities of q1 overflow" in str(caught.value)


def test_rates_overflowing_at_the_end_effector_name_the_signals() -> None:
    # q̇ = 1e100 rad/s and a lever of 1e150 are finite, but ω²·r = 1e350 is not.
    robot = rc.Robot([rc.Module("Rz")], end_effector=(1e150, 0, 0))
    with pytest.raises(InvalidInputError) as caught:
        simulate(robot, {"q1": Sampled(rate=1e100)}, t_end=1.0)
    assert caught.value.field == "signals"
    assert "the accelerations of EE overflow to inf or NaN" in str(caught.value)


def test_positions_overflowing_name_the_robot() -> None:
    robot = rc.Robot([rc.Module("Tx"), rc.Module("Tx")])
    far = Sampled(level=1e308)  # two slides of 1e308 put M2 at 2e308
    with pytest.raises(InvalidInputError, match="overflow to inf or NaN") as caught:
        simulate(robot, {"q1": far, "q2": far}, t_end=1.0)
    assert caught.value.field == "robot" or "q" in caught.value.field
    assert "\n" not in str(caught.value)


def test_overflow_checks_leave_good_runs_alone_and_warn_nothing() -> None:
    with np.errstate(all="raise"):
        motion = simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=10.0)
    assert np.isfinite(motion.columns()).all()


# -- tables and exports ------------------------------------------------------------------


@pytest.fixture(scope="module")
def long_motion():  # type: ignore[no-untyped-def]
    # 150 001 samples × 60 columns: a ~79 MB table, ~0.45 GB as Excel cells.
    return simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=150.0)


def test_table_is_refused_over_budget_and_built_within(long_motion) -> None:  # type: ignore[no-untyped-def]
    motion = simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=150.0)
    rc.set_memory_budget("70M")
    with pytest.raises(InvalidInputError) as caught:
        motion.table  # noqa: B018 - the property builds the table
    assert caught.value.field == "table"
    assert "150001 samples × 60 columns" in str(caught.value)
    with pytest.raises(InvalidInputError, match=r"^stats: needs about"):
        motion.stats()
    with pytest.raises(InvalidInputError, match=r"^other: needs about"):
        motion.compare(long_motion)
    rc.set_memory_budget(None)
    assert motion.table.shape == (150_001, 60)


def test_csv_text_in_memory_is_checked_but_files_are_chunked(tmp_path) -> None:  # type: ignore[no-untyped-def]
    # 40 001 samples × 61 cells: up to 0.13 GB of text in memory, a ~28 MB chunk to a file.
    motion = simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=40.0)
    motion.table  # noqa: B018 - cached, so only the CSV text counts
    rc.set_memory_budget("100M")
    for target in (None, io.StringIO()):
        with pytest.raises(InvalidInputError, match=r"^path: needs about") as caught:
            motion.to_csv(target)
        assert "a file path (written in chunks)" in caught.value.allowed
    path = tmp_path / "motion.csv"
    motion.to_csv(path)
    assert path.stat().st_size > 10_000_000  # the whole table, written chunk by chunk


def test_csv_text_is_returned_for_path_none() -> None:
    motion = simulate(rc.Robot([rc.Module("Tx")]), {"q1": Ramp()}, t_end=1.0, dt=0.5)
    text = motion.to_csv(None, flat=True)
    assert text is not None and text.splitlines()[0].startswith("time (s),M1_position_x")
    assert len(text.splitlines()) == 4


def test_excel_is_refused_over_budget(long_motion, tmp_path) -> None:  # type: ignore[no-untyped-def]
    pytest.importorskip("openpyxl")
    rc.set_memory_budget("200M")
    with pytest.raises(InvalidInputError, match=r"^path: needs about .* allowed: to_csv"):
        long_motion.to_excel(tmp_path / "motion.xlsx")
    assert not (tmp_path / "motion.xlsx").exists()


def test_export_estimates_scale_with_the_table() -> None:
    assert table_bytes(10_001, 60) == pytest.approx(1.1 * 8 * 10_001 * 61 + 1024**2)
    to_file = csv_bytes(1_000_000, 60, "out.csv")
    assert to_file == csv_bytes(10_000_000, 60, "out.csv")  # one chunk, whatever the length
    assert csv_bytes(1_000_000, 60, None) > 50 * 1_000_000 * 61


# -- kinks -------------------------------------------------------------------------------


def test_kinks_of_a_nanosecond_period_are_refused_quickly() -> None:
    fast = RepeatingSequence(times=[0, 1e-9], values=[0, 1])
    motion = simulate(one_joint(), {"q1": fast}, t_end=10.0, dt=1e-3)
    assert kink_count(fast, 0.0, 10.0) == pytest.approx(1e10, rel=1e-6)
    with pytest.raises(InvalidInputError) as caught:
        motion.kinks()
    assert caught.value.field == "signals[q1]"
    assert "fewer kinks (about 1e+10 in t = 0 … 10 s here)" in str(caught.value)


def test_kinks_in_a_child_under_a_memory_limit() -> None:
    fast = RepeatingSequence(times=[0, 0.5e-9, 1e-9], values=[0, 1, 0])

    def call() -> object:
        return simulate(one_joint(), {"q1": fast}, t_end=10.0).kinks()

    refused(Case("Motion.kinks", "1 ns period", call, Refused("signals[q1]"), risky=True))


def test_ordinary_kinks_are_listed() -> None:
    motion = simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=10.0)
    np.testing.assert_allclose(motion.kinks()["q3"], [0, 2, 4, 6, 8, 10])
