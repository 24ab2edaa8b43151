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

import json
from operator import attrgetter, is_
from typing import Any

import numpy as np
from matplotlib.text import Annotation, Text

from course.widgets.text_cache import FixedText

__all__ = ["FixedTextReplay", "TextReplay"]

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


#: What a text's commands depend on besides its anchor and font, as the objects it holds:
#: its setters store a new object for a new value (compared by identity, as a line's style).
_HELD_LAYOUT = attrgetter(
    "_visible", "_text", "_color", "_alpha", "_rotation", "_rotation_mode",
    "_horizontalalignment", "_verticalalignment", "_multialignment", "_linespacing",
    "_usetex", "_wrap", "_bbox_patch", "_path_effects", "_clipon", "clipbox", "_clippath",
    "_antialiased",
)  # fmt: skip


def _layout(text: Text, with_string: bool = True) -> tuple[tuple, int]:
    """All a text's commands depend on besides its anchor: a change means a new recording.

    The objects it holds, and the hash of its font (whose setters change it in place).
    """
    held = _HELD_LAYOUT(text)
    if not with_string:
        held = held[:1] + held[2:]
    if isinstance(text, Annotation):  # the offset from its point and how it is drawn
        held += (text._x, text._y, text._textcoords, text.arrow_patch)
    else:
        held += (text._transform,)
    return held, hash(text._fontproperties)


def _unchanged(layout: tuple[tuple, int], recorded: tuple[tuple, int]) -> bool:
    return layout[1] == recorded[1] and all(map(is_, layout[0], recorded[0]))


class TextReplay:
    """A text's drawing commands, moved by how far its anchor moved since they were recorded.

    Recorded only for a text drawn as nothing but text commands (no box, no
    arrow, no path effects), that stands where its anchor is: a plain text
    (its position through its transform) or an annotation offset from its
    point and never clipped by it. :meth:`draw` refuses (returns False) once
    anything but the anchor differs from the recorded (:func:`_layout`); new
    limits of its axes drop the recording of a text placed in their data
    (``FigureView`` listens for them), and ``FigureView.invalidate`` drops
    every recording. The commands' places are kept to 1/10,000 pixel, as the
    recorder keeps them.
    """

    def __init__(self, text: Text, layout: tuple, anchor: np.ndarray, commands: list) -> None:
        # commands: each text command's (x, y, the rest of its JSON), as the recorder keeps it.
        self.text, self.layout, self.anchor, self.commands = text, layout, anchor, commands

    @classmethod
    def record(cls, text: Text, recorder: Any) -> TextReplay | FixedTextReplay | None:
        """Draw ``text`` into ``recorder``; return its replay, or None if it cannot have one.

        A :class:`~course.widgets.text_cache.FixedText`'s is a :class:`FixedTextReplay`.
        """
        if isinstance(text, FixedText):
            return FixedTextReplay.record(text, recorder)
        anchor = _anchor(text, recorder)
        if anchor is None:
            text.draw(recorder)
            return None
        layout = _layout(text)
        start = len(recorder.commands)
        text.draw(recorder)
        texts = _texts_since(recorder, start)
        if len(texts) != len(recorder.commands) - start:
            return None  # drew something besides text
        return cls(text, layout, anchor, texts)

    def draw(self, recorder: Any) -> bool:
        """Add the text's commands where its anchor now is; False if it must be drawn anew."""
        text = self.text
        if not (text.get_visible() or self.layout[0][0]):
            return True  # hidden then and now: nothing to draw, whatever else changed
        if not self._same_layout():
            return False
        anchor = _anchor(text, recorder)
        if anchor is None:
            return False
        self.draw_at(recorder, anchor)
        text.stale = False
        return True

    def draw_at(self, recorder: Any, anchor: np.ndarray) -> None:
        """Add the text's commands for its anchor at ``anchor``, display pixels (y up)."""
        right, up = anchor - self.anchor
        for x, y, rest in self.commands:
            # The commands' y runs down the picture.
            recorder.add_text(round(x + float(right), 4), round(y - float(up), 4), rest)

    def holds_layout(self) -> bool:
        """Whether the text is shown and holds the layout it was recorded with."""
        return bool(self.text.get_visible()) and self._same_layout()

    def _same_layout(self) -> bool:
        return _unchanged(_layout(self.text), self.layout)


class FixedTextReplay:
    """The command of a :class:`~course.widgets.text_cache.FixedText` whose characters change.

    B(t)'s numbers change at every step of a drag and stay where they stand:
    the command differs from the recorded one by its string and by the
    place ``FixedText`` finds for it (``FixedText._origin``, measured once
    per ascent and descent). The rest of the command (font, colour, clip) is
    kept as recorded, its JSON too, until anything but the string differs
    from the recorded (:func:`_layout`); a string ``FixedText`` would not
    place itself (several lines, mathtext) is drawn anew.
    """

    def __init__(self, text: FixedText, layout: tuple, tail: str) -> None:
        self.text, self.layout, self.tail = text, layout, tail

    @classmethod
    def record(cls, text: FixedText, recorder: Any) -> FixedTextReplay | None:
        """Draw ``text`` into ``recorder``; return its replay, or None if it cannot have one."""
        start = len(recorder.commands)
        text.draw(recorder)
        texts = _texts_since(recorder, start)
        string = text.get_text()
        head = f'"text":{json.dumps(string)},'
        if len(texts) != 1 or len(recorder.commands) != start + 1 or not _placed(string):
            return None
        rest = texts[0][2]
        if not rest.startswith(head):
            return None  # drawn by Text.draw, as FixedText draws what it does not place
        return cls(text, _layout(text, with_string=False), rest[len(head) :])

    def draw(self, recorder: Any) -> bool:
        """Add the text's command for its current string; False if it must be drawn anew."""
        text = self.text
        string = text.get_text()
        if not self._same_layout():
            return False
        if not self.draw_string(recorder, string):
            return False
        text.stale = False
        return True

    def draw_string(self, recorder: Any, string: str) -> bool:
        """Add the command of the text showing ``string``, one line FixedText places itself.

        False, having added nothing, if ``FixedText`` cannot place it.
        """
        origin = self.text._origin(recorder, string) if _placed(string) else None
        if origin is None:
            return False
        x, y = origin
        recorder.add_text(
            round(float(x), 4), round(float(y), 4), f'"text":{json.dumps(string)},{self.tail}'
        )
        return True

    def holds_layout(self) -> bool:
        """Whether the text is shown and holds the layout it was recorded with, string aside."""
        return bool(self.text.get_visible()) and self._same_layout()

    def _same_layout(self) -> bool:
        return _unchanged(_layout(self.text, with_string=False), self.layout)


def _texts_since(recorder: Any, start: int) -> list[tuple[float, float, str]]:
    """The (x, y, rest of the JSON) of the text commands recorded from command ``start`` on."""
    return [parts for index, *parts in recorder.texts if index >= start]


def _placed(string: str) -> bool:
    """Whether ``FixedText`` places ``string`` itself: one line, no mathtext, not empty."""
    return bool(string) and "\n" not in string and "$" not in string
