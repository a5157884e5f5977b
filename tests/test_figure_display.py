"""A robotconf figure is a picture in a fresh notebook kernel, not ``<Figure size …>``."""

import os

import nbclient
import nbformat
import pytest

FIGURES = {
    "plot_robot": "rc.plot_robot(robot)",
    "plot_coordinates": "rc.plot_coordinates(motion)",
    "Motion.plot": "motion.plot('EE')",
    "Workspace.plot": "rc.workspace(robot, 2000, seed=1, progress=False).plot()",
}


@pytest.fixture(scope="module")
def executed_cells() -> dict[str, list]:
    # The kernel's own default backend (inline), as a student's JupyterLab has it.
    saved = os.environ.pop("MPLBACKEND", None)
    try:
        notebook = nbformat.v4.new_notebook()
        setup = (
            "import robotconf as rc\n"
            "robot = rc.preset('paper')\n"
            "motion = rc.simulate(robot, {'q3': rc.signals.RepeatingSequence()}, t_end=4.0)"
        )
        notebook.cells = [nbformat.v4.new_code_cell(setup)] + [
            nbformat.v4.new_code_cell(code) for code in FIGURES.values()
        ]
        nbclient.NotebookClient(notebook, kernel_name="python3", timeout=120).execute()
    finally:
        if saved is not None:
            os.environ["MPLBACKEND"] = saved
    return {name: cell.outputs for name, cell in zip(FIGURES, notebook.cells[1:], strict=True)}


@pytest.mark.parametrize("name", list(FIGURES))
def test_each_figure_displays_as_png_in_a_fresh_kernel(executed_cells, name):
    outputs = executed_cells[name]
    # A bare Figure without inline support shows only its text/plain "<Figure size …>".
    assert any("image/png" in output.get("data", {}) for output in outputs), outputs
