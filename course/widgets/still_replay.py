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

import itertools
from typing import Any

import numpy as np
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
        self.artist = artist
        # A grid's dozens of paths, stored and named in one go: one call, not one a path.
        self.calls: list[tuple[str, tuple]] = []
        for method, group in itertools.groupby(calls, key=lambda call: call[0]):
            group = list(group)
            if method == "_add_cleaned" and len(group) > 1:
                self.calls.append(("_paths", _path_run([arguments for _, arguments in group])))
            else:
                self.calls.extend(group)

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
            if method == "_paths":
                _add_path_run(recorder, *arguments)
            else:
                getattr(recorder, method)(*arguments)
        return True


def _path_run(calls: list[tuple]) -> tuple[list[tuple[int, int, str]], np.ndarray, np.ndarray]:
    """``_add_cleaned``'s arguments for several paths as one run: each path's (start in the
    run, count, style), and the run's vertices and codes, each path's closing STOP left out."""
    kept = [(style, vertices, codes) for style, vertices, codes in calls if len(codes) > 1]
    counts = [len(codes) - 1 for _, _, codes in kept]
    starts = list(itertools.accumulate(counts, initial=0))[:-1]
    paths = [
        (start, count, style)
        for start, count, (style, _, _) in zip(starts, counts, kept, strict=True)
    ]
    if not kept:
        return paths, np.zeros((0, 2)), np.zeros(0, np.uint8)
    vertices = np.concatenate([vertices[:-1] for _, vertices, _ in kept])
    codes = np.concatenate([codes[:-1] for _, _, codes in kept])
    return paths, vertices, codes


def _add_path_run(recorder: Any, paths: list, vertices: np.ndarray, codes: np.ndarray) -> None:
    """What ``recorder._add_cleaned`` makes of each of a run's paths, stored at once."""
    if recorder.log is not None:  # a replay being recorded: the run stays one
        recorder.log.append(("_paths", (paths, vertices, codes)))
    if not paths:
        return
    first, _count = recorder._add(vertices, codes)
    recorder.commands.extend(
        f'{{"path":[{first + start},{count}],{style}}}' for start, count, style in paths
    )
