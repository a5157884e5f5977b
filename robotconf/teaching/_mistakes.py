"""The usual mistakes in hand-derived kinematics, rebuilt as "wrong answers" to compare with.

Each :class:`Candidate` is what a student would have written after making one specific
mistake, evaluated at the same sample points as the expected matrix, together with the
sentence that explains the mistake. The checker recognises a mistake when the student's
wrong entries agree with a candidate.

Context-aware candidates need the robot and the matrix name (an
:class:`~robotconf.teaching.ExpectedMatrix` from ``expected_matrix`` or a derivation
step): wrong rotation direction of one module, offset after the rotation, a missing
offset or end-effector point, the other DH convention, degrees read as radians (and the
reverse), multiplication in the wrong order, and for a DH row the twist α with the wrong
sign or d and a swapped. Context-free candidates work on any matrix: transposed matrix,
two rows or two columns swapped, and, when the expected matrix is a rotation or a
homogeneous transform (see :func:`is_rotation_like`), a transposed rotation part.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..kinematics import (
    AXIS_NAMES,
    DH_CONVENTIONS,
    DH_PARAMETERS,
    DH_SYMBOLS,
    DHLink,
    Module,
    dh_formula,
)
from ._expected import ExpectedMatrix
from ._symbolic import sine_entries

__all__ = [
    "Candidate",
    "context_candidates",
    "generic_candidates",
    "is_rotation_like",
    "ROTATION_PATTERN",
]


def _sine_pattern(axis: int) -> str:
    minus, plus = sine_entries(axis)
    entries = sorted([(minus, "−sin"), (plus, "+sin")])
    return " and ".join(f"{sign} in entry ({r + 1},{c + 1})" for (r, c), sign in entries)


#: Where the sines sit in an elementary rotation (1-based entries), for the hints.
ROTATION_PATTERN = {axis: _sine_pattern(k) for k, axis in enumerate(AXIS_NAMES)}
#: Link mistakes reported under a shared code.
_MISTAKE_CODES = {
    "missing_d": "missing_offset",
    "missing_a": "missing_offset",
    "alpha_sign": "sign_error",
}


@dataclass(frozen=True)
class Candidate:
    """A wrong answer produced by one mistake.

    Attributes
    ----------
    code : str
        Mistake identifier, e.g. ``"wrong_order"``, ``"rotation_direction"``.
    message : str
        A sentence a student can act on (without the entry list).
    values : ndarray, shape (K, rows, cols)
        The wrong answer at the K sample points.
    """

    code: str
    message: str
    values: np.ndarray


def _fmt(value: float) -> str:
    from ._formatting import format_number

    return format_number(value, 4)


def _vector(values: tuple[float, ...]) -> str:
    return "(" + ", ".join(_fmt(v) for v in values) + ")"


def _translation(a: tuple[float, float, float]) -> np.ndarray:
    matrix = np.eye(4)
    matrix[:3, 3] = a
    return matrix


def _link_mistakes(link: Any) -> list[str]:
    revolute = link.joint_type == "revolute"
    # A module and a DH row invite different mistakes (an offset vs. the four parameters).
    if isinstance(link, Module):
        found = []
        if revolute:
            found.append("rotation_direction")
            if any(link.a):
                found.append("offset_after_rotation")
        if link.kind != "none" and any(link.a):
            found.append("missing_offset")
        return found
    found = ["rotation_direction"] if revolute else []
    found += ["missing_d"] if link.d != 0 else []
    found += ["missing_a"] if link.a != 0 else []
    found += ["alpha_sign"] if link.alpha != 0 else []
    found += ["swapped_d_a"] if revolute and link.d != link.a else []
    return found


def _other_convention(convention: str) -> str:
    return next(other for other in DH_CONVENTIONS if other != convention)


def _link_matrix(
    link: Any, q: float, mistake: str | None, units: str | None, convert_q: bool
) -> np.ndarray:
    """A link's numeric matrix at ``q`` as it comes out with ``mistake`` made.

    ``units`` (``"degrees"``/``"radians"``) reinterprets the constant DH angles and, when
    ``convert_q`` (a numeric configuration), the joint angle.
    """
    to_units = {"degrees": math.degrees, "radians": math.radians}.get(units or "")
    revolute = link.joint_type == "revolute"
    if to_units is not None and convert_q and revolute:
        q = to_units(q)
    if isinstance(link, Module):
        if mistake == "rotation_direction":
            return link.matrix(-q)
        if mistake == "missing_offset":
            return link.with_a((0.0, 0.0, 0.0)).matrix(q)
        if mistake == "offset_after_rotation":
            return link.with_a((0.0, 0.0, 0.0)).matrix(q) @ _translation(link.a)
        return link.matrix(q)
    changes: dict[str, Any] = {}
    if to_units is not None:
        changes["theta"], changes["alpha"] = to_units(link.theta), to_units(link.alpha)
    if mistake == "rotation_direction":
        changes["theta"] = -changes.get("theta", link.theta)
        q = -q
    if mistake == "missing_d":
        changes["d"] = 0.0
    if mistake == "missing_a":
        changes["a"] = 0.0
    if mistake == "alpha_sign":
        changes["alpha"] = -changes.get("alpha", link.alpha)
    if mistake == "swapped_d_a":
        changes["d"], changes["a"] = link.a, link.d
    if mistake == "convention":
        changes["convention"] = _other_convention(link.convention)
    return dataclasses.replace(link, **changes).matrix(q) if changes else link.matrix(q)


def _mistake_message(code: str, j: int, link: Any) -> str:
    label = f"A{j} (module M{j}"
    if isinstance(link, Module):
        label += f", {link.kind} with a = {_vector(link.a)})"
    else:
        row = ", ".join(f"{DH_SYMBOLS[name]}={_fmt(getattr(link, name))}" for name in DH_PARAMETERS)
        label += f", DH row {row})"
    if code == "rotation_direction":
        axis = link.axis
        return (
            f"The sine terms of {label} have the wrong sign, so the joint turns the wrong way: "
            f"a positive rotation about {axis} has {ROTATION_PATTERN[axis]}."
        )
    if code == "offset_after_rotation":
        return (
            f"In {label} the offset is applied after the rotation (Rot·Trans) instead of "
            "before it (Trans·Rot): a module first moves its origin by a in the parent frame, "
            "then rotates, so the last column of its matrix is just (ax, ay, az)."
        )
    if code == "missing_offset":
        return (
            f"The offset of {label} is missing: every module first translates by its "
            "a = (ax, ay, az) in the parent frame — put it in the last column of its matrix."
        )
    if code == "missing_d":
        return f"The link offset d of {label} is missing: Tz(d) moves along z by d."
    if code == "alpha_sign":
        return (
            f"The twist α of {label} has the wrong sign: α is the angle from the old z axis "
            "to the new one, measured about x by the right-hand rule, and Rx(α) has −sin α "
            "in entry (2,3) and +sin α in entry (3,2)."
        )
    if code == "swapped_d_a":
        return (
            f"The link offset d and the link length a of {label} are swapped: d is the "
            "distance along z (Tz(d)), a the distance along x (Tx(a))."
        )
    return f"The link length a of {label} is missing: Tx(a) moves along x by a."


class _Context:
    """Numeric robot variants at the sample points."""

    def __init__(self, expected: ExpectedMatrix, env: dict[str, np.ndarray], k: int) -> None:
        robot = expected.robot
        assert robot is not None
        self.robot = robot
        self.k = k
        self.expected = expected
        self.robots = [robot] * k
        if expected.lengths:
            from ._symbolic_chain import symbolic_chain

            places = symbolic_chain(robot, lengths=True, simplify=False).length_places
            self.robots = [self._with_lengths(places, env, i) for i in range(k)]
        if expected.q is not None:
            self.q = np.tile(np.asarray(expected.q, dtype=float), (k, 1))
        else:
            self.q = np.column_stack([env[name] for name in robot.coordinate_names])

    def _with_lengths(self, places: list, env: dict, i: int) -> Any:
        robot = self.robot
        labels = list(robot.module_names)
        links = list(robot.modules)
        point = list(robot.end_effector_point)
        for label, name, symbol in places:
            if symbol.name not in env:  # a length this matrix does not depend on
                continue
            value = float(env[symbol.name][i])
            if label == "EE":  # the point's coordinates are named Px, Py, Pz
                point[AXIS_NAMES.index(name[1])] = value
                continue
            j = labels.index(label)
            links[j] = links[j].with_parameters(**{name: value})
        return type(robot)(links, end_effector=point, active=robot.active, name=robot.name)

    def chain(self, i: int, mistakes: dict[int, str], units: str | None) -> list[np.ndarray]:
        """Transfer matrices of all modules at point i, with mistakes by module index."""
        robot = self.robots[i]
        out = []
        for j, link in enumerate(robot.modules):
            if j >= robot.active:
                out.append(np.eye(4))
            else:
                convert = self.expected.q is not None
                out.append(_link_matrix(link, float(self.q[i, j]), mistakes.get(j), units, convert))
        return out

    def value(
        self,
        mistakes: dict[int, str] | None = None,
        units: str | None = None,
        reverse: bool = False,
        drop_point: bool = False,
    ) -> np.ndarray:
        """The expected step's value with the given mistakes, shape (K, rows, cols)."""
        name = self.expected.name
        assert name is not None
        results = []
        for i in range(self.k):
            matrices = self.chain(i, mistakes or {}, units)
            if name.startswith("A"):
                results.append(matrices[int(name[1:]) - 1])
                continue
            count = len(matrices) if name == "p_EE" else int(name[1:])
            used = matrices[:count][::-1] if reverse else matrices[:count]
            pose = np.eye(4)
            for matrix in used:
                pose = pose @ matrix
            if name == "p_EE":
                point = np.zeros(3) if drop_point else self.robots[i].end_effector_point
                pose = (pose @ np.append(point, 1.0))[:, np.newaxis]
            results.append(pose)
        return np.array(results)


