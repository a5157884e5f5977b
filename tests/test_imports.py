"""``import robotconf`` pulls in numpy only: the core must import fast and without a front end."""

import subprocess
import sys

HEAVY = ("pandas", "sympy", "matplotlib", "ipywidgets", "meshcat", "IPython", "anywidget", "scipy")


def test_import_loads_no_presentation_or_heavy_libraries():
    code = (
        "import sys, robotconf\n"
        f"heavy = {HEAVY!r}\n"
        "print(','.join(sorted(m for m in heavy if m in sys.modules)))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=60
    )
    assert result.stdout.strip() == "", f"import robotconf loaded: {result.stdout.strip()}"
