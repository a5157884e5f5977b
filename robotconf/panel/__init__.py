"""The configurator panel (ipywidgets): a presentation layer over the numpy core.

Imported on first use of :func:`robotconf.configurator`, never by ``import robotconf``.
"""

from ._configurator import Configurator, configurator

__all__ = ["Configurator", "configurator"]
