"""Issue 23: the kernel's CPU time per drag step in lesson 01's app, against today's.

A drag step is one pointer move handled as the browser sends it
(``app.pointer("move", x, y)``): the control point moves, the construction is
updated, the picture redrawn and published. Its CPU time decides how many
students a core holds. Three ways, timed in the same run, in interleaved
batches of 20 steps along a circle of 40 pixels around P1 that never comes
back to a point it passed (:data:`ANGLE_STEP`), with ``time.process_time``
(CPU time, not wall time: the machine is shared):

- **full**: no blitting, the whole figure drawn by matplotlib and the whole
  picture encoded as PNG, at every step;
- **today** (the anchor): blitting as it was before this issue, the moving
  artists redrawn by matplotlib over a cached background, the whole title
  laid out, measured and rendered anew by FreeType, and the whole picture
  encoded as PNG (with today's faster RGB copy, so the anchor is if
  anything too fast);
- **patched**: the moving artists drawn by Agg over the cached background
  with Agg's glyph bitmaps and text layouts cached (numbers laid out from
  their pairs), unused level lines skipped, lines drawn by replaying their
  Agg calls with their new data (``LineReplay``), the title's start drawn
  once into the background and only B(t)'s numbers redrawn, placed without
  being measured (``FixedText``), and only the changed rectangles encoded
  and sent (``FigureView.publish_patches``): what apps whose moving parts
  the browser cannot draw still do;
- **now**: the moving artists sent as drawing commands that the browser
  carries out over the background it was sent once
  (``FigureView.publish_drawing``, ``course.widgets.browser_drawing``):
  nothing is drawn or encoded; a moving line's paint is read once and each
  step builds only its vertices (``LineReplay``), a point's label keeps its
  commands and moves them with its point (``TextReplay``).

Goal: **now** at most half of **today**. Prints each way's CPU time per step
(the fastest batch and the median batch, in ms) and the ratios, and the bytes
each step sends (the message's JSON and its buffers).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import statistics
import sys
import time
from collections.abc import Iterator
from functools import partial
from pathlib import Path

import numpy as np

REPOSITORY = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPOSITORY))

from course.lessons.l01_de_casteljau.apps import DeCasteljauApp  # noqa: E402
from course.widgets import figure_view, line_replay, text_cache  # noqa: E402
from course.widgets.base import SliderApp  # noqa: E402

BATCH = 20
GOAL = 0.5
# Radians per step round the circle: not a fraction of a turn, so the path never comes
# back to a point it passed, as a student's drag seldom does. (A path that came back
# every 50 steps let matplotlib's cache of text sizes answer B(t)'s numbers from
# memory, for every way: a millisecond a step that a real drag pays.)
ANGLE_STEP = 0.1234
#: The first version's path (``--returning``): a 50th of a turn, back at its points every
#: 50 steps. The anchor then measures its title from memory (12 ms rather than 17).
RETURNING_ANGLE_STEP = 2 * np.pi / 50


def _draw_unrecorded(cls: type, line: object, renderer: object) -> None:
    """The anchor draws every line as matplotlib does, at every step."""
    line.draw(renderer)


@contextlib.contextmanager
def as_before(app: DeCasteljauApp) -> Iterator[None]:
    """Inside, ``app``'s drag steps are drawn as before issue 23 (the anchor, **today**).

    The whole title is redrawn at every step and the whole picture encoded
    and published, with Agg's own glyph drawing and every artist drawn.
    ``benchmarks/bench_hub.py`` drags the lesson's app in a student's kernel
    this way too (its **today** line).
    """
    view, saved = app.view, (vars(app).copy(), vars(app.view).copy())
    view.draw_in_browser = False
    view.publish_patches = lambda: False
    app.grab_started = partial(SliderApp.grab_started, app)
    app.grab_ended = partial(SliderApp.grab_ended, app)
    install, empty = text_cache.GlyphCache.install, figure_view.empty_line
    record, origin = line_replay.LineReplay.record, text_cache.FixedText._origin
    text_cache.GlyphCache.install = classmethod(lambda cls, renderer: None)
    figure_view.empty_line = lambda artist: False
    line_replay.LineReplay.record = classmethod(_draw_unrecorded)
    text_cache.FixedText._origin = lambda text, renderer, shown: None  # drawn as Text
    try:
        yield
    finally:
        text_cache.GlyphCache.install, figure_view.empty_line = install, empty
        line_replay.LineReplay.record, text_cache.FixedText._origin = record, origin
        for instance, attributes in zip((app, view), saved, strict=True):
            for name in ("grab_started", "grab_ended", "draw_in_browser", "publish_patches"):
                if name in attributes:
                    setattr(instance, name, attributes[name])
                else:
                    vars(instance).pop(name, None)


class Measured:
    """One way of handling a drag: the app, its pointer on P1, and what it sent."""

    def __init__(self, name: str, angle_step: float = ANGLE_STEP) -> None:
        self.name = name
        self.angle_step = angle_step
        self.app = DeCasteljauApp(t=0.5)
        self.sent_bytes: list[int] = []
        self.app.view.image.send = self.keep
        if name == "full":
            self.app.BLIT = False  # canvas.draw() and a whole picture at every step
            for artist in self.app.moving:
                artist.set_animated(False)  # else canvas.draw() leaves them out
        if name != "now":
            self.app.view.draw_in_browser = False
        self.app.refresh()
        handle = self.app.handles()[1]
        self.centre = self.app.picture_point(handle.axes, handle.at)
        with self.as_before():
            self.app.pointer("down", *self.centre)
        self.step = 0
        self.batches: list[float] = []

    def keep(self, content: dict, buffers: list | None = None) -> None:
        self.sent_bytes.append(len(json.dumps(content)) + sum(map(len, buffers or [])))

    def as_before(self) -> contextlib.AbstractContextManager:
        """The anchors, full and today, draw as before; patched and now as they are."""
        if self.name in ("full", "today"):
            return as_before(self.app)
        return contextlib.nullcontext()

    def batch(self) -> None:
        value = self.app.view.image.value
        with self.as_before():
            start = time.process_time()
            for _ in range(BATCH):
                self.step += 1
                angle = self.step * self.angle_step
                self.app.pointer("move", *(self.centre + 40 * np.array([np.cos(angle), 1])))
                self.app.pointer("move", *(self.centre + 40 * np.array([1, np.sin(angle)])))
            self.batches.append((time.process_time() - start) / (2 * BATCH))
        stepwise = self.name in ("patched", "now")
        if stepwise and self.app.view.image.value != value:
            raise AssertionError("a drag changed the whole picture before the release")
        if not stepwise:
            self.sent_bytes.append(len(self.app.view.image.value))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=9, help="interleaved batches per way")
    parser.add_argument(
        "--returning",
        action="store_true",
        help="the first version's path, back at its points every 50 steps",
    )
    args = parser.parse_args()
    step = RETURNING_ANGLE_STEP if args.returning else ANGLE_STEP
    ways = [Measured(name, step) for name in ("full", "today", "patched", "now")]
    for way in ways:
        way.batch()  # warm-up: caches, the background, the first patch
        way.batches.clear()
        way.sent_bytes.clear()
    for _ in range(args.rounds):
        for way in ways:
            way.batch()
    print(f"Lesson 01's app, 500 x 500, a drag of P1: CPU time per step over {args.rounds} ")
    print(f"interleaved batches of {2 * BATCH} steps (time.process_time), along a path")
    print("back at its points every 50 steps" if args.returning else "that never returns")
    print(f"{'way':<7} {'best ms':>8} {'median ms':>10} {'kB sent per step':>17}")
    for way in ways:
        sent = statistics.median(way.sent_bytes) / 1000
        print(
            f"{way.name:<7} {min(way.batches) * 1e3:>8.2f} "
            f"{statistics.median(way.batches) * 1e3:>10.2f} {sent:>17.1f}"
        )
    full, today, patched, now = (statistics.median(way.batches) for way in ways)
    ratio = now / today
    print(
        f"now / today: {ratio:.2f} (goal <= {GOAL}); now / full: {now / full:.2f}; "
        f"patched / today: {patched / today:.2f}"
    )
    print(f"goal {'met' if ratio <= GOAL else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
