"""The configurator panel (ipywidgets): one state, drawn by every view, changed by actions.

Imported on first use of :func:`robotconf.configurator`, never by ``import robotconf``.

The panel
    :class:`Configurator` (``panel.state``, ``panel.apply(action)``, ``panel.robot``,
    ``panel.scene``, ``panel.undo()``, ``panel.redo()``), :func:`configurator`
The state and the actions
    :mod:`robotconf.panel.state` (:class:`PanelState` and its parts),
    :mod:`robotconf.panel.actions` (one class per user action)

docs/panel.md describes the state, the actions and the flow of one q move.
"""

from typing import Any

from . import actions, state
from .state import PanelState

__all__ = ["Configurator", "configurator", "PanelState", "actions", "state"]


def __getattr__(name: str) -> Any:
    # The widgets load with the panel itself: the state and the actions need none.
    if name in ("Configurator", "configurator"):
        from . import _configurator

        return getattr(_configurator, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
