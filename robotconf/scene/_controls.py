"""The scene's own control bar: animation, view, labels, frames and trace, above the pane.

Every control calls one public :class:`~robotconf.scene.Scene` method, and the bar
follows the scene back (``sync``): an animation started from the panel enables the
player, and the time the page reports moves the scrubber without seeking.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import ipywidgets as widgets

if TYPE_CHECKING:
    from ._scene import Scene

__all__ = ["SceneControls"]

#: Playback speeds offered (× real time).
SPEEDS = (0.25, 0.5, 1.0, 2.0, 4.0)
_LABELS = (("labels off", "off"), ("names", "names"), ("names + positions", "positions"))


def _button(icon: str, tooltip: str, description: str = "") -> widgets.Button:
    width = "34px" if not description else "auto"
    return widgets.Button(
        icon=icon, tooltip=tooltip, description=description, layout=widgets.Layout(width=width)
    )


def _speed_options(extra: float) -> list[tuple[str, float]]:
    speeds = sorted({*SPEEDS, float(extra)})
    return [(f"{s:g}×", s) for s in speeds]


class SceneControls:
    """A compact bar of ipywidgets that drives one scene.

    Parameters
    ----------
    scene : Scene

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, Scene
    >>> scene = Scene(rc.preset("paper"), channel=RecordingChannel())
    >>> scene.controls.labels.value = "names"
    >>> scene.label_mode, scene.channel.kinds()[-1]
    ('names', 'labels')
    """

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self._quiet = False
        #: The playback time sync() last showed (motion seconds).
        self._shown_time = 0.0
        self.play = _button("play", "play the animation")
        self.pause = _button("pause", "pause the animation")
        self.speed = widgets.Dropdown(
            options=_speed_options(1.0),
            value=1.0,
            tooltip="playback speed",
            layout=widgets.Layout(width="72px"),
        )
        self.time = widgets.FloatSlider(
            value=0.0,
            min=0.0,
            max=1.0,
            step=0.01,
            description="t",
            readout_format=".2f",
            continuous_update=True,
            style={"description_width": "12px"},
            layout=widgets.Layout(width="220px"),
        )
        self.fit = _button("expand", "fit the view to the robot", "fit")
        self.labels = widgets.Dropdown(
            options=_LABELS, value=scene.label_mode, layout=widgets.Layout(width="150px")
        )
        self.frames = widgets.ToggleButton(
            value=scene.frames_shown,
            description="frames",
            tooltip="x, y, z axes of every frame",
            layout=widgets.Layout(width="auto"),
        )
        self.trace = widgets.ToggleButton(
            value=scene.trace_shown,
            description="trace",
            tooltip="the end-effector's path during an animation",
            layout=widgets.Layout(width="auto"),
        )
        self.widget = widgets.HBox(
            [
                self.play,
                self.pause,
                self.speed,
                self.time,
                self.fit,
                self.labels,
                self.frames,
                self.trace,
            ],
            layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
        )
        self.widget.add_class("robotconf-scene-controls")
        self.play.on_click(lambda _: self.scene.play())
        self.pause.on_click(lambda _: self.scene.pause())
        self.fit.on_click(lambda _: self.scene.fit_view())
        self._observe(self.speed, lambda value: self.scene.set_speed(value))
        self._observe(self.time, self._scrubbed)
        self._observe(self.labels, lambda value: self.scene.set_label_mode(value))
        self._observe(self.frames, lambda value: self.scene.show_frames(value))
        self._observe(self.trace, lambda value: self.scene.show_trace(value))
        self.sync()

    def close(self) -> None:
        """Close the bar and every control in it."""
        for child in self.widget.children:
            child.close()
        self.widget.close()

    def _observe(self, control: widgets.ValueWidget, call: Any) -> None:
        def changed(change: dict[str, Any]) -> None:
            # A value set by sync() mirrors the scene: calling back would loop (a reported
            # playback time would seek and pause the animation).
            if not self._quiet:
                call(change["new"])

        control.observe(changed, "value")

    def _scrubbed(self, value: float) -> None:
        # The page's slider rounds a time the kernel showed to its step and sends it back:
        # that is not the student scrubbing, and seeking would pause the animation.
        if abs(value - self._shown_time) > self.time.step:
            self.scene.seek(value)

    def sync(self) -> None:
        """Show the scene's state: player enabled with an animation, its time and speed."""
        scene, state = self.scene, self.scene.animation
        self._quiet = True
        try:
            for control in (self.play, self.pause, self.speed, self.time):
                control.disabled = state is None
            if state is not None:
                if self.speed.value != state.speed:
                    self.speed.options = _speed_options(state.speed)
                    self.speed.value = state.speed
                top, step = max(state.duration, 1e-6), max(state.duration / 500.0, 1e-3)
                if (self.time.max, self.time.step) != (top, step):
                    self.time.max, self.time.step = top, step
                self._shown_time = state.time
                self.time.value = state.time
            self.labels.value = scene.label_mode
            self.frames.value = scene.frames_shown
            self.trace.value = scene.trace_shown
        finally:
            self._quiet = False
