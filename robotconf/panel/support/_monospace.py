"""Preformatted text (matrices) in a fixed-width font, whatever page the panel is on.

``rc.derivation`` prints matrices as columns aligned with spaces, which only line up in
a fixed-width font. JupyterLab's stylesheet gives ``<pre>`` its code font, but Voilà's
page does not: there a widget's ``<pre>`` inherits the page's sans-serif font and the
columns drift apart. So the panel styles the element itself.
"""

from __future__ import annotations

import html

__all__ = ["MONOSPACE_STYLE", "preformatted"]

#: Font: the notebook's code font when the page defines one; the trailing generic family
#: keeps the text fixed-width when a theme names a font this computer lacks.
#: Line height: ipywidgets gives the content of an HTML widget the height of a control row
#: (28 px) as line height, to align one-line labels; a matrix's rows would inherit it and
#: stand apart, its brackets broken into dashes.
MONOSPACE_STYLE = (
    "font-family: var(--jp-code-font-family, monospace), monospace; "
    "line-height: var(--jp-code-line-height, 1.3)"
)


def preformatted(text: str) -> str:
    """``text`` HTML-escaped in a ``<pre>`` with a fixed-width font.

    Parameters
    ----------
    text : str
        Plain text; any markup in it is shown, never interpreted.

    Returns
    -------
    str
        HTML for an ``ipywidgets.HTML`` value.

    Examples
    --------
    >>> preformatted("[ 1  0 ]\\n[ 0 <b> ]")
    '<pre style="font-family: ...">[ 1  0 ]\\n[ 0 &lt;b&gt; ]</pre>'
    """
    return f'<pre style="{MONOSPACE_STYLE}">{html.escape(text)}</pre>'
