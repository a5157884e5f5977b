"""The scene draws snapshots: ``show(robot.at(q))`` without a kernel pass of its own, and
a scene made of small parts that only know the scene's outbox."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics.kernel import _kernel
from robotconf.kinematics.robot import _snapshot
from robotconf.scene import ROOT, RecordingChannel, RobotDrawing, Scene

ROBOT_PATH = f"{ROOT}/robot"
SCENE = Path(rc.__file__).parent / "scene"
#: The scene's parts: each is given the scene's outbox (and callables), nothing else.
PARTS = {
    "_robot_layer.py": "RobotLayer",
    "_ghosts.py": "GhostsLayer",
    "_target.py": "TargetMarker",
    "_taught_points.py": "TaughtPointsLayer",
    "_playback.py": "Playback",
    "_points.py": "PointClouds",
}


def _wire(ops, path: str) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The last matrix sent for ``path`` (4×4, as float32 on the wire)."""
    found = None
    for op in ops:
        if op.content["op"] == "transforms" and path in op.content["paths"]:
            k = op.content["paths"].index(path)
            data = np.frombuffer(op.buffers[0], dtype=np.float32).reshape(-1, 4, 4)
            found = data[k].T
    assert found is not None, path
    return found


@pytest.fixture
def kernel_passes(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Counts every pass of the kinematics kernel (all go through ``_kernel._run``)."""
    calls: list[int] = []
    run, chain = _kernel._run, _snapshot.run_chain

    def counted(original):  # type: ignore[no-untyped-def]
        def wrapper(*args, **kwargs):  # type: ignore[no-untyped-def]
            calls.append(1)
            return original(*args, **kwargs)

        return wrapper

    monkeypatch.setattr(_kernel, "_run", counted(run))
    monkeypatch.setattr(_snapshot, "run_chain", counted(chain))
    return calls


@pytest.mark.parametrize("name", ["paper", "puma560", "stanford", "scara"])
def test_a_q_step_costs_the_scene_no_kernel_pass(name: str, kernel_passes: list[int]) -> None:
    robot = rc.preset(name)
    scene = Scene(robot, channel=RecordingChannel())
    lo, hi = robot.joint_limits().T
    for q in np.random.default_rng(3).uniform(lo, hi, (5, robot.n)):
        moved = robot.with_q(q)  # a new robot object each step, as the panel's state holds
        snapshot = moved.at()
        kernel_passes.clear()
        scene.show(snapshot)
        assert kernel_passes == [], name
        assert scene.snapshot is snapshot and scene.robot is moved
        np.testing.assert_array_equal(scene.q, q)
    kernel_passes.clear()
    scene.update(robot.q)  # update(q) = show(robot.at(q)): the one pass is robot.at's
    assert len(kernel_passes) == 1


def test_show_draws_the_snapshots_own_numbers(paper_robot: rc.Robot) -> None:
    scene = Scene(paper_robot, channel=RecordingChannel())
    q = np.array([0.4, -0.7, 1.1])
    snapshot = paper_robot.at(q)
    scene.channel.clear()
    scene.show(snapshot)
    # One message: the transforms and the label texts that changed.
    assert len(scene.channel.messages) == 1
    assert [op.content["op"] for op in scene.channel.messages[0]] == ["transforms", "labels"]
    drawing = scene._robot.drawing
    assert drawing is not None
    expected = drawing.placements(q).matrices()  # the batch path, the robot's own calls
    before = drawing.placements(paper_robot.q).matrices().astype(np.float32)
    (transforms,) = [op for op in scene.channel.ops if op.content["op"] == "transforms"]
    sent = set(transforms.content["paths"])
    for k, path in enumerate(drawing.paths):
        if f"{ROBOT_PATH}/{path}" in sent:
            wire = _wire(scene.channel.ops, f"{ROBOT_PATH}/{path}")
            np.testing.assert_array_equal(wire, expected[k].astype(np.float32))
        else:  # not sent: it did not move (the base, the first link)
            np.testing.assert_array_equal(before[k], expected[k].astype(np.float32))
    assert {f"{ROBOT_PATH}/base/frame", f"{ROBOT_PATH}/links/0"}.isdisjoint(sent)
    np.testing.assert_allclose(
        _wire(scene.channel.ops, f"{ROBOT_PATH}/ee/sphere")[:3, 3], snapshot.end_effector, atol=1e-4
    )
    assert scene.labels()[-1] == str(snapshot.points[-1])


def test_set_robot_and_update_are_show_of_a_snapshot(paper_robot: rc.Robot) -> None:
    q = [0.3, -0.2, 0.9]
    by_show = Scene(paper_robot, channel=RecordingChannel())
    by_show.show(paper_robot.at(q))
    by_update = Scene(paper_robot, channel=RecordingChannel())
    by_update.update(q)
    by_set = Scene(paper_robot, channel=RecordingChannel())
    by_set.set_robot(paper_robot, q)
    for scene in (by_update, by_set):
        assert [op.content for op in scene.channel.ops[-2:]] == [
            op.content for op in by_show.channel.ops[-2:]
        ]
        assert scene.channel.ops[-2].buffers == by_show.channel.ops[-2].buffers
    with pytest.raises(rc.InvalidInputError, match="^snapshot:"):
        by_show.show(paper_robot)  # type: ignore[arg-type]


def test_objects_are_rebuilt_only_for_a_new_structure_or_size(paper_robot: rc.Robot) -> None:
    scene = Scene(paper_robot, channel=RecordingChannel())
    drawing = scene._robot.drawing
    scene.channel.clear()
    # Other lengths, same joints, within a factor 2: the same objects move.
    longer = paper_robot.with_module(2, rc.Module("Ry", a=(45, 0, 0)))
    scene.show(longer.at([0.1, 0.2, 0.3]))
    assert scene._robot.drawing is drawing and "set_object" not in scene.channel.kinds()
    # A prismatic slide far out is still the same robot: no rebuild on a q step.
    cartesian = rc.preset("cartesian")
    slider = Scene(cartesian, channel=RecordingChannel())
    built = slider._robot.drawing
    slider.update([0.0, 0.0, 20 * rc.characteristic_length(cartesian)])
    assert slider._robot.drawing is built
    # Ten times the lengths: rebuilt at the new size, and the view fitted again.
    scene.channel.clear()
    scene.show(rc.preset("paper", l1=200, l2=300, l3=400).at())
    kinds = scene.channel.kinds()
    assert kinds[0] == "delete" and "set_object" in kinds and kinds[-1] == "fit"
    assert scene._robot.drawing is not drawing


def test_the_scene_is_made_of_parts_that_know_only_its_outbox() -> None:
    from robotconf.scene import _scene

    for file, name in PARTS.items():
        tree = ast.parse((SCENE / file).read_text())
        imported = {
            node.module
            for node in ast.walk(tree)
            if isinstance(node, ast.ImportFrom) and node.module is not None
        }
        assert "_scene" not in imported, file  # a part never reaches back into the hub
        assert not any(  # no stubs for a host's private methods
            isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
            for node in ast.walk(tree)
        ), file
        module = __import__(f"robotconf.scene.{file[:-3]}", fromlist=[name])
        parameters = list(inspect.signature(getattr(module, name)).parameters)
        assert parameters[0] == "outbox", (name, parameters)
    # The hub composes: no base classes but object.
    assert _scene.Scene.__bases__ == (object,)
    assert sum(1 for _ in SCENE.glob("*.py")) <= 20
    for path in list(SCENE.glob("*.py")) + list(SCENE.glob("js/*.js")):
        assert len(path.read_text().splitlines()) <= 500, path.name


def test_a_drawing_places_a_snapshot_as_the_batch_does() -> None:
    rng = np.random.default_rng(11)
    for name in ("puma560", "ur5", "stanford", "cartesian", "scara"):
        robot = rc.preset(name)
        drawing = RobotDrawing(robot, 1.0)
        lo, hi = robot.joint_limits().T
        qs = rng.uniform(lo, hi, (6, robot.n))
        batch = drawing.placements(qs).matrices()
        for q, expected in zip(qs, batch, strict=True):
            np.testing.assert_allclose(drawing.place(robot.at(q)), expected, rtol=0, atol=1e-12)
