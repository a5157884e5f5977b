"""Per-student variants: the same id gives the same numbers everywhere, ids differ."""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from collections import Counter

import numpy as np
import pytest

import robotconf as rc


def _by_hand(student: str, lesson: str, name: str, count: int) -> int:
    """The documented recipe, written out independently: SHA-256 → 64 bits → index."""
    text = "\0".join(("robotconf-variant-v1", student, lesson, name))
    return int.from_bytes(hashlib.sha256(text.encode()).digest()[:8], "big") % count


def test_values_follow_the_documented_recipe():
    v = rc.Variant("s1234567", "10_paper_lab")
    assert v.length("l1", 15, 30) == 15 + _by_hand("s1234567", "10_paper_lab", "l1", 16)
    choices = [30, 45, 60, 90]
    k = _by_hand("s1234567", "10_paper_lab", "q", 4)
    assert v.angle("q", choices) == pytest.approx(np.radians(choices[k]), abs=0)
    assert (
        v.choice("robot", ["a", "b", "c"])
        == "abc"[_by_hand("s1234567", "10_paper_lab", "robot", 3)]
    )


def test_pinned_numbers_do_not_change_between_releases():
    # An answer key printed last term must still match: these numbers are fixed forever.
    v = rc.Variant("demo", "10_paper_lab")
    assert v.length("l1", 15, 30) == 19.0
    assert v.length("l2", 20, 40, step=5) == 25.0
    assert v.length("A", 1.6, 2.5, step=0.1) == 1.8
    assert v.angle("q", [30, 45, 60, 90]) == np.radians(60)
    assert [rc.Variant(s, "10_paper_lab").length("l1", 15, 30) for s in ("alice", "bob")] == [
        30.0,
        24.0,
    ]


def test_numbers_do_not_depend_on_python_hash_randomization():
    code = (
        "import robotconf as rc; v = rc.Variant('alice', 'x');"
        "print(v.length('l1', 0, 1000), v.choice('c', list(range(97))))"
    )
    here = rc.Variant("alice", "x")
    expected = f"{here.length('l1', 0, 1000)} {here.choice('c', list(range(97)))}"
    env = {**os.environ, "PYTHONHASHSEED": "12345"}
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == expected


def test_each_name_is_independent_of_order_and_of_other_draws():
    a = rc.Variant("bob", "09")
    first = (a.length("l1", 10, 50), a.length("l2", 10, 50))
    b = rc.Variant("bob", "09")
    b.angle("unrelated", [1, 2, 3])
    second = (b.length("l1", 10, 50), b.length("l2", 10, 50))
    c = rc.Variant("bob", "09")
    third = tuple(reversed((c.length("l2", 10, 50), c.length("l1", 10, 50))))
    assert first == second == third


def test_spaces_and_case_of_the_id_do_not_matter_but_the_lesson_does():
    base = rc.Variant("S1234567", "lab").length("l1", 0, 10_000)
    assert rc.Variant("  s1234567 ", "lab").length("l1", 0, 10_000) == base
    assert rc.Variant("s1234567", "lab").student_id == "s1234567"
    assert rc.Variant("s1234567", "other lab").length("l1", 0, 10_000) != base


def test_different_ids_get_different_numbers_spread_evenly():
    values = [rc.Variant(f"student{i}", "lab").length("l", 1, 4) for i in range(4000)]
    counts = Counter(values)
    assert set(counts) == {1.0, 2.0, 3.0, 4.0}
    assert all(abs(n / 4000 - 0.25) < 0.03 for n in counts.values()), counts
    wide = {rc.Variant(f"student{i}", "lab").length("l", 0, 999_999) for i in range(50)}
    assert len(wide) == 50


def test_length_grid_includes_both_ends_and_rounds_steps():
    seen = {rc.Variant(f"id{i}", "lab").length("l", 2.0, 2.3, step=0.1) for i in range(300)}
    assert seen == {2.0, 2.1, 2.2, 2.3}
    assert rc.Variant("x", "lab").length("l", 30, 30) == 30.0
    assert rc.Variant("x", "lab").length("l", 1, 2.5, step=1) in (1.0, 2.0)


def test_angle_is_in_radians_and_choice_returns_items():
    degrees = {
        round(float(np.degrees(rc.Variant(f"id{i}", "lab").angle("q", [30, 45]))), 9)
        for i in range(100)
    }
    assert degrees == {30.0, 45.0}
    table = [(0, 2), (0, 3)]
    assert rc.Variant("x", "lab").choice("t", table) in table


def test_drawn_lists_everything_as_returned_and_is_a_copy():
    v = rc.Variant("demo", "lab")
    l1 = v.length("l1", 10, 20)
    q = v.angle("q", [90])
    assert v.choice("c", ["only"]) == "only"
    assert v.drawn == {"l1": l1, "q": np.pi / 2, "c": "only"}
    assert q == np.pi / 2
    v.drawn["l1"] = -1
    assert v.drawn["l1"] == l1
    assert "demo" in repr(v) and "lab" in repr(v)


def test_drawing_a_name_again_gives_the_same_value_or_refuses_another_range():
    v = rc.Variant("demo", "lab")
    assert v.length("l1", 10, 20) == v.length("l1", 10, 20)
    with pytest.raises(rc.InvalidInputError, match="already drawn with another range") as info:
        v.length("l1", 10, 30)
    assert info.value.field == "name"


@pytest.mark.parametrize(
    ("student_id", "problem"),
    [
        ("", "empty"),
        ("   ", "empty"),
        ("x" * 65, "65 characters"),
        ("ab\ncd", "control character"),
        ("ab\x00", "control character"),
        (12345, "not text"),
        (None, "not text"),
    ],
)
def test_bad_student_ids_are_refused_naming_the_field(student_id, problem):
    with pytest.raises(rc.InvalidInputError, match=problem) as info:
        rc.Variant(student_id, "lab")
    assert info.value.field == "student_id"


def test_longest_id_and_unicode_ids_are_fine():
    assert rc.Variant("x" * 64, "lab").student_id == "x" * 64
    assert rc.Variant("Žofia Müller", "lab").length("l", 0, 9) in range(10)
    with pytest.raises(rc.InvalidInputError) as info:
        rc.Variant("demo", "")
    assert info.value.field == "lesson"


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda v: v.length("l", 5, 1), "hi"),
        (lambda v: v.length("l", 0, 1, step=0), "step"),
        (lambda v: v.length("l", 0, 1, step=-1), "step"),
        (lambda v: v.length("l", 0, 1e9, step=1), "step"),
        (lambda v: v.length("l", float("nan"), 1), "lo"),
        (lambda v: v.angle("q", []), "choices_deg"),
        (lambda v: v.angle("q", [30, "45"]), "choices_deg[1]"),
        (lambda v: v.choice("c", "abc"), "seq"),
        (lambda v: v.length("", 0, 1), "name"),
    ],
)
def test_bad_ranges_are_refused(call, field):
    with pytest.raises(rc.InvalidInputError) as info:
        call(rc.Variant("demo", "lab"))
    assert info.value.field == field


def test_generator_is_seeded_from_the_id():
    def draw(student):
        return rc.Variant(student, "lab").generator("q").uniform(size=4)

    assert np.array_equal(draw("a"), draw("A "))
    assert not np.array_equal(draw("a"), draw("b"))
