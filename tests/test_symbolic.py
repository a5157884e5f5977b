"""Symbolic matrices: the paper's validation case and agreement with the numpy core."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import sympy

from robotconf import DHLink, Module, Robot, dh_matrix, transfer_matrix
from robotconf.teaching import (
    dh_factors,
    elementary_matrix,
    exact_number,
    module_matrix,
    simplify_matrix,
    symbolic_chain,
)

q1, q2, q3, l1, l2, l3 = sympy.symbols("q1 q2 q3 l1 l2 l3", real=True)


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(7)


def _numeric(matrix: sympy.Matrix, values: dict) -> np.ndarray:
    return np.array(matrix.subs(values).evalf(), dtype=float)


def test_paper_transfer_matrices_match_eq_17_to_19(paper_robot):
    chain = symbolic_chain(paper_robot, lengths=True)
    a1, a2, a3 = chain.transfer
    assert a1 == sympy.Matrix(
        [
            [sympy.cos(q1), -sympy.sin(q1), 0, 0],
            [sympy.sin(q1), sympy.cos(q1), 0, 0],
            [0, 0, 1, 0],
            [0, 0, 0, 1],
        ]
    )
    assert a2[2, :] == sympy.Matrix([[-sympy.sin(q2), 0, sympy.cos(q2), l1]])
    assert sympy.Matrix([[l2, 0, 0, 1]]) == a3[:, 3].T
    assert sympy.Matrix([[l3, 0, 0, 1]]) == chain.point.T
    assert chain.lengths == {l1: 20, l2: 30, l3: 40}
    assert [(place, name) for place, name, _ in chain.length_places] == [
        ("M2", "az"),
        ("M3", "ax"),
        ("EE", "Px"),
    ]


def test_paper_m3_reads_like_a_textbook(paper_robot):
    m3 = symbolic_chain(paper_robot, lengths=True).frame_poses()[2]
    c23, s23 = sympy.cos(q2 + q3), sympy.sin(q2 + q3)
    expected = sympy.Matrix(
        [
            [
                sympy.cos(q1) * c23,
                -sympy.sin(q1),
                sympy.cos(q1) * s23,
                l2 * sympy.cos(q1) * sympy.cos(q2),
            ],
            [
                sympy.sin(q1) * c23,
                sympy.cos(q1),
                sympy.sin(q1) * s23,
                l2 * sympy.sin(q1) * sympy.cos(q2),
            ],
            [-s23, 0, c23, l1 - l2 * sympy.sin(q2)],
            [0, 0, 0, 1],
        ]
    )
    assert m3 == expected  # structurally, not just numerically
    assert str(m3[0, 0]) == "cos(q1)*cos(q2 + q3)"


def test_paper_p_ee_symbolic_and_parking_position(paper_robot):
    chain = symbolic_chain(paper_robot, lengths=True)
    p = chain.end_effector()
    assert sympy.expand(p[2] - (l1 - l2 * sympy.sin(q2) - l3 * sympy.sin(q2 + q3))) == 0
    assert (
        sympy.simplify(p[0] - sympy.cos(q1) * (l2 * sympy.cos(q2) + l3 * sympy.cos(q2 + q3))) == 0
    )
    parking = {**chain.values(), q1: 0, q2: 0, q3: 0}
    origins = [tuple(m[:3, 3].subs(parking)) for m in chain.frame_poses()]
    assert origins == [(0, 0, 0), (0, 0, 20), (30, 0, 20)]
    ee = p.subs(parking)
    assert tuple(ee) == (70, 0, 20, 1)
    assert all(isinstance(v, sympy.Integer) for v in ee)  # exact: 20, not 20.0


def test_exact_numbers_without_length_symbols(paper_robot):
    m2 = symbolic_chain(paper_robot).frame_poses()[1]
    assert m2[2, 3] == 20 and isinstance(m2[2, 3], sympy.Integer)
    assert "20.0" not in str(m2)


@pytest.mark.parametrize("kind", ["none", "Rx", "Ry", "Rz", "Tx", "Ty", "Tz", "fixed"])
def test_module_matrix_equals_core_exactly_after_substitution(kind, rng):
    for _ in range(5):
        q = float(rng.uniform(-3, 3))
        a = tuple(float(v) for v in rng.uniform(-5, 5, 3))
        t = sympy.Symbol("t", real=True)
        symbolic = module_matrix(kind, t, a)
        np.testing.assert_allclose(
            _numeric(symbolic, {t: q}), transfer_matrix(kind, q, a), rtol=0, atol=1e-12
        )


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_dh_factors_product_equals_core(convention, rng):
    for _ in range(5):
        theta, d, a, alpha = (float(v) for v in rng.uniform(-2, 2, 4))
        product = sympy.eye(4)
        for _, m in dh_factors(theta, d, a, alpha, convention):
            product = product * m
        np.testing.assert_allclose(
            np.array(product.evalf(), dtype=float),
            dh_matrix(theta, d, a, alpha, convention),
            atol=1e-12,
        )


def test_dh_standard_matches_paper_eq_10():
    th, d, a, al = sympy.symbols("theta d a alpha", real=True)
    product = sympy.eye(4)
    for _, m in dh_factors(th, d, a, al):
        product = product * m
    c, s, ca, sa = sympy.cos(th), sympy.sin(th), sympy.cos(al), sympy.sin(al)
    eq10 = sympy.Matrix(
        [[c, -s * ca, s * sa, a * c], [s, c * ca, -c * sa, a * s], [0, sa, ca, d], [0, 0, 0, 1]]
    )
    assert sympy.simplify(product - eq10) == sympy.zeros(4, 4)


def test_mixed_robot_chain_equals_core_at_random_configurations(rng):
    robot = Robot(
        [
            Module("Rz", a=(0, 0, 0.4)),
            DHLink(theta=0.3, d=0.2, a=0.5, alpha=np.pi / 2, joint="R"),
            Module("Tx", a=(0.1, 0.2, 0)),
            DHLink(theta=0, d=0.1, a=0.3, alpha=-np.pi / 2, joint="P", convention="modified"),
            Module("fixed", a=(0, 0, 0.05)),
            Module("none"),
            Module("Rx", a=(0.2, 0, 0)),
        ],
        end_effector=(0.1, 0, 0.2),
        active=5,
    )
    chain = symbolic_chain(robot, lengths=True)
    for _ in range(4):
        q = rng.uniform(-2, 2, robot.n)
        values = {
            **chain.values(),
            **dict(zip(chain.q_symbols, (float(v) for v in q), strict=True)),
        }
        for name, symbolic, numeric in (
            ("A", chain.transfer, robot.transfer_matrices(q)),
            ("M", chain.frame_poses(), robot.frame_poses(q)),
        ):
            for i, matrix in enumerate(symbolic):
                np.testing.assert_allclose(
                    _numeric(matrix, values), numeric[i], atol=1e-12, err_msg=f"{name}{i + 1}"
                )
        np.testing.assert_allclose(
            _numeric(chain.end_effector(), values)[:3, 0], robot.end_effector(q), atol=1e-12
        )


def test_given_configuration_is_exact(paper_robot):
    chain = symbolic_chain(paper_robot, q=[np.pi / 2, 0, 0])
    assert chain.q == [sympy.pi / 2, 0, 0]
    assert chain.frame_poses()[0][:3, :3] == sympy.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])


def test_simplify_matrix_folds_angle_sums():
    m = sympy.Matrix([[sympy.cos(q1) * sympy.sin(q2) + sympy.sin(q1) * sympy.cos(q2)]])
    assert simplify_matrix(m)[0, 0] == sympy.sin(q1 + q2)


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        (20.0, sympy.Integer(20)),
        (0.5, sympy.Rational(1, 2)),
        (np.pi / 2, sympy.pi / 2),
        (-np.pi, -sympy.pi),
        (0.0, sympy.Integer(0)),
        (0.4318, sympy.Rational(2159, 5000)),
    ],
)
def test_exact_number(value, expected):
    assert exact_number(value) == expected


def test_exact_number_keeps_awkward_floats_as_floats():
    assert isinstance(exact_number(0.123456789123), sympy.Float)


def test_error_branches():
    with pytest.raises(ValueError, match="value: must be finite"):
        exact_number(float("nan"))
    with pytest.raises(ValueError, match="kind: invalid value 'Rq'"):
        elementary_matrix("Rq", 1)
    with pytest.raises(ValueError, match="kind: unknown movement type 'Rw'"):
        module_matrix("Rw", 0, (0, 0, 0))
    with pytest.raises(ValueError, match="convention: unknown DH convention 'craig'"):
        dh_factors(0, 0, 0, 0, "craig")
    robot = Robot([Module("Rz"), Module("Rz")])
    with pytest.raises(ValueError, match="q: expected shape"):
        symbolic_chain(robot, q=[1, 2, 3])
    with pytest.raises(ValueError, match=r"q: got a trajectory of shape \(2, 2\)"):
        symbolic_chain(robot, q=[[1, 2], [3, 4]])


def test_import_robotconf_stays_numpy_only():
    code = (
        "import sys, robotconf, robotconf.teaching; "
        "assert 'sympy' not in sys.modules, 'sympy imported'; "
        "assert 'pandas' not in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=".")


def test_dh_factor_order_and_joint_parameter_come_from_the_conventions():
    from robotconf.kinematics import (
        DH_CONVENTIONS,
        DH_FACTORS,
        DH_JOINT_PARAMETER,
        DH_LENGTHS,
        MODULE_OFFSETS,
    )

    for convention in DH_CONVENTIONS:
        got = [kind for kind, _ in dh_factors(0, 0, 0, 0, convention)]
        assert got == [kind for kind, _ in DH_FACTORS[convention]]
    assert DH_JOINT_PARAMETER == {"revolute": "theta", "prismatic": "d"}
    assert DH_LENGTHS == ("d", "a")
    assert MODULE_OFFSETS == ("ax", "ay", "az")


@pytest.mark.parametrize("kind", ["Rx", "Ry", "Rz"])
def test_sine_entries_match_the_numpy_kernel(kind):
    from robotconf.kinematics import kind_axis
    from robotconf.teaching import sine_entries

    minus, plus = sine_entries(kind_axis(kind))
    matrix = transfer_matrix(kind, 0.3)
    assert matrix[minus] == pytest.approx(-np.sin(0.3), abs=1e-15)
    assert matrix[plus] == pytest.approx(np.sin(0.3), abs=1e-15)


def test_link_parameters_read_and_replace_by_name():

    module = Module("Ry", a=(1, 2, 3))
    row = DHLink(0.1, 0.2, 0.3, 0.4, "P", "modified", name="j")
    assert module.parameters() == {"ax": 1.0, "ay": 2.0, "az": 3.0}
    assert row.parameters() == {"theta": 0.1, "d": 0.2, "a": 0.3, "alpha": 0.4}
    assert Module("none", a=(1, 0, 0)).length_parameters() == ()
    assert row.length_parameters() == ("d", "a")
    assert module.with_parameters(ay=5.0) == Module("Ry", a=(1, 5, 3))
    assert row.with_parameters(d=0.7) == DHLink(0.1, 0.7, 0.3, 0.4, "P", "modified", name="j")
    with pytest.raises(ValueError, match="d: not a module offset"):
        module.with_parameters(d=1.0)
    with pytest.raises(ValueError, match="ax: not a DH parameter"):
        row.with_parameters(ax=1.0)
