"""Modules: the paper's seven movement types (docs/conventions.md) plus ``fixed``."""

import numpy as np
import pytest

import robotconf as rc

from .conftest import assert_transform_close, reference_matrix

KINDS = ["none", "Rx", "Ry", "Rz", "Tx", "Ty", "Tz", "fixed"]
Q_VALUES = [0.0, 0.7, -1.3, np.pi / 2, np.pi, 2.5, -7.0]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("q", Q_VALUES)
def test_matrix_matches_design_table(kind, q):
    a = (1.5, -2.0, 3.25)
    assert_transform_close(rc.transfer_matrix(kind, q, a), reference_matrix(kind, q, a))
    assert_transform_close(rc.Module(kind, a=a, q=q).matrix(), reference_matrix(kind, q, a))


@pytest.mark.parametrize("kind", KINDS)
def test_matrix_batched_over_q(kind, rng):
    a = (0.5, 0.25, -1.0)
    q = rng.uniform(-4, 4, 37)
    batch = rc.Module(kind, a=a).matrix(q)
    assert batch.shape == (37, 4, 4)
    for sample, value in zip(batch, q, strict=True):
        assert_transform_close(sample, reference_matrix(kind, value, a))


def test_rotation_by_quarter_turn_by_hand():
    # Rz(90°) sends x to y and y to -x, then the offset is added.
    assert_transform_close(
        rc.transfer_matrix("Rz", np.pi / 2, (1, 2, 3)),
        [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]],
    )
    # Rx(90°) sends y to z and z to -y.
    assert_transform_close(
        rc.transfer_matrix("Rx", np.pi / 2),
        [[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
    )


@pytest.mark.parametrize(
    ("given", "name", "code"),
    [
        (0, "none", 0),
        (1, "Rx", 1),
        (2, "Ry", 2),
        (3, "Rz", 3),
        (4, "Tx", 4),
        (5, "Ty", 5),
        (6, "Tz", 6),
        ("rz", "Rz", 3),
        ("TZ", "Tz", 6),
        (" Ry ", "Ry", 2),
        ("null", "none", 0),
        ("Fixed", "fixed", None),
        (np.int64(4), "Tx", 4),
    ],
)
def test_kind_names_and_paper_codes(given, name, code):
    module = rc.Module(given)
    assert module.kind == name
    assert module.code == code


@pytest.mark.parametrize(
    ("kind", "joint_type", "axis", "unit"),
    [
        ("none", "none", None, ""),
        ("fixed", "fixed", None, ""),
        ("Rx", "revolute", "x", "rad"),
        ("Ry", "revolute", "y", "rad"),
        ("Tz", "prismatic", "z", "length"),
    ],
)
def test_joint_description(kind, joint_type, axis, unit):
    module = rc.Module(kind)
    assert (module.joint_type, module.axis, module.unit) == (joint_type, axis, unit)
    assert module.is_joint == (joint_type in ("revolute", "prismatic"))


@pytest.mark.parametrize(
    "module",
    [
        rc.Module("Rz"),
        rc.Module("Ry", a=(0, 0, 20)),
        rc.Module("Tx", a=(1e-17, -0.1, 3), q=0.125, name="slide"),
        rc.Module("fixed", a=(0.1, 0.2, 0.3)),
    ],
)
def test_repr_round_trips(module):
    assert eval(repr(module), {"Module": rc.Module}) == module


def test_repr_is_short_for_defaults():
    assert repr(rc.Module(3)) == "Module('Rz')"
    assert repr(rc.Module("ry", a=(0, 0, 20))) == "Module('Ry', a=(0.0, 0.0, 20.0))"


def test_modules_are_immutable_and_hashable():
    module = rc.Module("Rz", q=0.5)
    with pytest.raises(AttributeError):
        module.q = 1.0  # type: ignore[misc]
    assert module.with_q(1.0).q == 1.0 and module.q == 0.5
    assert module.with_a((1, 2, 3)).a == (1.0, 2.0, 3.0)
    assert module.with_kind("Tx").kind == "Tx"
    assert module.with_name("base").name == "base"
    assert len({module, rc.Module("Rz", q=0.5), rc.Module("Rz")}) == 2


@pytest.mark.parametrize("kind", ["Rx", "Ry", "Rz", "Tx", "Ty", "Tz"])
@pytest.mark.parametrize("order", [1, 2, 3])
def test_matrix_derivative_matches_finite_differences(kind, order):
    module = rc.Module(kind, a=(0.3, -0.2, 0.9))
    q, h = 0.4, 1e-3
    # Central differences of the (order-1)-th derivative: error O(h²).
    if order == 1:
        numeric = (module.matrix(q + h) - module.matrix(q - h)) / (2 * h)
    else:
        lower = order - 1
        numeric = (
            module.matrix_derivative(q + h, lower) - module.matrix_derivative(q - h, lower)
        ) / (2 * h)
    np.testing.assert_allclose(module.matrix_derivative(q, order), numeric, atol=1e-6)


def test_matrix_derivative_by_hand():
    # d/dq Rz(q) at q = 0 is the generator [[0, -1, 0], [1, 0, 0], [0, 0, 0]], no translation.
    expected = np.zeros((4, 4))
    expected[0, 1], expected[1, 0] = -1, 1
    np.testing.assert_allclose(rc.Module("Rz", a=(5, 5, 5)).matrix_derivative(0.0), expected)
    # A prismatic joint moves at unit speed along its axis; its second derivative is zero.
    slide = rc.Module("Ty", a=(1, 2, 3))
    np.testing.assert_array_equal(slide.matrix_derivative(0.7)[:3, 3], [0, 1, 0])
    np.testing.assert_array_equal(slide.matrix_derivative(0.7, order=2), np.zeros((4, 4)))
    np.testing.assert_array_equal(rc.Module("fixed", a=(1, 2, 3)).matrix_derivative(), 0)
