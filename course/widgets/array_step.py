"""A drag's step drawn straight from the app's arrays, with the paints its last step recorded.

During a drag, :meth:`~course.widgets.figure_view.FigureView.publish_drawing`
sends the browser the moving artists as drawing commands: it records each
artist's *paints* (style, transform, clip) at one step and replays them at
the next (:class:`~course.widgets.line_replay.LinePaint`,
:class:`~course.widgets.text_replay.TextReplay`). A step still goes through
the artists: the app sets each line's data, the view checks each style, reads
each line's data back and lays each label out. In lesson 01 that was 1.5 ms
of a 1.8 ms step in a kernel that idles between steps, where the floor (a
comm that only answers) costs 3.7 ms.

:class:`ArrayStep` skips the artists. An app whose moving geometry is a few
arrays (lesson 01: the levels of de Casteljau's construction, the curve,
B(t)) hands it those arrays, and the step adds the recorded paints'
commands for them, in the view's drawing order, and sends them as
``publish_drawing`` does. The artists keep their last data until the app's next ``update()``
(the release's, at the latest). :meth:`ArrayStep.start` returns None, and
the app takes the usual step, whenever a replay is missing, a style or
layout changed since it was recorded, or a moving artist the app does not
draw would draw something.

The apps are the only callers (``UNCHECKED = True``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.artist import Artist

from course.widgets.figure_view import FigureView
from course.widgets.line_replay import LinePaint, empty_line
from course.widgets.text_replay import FixedTextReplay, TextReplay

__all__ = ["ArrayStep"]

UNCHECKED = True  # see the module docstring


class ArrayStep:
    """One step's drawing commands, made from arrays by :meth:`draw`, then :meth:`send`."""

    def __init__(self, view: FigureView, recorder: Any, replays: dict, order: list) -> None:
        self.view, self.recorder, self.replays, self.order = view, recorder, replays, order

    @classmethod
    def start(cls, view: FigureView, moving: list[Artist], drawn: set[Artist]) -> ArrayStep | None:
        """A step of ``view`` whose ``moving`` artists are ``drawn`` from arrays, or None.

        Each of ``drawn`` must hold a replay of its last step, in the style or
        layout it was recorded with; every other moving artist must draw
        nothing (hidden, or a line without data).
        """
        drawing = view.array_drawing()
        if drawing is None:
            return None
        recorder, replays = drawing
        order = []
        for artist in moving:
            if artist not in drawn:
                if artist.get_visible() and not empty_line(artist):
                    return None
                continue
            replay = replays.get(artist)
            if isinstance(replay, LinePaint):
                if not replay.holds_style():
                    return None
            elif not (isinstance(replay, (TextReplay, FixedTextReplay)) and replay.holds_layout()):
                return None
            order.append(artist)
        return cls(view, recorder, replays, order)

    def draw(
        self,
        lines: dict[Artist, np.ndarray],
        labels: dict[Artist, np.ndarray],
        texts: dict[Artist, str],
    ) -> bool:
        """Add the drawn artists' commands, in the order the view draws them.

        ``lines`` maps a line to its vertices, (N, 2) data coordinates, N > 0,
        finite; ``labels`` a text to its anchor in display pixels, y up (an
        annotation offset from its point: its axes' ``transData`` of the
        point); ``texts`` a ``FixedText`` to its string. False if a string
        cannot be placed as ``FixedText`` places it: then nothing may be sent,
        and the app takes the usual step.
        """
        recorder, replays = self.recorder, self.replays
        for artist in self.order:
            if artist in lines:
                replays[artist].draw_vertices(recorder, lines[artist])
            elif artist in labels:
                replays[artist].draw_at(recorder, labels[artist])
            elif not replays[artist].draw_string(recorder, texts[artist]):
                return False
        return True

    def send(self) -> None:
        """Send the step to the browser."""
        self.view.send_drawing()