def context_candidates(
    expected: ExpectedMatrix, env: dict[str, np.ndarray], k: int
) -> list[Candidate]:
    """Wrong answers from the mistakes that need to know the robot and the matrix.

    Parameters
    ----------
    expected : ExpectedMatrix
        With robot and name.
    env : dict of str to ndarray, shape (K,)
        Sample values of the symbols.
    k : int
        Number of sample points.

    Returns
    -------
    list of Candidate
    """
    if not expected.has_context:
        return []
    context = _Context(expected, env, k)
    robot = context.robot
    name = expected.name
    assert name is not None
    index = expected.index or 1
    last = index if name.startswith(("A", "M")) else robot.n
    first = index if name.startswith("A") else 1
    candidates = []
    for j in range(first - 1, min(last, robot.active)):
        link = robot.modules[j]
        for mistake in _link_mistakes(link):
            message = _mistake_message(mistake, j + 1, link)
            code = _MISTAKE_CODES.get(mistake, mistake)
            candidates.append(Candidate(code, message, context.value({j: mistake})))
    dh_links = [j for j in range(first - 1, last) if isinstance(robot.modules[j], DHLink)]
    if dh_links:
        convention = robot.modules[dh_links[0]].convention  # type: ignore[attr-defined]
        other = _other_convention(convention)
        message = (
            f"You used the {other} DH convention ({dh_formula(other)}) but this table is "
            f"{convention} DH ({dh_formula(convention)}); multiply the four factors in that "
            "order."
        )
        mistakes = {j: "convention" for j in dh_links}
        candidates.append(Candidate("dh_convention", message, context.value(mistakes)))
    has_revolute = any(robot.modules[j].joint_type == "revolute" for j in range(last))
    if has_revolute and (expected.q is not None or dh_links):
        message = (
            "Your numbers are what you get with angles in degrees fed to sin and cos as if "
            "they were radians (calculator in radian mode). Convert first: "
            "radians = degrees × π/180."
        )
        candidates.append(Candidate("degrees_as_radians", message, context.value(units="degrees")))
    if has_revolute and expected.q is not None:
        message = (
            "Your numbers are what you get with a calculator in degree mode: the angles here "
            "are in radians, so switch it to radian mode (or convert: degrees = rad × 180/π)."
        )
        candidates.append(Candidate("radians_as_degrees", message, context.value(units="radians")))
    if name.startswith("M") and index >= 2 or name == "p_EE" and robot.n >= 2:
        count = index if name.startswith("M") else robot.n
        wrong, right = ("A2·A1", "A1·A2") if count == 2 else (f"A{count}·…·A1", f"A1·…·A{count}")
        message = (
            f"You multiplied in the wrong order ({wrong} instead of {right}): "
            "M_i = M_(i-1)·A_i — each new transfer matrix goes on the right, because it is "
            "written in the frame of the module before it."
        )
        candidates.append(Candidate("wrong_order", message, context.value(reverse=True)))
    if name == "p_EE" and any(robot.end_effector_point):
        message = (
            f"The end-effector point P = {_vector(tuple(robot.end_effector_point))} is "
            f"missing: p_EE = M{robot.n}·[Px, Py, Pz, 1]ᵀ, not the origin of the last frame."
        )
        candidates.append(Candidate("missing_offset", message, context.value(drop_point=True)))
    return candidates


