"""The README's Python examples run and print what their comments claim."""

import pathlib
import re

import numpy as np

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"


def python_blocks() -> list[str]:
    return re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)


def test_readme_quickstart_runs_and_matches_the_paper():
    blocks = python_blocks()
    assert blocks, "README.md has no python example"
    namespace: dict = {}
    # The README is our own file in this repository, not user input.
    exec(compile(blocks[0], str(README), "exec"), namespace)  # noqa: S102
    robot = namespace["robot"]
    np.testing.assert_array_equal(
        robot.frame_origins([0, 0, 0]), [[0, 0, 0], [0, 0, 20], [30, 0, 20]]
    )
    np.testing.assert_array_equal(robot.end_effector([0, 0, 0]), [70, 0, 20])


def test_readme_motion_and_checker_examples_run(tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    for block in python_blocks()[:2]:
        exec(compile(block, str(README), "exec"), namespace)  # noqa: S102
    motion = namespace["motion"]
    z = motion.table[("EE", "position", "z")].to_numpy()
    q3 = motion.q[:, 2]
    np.testing.assert_allclose(z, 20 - 40 * np.sin(q3), atol=1e-9)


def test_readme_shows_the_two_commands():
    text = README.read_text(encoding="utf-8")
    assert "make lab" in text and "make test" in text


def test_readme_scene_and_library_examples_run(tmp_path, monkeypatch):
    import matplotlib

    import robotconf as rc

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    for block in python_blocks()[:4]:
        exec(compile(block, str(README), "exec"), namespace)  # noqa: S102
    scene = namespace["scene"]
    assert scene.labels()[-1] == rc.format_point("EE", namespace["robot"].end_effector(scene.q))
    assert (tmp_path / "robot.html").stat().st_size > 800_000
    assert rc.load(tmp_path / "ur5.json") == namespace["ur5"]
    assert namespace["ws"].points.shape == (100_000, 3)
    assert "<robot" in namespace["urdf"]
