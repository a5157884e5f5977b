"""The viewer's JavaScript: meshcat's bundled three.js viewer and robotconf's glue.

meshcat's viewer (``viewer/dist/main.min.js``) ships inside the ``meshcat`` wheel, not in
robotconf. It is located through the import system *without running* meshcat's
``__init__``: that would load pyzmq, tornado, Pillow and IPython's shell for meshcat's
server, none of which a notebook needs and none of which exists in a browser kernel
(Pyodide, JupyterLite). Only the file is read; no meshcat Python code runs.
"""

from __future__ import annotations

from functools import cache
from importlib.util import find_spec
from pathlib import Path

__all__ = ["meshcat_bundle", "meshcat_source", "script"]

_JS = Path(__file__).parent / "js"

#: Where the viewer bundle sits inside the installed ``meshcat`` package.
BUNDLE = ("viewer", "dist", "main.min.js")

_INSTALL = (
    "robotconf's 3D scene runs meshcat's three.js viewer, read from the installed meshcat "
    "package ({problem}). Install it with `pip install meshcat` (in JupyterLite: "
    "`await piplite.install('meshcat', deps=False)`), then restart the kernel."
)


def meshcat_bundle() -> Path:
    """The path of meshcat's viewer bundle, found without importing meshcat.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    RuntimeError
        meshcat is not installed, or its package holds no viewer bundle.

    Examples
    --------
    >>> meshcat_bundle().name
    'main.min.js'
    """
    # find_spec on a top-level name only searches sys.path: the package is not executed.
    spec = find_spec("meshcat")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError(_INSTALL.format(problem="meshcat is not installed"))
    for folder in spec.submodule_search_locations:
        bundle = Path(folder).joinpath(*BUNDLE)
        if bundle.is_file():
            return bundle
    raise RuntimeError(_INSTALL.format(problem=f"no {'/'.join(BUNDLE)} in meshcat"))


@cache
def meshcat_source() -> str:
    """meshcat's bundled three.js viewer (``main.min.js``), read once."""
    return meshcat_bundle().read_text(encoding="utf-8")


@cache
def script(*names: str) -> str:
    """robotconf's viewer JavaScript files (``js/NAME.js``), concatenated.

    >>> "function rcApply" in script("glue")
    True
    """
    return "\n".join((_JS / f"{name}.js").read_text(encoding="utf-8") for name in names)
