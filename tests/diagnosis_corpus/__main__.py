"""``python -m tests.diagnosis_corpus``: print the per-family table (Markdown).

``--failures`` also lists every case whose outcome is not the expected one.
"""

from __future__ import annotations

import sys

from . import CASES
from .measure import family_table, format_table, judge, primary_rate


def main(argv: list[str]) -> int:
    outcomes = [judge(case) for case in CASES]
    print(format_table(family_table(outcomes)))
    wrong = [o for o in outcomes if not o.case.ok]
    print(
        f"\nprimary diagnosis right for {primary_rate(outcomes):.1%} of {len(wrong)} wrong answers"
    )
    if "--failures" in argv:
        for o in outcomes:
            if o.grade != "right":
                print(f"\n{o.grade}: {o.case.id}: expected {o.case.diagnosis}, got {o.diagnosis}")
                for hint in o.hints:
                    print(f"  - {hint}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
