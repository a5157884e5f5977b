"""Hostile and edge inputs at every entry point, as a student, a careless instructor and an
attacker would write them.

Each case ends in an ``rc.InvalidInputError`` (a ``ValueError``) naming the field, or in
a correct result, within its budget; risky ones run in a forked child under a time and
memory limit (see ``tests/hostile_harness.py``). ``test_corpus_is_large`` keeps the
corpus from shrinking unnoticed.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
import sympy

import robotconf as rc
from robotconf import signals as sg

from .hostile_harness import Case, Judged, Refused, Returns, run_case

PAPER_EE = np.array([70.0, 0.0, 20.0])
TAGS = '<img src=x onerror="window.__pwned=1">'


def paper() -> rc.Robot:
    return rc.preset("paper")


def modules(*links: rc.Module) -> rc.Robot:
    return rc.Robot(list(links))


def setup_text(robot: dict | None = None, **top: Any) -> str:
    data: dict[str, Any] = {
        "format": "robotconf",
        "version": 1,
        "robot": robot if robot is not None else json.loads(paper().to_json())["robot"],
    }
    data.update(top)
    return json.dumps(data)


def link(**fields: Any) -> dict[str, Any]:
    return {"type": "module", "kind": "Rz", **fields}


def one_link_robot(**fields: Any) -> dict[str, Any]:
    return {"links": [link(**fields)]}


def close(expected: Any) -> Callable[[Any], bool]:
    return lambda result: bool(np.allclose(result, expected, rtol=1e-12, atol=1e-12))


def is_paper_ee(robot: rc.Robot) -> bool:
    return bool(np.allclose(robot.end_effector([0, 0, 0]), PAPER_EE))


CASES: list[Case] = []


def add(entry: str, name: str, call: Callable[[], Any], expect: Any, **options: Any) -> None:
    CASES.append(Case(entry, name, call, expect, **options))


# -- modules ----------------------------------------------------------------------------

for label, kind in [
    ("unknown kind", "Rw"),
    ("empty kind", ""),
    ("markup kind", "<script>alert(1)</script>"),
    ("long kind", "Rz" * 5000),
    ("bytes kind", b"Rz"),
    ("float kind", 1.5),
    ("bool kind", True),
    ("list kind", ["Rz"]),
    ("dunder kind", "__class__"),
    ("code 9", 9),
    ("negative code", -1),
]:
    add("Module", label, lambda kind=kind: rc.Module(kind), Refused("kind"))

for label, offsets in [
    ("NaN offset", (math.nan, 0, 0)),
    ("inf offset", (0, math.inf, 0)),
    ("-inf offset", (0, 0, -math.inf)),
    ("two offsets", (1, 2)),
    ("four offsets", (1, 2, 3, 4)),
    ("text offsets", "1,2,3"),
    ("complex offset", (1 + 0j, 0, 0)),
    ("imaginary offset", (1j, 0, 0)),
    ("bool offsets", (True, False, True)),
    ("numpy text offsets", np.array(["1", "2", "3"])),
    ("datetime offsets", np.array(["2020-01-01"] * 3, dtype="datetime64[D]")),
    ("timedelta offsets", np.array([1, 2, 3], dtype="timedelta64[s]")),
    ("nested offsets", ((1, 2, 3),)),
    ("object offset", (object(), 0, 0)),
    ("dict offsets", {"x": 1}),
    ("overflowing text float", (float("1e308") * 10, 0, 0)),
]:
    add("Module", label, lambda offsets=offsets: rc.Module("Rz", a=offsets), Refused("a"))

for label, q in [
    ("NaN q", math.nan),
    ("inf q", math.inf),
    ("text q", "0.5"),
    ("complex q", 0.5 + 0j),
    ("bool q", True),
    ("list q", [1, 2]),
    ("datetime q", np.datetime64("2020-01-01")),
    ("numpy bool q", np.bool_(True)),
    ("None q", None),
]:
    add("Module", label, lambda q=q: rc.Module("Rz", q=q), Refused("q"))

for label, name in [
    ("int name", 5),
    ("huge name", "x" * 10_000),
    ("bytes name", b"M1"),
]:
    add("Module", label, lambda name=name: rc.Module("Rz", name=name), Refused("name"))

add(
    "Module",
    "markup name kept as text",
    lambda: rc.Module("Rz", name=TAGS).name,
    Returns(lambda name: name == TAGS, "the name unchanged"),
)
for label, limits in [
    ("reversed limits", (1.0, 0.0)),
    ("NaN limit", (math.nan, 1.0)),
    ("text limits", ("a", "b")),
    ("three limits", (0.0, 1.0, 2.0)),
    ("complex limits", (0j, 1j)),
]:
    add("Module", label, lambda limits=limits: rc.Module("Rz", limits=limits), Refused("limits"))
add("Module", "limits on fixed", lambda: rc.Module("none", limits=(0, 1)), Refused("limits"))

# -- DH links ---------------------------------------------------------------------------

for parameter, value in [
    ("theta", math.nan),
    ("d", math.inf),
    ("a", "30"),
    ("alpha", 1j),
    ("joint", "X"),
    ("joint", "revolute joint"),
    ("convention", "craig-ish"),
    ("convention", None),
    ("q", math.nan),
    ("d", True),
]:
    add(
        "DHLink",
        f"{parameter}={value!r}",
        lambda parameter=parameter, value=value: rc.DHLink(**{parameter: value}),
        Refused(parameter),
    )

# -- robots -----------------------------------------------------------------------------

add("Robot", "no links", lambda: rc.Robot([]), Refused("modules"))
add("Robot", "links not a list", lambda: rc.Robot("RzRyRy"), Refused("modules"))
add("Robot", "text links", lambda: rc.Robot(["Rz", "Ry"]), Refused("modules"))
add("Robot", "65 links", lambda: rc.Robot([rc.Module("Rz")] * 65), Refused("modules"))
add(
    "Robot",
    "10^6 links",
    lambda: rc.Robot([rc.Module("Rz")] * 1_000_000),
    Refused("modules"),
    risky=True,
)
add(
    "Robot",
    "NaN end effector",
    lambda: rc.Robot([rc.Module("Rz")], end_effector=(math.nan, 0, 0)),
    Refused("end_effector"),
)
add(
    "Robot",
    "complex end effector",
    lambda: rc.Robot([rc.Module("Rz")], end_effector=(1j, 0, 0)),
    Refused("end_effector"),
)
for value in (0, 4, True, 1.5, "2"):
    add(
        "Robot",
        f"active={value!r}",
        lambda value=value: rc.Robot(paper().modules, active=value),
        Refused("active"),
    )
add(
    "Robot",
    "module named EE",
    lambda: rc.Robot([rc.Module("Rz", name="EE")]),
    Refused("name"),
)
add(
    "Robot",
    "module named like another's coordinate",
    lambda: rc.Robot([rc.Module("Rz", name="q2"), rc.Module("Ry")]),
    Refused("name"),
)
add(
    "Robot",
    "two modules with one name",
    lambda: rc.Robot([rc.Module("Rz", name="base"), rc.Module("Ry", name="base")]),
    Refused("name"),
)
add(
    "Robot",
    "markup robot name, right numbers",
    lambda: rc.Robot(paper().modules, end_effector=(40, 0, 0), name=TAGS),
    Returns(is_paper_ee, "the paper's end-effector (70, 0, 20)"),
)

# -- robot methods ----------------------------------------------------------------------

for label, q in [
    ("too few q", [1, 2]),
    ("NaN q", [0, math.nan, 0]),
    ("complex q", np.array([0, 1j, 0])),
    ("text q", ["0", "1", "2"]),
    ("bool q", [True, False, True]),
    ("datetime q", np.array(["2020-01-01"] * 3, dtype="datetime64[D]")),
    ("3-d q", np.zeros((2, 2, 3))),
    ("ragged q", [[0, 0, 0], [0, 0]]),
]:
    add("Robot.end_effector", label, lambda q=q: paper().end_effector(q), Refused("q"))
    add("Robot.frame_poses", label, lambda q=q: paper().frame_poses(q), Refused("q"))
add(
    "Robot.jacobian",
    "NaN q",
    lambda: paper().jacobian([0, math.nan, 0]),
    Refused("q"),
)
add(
    "Robot.end_effector",
    "huge but finite q on a rotation",
    lambda: paper().end_effector([1e300, 0, 0]),
    Returns(lambda p: bool(np.all(np.isfinite(p)) and np.hypot(p[0], p[1]) <= 70 + 1e-9)),
)
add(
    "Robot.end_effector",
    "two Tx offsets of 1e308 overflow",
    lambda: modules(
        rc.Module("Tx", a=(1e308, 0, 0)), rc.Module("Tx", a=(1e308, 0, 0))
    ).end_effector(),
    Refused(""),
)
add(
    "Robot.end_effector",
    "prismatic q of 1e308 twice overflows",
    lambda: modules(rc.Module("Tx"), rc.Module("Tx")).end_effector([1e308, 1e308]),
    Refused(""),
)
add(
    "Robot.frame_poses",
    "DH lengths of 1e308 overflow",
    lambda: rc.Robot.from_dh([(0, 1e308, 1e308, 0, "R"), (0, 1e308, 1e308, 0, "R")]).frame_poses(),
    Refused(""),
)
add(
    "Robot.frame_poses",
    "10^7 samples over a small budget",
    lambda: paper().frame_poses(np.zeros((10_000_000, 3))),
    Refused("q"),
    risky=True,
    setup=lambda: rc.set_memory_budget("256M"),
)
add(
    "Robot.end_effector",
    "10^5 samples, right numbers",
    lambda: paper().end_effector(np.zeros((100_000, 3))),
    Returns(lambda p: p.shape == (100_000, 3) and bool(np.allclose(p, PAPER_EE))),
)
add(
    "to_urdf",
    "overflowing robot never writes inf",
    lambda: rc.to_urdf(modules(rc.Module("Tx", a=(1e308, 0, 0)), rc.Module("Tx", a=(1e308, 0, 0)))),
    Refused(""),
)
add(
    "to_urdf",
    "markup names are escaped XML",
    lambda: rc.to_urdf(rc.Robot([rc.Module("Rz", name=TAGS)], name=TAGS)),
    Returns(lambda text: "<img" not in text and "&lt;img" in text, "escaped names"),
)

# -- signals ----------------------------------------------------------------------------

for label, build, field in [
    ("Sine NaN amplitude", lambda: sg.Sine(amplitude=math.nan), "amplitude"),
    ("Sine negative frequency", lambda: sg.Sine(frequency=-1), "frequency"),
    ("Sine complex phase", lambda: sg.Sine(phase=1j), "phase"),
    ("Sine text bias", lambda: sg.Sine(bias="1"), "bias"),
    ("Sine bool amplitude", lambda: sg.Sine(amplitude=True), "amplitude"),
    ("Cubic zero duration", lambda: sg.Cubic(duration=0), "duration"),
    ("Cubic denormal duration", lambda: sg.Cubic(duration=5e-324), "duration"),
    ("Quintic denormal duration", lambda: sg.Quintic(duration=5e-324), "duration"),
    ("Trapezoidal denormal duration", lambda: sg.Trapezoidal(duration=5e-324), "duration"),
    ("Trapezoidal accel fraction 0.9", lambda: sg.Trapezoidal(accel_fraction=0.9), "accel"),
    ("Step inf time", lambda: sg.Step(step_time=math.inf), "step_time"),
    ("Ramp NaN slope", lambda: sg.Ramp(slope=math.nan), "slope"),
    ("Constant complex", lambda: sg.Constant(1j), "level"),
    (
        "Repeating times not increasing",
        lambda: sg.RepeatingSequence(times=[0, 2, 1], values=[0, 1, 2]),
        "times",
    ),
    (
        "Repeating 10^5 points",
        lambda: sg.RepeatingSequence(times=np.arange(100_001.0), values=np.zeros(100_001)),
        "times",
    ),
    (
        "Repeating lengths differ",
        lambda: sg.RepeatingSequence(times=[0, 1], values=[0, 1, 2]),
        "values",
    ),
    ("Affine NaN scale", lambda: sg.Sine() * math.nan, "scale"),
]:
    add("signals", label, build, Refused(field))

add(
    "signals",
    "Sine 1e300 at 1e10 Hz overflows its acceleration",
    lambda: sg.Sine(amplitude=1e300, frequency=1e10).acceleration([0.1]),
    Refused(""),
)
add(
    "signals",
    "Ramp 1e308 slope overflows at t=1e10",
    lambda: sg.Ramp(slope=1e308).value([1e10]),
    Refused(""),
)
add(
    "signals",
    "kinks of a 1e-9 s period over 10 s",
    lambda: sg.RepeatingSequence(times=[0, 1e-9], values=[0, 1]).kinks(0.0, 10.0),
    Refused(""),
    risky=True,
)
add(
    "signals",
    "value at NaN time",
    lambda: sg.Sine().value([math.nan]),
    Refused("t"),
)
add(
    "signals",
    "Sine values, right numbers",
    lambda: sg.Sine(amplitude=2, frequency=0.25).value([0.0, 1.0]),
    Returns(close([0.0, 2.0])),
)

# -- signal specs (text) ----------------------------------------------------------------

for label, spec in [
    ("empty spec", ""),
    ("no equals", "q3 sine"),
    ("q0", "q0=sine"),
    ("q99999", "q99999=sine"),
    ("unknown kind", "q3=exec:amplitude=1"),
    ("call in a number", "q3=sine:amplitude=__import__('os')"),
    ("power tower", "q3=sine:amplitude=9**9**9"),
    ("overflowing number", "q3=sine:frequency=1e400"),
    ("NaN number", "q3=sine:amplitude=nan"),
    ("repeated key", "q3=sine:amplitude=1,amplitude=2"),
    ("unknown key", "q3=sine:volume=11"),
    ("NUL byte", "q3=sine:amplitude=1\x00"),
    ("newline injection", "q3=sine:amplitude=1\nq1=sine"),
    ("5100-digit integer", "q3=sine:amplitude=" + "9" * 5100),
    ("markup", f"q3=sine:amplitude={TAGS}"),
]:
    add("signal spec", label, lambda spec=spec: sg.parse_signal_spec(spec), Refused(""))
add(
    "signal spec",
    "Arabic digits read as 12 or refused",
    lambda: sg.parse_signal_spec("q3=sine:amplitude=١٢")[1].value([0.25]),
    Judged("signal", close([12.0]), "amplitude 12"),
)
for label, spec in [("not text", 5), ("None", None), ("bytes", b"q3=sine")]:
    add("signal spec", label, lambda spec=spec: sg.parse_signal_spec(spec), Refused(""))
add(
    "signal spec",
    "10,000-character number",
    lambda: sg.parse_signal_spec("q3=sine:amplitude=" + "1" * 9_980),
    Refused(""),
    risky=True,
    seconds=10,
)
add(
    "signal spec",
    "10^6-character number",
    lambda: sg.parse_signal_spec("q3=sine:amplitude=" + "1." * 500_000),
    Refused(""),
    risky=True,
    seconds=10,
)
add(
    "signal spec",
    "10^4 digits of pi factor",
    lambda: sg.parse_signal_spec("q3=sine:phase=" + "2" * 5000 + "*pi"),
    Refused(""),
    risky=True,
    seconds=10,
)
add(
    "signal spec",
    "a well-formed spec, right numbers",
    lambda: sg.parse_signal_spec("q3=sine:amplitude=0.5,frequency=0.25")[1].value([1.0]),
    Returns(close([0.5])),
)

# -- robot files ------------------------------------------------------------------------

for label, text, field in [
    ("not JSON", "{robot: 1}", ""),
    ("JSON list", "[1, 2]", ""),
    ("NaN", setup_text(one_link_robot(q=0.0)).replace("0.0", "NaN", 1), "q"),
    (
        "Infinity offset",
        setup_text(one_link_robot(a=[1, 2, 3])).replace("1, 2, 3", "Infinity, 2, 3"),
        "a",
    ),
    ("1e400", setup_text(one_link_robot(q=0.5)).replace("0.5", "1e400"), "q"),
    (
        "31-digit integer",
        setup_text(one_link_robot(q=1)).replace('"q": 1', '"q": ' + "9" * 31),
        "q",
    ),
    (
        "5100-digit integer",
        setup_text(one_link_robot(q=1)).replace('"q": 1', '"q": ' + "9" * 5100),
        "q",
    ),
    ("boolean q", setup_text(one_link_robot(q=True)), "q"),
    ("number as text", setup_text(one_link_robot(q="0.5")), "q"),
    ("kind code", setup_text(one_link_robot(kind=3)), "kind"),
    ("markup kind", setup_text(one_link_robot(kind=TAGS)), "kind"),
    ("unknown key", setup_text(one_link_robot(script="alert(1)")), "script"),
    ("__proto__ key", setup_text(one_link_robot(__proto__={"polluted": 1})), "__proto__"),
    ("duplicate key", setup_text(one_link_robot(q=0)).replace('"q": 0', '"q": 0, "q": 1'), "q"),
    ("version 2", setup_text(version=2), "version"),
    ("version true", setup_text(version=True), "version"),
    ("format python", setup_text(format="pickle"), "format"),
    ("65 links", setup_text({"links": [link()] * 65}), "links"),
    ("name of 201 characters", setup_text({"links": [link()], "name": "x" * 201}), "name"),
    ("name as a list", setup_text({"links": [link()], "name": ["x"]}), "name"),
    ("active 0", setup_text({"links": [link()], "active": 0}), "active"),
    ("end effector of 2", setup_text({"links": [link()], "end_effector": [1, 2]}), "end_effector"),
    ("limits reversed", setup_text(one_link_robot(limits=[1, 0])), "limits"),
    (
        "dh without convention",
        setup_text(
            {"links": [{"type": "dh", "theta": 0, "d": 0, "a": 1, "alpha": 0, "joint": "R"}]}
        ),
        "convention",
    ),
    ("signal for q9", setup_text(signals={"q9": {"type": "Constant", "level": 1}}), "q9"),
    ("signal of type eval", setup_text(signals={"q1": {"type": "eval", "code": "1"}}), "type"),
    (
        "signal nested 17 deep",
        setup_text(
            signals={
                "q1": json.loads(
                    '{"type": "Affine", "base": ' * 17 + '{"type": "Constant"}' + "}" * 17
                )
            }
        ),
        "signals",
    ),
    (
        "Sum of 65 terms",
        setup_text(signals={"q1": {"type": "Sum", "terms": [{"type": "Constant"}] * 65}}),
        "terms",
    ),
    (
        "Repeating of 10,001 points",
        setup_text(
            signals={
                "q1": {
                    "type": "RepeatingSequence",
                    "times": list(range(10_001)),
                    "values": [0] * 10_001,
                }
            }
        ),
        "times",
    ),
    ("dt 0", setup_text(simulation={"t_end": 1, "dt": 0}), "dt"),
    ("dt denormal", setup_text(simulation={"t_end": 1, "dt": 5e-324}), "dt"),
    (
        "span of ±1e308",
        setup_text(simulation={"t0": -1e308, "t_end": 1e308, "dt": 1}),
        "simulation",
    ),
    ("10^9 samples", setup_text(simulation={"t_end": 1000, "dt": 1e-6}), "simulation"),
    ("method eval", setup_text(simulation={"t_end": 1, "method": "eval"}), "method"),
    ("t_end missing", setup_text(simulation={"dt": 0.1}), "t_end"),
]:
    add("load_setup", label, lambda text=text: rc.load_setup(text), Refused(field))
add(
    "load_setup",
    "file over 1 MB",
    lambda: rc.load_setup(setup_text() + " " * 1_000_001),
    Refused(""),
)
add("load_setup", "UTF-16 bytes", lambda: rc.load_setup(setup_text().encode("utf-16")), Refused(""))
add(
    "load_setup",
    "JSON nested 10^5 deep",
    lambda: rc.load_setup("[" * 100_000 + "]" * 100_000),
    Refused(""),
    risky=True,
)
add(
    "load_setup",
    "markup names survive as text, right numbers",
    lambda: (
        rc.load_setup(setup_text({**json.loads(paper().to_json())["robot"], "name": TAGS})).robot
    ),
    Returns(lambda robot: robot.name == TAGS and is_paper_ee(robot)),
)
add(
    "load_setup",
    "byte-order mark is fine",
    lambda: rc.load_setup(("\ufeff" + setup_text()).encode()).robot,
    Returns(is_paper_ee),
)
add("load", "a missing file", lambda: rc.load("/nonexistent/robot.json"), Refused(""))
add("load", "a directory", lambda: rc.load("/"), Refused(""))

# -- simulation -------------------------------------------------------------------------

for label, options, field in [
    ("dt 0", {"dt": 0}, "dt"),
    ("dt negative", {"dt": -1e-3}, "dt"),
    ("dt NaN", {"dt": math.nan}, "dt"),
    ("dt denormal", {"dt": 5e-324}, "dt"),
    ("dt complex", {"dt": 1e-3 + 0j}, "dt"),
    ("dt bool", {"dt": True}, "dt"),
    ("dt text", {"dt": "0.001"}, "dt"),
    ("t_end before t0", {"t_end": -1.0}, "t_end"),
    ("span of ±1e308", {"t0": -1e308, "t_end": 1e308}, ""),
    ("method eval", {"method": "eval"}, "method"),
    ("method 1", {"method": 1}, "method"),
    ("10^9 samples", {"t_end": 1000.0, "dt": 1e-6}, ""),
]:
    add(
        "simulate",
        label,
        lambda options=options: rc.simulate(paper(), {}, **{"t_end": 1.0, **options}),
        Refused(field),
    )
add(
    "simulate",
    "10^7 samples over a small budget",
    lambda: rc.simulate(paper(), {"q3": sg.Sine()}, t_end=9.99, dt=1e-6),
    Refused(""),
    risky=True,
    setup=lambda: rc.set_memory_budget("512M"),
)
add(
    "simulate",
    "signal for an unknown coordinate",
    lambda: rc.simulate(paper(), {"q7": sg.Sine()}, t_end=1.0),
    Refused("signals", "q7"),
)
add(
    "simulate",
    "signal that is text",
    lambda: rc.simulate(paper(), {"q1": "sin(t)"}, t_end=1.0),
    Refused("q1"),
)
add(
    "simulate",
    "Sine 1e300 at 1e10 Hz overflows",
    lambda: rc.simulate(
        paper(), {"q1": sg.Sine(amplitude=1e300, frequency=1e10)}, t_end=1e-3, dt=1e-4
    ),
    Refused(""),
)
add(
    "simulate",
    "prismatic positions overflow",
    lambda: rc.simulate(
        modules(rc.Module("Tx"), rc.Module("Tx")), {"q1": 1e308, "q2": 1e308}, t_end=0.01
    ),
    Refused(""),
)
add(
    "simulate",
    "the paper's sawtooth, right numbers",
    lambda: rc.simulate(
        paper(), {"q3": sg.RepeatingSequence([0, 2], [0, 2]) * 0.5}, t_end=1.0, dt=0.5
    ).position[..., -1, :],
    Returns(
        close(
            [
                [70.0, 0.0, 20.0],
                [30 + 40 * math.cos(0.25), 0.0, 20 - 40 * math.sin(0.25)],
                [30 + 40 * math.cos(0.5), 0.0, 20 - 40 * math.sin(0.5)],
            ]
        )
    ),
)
add(
    "Motion.kinks",
    "a 1e-9 s period over 10 s",
    lambda: rc.simulate(
        paper(), {"q3": sg.RepeatingSequence([0, 1e-9], [0, 1])}, t_end=10.0, dt=0.5
    ).kinks(),
    Refused(""),
    risky=True,
)
add(
    "Motion.to_csv",
    "a table over a small budget",
    lambda: rc.simulate(paper(), {"q3": sg.Sine()}, t_end=20.0, dt=1e-4).to_csv("/dev/null"),
    Refused(""),
    risky=True,
    seconds=60,
    setup=lambda: rc.set_memory_budget("200M"),
)

# -- workspace --------------------------------------------------------------------------

for label, samples in [
    ("-1 samples", -1),
    ("10^12 samples", 10**12),
    ("text samples", "1e6"),
    ("1.5 samples", 1.5),
    ("bool samples", True),
]:
    add(
        "workspace",
        label,
        lambda samples=samples: rc.workspace(paper(), samples=samples),
        Refused("samples"),
    )
add(
    "workspace",
    "5·10^7 samples over a small budget",
    lambda: rc.workspace(paper(), samples=50_000_000),
    Refused("samples"),
    risky=True,
    setup=lambda: rc.set_memory_budget("256M"),
)
add(
    "workspace",
    "reach of the paper robot",
    lambda: rc.workspace(paper(), samples=20_000, seed=1).points,
    Returns(lambda p: bool(np.linalg.norm(p - [0, 0, 20], axis=-1).max() <= 70.0 + 1e-9)),
)

# -- homework checker (student text) ----------------------------------------------------

A1 = "[[cos(q1), -sin(q1), 0, 0], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]"


def a1_with(entry: str) -> str:
    return A1.replace("-sin(q1)", entry, 1)


def check_a1(answer: str) -> rc.MatrixCheck:
    return rc.check_matrix(answer, rc.expected_matrix(paper(), "A1"))


def not_accepted(result: rc.MatrixCheck) -> bool:
    return not result.ok


SIN_Q1 = sympy.Matrix([[sympy.sin(sympy.Symbol("q1"))]])


for label, answer in [
    ("sin(1000000*q1)", "sin(1000000*q1)"),
    ("tan(1000000*q1)", "tan(1000000*q1)"),
    ("((q1+1)**64+1)**64", "((q1+1)**64+1)**64"),
    ("q1**(10**6)", "q1**(10**6)"),
    ("nested sines", "sin(" * 40 + "q1" + ")" * 40),
    ("cos(q1)**1000", "cos(q1)**1000"),
    ("(sin(q1)+cos(q1))**200", "(sin(q1)+cos(q1))**200"),
    ("sqrt(sqrt(sqrt(q1**999)))", "sqrt(sqrt(sqrt(q1**999)))"),
    ("sum of 2000 terms", "+".join(f"sin({k}*q1)" for k in range(1, 2000))),
]:
    add(
        "check_matrix",
        f"wrong 1×1 {label}",
        lambda answer=answer: rc.check_matrix(answer, SIN_Q1),
        Judged("student", not_accepted, "a not-ok verdict"),
        risky=True,
        seconds=10,
    )
    add(
        "check_matrix",
        f"A1 with {label}",
        lambda answer=answer: check_a1(a1_with(answer)),
        Judged("student", not_accepted, "a not-ok verdict"),
        risky=True,
        seconds=10,
    )
for label, answer in [
    ("1+sqrt(-1)", "1+sqrt(-1)"),
    ("sqrt(-1)", "sqrt(-1)"),
    ("(-1)**(1/2)", "(-1)**(1/2)"),
    ("I", "I"),
    ("1j", "1j"),
]:
    add(
        "check_matrix",
        f"imaginary {label}",
        lambda answer=answer: rc.check_matrix(answer, 1),
        Refused(""),
        risky=True,
        seconds=10,
    )
add(
    "check_matrix",
    "A1 with sqrt(-1) in an entry",
    lambda: check_a1(A1.replace("0, 0, 1, 0", "0, sqrt(-1), 1, 0")),
    Refused(""),
    risky=True,
    seconds=10,
)
for label, answer in [
    ("import", "__import__('os').system('echo pwned')"),
    ("lambda", "(lambda: 1)()"),
    ("dunder", "q1.__class__"),
    ("power tower", "9**9**9**9"),
    ("5100-digit integer", "1" * 5100),
    ("10^4 parentheses", "(" * 10_000 + "1" + ")" * 10_000),
    ("10^6 characters", "1+" * 500_000 + "1"),
    ("exp", "exp(q1)"),
    ("eval", "eval('1')"),
    ("attribute call", "sin.__globals__"),
    ("markup", TAGS),
    ("unbalanced", "[[1, 2], [3, 4]"),
    ("ragged", "[[1, 2], [3]]"),
    ("empty", ""),
    ("unknown symbol", "q1 + x_secret"),
]:
    add(
        "check_matrix",
        label,
        lambda answer=answer: rc.check_matrix(answer, SIN_Q1),
        Refused("student"),
        risky=True,
        seconds=10,
    )
add(
    "check_matrix",
    "the right A1, written as text",
    lambda: check_a1(A1),
    Returns(lambda result: result.ok, "accepted"),
)
add(
    "check_matrix",
    "the right A1 in another form",
    lambda: check_a1(A1.replace("cos(q1), -sin(q1)", "sin(q1 + pi/2), -cos(q1 - pi/2)")),
    Returns(lambda result: result.ok, "accepted"),
)
add(
    "check_matrix",
    "3.1416 for pi within tolerance",
    lambda: rc.check_matrix("3.1416", math.pi, tol=1e-3),
    Returns(lambda result: result.ok, "accepted"),
)
add(
    "check_matrix",
    "a boolean entry",
    lambda: rc.check_matrix([[True]], 1),
    Refused(""),
)
add(
    "check_matrix",
    "a complex numpy entry",
    lambda: rc.check_matrix(np.array([[1 + 1j]]), 1),
    Refused(""),
)

# -- derivation, presets, budget --------------------------------------------------------

add(
    "derivation",
    "numeric steps of the paper robot, right numbers",
    lambda: rc.derivation(paper()).steps[-1].matrix[:3, 0],
    Returns(close(PAPER_EE)),
)
add("derivation", "q of the wrong length", lambda: rc.derivation(paper(), q=[1]), Refused("q"))
add(
    "derivation", "precision -1", lambda: rc.derivation(paper(), precision=-1), Refused("precision")
)
add(
    "derivation",
    "precision 10^6",
    lambda: rc.derivation(paper(), precision=10**6),
    Refused("precision"),
)
for name in ("../../etc/passwd", "", TAGS, 5, None):
    add("preset", f"name {name!r}", lambda name=name: rc.preset(name), Refused("name"))
for value in ("abc", -1, 0, True, 1.5, "1e999G"):
    add(
        "set_memory_budget",
        repr(value),
        lambda value=value: rc.set_memory_budget(value),
        Refused(""),
    )


# -- the tests --------------------------------------------------------------------------


def test_corpus_is_large() -> None:
    assert len(CASES) >= 150
    assert len({case.id for case in CASES}) == len(CASES), "case names must be unique"
    assert sum(case.risky for case in CASES) >= 30


@pytest.mark.parametrize("case", CASES, ids=[case.id for case in CASES])
def test_hostile_input(case: Case) -> None:
    kind, type_name, text, ok, seconds = run_case(case)
    expected = (
        f"refusal naming {case.expect.field!r}"
        if isinstance(case.expect, Refused)
        else case.expect.what
    )
    assert ok, f"{case.id}: expected {expected}; got {kind} {type_name}: {text} ({seconds:.2f} s)"
