"""How the panel shows things: the tab in front, the scene's options, result views, and
the playback of an animation. None of it changes the robot; none of it is undone.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["ViewOptions", "Playback", "TABS", "LABEL_MODES", "RESULT_VIEWS", "SOURCES"]

#: The result tabs under the editor and the 3D view, in order (the view is no tab).
TABS = ("motion", "matrices", "reach", "program", "files")
#: What the 3D labels show.
LABEL_MODES = ("off", "names", "positions")
#: The three views of a run on the Motion tab.
RESULT_VIEWS = ("table", "statistics", "plot")
#: Which run an animation plays: the Motion tab's, or the Program tab's.
SOURCES = ("motion", "program")


@dataclass(frozen=True)
class ViewOptions:
    """What the panel shows, apart from the robot.

    Attributes
    ----------
    tab : str
        One of :data:`TABS`: the result tab in front.
    labels : str
        One of :data:`LABEL_MODES`.
    frames : bool
        RGB triads at the module frames.
    trace : bool
        The end effector's path during an animation.
    symbolic, lengths, latex : bool
        The Matrices tab: symbolic matrices, lengths as symbols, LaTeX instead of text.
    result_point : str
        The point the Motion tab's results show (a module name, ``"EE"`` or ``"all"``).
    result_view : str
        One of :data:`RESULT_VIEWS`.
    overlay : bool
        The plot shows the same run with the other derivative method, dashed.
    displacement : bool
        The plot shows the displacement from the start instead of the position.

    Examples
    --------
    >>> ViewOptions().tab, ViewOptions().labels
    ('motion', 'positions')
    """

    tab: str = "motion"
    labels: str = "positions"
    frames: bool = False
    trace: bool = False
    symbolic: bool = False
    lengths: bool = False
    latex: bool = False
    result_point: str = "EE"
    result_view: str = "table"
    overlay: bool = False
    displacement: bool = False


@dataclass(frozen=True)
class Playback:
    """The animation in the 3D view, as the page last reported it or the student asked.

    The page plays an animation itself; the kernel only learns where it is when it
    starts, stops, is scrubbed or ends.

    Attributes
    ----------
    source : str or None
        One of :data:`SOURCES` (which run is loaded), or ``None``: no animation, the
        view shows the robot at its q.
    playing : bool
    speed : float
        1 is real time.
    time : float
        Motion time where playback was last reported (s).

    Examples
    --------
    >>> Playback().source is None, Playback(source="motion", playing=True).speed
    (True, 1.0)
    """

    source: str | None = None
    playing: bool = False
    speed: float = 1.0
    time: float = 0.0
