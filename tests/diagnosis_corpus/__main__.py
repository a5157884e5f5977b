"""``python -m tests.diagnosis_corpus``: print the tables (Markdown).

In-sample (written while the diagnoses were built) and held-out (written afterwards,
without reading the diagnosis code) separately, per family and per lesson group.
``--failures`` also lists every case whose outcome is not the expected one.
"""

from __future__ import annotations

import sys

from . import CASES
from .measure import family_table, format_table, judge, lesson_group, primary_rate


def _summary(title: str, outcomes: list) -> str:
    wrong = [o for o in outcomes if not o.case.ok]
    accepts = sum(o.grade == "false accept" for o in outcomes)
    rejects = sum(o.grade == "false reject" for o in outcomes)
    return (
        f"{title}: {len(outcomes)} answers ({len(outcomes) - len(wrong)} right, {len(wrong)} "
        f"wrong): right primary diagnosis for {primary_rate(outcomes):.1%} of the wrong ones; "
        f"{accepts} false accepts, {rejects} false rejects"
    )


def main(argv: list[str]) -> int:
    outcomes = [judge(case) for case in CASES]
    for split in ("in-sample", "held-out"):
        chosen = [o for o in outcomes if o.case.split == split]
        print(f"## {split}\n")
        print(format_table(family_table(chosen)))
        print()
        for group in ("lessons 1–8", "lessons 9–12"):
            part = [o for o in chosen if lesson_group(o.case) == group]
            if part:
                print("- " + _summary(f"{split}, {group}", part))
        print()
    print(_summary("all", outcomes))
    if "--failures" in argv:
        for o in outcomes:
            if o.grade != "right":
                print(f"\n{o.grade}: {o.case.id}: expected {o.case.diagnosis}, got {o.diagnosis}")
                for hint in o.hints:
                    print(f"  - {hint}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
