"""An artist's drawing commands, made again while matplotlib says the artist has not changed.

During a drag the browser draws the moving artists from commands
(:mod:`course.widgets.browser_drawing`). Some of them move with the others
without changing: lesson 03's pixel grids are drawn over the triangles'
pixels at every step, 68 grid lines whose commands cost most of the step.
:class:`StillReplay` keeps what the recorder made of an artist's draw (each
command's making, ``CommandRecorder.log``) and makes it again, with its
places in the new step's buffers, for as long as the artist is not *stale*:
matplotlib marks an artist stale whenever one of its setters changes it.
New limits of its axes drop the replay of an artist drawn through their data
(``FigureView`` listens for them, since the artist is not marked stale);
``FigureView.invalidate`` drops every replay, as does a whole draw of the figure.

``FigureView.publish_drawing`` is this module's only caller, with artists the
apps made (``UNCHECKED = True``).
"""

from __future__ import annotations

from typing import Any

from matplotlib.artist import Artist

__all__ = ["StillReplay"]

UNCHECKED = True  # see the module docstring


class StillReplay:
    """The commands of an artist's last draw, made again while it is not stale.

    Examples
    --------
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> from matplotlib.collections import LineCollection
    >>> from matplotlib.figure import Figure
    >>> from course.widgets.browser_drawing import CommandRecorder
    >>> figure = Figure(figsize=(1, 1), dpi=100)
    >>> grid = figure.add_artist(LineCollection([[(0, 0), (1, 1)], [(0, 1), (1, 0)]]))
    >>> recorder = CommandRecorder(FigureCanvasAgg(figure).get_renderer())
    >>> replay = StillReplay.record(grid, recorder)
    >>> first = recorder.finish()
    >>> recorder.start()
    >>> replay.draw(recorder), recorder.finish() == first
    (True, True)
    >>> grid.set_color("red")  # stale: drawn anew
    >>> replay.draw(recorder)
    False
    """

    def __init__(self, artist: Artist, calls: list[tuple[str, tuple]]) -> None:
        self.artist, self.calls = artist, calls

    @classmethod
    def record(cls, artist: Artist, recorder: Any) -> StillReplay | None:
        """Draw ``artist`` into ``recorder``; return its replay, or None if it stays stale."""
        recorder.log = []
        try:
            artist.draw(recorder)
        finally:
            calls, recorder.log = recorder.log, None
        return None if artist.stale else cls(artist, calls)

    def draw(self, recorder: Any) -> bool:
        """Make the artist's commands again; False if it changed since (stale)."""
        if self.artist.stale:
            return False
        for method, arguments in self.calls:
            getattr(recorder, method)(*arguments)
        return True
