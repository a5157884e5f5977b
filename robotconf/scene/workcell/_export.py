"""What the bar of an exported cell page applies, computed when the file is written.

A page exported without a kernel answers its bar's requests from lists of ops written
with it (:func:`robotconf.scene._html.scene_html`): one list per labels mode, per state
of the frames, trace and capsules switches, and the fit.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .._commands import Op, SceneLog
from .._html import fit_ops, trace_choices
from .._labels import LABEL_MODES
from .._playback import Playback
from ._capsules import CapsulesLayer
from ._entities import EntitiesLayer
from ._paths import CONTACTS, NAMES
from ._robots import RobotsLayer

__all__ = ["cell_bar_choices", "names_visibility"]


def names_visibility(mode: str, contacts: bool) -> list[Op]:
    """Show or hide the objects' and frames' labels (and a run's contact labels when
    ``contacts``) as the labels mode says."""
    paths = [NAMES, f"{CONTACTS}/labels"] if contacts else [NAMES]
    return [Op({"op": "visible", "paths": paths, "value": mode != "off"})]


def cell_bar_choices(
    robots: RobotsLayer,
    entities: EntitiesLayer,
    capsules: CapsulesLayer,
    playback: Playback,
    log: SceneLog,
    options: Callable[..., Op],
    digits: int,
) -> dict[str, Any]:
    """``{"labels": {mode: ops}, "frames": {"true": ops, "false": ops}, "trace": {…},
    "capsules": {…}, "fit": ops}``; each list ends with the ``options`` op the bar then
    shows.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import CellScene, RecordingChannel
    >>> cell = rc.Cell(); cell.add_robot("arm", rc.preset("paper"))
    >>> scene = CellScene(cell, channel=RecordingChannel())
    >>> choices = scene._bar_choices()
    >>> sorted(choices), choices["capsules"]["true"][-1].content["capsules"]
    (['capsules', 'fit', 'frames', 'labels', 'trace'], True)
    """
    labels = {}
    for mode in LABEL_MODES:
        ops = [op for layer in robots.layers.values() for op in layer.label_ops(mode)]
        ops += names_visibility(mode, playback.loaded)
        ops += entities.label_ops(mode, digits)
        labels[mode] = [*ops, options(labels=mode)]
    frames = {
        str(value).lower(): [
            *(layer.visibility_op("frames", value) for layer in robots.layers.values()),
            options(frames=value),
        ]
        for value in (True, False)
    }
    shown = {
        str(value).lower(): [capsules.visibility_op(value), options(capsules=value)]
        for value in (True, False)
    }
    return {
        "labels": labels,
        "frames": frames,
        "trace": trace_choices(playback, options),
        "capsules": shown,
        "fit": fit_ops(log),
    }
