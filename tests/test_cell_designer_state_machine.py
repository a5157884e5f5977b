"""The one-state property of the designer: whatever a student does, in whatever order, the
view, the table and the bound file show the same cell.

A stateful hypothesis test drives a bound designer through long random sequences of what a
student does in the page — objects, frames and robots added, removed, renamed and moved
onto others; poses, sizes and q typed (garbage too); units; the reach map; moves added,
retargeted, edited and reordered; Run; undo and redo; a mesh uploaded — and after every
step checks that the fake view's cell, every number the table shows, the bound cell file
(with its programs) and ``designer.cell`` agree, that undo then redo is the identity and
that a unit switch changes no number.
"""

from __future__ import annotations

import datetime
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule

import robotconf as rc
from robotconf.cell_designer.state import FrameItem, ObjectItem, RobotItem, pose_numbers
from robotconf.panel.form import display_number

from .test_cell_designer_support import (
    make_designer,
    paper_on_table,
    row_of,
    same_cell,
    show_tab,
    use,
)
from .test_cell_files import STL_TEXT

NOW = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)
TYPED = st.one_of(
    st.integers(-150, 150).map(str),
    st.sampled_from(["12.5", "-0.25", "0", "abc", "nan", "1e999", "", "1e200"]),
)
NAMES = st.sampled_from(["table", "fixture", "pick", "bench", "a/b", " ", "box1", "x" * 300])


