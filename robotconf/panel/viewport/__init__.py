"""The view column: the end-effector line and the 3D scene, drawn from the state."""

from ._scene_slot import PlaceholderScene, SceneLike, default_scene_factory
from ._viewport import EE_CLASS, NO_EXTRAS, Call, Extras, ViewportView, end_effector_text

__all__ = [
    "SceneLike",
    "PlaceholderScene",
    "default_scene_factory",
    "ViewportView",
    "Extras",
    "Call",
    "NO_EXTRAS",
    "end_effector_text",
    "EE_CLASS",
]
