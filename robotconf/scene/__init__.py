"""The 3D scene: the robot in meshcat's three.js viewer, inside any notebook front end.

>>> import robotconf as rc
>>> from robotconf.scene import RecordingChannel, Scene
>>> scene = Scene(rc.Robot([rc.Module("Tz")], end_effector=(0, 0, 1)), channel=RecordingChannel())
>>> scene.labels()
['M1 (0.0, 0.0, 0.0)', 'EE (0.0, 0.0, 1.0)']
"""

from ._commands import RecordingChannel
from ._scene import Scene, view

__all__ = ["RecordingChannel", "Scene", "view"]