class Student(RuleBasedStateMachine):
    """One student, one designer bound to a cell file, any sequence of clicks."""

    def __init__(self) -> None:
        super().__init__()
        self.folder = tempfile.TemporaryDirectory()
        self.path = Path(self.folder.name) / "cell.json"
        paper_on_table().save(self.path)
        self.designer = make_designer(self.path)

    def teardown(self) -> None:
        self.folder.cleanup()

    def _names(self, kinds: tuple[type, ...]) -> list[str]:
        return [i.name for i in self.designer.state.cell.items if isinstance(i, kinds)]

    # -- the cell -----------------------------------------------------------------------

    @rule(kind=st.sampled_from(["box", "cylinder", "sphere", "frame"]))
    def add_an_object_or_frame(self, kind: str) -> None:
        use(self.designer, f"add.{kind}").click()

    @rule(preset=st.sampled_from(["paper", "planar_2r", "scara"]))
    def add_a_robot(self, preset: str) -> None:
        if len(self.designer.state.cell.robots) < 3:
            use(self.designer, "add.robot.preset").choose(preset)
            use(self.designer, "add.robot").click()

    @rule(data=st.data(), text=TYPED)
    def type_a_pose_number(self, data: st.DataObject, text: str) -> None:
        names = self._names((ObjectItem, FrameItem, RobotItem))
        if names:
            name = data.draw(st.sampled_from(names))
            use(
                self.designer, f"{row_of(self.designer, name)}.pose{data.draw(st.integers(0, 5))}"
            ).type(text)

    @rule(data=st.data(), text=TYPED)
    def type_a_size_or_q(self, data: st.DataObject, text: str) -> None:
        show_tab(self.designer, "Cell")
        keys = [
            k
            for form in (self.designer.table.form, self.designer.robots.form)
            for k in form.control_keys()
            if k.rsplit(".", 1)[-1][:4] in ("size", "radi", "leng", "scal", "q0", "q1", "q2", "q3")
        ]
        if keys:
            use(self.designer, data.draw(st.sampled_from(keys))).type(text)

    @rule(data=st.data(), new=NAMES)
    def rename(self, data: st.DataObject, new: str) -> None:
        names = self._names((ObjectItem, FrameItem, RobotItem))
        if names:
            use(
                self.designer, f"{row_of(self.designer, data.draw(st.sampled_from(names)))}.name"
            ).type(new)

    @rule(data=st.data())
    def place_on_another(self, data: st.DataObject) -> None:
        names = self._names((ObjectItem, FrameItem, RobotItem))
        if names:
            key = f"{row_of(self.designer, data.draw(st.sampled_from(names)))}.parent"
            user = use(self.designer, key)
            options = [o[1] for o in self._options(key)]
            user.choose(data.draw(st.sampled_from(options)))

    def _options(self, key: str) -> list[list[str]]:
        for form in (self.designer.table.form, self.designer.robots.form):
            if key in form.control_keys():
                return form.control(key)["options"]
        return []

    @rule(data=st.data(), what=st.sampled_from(["select", "remove"]))
    def select_or_remove(self, data: st.DataObject, what: str) -> None:
        names = self._names((ObjectItem, FrameItem, RobotItem))
        if names:
            use(
                self.designer, f"{row_of(self.designer, data.draw(st.sampled_from(names)))}.{what}"
            ).click()

    @rule()
    def upload_a_mesh(self) -> None:
        content = STL_TEXT.encode()
        entry = {"name": "plate.stl", "type": "", "size": len(content), "last_modified": NOW}
        self.designer.mesh_upload.value = ({**entry, "content": memoryview(content)},)

    # -- units, view, history -----------------------------------------------------------

    @rule(degrees=st.booleans(), unit=st.sampled_from(["mm", "m", "units"]))
    def switch_units(self, degrees: bool, unit: str) -> None:
        designer = self.designer
        before = designer.state.document
        use(designer, "angle_unit").choose(degrees)
        assert designer.state.document is before  # the angle unit is only the screen's
        use(designer, "length_unit").choose(unit)
        after = designer.state.document
        assert after.cell.items == before.cell.items and after.programs == before.programs

    @rule(on=st.booleans())
    def reach_map(self, on: bool) -> None:
        designer = self.designer
        if designer.state.cell.robots:
            use(designer, "reach.step").type("50")
            use(designer, "reach.on").check(on)

    @rule(undo=st.booleans())
    def undo_or_redo(self, undo: bool) -> None:
        (self.designer.undo if undo else self.designer.redo)()

    @rule()
    def undo_then_redo_is_the_identity(self) -> None:
        designer = self.designer
        if designer.can_undo:
            before = designer.state.document
            designer.undo()
            designer.redo()
            assert designer.state.document == before

    # -- programs -----------------------------------------------------------------------

    @rule(data=st.data(), what=st.sampled_from(["add", "kind", "target", "number", "row", "run"]))
    def edit_a_program(self, data: st.DataObject, what: str) -> None:
        designer = self.designer
        show_tab(designer, "Programs")
        keys = designer.programs_tab.form.control_keys()
        # Labels and notes have keys like "move[0]#0.3" (their row, line and place).
        moves = sorted({k.split(".")[0] for k in keys if k.startswith("move[") and "#" not in k})
        if what == "add" or not moves:
            adds = [k for k in keys if k.endswith(".add")]
            if adds:
                add = data.draw(st.sampled_from(adds))
                use(designer, add + "_kind").choose(
                    data.draw(st.sampled_from(["PTP", "LIN", "CIRC", "Wait"]))
                )
                use(designer, add).click()
            return
        move = data.draw(st.sampled_from(moves))
        if what == "kind":
            use(designer, f"{move}.kind").choose(
                data.draw(st.sampled_from(["PTP", "LIN", "CIRC", "Wait"]))
            )
        elif what == "target" and f"{move}.target" in keys:
            options = [
                o[1] for o in designer.programs_tab.form.control(f"{move}.target")["options"]
            ]
            use(designer, f"{move}.target").choose(data.draw(st.sampled_from(options)))
        elif what == "number":
            boxes = [
                k
                for k in keys
                if k.startswith(move + ".")
                and designer.programs_tab.form.control(k)["type"] == "number"
            ]
            if boxes:
                use(designer, data.draw(st.sampled_from(boxes))).type(data.draw(TYPED))
        elif what == "row":
            use(designer, f"{move}.{data.draw(st.sampled_from(['up', 'down', 'delete']))}").click()
        elif what == "run" and data.draw(st.integers(0, 3)) == 0:  # Run costs: now and then
            use(designer, "run").click()

    # -- what must hold after every step ------------------------------------------------

    @invariant()
    def the_view_the_table_and_the_file_show_the_cell(self) -> None:
        designer = self.designer
        cell = designer.cell
        assert same_cell(designer.scene.cell, cell)
        saved, programs = rc.load_cell(self.path, with_programs=True)
        assert same_cell(saved, cell)
        assert programs == designer.programs
        show_tab(designer, "Cell")
        units = designer.state.units
        for item in designer.state.cell.items:
            form = designer.robots.form if isinstance(item, RobotItem) else designer.table.form
            prefix = row_of(designer, item.name)
            numbers = pose_numbers(item.pose)
            for k, value in enumerate(numbers):
                control = form.control(f"{prefix}.pose{k}")
                if "text" not in control:  # a refused typed value shows its text instead
                    unit = "length" if k < 3 else "rad"
                    assert control["value"] == display_number(
                        units.to_shown(value, unit), control["step"]
                    )
            if isinstance(item, RobotItem):
                for k, value in enumerate(item.robot.q):
                    control = form.control(f"{prefix}.q{k}")
                    if "text" not in control:
                        unit = item.robot.modules[k].unit
                        assert control["value"] == display_number(
                            units.to_shown(float(value), unit), control["step"]
                        )

    @invariant()
    def nothing_is_lost_to_a_failure(self) -> None:
        assert "view" not in self.designer.errors, self.designer.errors
        assert not any("internal error" in m for m in self.designer.errors.values()), (
            self.designer.errors
        )


Student.TestCase.settings = settings(
    max_examples=2,
    stateful_step_count=220,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
TestStudent = Student.TestCase
