"""Step-by-step derivations: numbers, symbols, text and LaTeX."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest
import sympy

import robotconf as rc
from robotconf import Module, Robot
from robotconf.teaching import Derivation, derivation, format_number

q1, q2, q3, l1, l2, l3 = sympy.symbols("q1 q2 q3 l1 l2 l3", real=True)


@pytest.fixture
def paper_robot(paper_robot: Robot) -> Robot:
    """The shared paper robot (conftest), named so reprs can be checked."""
    return paper_robot.with_name("RzRyRy")


@pytest.fixture
def dh_arm() -> Robot:
    return Robot.from_dh([(0, 0.5, 1, np.pi / 2, "R"), (0, 0, 2, 0, "R")], end_effector=(0.5, 0, 0))


def test_step_names_and_order(paper_robot):
    steps = derivation(paper_robot, q=[0, 0, 0])
    assert isinstance(steps, Derivation)
    assert [s.name for s in steps] == ["A1", "A2", "A3", "M1", "M2", "M3", "p_EE"]
    assert len(steps) == 7
    assert steps["m3"] is steps["M3"] and steps["EE"] is steps["p_EE"]
    assert steps["P"] is steps["p_EE"] and steps["a_2"] is steps["A2"]
    assert [s.kind for s in steps] == ["transfer"] * 3 + ["pose"] * 3 + ["end_effector"]


def test_numeric_parking_position_matches_paper(paper_robot):
    steps = derivation(paper_robot, q=[0, 0, 0])
    origins = [tuple(steps[f"M{i}"].matrix[:3, 3]) for i in (1, 2, 3)]
    assert origins == [(0, 0, 0), (0, 0, 20), (30, 0, 20)]
    np.testing.assert_array_equal(steps["p_EE"].matrix[:, 0], [70, 0, 20, 1])


def test_numeric_text_has_no_noise_and_whole_numbers(paper_robot):
    text = str(derivation(paper_robot, q=[np.pi / 2, 0, 0]))
    assert "e-17" not in text and "6.123" not in text  # cos(pi/2) noise shows as 0
    assert "20.0" not in text
    assert "p_EE = [ 70 ]" in text and "       [ 20 ]" in text
    lines = derivation(paper_robot, q=[np.pi / 2, 0, 0])["M1"].__str__().splitlines()
    assert lines[1:5] == [
        "     [ 0  -1  0  0 ]",
        "M1 = [ 1   0  0  0 ]",
        "     [ 0   0  1  0 ]",
        "     [ 0   0  0  1 ]",
    ]


def test_precision_is_configurable(paper_robot):
    assert "0.9553" in str(derivation(paper_robot, q=[0.3, 0, 0]))
    two = str(derivation(paper_robot, q=[0.3, 0, 0], precision=2))
    assert "0.96" in two and "0.9553" not in two


def test_symbolic_paper_derivation(paper_robot):
    steps = derivation(paper_robot, symbolic=True, lengths=True)
    assert steps.lengths == {l1: 20, l2: 30, l3: 40}
    assert steps["M3"].matrix[0, 0] == sympy.cos(q1) * sympy.cos(q2 + q3)
    assert steps["A2"].description == "Ry(q2) with a = (0, 0, l1)"
    assert steps["M2"].description == "M1·A2"
    parking = {**steps.lengths, q1: 0, q2: 0, q3: 0}
    assert tuple(steps["p_EE"].matrix.subs(parking)) == (70, 0, 20, 1)
    text = str(steps)
    assert "where l1 = 20, l2 = 30, l3 = 40" in text
    assert "cos(q1)*cos(q2 + q3)" in text


def test_symbolic_substitution_equals_numpy_core(paper_robot, dh_arm):
    rng = np.random.default_rng(3)
    for robot in (paper_robot, dh_arm):
        symbolic = derivation(robot, symbolic=True, lengths=True)
        for _ in range(3):
            q = rng.uniform(-3, 3, robot.n)
            numeric = derivation(robot, q=q)
            values = {
                **symbolic.lengths,
                **{sympy.Symbol(f"q{i + 1}", real=True): float(v) for i, v in enumerate(q)},
            }
            for step in symbolic:
                got = np.array(step.matrix.subs(values).evalf(), dtype=float)
                np.testing.assert_allclose(
                    got, numeric[step.name].matrix, atol=1e-12, err_msg=step.name
                )


def test_dh_steps_show_factors_in_convention_order(dh_arm):
    steps = derivation(dh_arm, symbolic=True)
    a1 = steps["A1"]
    assert [label for label, _ in a1.factors] == ["Rz(q1)", "Tz(1/2)", "Tx(1)", "Rx(pi/2)"]
    product = sympy.eye(4)
    for _, m in a1.factors:
        product = product * m
    assert sympy.simplify(product - a1.matrix) == sympy.zeros(4, 4)
    assert a1.matrix[2, :] == sympy.Matrix([[0, 1, 0, sympy.Rational(1, 2)]])
    text = str(a1)
    assert "= Rz(q1)·Tz(1/2)·Tx(1)·Rx(pi/2)" in text
    assert "standard DH Rz(θ)·Tz(d)·Tx(a)·Rx(α)" in text
    modified = Robot.from_dh([(0, 0.5, 1, np.pi / 2, "R")], convention="modified")
    labels = [label for label, _ in derivation(modified, symbolic=True)["A1"].factors]
    assert labels == ["Rx(pi/2)", "Tx(1)", "Rz(q1)", "Tz(1/2)"]
    numeric = derivation(dh_arm, q=[0, 0])["A1"]
    assert [label for label, _ in numeric.factors] == ["Rz(0)", "Tz(0.5)", "Tx(1)", "Rx(1.5708)"]
    np.testing.assert_allclose(
        numeric.factors[0][1]
        @ numeric.factors[1][1]
        @ numeric.factors[2][1]
        @ numeric.factors[3][1],
        numeric.matrix,
        atol=1e-15,
    )


def test_latex_rendering(paper_robot):
    steps = derivation(paper_robot, symbolic=True, lengths=True)
    source = steps.latex()
    assert source.startswith("\\begin{aligned}") and source.endswith("\\end{aligned}")
    assert source.count("\\begin{bmatrix}") == 7
    assert "\\cos{\\left(q_{1} \\right)}" in source
    assert "M_{3} &= \\text{M2$\\cdot$A3}" in source
    assert "p_{EE}" in source
    assert steps._repr_latex_() == "$$" + source + "$$"
    assert steps["A1"]._repr_latex_().startswith("$$\\begin{aligned}")
    numeric = derivation(paper_robot, q=[0, 0, 0]).latex()
    assert "\\begin{bmatrix} 70 \\\\ 0 \\\\ 20 \\\\ 1 \\end{bmatrix}" in numeric


def test_latex_text_escapes_specials():
    robot = Robot([Module("Rz")], name="my_robot & co")
    source = derivation(robot, q=[0]).latex()
    assert "my\\_robot \\& co" in source


def test_inactive_module_is_identity():
    robot = Robot([Module("Rz"), Module("Tx", a=(1, 0, 0))], active=1)
    steps = derivation(robot, symbolic=True)
    assert steps["A2"].matrix == sympy.eye(4)
    assert "inactive" in steps["A2"].description
    assert "inactive" in derivation(robot, q=[0, 1])["A2"].description
    np.testing.assert_array_equal(derivation(robot, q=[0, 1])["A2"].matrix, np.eye(4))


def test_symbolic_at_given_configuration_is_exact(paper_robot):
    steps = derivation(paper_robot, q=[np.pi / 2, 0, 0], symbolic=True)
    assert steps["M3"].matrix[1, 3] == 30
    assert steps.q == (np.pi / 2, 0.0, 0.0)
    assert "at q = (1.5708, 0, 0)" in str(steps)


def test_format_number():
    assert format_number(1e-13) == "0"
    assert format_number(-1e-13) == "0"
    assert format_number(2.0) == "2"
    assert format_number(-0.5) == "-0.5"
    assert format_number(1 / 3, 2) == "0.33"
    assert format_number(float("inf")) == "inf"


def test_repr_and_matrices(paper_robot):
    steps = derivation(paper_robot, q=[0, 0, 0])
    assert repr(steps) == "<Derivation of RzRyRy: A1, A2, A3, M1, M2, M3, p_EE>"
    assert list(steps.matrices) == ["A1", "A2", "A3", "M1", "M2", "M3", "p_EE"]
    assert repr(steps["A1"]).startswith("<DerivationStep A1: Rz(q1)")


def test_error_branches(paper_robot):
    with pytest.raises(ValueError, match="lengths: needs symbolic"):
        derivation(paper_robot, lengths=True)
    with pytest.raises(
        ValueError, match="precision: out of range: 20; allowed: an integer from 0 to 15"
    ):
        derivation(paper_robot, precision=20)
    with pytest.raises(ValueError, match="precision: not an integer: 2.5"):
        derivation(paper_robot, precision=2.5)
    with pytest.raises(ValueError, match=r"q: expected shape \(3,\)"):
        derivation(paper_robot, q=[0, 0])
    with pytest.raises(ValueError, match="q: .*one configuration"):
        derivation(paper_robot, q=[[0, 0, 0], [1, 1, 1]])
    with pytest.raises(ValueError, match="robot: not a robot"):
        derivation("RzRyRy")
    with pytest.raises(ValueError, match="name: unknown matrix name 'M7'; allowed: A1 … A3"):
        derivation(paper_robot, q=[0, 0, 0])["M7"]


# -- LaTeX that pdflatex compiles -------------------------------------------------------


def _paper_robots() -> list[rc.Robot]:
    modules = rc.preset("paper")
    dh = rc.Robot.from_dh(
        [(0, 20, 0, -np.pi / 2, "R"), (0, 0, 30, 0, "R"), (0, 0, 40, 0, "R")], name="paper DH"
    )
    return [modules, dh]


@pytest.mark.parametrize("symbolic", [False, True])
def test_the_latex_of_the_paper_robot_is_plain_ascii(symbolic):
    # pdflatex stops on U+1D40 (ᵀ) and has no Greek in text mode: every symbol of
    # robotconf's own texts is written in LaTeX (inline math inside \text{}).
    for robot in _paper_robots():
        latex = rc.derivation(robot, symbolic=symbolic, lengths=symbolic).latex()
        assert latex.isascii(), sorted({ch for ch in latex if not ch.isascii()})
        assert "$^{\\mathsf T}$" in latex and "$\\cdot$" in latex
        assert latex.count("$") % 2 == 0


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_the_latex_of_the_paper_robot_compiles(tmp_path):
    body = "\n".join(
        "\\[" + rc.derivation(robot, symbolic=symbolic, lengths=symbolic).latex() + "\\]"
        for robot in _paper_robots()
        for symbolic in (False, True)
    )
    source = tmp_path / "derivation.tex"
    source.write_text(
        "\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n"
        + body
        + "\n\\end{document}\n",
        encoding="utf-8",
    )
    done = subprocess.run(
        ["pdflatex", "-interaction=nonstopmode", "-halt-on-error", source.name],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stdout[-2000:]
    assert (tmp_path / "derivation.pdf").stat().st_size > 1000