def is_rotation_like(values: np.ndarray, tol: float = 1e-3) -> bool:
    """Whether a matrix is a rotation (3×3) or a homogeneous transform (4×4).

    Parameters
    ----------
    values : ndarray, shape (K, rows, cols)
        The matrix at the K sample points.
    tol : float
        Absolute tolerance of ``RᵀR = I`` (and of the bottom row ``(0, 0, 0, 1)``).

    Returns
    -------
    bool
        True when the top-left 3×3 block is orthonormal at every point and, for a 4×4
        matrix, the bottom row is ``(0, 0, 0, 1)``.

    Examples
    --------
    >>> is_rotation_like(np.eye(4)[np.newaxis]), is_rotation_like(np.ones((1, 3, 3)))
    (True, False)
    """
    shape = values.shape[1:]
    if shape not in ((3, 3), (4, 4)) or not np.all(np.isfinite(values)):
        return False
    block = values[:, :3, :3]
    gram = np.swapaxes(block, 1, 2) @ block
    if not np.allclose(gram, np.eye(3), atol=tol, rtol=0.0):
        return False
    return shape == (3, 3) or bool(np.allclose(values[:, 3, :], [0, 0, 0, 1], atol=tol, rtol=0.0))


def generic_candidates(values: np.ndarray) -> list[Candidate]:
    """Wrong answers that any matrix allows: transposes and swapped rows or columns.

    Parameters
    ----------
    values : ndarray, shape (K, rows, cols)
        The expected matrix at the sample points.

    Returns
    -------
    list of Candidate
        A transposed rotation part only for a rotation or homogeneous transform (its
        wording speaks of frame axes), a transposed matrix only for a square one (a
        non-square one has another shape when transposed: see the checker's shape hint).
    """
    _, rows, cols = values.shape
    candidates = []
    rotation = is_rotation_like(values)
    if rotation:
        wrong = values.copy()
        wrong[:, :3, :3] = np.swapaxes(values[:, :3, :3], 1, 2)
        message = (
            "The rotation part (rows 1–3, columns 1–3) is transposed: each column of the "
            "rotation part is an axis of the new frame written in the old frame — write the "
            "axes as columns, not as rows."
        )
        candidates.append(Candidate("transposed_rotation", message, wrong))
    if rows == cols and rows >= 2:
        transposed = np.swapaxes(values, 1, 2)
        if not (candidates and np.allclose(candidates[0].values, transposed)):
            message = (
                "The whole matrix is transposed (yours is the transpose of the expected "
                "one): write each row as a row, not as a column."
            )
            if rotation and rows == 4:
                message = (
                    "The whole matrix is transposed: the translation belongs in the last "
                    "column and the row (0, 0, 0, 1) at the bottom."
                )
            candidates.append(Candidate("transposed_matrix", message, transposed))
    for axis, word in ((1, "Rows"), (2, "Columns")):
        size = values.shape[axis]
        for a in range(size):
            for b in range(a + 1, size):
                order = list(range(size))
                order[a], order[b] = b, a
                wrong = values[:, order, :] if axis == 1 else values[:, :, order]
                message = (
                    f"{word} {a + 1} and {b + 1} are swapped: check which "
                    f"{'coordinate (x, y, z) each row' if axis == 1 else 'axis each column'}"
                    " stands for."
                )
                candidates.append(Candidate(f"{word[:-1].lower()}_swap", message, wrong))
    return candidates
