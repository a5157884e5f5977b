"""The work cell in the 3D scene: ``rc.view(cell)``.

The scene
    :class:`CellScene` — every robot of a :class:`~robotconf.cell.Cell` at its base and
    its ``q``, every object and frame with its name, the collision capsules
    (``show_capsules``), a run played on one clock with its contacts red
    (``animate(cell_run)``), reach maps (``show_reach_map``), an outlined entry
    (``select``), the standalone page (``export_html``). Its interface is listed in
    :mod:`robotconf.scene.workcell._cell_scene`.
Building blocks
    :func:`capsule_placement` (a capsule's cylinder and balls along its segment),
    :func:`contact_text` (a contact's label), :func:`reach_colors` (a reach map's ramp)

>>> import robotconf as rc
>>> from robotconf.scene import RecordingChannel
>>> cell = rc.Cell(unit="mm")
>>> cell.add_robot("arm", rc.preset("paper"))
>>> scene = CellScene(cell, channel=RecordingChannel())
>>> scene.labels()[-1]
'EE (70.0, 0.0, 20.0) mm'
"""

from ._capsules import capsule_placement
from ._cell_scene import CellScene
from ._contacts import contact_text
from ._reach_map import reach_colors

__all__ = ["CellScene", "capsule_placement", "contact_text", "reach_colors"]
