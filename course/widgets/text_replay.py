"""A moving label's drawing commands, recorded once and moved with the point it labels.

During a drag the browser draws the moving artists from commands
(:mod:`course.widgets.browser_drawing`). A point's label (lesson 01's P0,
P1, ...) keeps its string, font and colour while its point moves: its
commands differ from the last ones only by where they stand. Laying the text
out again at every step (``Text.draw``: its lines measured, its transform
composed, its graphics context set up) cost a fifth of a step.
:class:`TextReplay` records the commands of the label's draw once and, at
later steps, moves them by how far the label's anchor moved in the picture.

``FigureView.publish_drawing`` is this module's only caller, with artists the
apps made (``UNCHECKED = True``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.text import Annotation, Text

__all__ = ["TextReplay"]

UNCHECKED = True  # see the module docstring

#: An annotation's text coordinates that are an offset from the point it annotates.
_OFFSETS = ("offset points", "offset pixels", "offset fontsize")


def _anchor(text: Text, renderer: Any) -> np.ndarray | None:
    """Where ``text`` stands in display pixels (y up); None if it cannot be moved as a whole.

    A plain text stands at its position through its transform; an annotation
    whose text is offset from its point, at its point.
    """
    if isinstance(text, Annotation):
        if text.anncoords not in _OFFSETS or text.get_annotation_clip() is not False:
            return None  # placed apart from its point, or hidden when its point leaves
        return np.asarray(text._get_position_xy(renderer), dtype=float)
    if type(text).draw is not Text.draw:  # drawn its own way (FixedText)
        return None
    return text.get_transform().transform(text.get_unitless_position())


def _layout(text: Text) -> tuple:
    """All a text's commands depend on besides its anchor: a change means a new recording."""
    annotation = (
        (text.xyann, text.anncoords, text.arrow_patch is None)
        if isinstance(text, Annotation)
        else ()
    )
    return (
        text.get_visible(),
        text.get_text(),
        hash(text.get_fontproperties()),
        str(text.get_color()),
        text.get_alpha(),
        text.get_visible(),
        text.get_rotation_mode(),
        text.get_horizontalalignment(),
        text.get_verticalalignment(),
        text._multialignment,
        text._linespacing,
        text.get_usetex(),
        text.get_wrap(),
        text.get_bbox_patch() is None,
        text.get_path_effects() == [],
        text.get_clip_on(),
        id(text.get_clip_box()),
        text.get_clip_path() is None,
        id(text.get_transform()) if not isinstance(text, Annotation) else 0,
        *annotation,
    )


class TextReplay:
    """A text's drawing commands, moved by how far its anchor moved since they were recorded.

    Recorded only for a text drawn as nothing but text commands (no box, no
    arrow, no path effects), that stands where its anchor is: a plain text
    (its position through its transform) or an annotation offset from its
    point and never clipped by it. :meth:`draw` refuses (returns False) once
    anything but the anchor differs from the recorded (:func:`_layout`); a
    new view comes with ``FigureView.invalidate``, which drops every
    recording. The commands' places are kept to 1/10,000 pixel, as the
    recorder keeps them.
    """

    def __init__(self, text: Text, layout: tuple, anchor: np.ndarray, commands: list) -> None:
        self.text, self.layout, self.anchor, self.commands = text, layout, anchor, commands

    @classmethod
    def record(cls, text: Text, recorder: Any) -> TextReplay | None:
        """Draw ``text`` into ``recorder``; return its replay, or None if it cannot have one."""
        anchor = _anchor(text, recorder)
        if anchor is None:
            text.draw(recorder)
            return None
        layout = _layout(text)
        start = len(recorder.commands)
        text.draw(recorder)
        commands = recorder.commands[start:]
        if any("text" not in command for command in commands):
            return None
        return cls(text, layout, anchor, [dict(command) for command in commands])

    def draw(self, recorder: Any) -> bool:
        """Add the text's commands where its anchor now is; False if it must be drawn anew."""
        text = self.text
        if not (text.get_visible() or self.layout[0]):
            return True  # hidden then and now: nothing to draw, whatever else changed
        if _layout(text) != self.layout:
            return False
        anchor = _anchor(text, recorder)
        if anchor is None:
            return False
        right, up = anchor - self.anchor
        for command in self.commands:
            moved = dict(command)
            # The commands' y runs down the picture.
            moved["x"] = round(command["x"] + float(right), 4)
            moved["y"] = round(command["y"] - float(up), 4)
            recorder.commands.append(moved)
        text.stale = False
        return True
