"""A robotconf figure is a picture in a fresh notebook kernel, not ``<Figure size …>``."""

import os

import nbclient
import nbformat


def test_plot_robot_displays_as_png_in_a_fresh_kernel(tmp_path, monkeypatch):
    # The kernel's own default backend (inline), as a student's JupyterLab has it.
    monkeypatch.delenv("MPLBACKEND", raising=False)
    notebook = nbformat.v4.new_notebook()
    notebook.cells = [
        nbformat.v4.new_code_cell("import robotconf as rc\nrc.plot_robot(rc.preset('paper'))")
    ]
    nbclient.NotebookClient(notebook, kernel_name="python3", timeout=120).execute(cwd=str(tmp_path))
    outputs = notebook.cells[0].outputs
    assert any("image/png" in output.get("data", {}) for output in outputs), outputs
    assert "MPLBACKEND" not in os.environ
