"""The verdict on an inverse-kinematics answer: an :class:`AnswerCheck` that also says
where the answer's end effector lands and which solution branch it is."""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from typing import Any

from ..checks._result import AnswerCheck, explains_all

__all__ = ["IKCheck", "IK_DIAGNOSES", "verdict"]

#: Every diagnosis code an :class:`IKCheck` may carry, with what it means.
IK_DIAGNOSES = {
    "no_answer": "the answer is still None",
    "not_a_number": "the answer holds symbols (q1, l2, …) where numbers are asked",
    "too_complicated": "an entry is too large for the checker to evaluate",
    "shape": "the wrong number of joint values (or several solutions where one is asked)",
    "too_rounded": "a solution rounded to too few digits to reach the target",
    "degrees_as_radians": "joint angles in degrees where radians are asked",
    "atan_quadrant": "a joint angle off by half a turn: atan(y/x) where atan2(y, x) was needed",
    "cosine_law_sign": "the elbow's cosine-law sign slipped: q1 and q2 from different "
    "branches, or the inner angle of the elbow triangle taken for the joint angle",
    "sign_error": "the first joint turned the wrong way",
    "wrong_target": "a solution for another target (coordinates swapped or a sign changed)",
    "outside_limits": "a solution outside the joint ranges, where they matter",
    "duplicate": "one solution of a set given twice (or a whole turn away)",
    "missing": "solutions of a set left out (named by their branch, e.g. elbow up)",
    "wrong": "does not reach the target, with no recognised mistake",
}


@dataclass(frozen=True, eq=False)
class IKCheck(AnswerCheck):
    """The verdict of :func:`check_ik_solution` or :func:`check_ik_solutions`.

    Everything of :class:`AnswerCheck` (``ok``, ``hints``, ``diagnosis`` from
    :data:`IK_DIAGNOSES`, ``name``, ``headline``…), and:

    Attributes
    ----------
    student : ndarray or None
        The answer's joint values: shape (n,) for one solution, (k, n) for a set.
    expected : ndarray
        The target the answer is judged against: a point (3,) or a pose (4, 4).
    reached : ndarray or None
        Where the answer's end effector lands: (3,), or (k, 3) for a set.
    branches : tuple of str
        The closed-form branch (``"elbow up"``) each solution of the answer is, ``""``
        where it is none or the robot has no closed form.
    notes : list of str
        Remarks on a right answer (a solution outside the joint ranges); shown after
        "correct".

    Examples
    --------
    >>> import robotconf as rc
    >>> result = rc.check_ik_solution([0, "pi/2"], rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0])
    >>> result.ok, result.branches, result.reached.round(6) + 0.0
    (True, ('elbow down',), array([1., 1., 0.]))
    """

    reached: Any = None
    branches: tuple[str, ...] = ()
    notes: list[str] = field(default_factory=list)

    def __str__(self) -> str:
        text = super().__str__()
        if self.ok and self.notes:
            text += "".join(f"\n- {note}" for note in self.notes)
        return text

    def __repr__(self) -> str:
        return f"<IKCheck ok={self.ok} diagnosis={self.diagnosis!r}>"

    def _repr_html_(self) -> str:
        text = super()._repr_html_()
        if self.ok and self.notes:
            items = "".join(f"<li>{html.escape(note)}</li>" for note in self.notes)
            text = text[: -len("</div>")] + f"<ul>{items}</ul></div>"
        return text


def verdict(
    hints: list[str],
    codes: list[str],
    name: str,
    student: Any,
    expected: Any,
    hint: str | None,
    **more: Any,
) -> IKCheck:
    """An :class:`IKCheck`: right when there are no hints; else the first code is the
    diagnosis and the exercise's own ``hint`` follows the others (not for "no answer")."""
    if not hints:
        return IKCheck(True, [], None, name, student, expected, **more)
    if hint and codes[:1] != ["no_answer"]:
        hints = [*hints, hint]
    more.setdefault("complete", explains_all(codes))
    return IKCheck(False, hints, codes[0], name, student, expected, **more)
