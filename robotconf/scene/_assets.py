"""The viewer's JavaScript: meshcat's bundled three.js viewer and robotconf's glue.

meshcat's viewer (``main.min.js``) is copied into robotconf when it is built
(``js/meshcat/``, with its license; see ``setup.py``): robotconf never runs meshcat's
Python, whose package is a ZeroMQ server (pyzmq, tornado, pyngrok, ...) that a notebook
does not need and a browser kernel (Pyodide, JupyterLite) cannot install. A source
checkout that was not built falls back to an installed ``meshcat`` package, located
through the import system *without running* its ``__init__``: only the file is read.
"""

from __future__ import annotations

from functools import cache
from importlib.util import find_spec
from pathlib import Path

__all__ = ["meshcat_bundle", "meshcat_source", "script"]

_JS = Path(__file__).parent / "js"

#: The viewer bundle as robotconf's build copies it in.
PACKAGED = _JS / "meshcat" / "main.min.js"

#: Where the viewer bundle sits inside an installed ``meshcat`` package.
BUNDLE = ("viewer", "dist", "main.min.js")

_INSTALL = (
    "robotconf's 3D scene runs meshcat's three.js viewer, which robotconf's build copies "
    "into the package ({problem}). Reinstall robotconf from its wheel, or install the "
    "viewer's source with `pip install meshcat`, then restart the kernel."
)


def meshcat_bundle() -> Path:
    """The path of meshcat's viewer bundle: robotconf's own copy, else meshcat's package.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    RuntimeError
        Neither robotconf's build nor an installed meshcat package has the bundle.

    Examples
    --------
    >>> meshcat_bundle().name
    'main.min.js'
    """
    if PACKAGED.is_file():
        return PACKAGED
    # find_spec on a top-level name only searches sys.path: the package is not executed.
    spec = find_spec("meshcat")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError(_INSTALL.format(problem="this copy of robotconf was not built"))
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
