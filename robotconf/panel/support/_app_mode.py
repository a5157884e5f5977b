"""App mode: the panel without a notebook around it (Voilà), so without hints about cells.

In a notebook the panel names the one call behind a view ("or ``panel.save(path)`` in a
cell"), so students meet the API while they click. Voilà shows only the outputs of a
notebook: there is no cell to type into, and such a hint would send students looking for
one. In app mode the panel drops these hints and keeps everything else.

Voilà starts every kernel it serves with ``VOILA_*`` variables in its environment (base
URL, server URL, whether the kernel was preheated), both for a kernel started for a page
and for a preheated one, while JupyterLab, Notebook and nbconvert set none of them. Their
presence is the signal; an explicit ``app=True`` or ``app=False`` always wins over it.
"""

from __future__ import annotations

import os
from collections.abc import Mapping

from ..._errors import InvalidInputError

__all__ = ["VOILA_VARIABLES", "running_in_voila", "app_mode", "code_hint"]

#: Set by Voilà in the environment of the kernels it starts (one is enough).
VOILA_VARIABLES = (
    "VOILA_BASE_URL",
    "VOILA_SERVER_URL",
    "VOILA_PREHEAT",
    "VOILA_APP_PORT",
    "VOILA_KERNEL_ID",
)


def running_in_voila(environ: Mapping[str, str] | None = None) -> bool:
    """Whether this kernel was started by Voilà.

    Parameters
    ----------
    environ : mapping, optional
        The environment to look at (default: ``os.environ``).

    Returns
    -------
    bool
        ``True`` when any of :data:`VOILA_VARIABLES` is set.

    Examples
    --------
    >>> running_in_voila({"VOILA_BASE_URL": "/", "VOILA_PREHEAT": "False"})
    True
    >>> running_in_voila({"JPY_SESSION_NAME": "configurator.ipynb"})  # JupyterLab
    False
    """
    env = os.environ if environ is None else environ
    return any(name in env for name in VOILA_VARIABLES)


def app_mode(app: bool | None = None, environ: Mapping[str, str] | None = None) -> bool:
    """``app`` when given, else whether the panel runs in Voilà.

    Parameters
    ----------
    app : bool or None
        ``True``: no notebook around the panel; ``False``: a notebook; ``None``: detect.
    environ : mapping, optional
        The environment the detection looks at (default: ``os.environ``).

    Returns
    -------
    bool

    Raises
    ------
    InvalidInputError
        When ``app`` is neither a bool nor ``None``.

    Examples
    --------
    >>> app_mode(None, {"VOILA_KERNEL_ID": "0b6c…"})
    True
    >>> app_mode(False, {"VOILA_KERNEL_ID": "0b6c…"})  # the explicit choice wins
    False
    >>> app_mode("yes")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: app: invalid value 'yes'; allowed: True, False or None ...
    """
    if app is None:
        return running_in_voila(environ)
    if not isinstance(app, bool):
        raise InvalidInputError("app", app, "True, False or None (detect Voilà)")
    return app


def code_hint(text: str, app: bool) -> str:
    """``text`` in a notebook, ``""`` in the app: for a hint that points to code.

    Parameters
    ----------
    text : str
        The hint, written to be appended to a sentence (it starts with a space).
    app : bool
        Whether the panel runs as an app (see :func:`app_mode`).

    Returns
    -------
    str

    Examples
    --------
    >>> "Save as JSON" + code_hint(" (or <code>panel.save(path)</code> in a cell)", False)
    'Save as JSON (or <code>panel.save(path)</code> in a cell)'
    >>> "Save as JSON" + code_hint(" (or <code>panel.save(path)</code> in a cell)", True)
    'Save as JSON'
    """
    return "" if app else text
