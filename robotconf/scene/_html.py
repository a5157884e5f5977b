"""A scene as one self-contained HTML file: viewer code inline, no network at all.

The page is the notebook's page without a kernel: the same bar above the same pane
(``js/``), the animation played by the page's own player. In the notebook the bar asks the
kernel, which sends the ops of the choice; here the view options (labels mode, frames,
trace, fit) are answered from ops computed when the file was written, one list per choice
(:func:`bar_choices`).
"""

from __future__ import annotations

import base64
import html
import json
from collections.abc import Callable, Mapping
from typing import Any

from ._assets import meshcat_source, script
from ._commands import Op, SceneLog, command_op, pack_ops
from ._fit import CENTRED
from ._labels import LABEL_MODES
from ._playback import TRACE, Playback
from ._robot_layer import RobotLayer
from ._taught_points import TaughtPointsLayer

__all__ = ["scene_html", "bar_choices", "script_safe", "PAGE_SCRIPTS"]

#: The page's code of a scene (``js/``), shared by the widget and the HTML export: the
#: viewer glue, the labels, the player, the bar, and the page that holds them.
PAGE_SCRIPTS = ("glue", "labels", "player", "bar", "mount")

_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title}</title>
<style>
  html, body {{ margin: 0; height: 100%; overflow: hidden; font-family: sans-serif; }}
  #scene {{ width: 100%; height: 100%; }}
</style>
</head>
<body>
<div id="scene"></div>
<script id="robotconf-scene-log" type="application/json">{log}</script>
<script type="module">
{code}
const MESHCAT_SOURCE = {source};
const log = JSON.parse(document.getElementById("robotconf-scene-log").textContent);
const buffers = log.buffers.map((b64) => Uint8Array.from(atob(b64), (c) => c.charCodeAt(0)));
let handle = null;
// No kernel here: the bar's requests are answered from the choices written with the page.
const answer = (message) => {{
  if (message.kind !== "request" || !handle) return;
  const request = message.request;
  const choices = log.choices[request.kind];
  const key = request.kind === "labels" ? request.mode : String(request.value);
  const ops = request.kind === "fit" ? choices : choices && choices[key];
  if (ops && ops.length) rcApply(handle.viewer, ops, buffers);
}};
const page = rcScenePage(document.getElementById("scene"), undefined, answer);
rcLoadMeshcat(MESHCAT_SOURCE).then((MeshCat) => {{
  handle = rcStartViewer(MeshCat, page);
  rcApply(handle.viewer, log.ops, buffers);
  document.body.dataset.robotconfScene = "ready";
  window.robotconfViewer = handle.viewer;
}});
</script>
</body>
</html>
"""


def scene_html(
    ops: list[Op],
    choices: Mapping[str, Mapping[str, list[Op]] | list[Op]] | None = None,
    title: str = "robot",
) -> str:
    """An HTML page that replays ``ops`` in meshcat's viewer, fully offline.

    Parameters
    ----------
    ops : list of Op
        A scene's replay (its log, then where its player stands).
    choices : dict, optional
        What the bar's requests apply: ``{"labels": {mode: ops}, "frames": {"true": ops,
        "false": ops}, "trace": {…}, "fit": ops}``.
    title : str
        Page title (HTML-escaped; label texts travel as JSON and are written as text,
        never parsed as HTML).

    Returns
    -------
    str
    """
    contents, buffers = pack_ops(ops)
    packed_choices: dict[str, object] = {}
    for kind, value in (choices or {}).items():
        if isinstance(value, Mapping):
            packed_choices[kind] = {key: pack_ops(v, buffers)[0] for key, v in value.items()}
        else:
            packed_choices[kind] = pack_ops(value, buffers)[0]
    log = json.dumps(
        {
            "ops": contents,
            "choices": packed_choices,
            "buffers": [base64.b64encode(b).decode("ascii") for b in buffers],
        }
    )
    return _PAGE.format(
        title=html.escape(title),
        log=script_safe(log),
        code=script(*PAGE_SCRIPTS),
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


def bar_choices(
    robot: RobotLayer,
    taught: TaughtPointsLayer,
    playback: Playback,
    log: SceneLog,
    options: Callable[..., Op],
) -> dict[str, Any]:
    """``{"labels": {mode: ops}, "frames": {"true": ops, "false": ops}, "trace": {…},
    "fit": ops}``; each list ends with the ``options`` op the bar then shows.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, Scene
    >>> scene = Scene(rc.preset("paper"), channel=RecordingChannel())
    >>> choices = bar_choices(scene._robot, scene._taught, scene._playback,
    ...                       scene._outbox.log, scene._options_op)
    >>> choices["labels"]["names"][1].content["texts"]
    ['M1', 'M2', 'M3', 'EE']
    """
    labels = {
        mode: [
            *robot.label_ops(mode),
            taught.visibility_op(mode != "off"),
            options(labels=mode),
        ]
        for mode in LABEL_MODES
    }
    frames = {
        str(value).lower(): [robot.visibility_op("frames", value), options(frames=value)]
        for value in (True, False)
    }
    trace: dict[str, list[Op]] = {"true": [], "false": []}
    if playback.loaded:
        delete = command_op({"type": "delete", "path": TRACE})
        trace = {
            "true": [playback.trace_op(), options(trace=True)],
            "false": [delete, options(trace=False)],
        }
    # The fit as last sent: the centring transforms and the camera's distance.
    fit = [op for op in log.ops() if op.content["op"] == "fit" or _centring(op)]
    return {"labels": labels, "frames": frames, "trace": trace, "fit": fit}


def _centring(op: Op) -> bool:
    content = op.content
    return (
        content["op"] == "command"
        and content["command"]["type"] == "set_transform"
        and content["command"]["path"] in CENTRED
    )
