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

from . import actions, state
from ._configurator import Configurator, configurator
from .state import PanelState

__all__ = ["Configurator", "configurator", "PanelState", "actions", "state"]
