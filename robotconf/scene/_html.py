"""A scene as one self-contained HTML file: viewer code inline, no network at all."""

from __future__ import annotations

import base64
import html
import json

from ._assets import meshcat_source, script
from ._commands import Op, pack_ops

__all__ = ["scene_html", "script_safe"]

_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title}</title>
<style>
  html, body {{ margin: 0; height: 100%; overflow: hidden; font-family: sans-serif; }}
  #wrapper {{ position: relative; width: 100%; height: 100%; }}
  #scene {{ width: 100%; height: 100%; }}
</style>
</head>
<body>
<div id="wrapper"><div id="scene"></div></div>
<script id="robotconf-scene-log" type="application/json">{log}</script>
<script type="module">
{glue}
const MESHCAT_SOURCE = {source};
const log = JSON.parse(document.getElementById("robotconf-scene-log").textContent);
const buffers = log.buffers.map((b64) => Uint8Array.from(atob(b64), (c) => c.charCodeAt(0)));
rcLoadMeshcat(MESHCAT_SOURCE).then((MeshCat) => {{
  const element = document.getElementById("scene");
  const handle = rcCreateViewer(MeshCat, element, undefined);
  rcApply(handle.viewer, log.ops, buffers);
  document.body.dataset.robotconfScene = "ready";
  window.robotconfViewer = handle.viewer;
}});
</script>
</body>
</html>
"""


def scene_html(ops: list[Op], title: str = "robot") -> str:
    """An HTML page that replays ``ops`` in meshcat's viewer, fully offline.

    Parameters
    ----------
    ops : list of Op
        A scene log (:meth:`SceneLog.ops`).
    title : str
        Page title (HTML-escaped; label texts travel as JSON and are drawn on a canvas,
        never parsed as HTML).

    Returns
    -------
    str
    """
    contents, buffers = pack_ops(ops)
    log = json.dumps(
        {"ops": contents, "buffers": [base64.b64encode(b).decode("ascii") for b in buffers]}
    )
    return _PAGE.format(
        title=html.escape(title),
        log=script_safe(log),
        glue=script("glue"),
        source=script_safe(json.dumps(meshcat_source())),
    )


def script_safe(text: str) -> str:
    """JSON text that cannot end or re-open the ``<script>`` element it is written in.

    Label texts carry user names such as ``</script><img onerror=…>``; ``"</"`` would end
    the element and ``"<!--"`` changes how the browser finds its end. Writing every
    ``<`` as the JSON escape ``\\u003c`` (and ``>``, ``&`` alike) leaves no markup at all,
    and ``JSON.parse`` (or the JavaScript string literal) gives back the same text.

    >>> safe = script_safe(json.dumps("</script><!--"))
    >>> "<" in safe, json.loads(safe)
    (False, '</script><!--')
    """
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")
