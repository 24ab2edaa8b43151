"""The student's pointer on an app's picture: what a press grabs, a drag, a click.

Where a parameter is a point (a control point, a vertex, where to paste), the
student drags it on the picture. An app lists what can be grabbed as
:class:`Handle` objects in data coordinates; :meth:`PointerMixin.pointer` maps a
press, a move or a release at a picture pixel through the axes' inverse
transform and calls the app's :meth:`~PointerMixin.drag`. The browser sends at
most one move at a time (``picture.js``), so a drag never queues redraws.
What is held is marked with a ring or an outline in :data:`HIGHLIGHT`.

:class:`PointerMixin` is mixed into :class:`~course.widgets.base.SliderApp`, the
only class that uses it: its methods run on an app, whose figure, view,
controls and redrawing they use, and :meth:`~PointerMixin.pointer` checks what
the browser sends. A mixin cannot be built alone, so the fuzz test skips this
module (``UNCHECKED = True``); it fuzzes the apps.
"""

from __future__ import annotations

import math
from contextlib import ExitStack
from dataclasses import dataclass
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from course._validate import describe
from course.i18n import _

__all__ = ["HIGHLIGHT", "Handle", "PointerMixin"]

UNCHECKED = True  # see the module docstring

#: The colour of what the student holds (Okabe and Ito's orange, colour-blind safe).
HIGHLIGHT = "#E69F00"


@dataclass(frozen=True)
class Handle:
    """Something on the picture a student can grab, in the data coordinates of ``axes``.

    A point (``box`` is None) is grabbed within :attr:`PointerMixin.GRAB_RADIUS`
    picture pixels of ``at``; a box ``(x0, y0, x1, y1)`` anywhere inside it,
    and it moves by its anchor ``at``. A drag keeps the offset between the
    pointer and the anchor, so nothing jumps when it is grabbed off-centre.
    """

    name: str
    axes: Axes
    at: tuple[float, float]
    box: tuple[float, float, float, float] | None = None


@dataclass
class _Grab:
    handle: Handle
    offset: np.ndarray
    start: tuple[float, float]


class PointerMixin:
    """Handles on an app's picture, grabbed, dragged and clicked with the pointer.

    Apps with points to drag implement :meth:`handles` and :meth:`drag` (and,
    if they like, :meth:`click` and :meth:`double_click`); a test drives them
    with :meth:`pointer`, as the browser does. The app that mixes this in
    calls its ``__init__`` and provides ``figure``, ``view``, ``controls``,
    ``status``, ``moving``, ``BLIT``, ``animate()``, ``holding()`` and
    ``refresh()`` (:class:`~course.widgets.base.SliderApp` does).
    """

    #: How near a point, in picture pixels, a press grabs it.
    GRAB_RADIUS = 10.0
    #: How far a press may move, in picture pixels, and still count as a click.
    CLICK_SLOP = 4.0

    def __init__(self) -> None:
        self.grabbed: str | None = None
        self._grab: _Grab | None = None
        # While a handle is held, the controls a drag sets are synced to the browser at
        # the release only: one message less at every step (the picture shows them live).
        self._held_sync = ExitStack()
        self._press: tuple[float, float] | None = None
        self._rings: dict[Axes, tuple[Line2D, Rectangle]] = {}
        # Artists that move with one handle only (its label): while another is
        # dragged they join the cached background, as text is slow to draw.
        self.handle_artists: dict[str, list[Any]] = {}

    # --- what can be grabbed: apps with points override these -------------------

    def handles(self) -> list[Handle]:
        """What a press can grab, in the order a tie is settled (first wins)."""
        return []

    def drag(self, name: str, point: np.ndarray) -> None:
        """Move handle ``name`` so that its anchor is at ``point`` (data coordinates)."""
        raise NotImplementedError(f"{type(self).__name__} has no draggable {name!r}")

    def click(self, axes: Axes, point: np.ndarray) -> bool:
        """A click on no handle, at ``point`` in ``axes``; True if it changed something."""
        return False

    def grab_started(self, name: str) -> None:
        """Handle ``name`` is held: the other handles' own artists join the background."""
        if not self.BLIT:
            return
        held = []
        for other, artists in self.handle_artists.items():
            for artist in artists if other != name else ():
                if artist in self.moving:
                    artist.set_animated(False)
                    self.moving.remove(artist)
                    held.append(artist)
        self.view.hold(held)

    def grab_ended(self, name: str) -> None:
        """Handle ``name`` is let go: every handle's artists move again."""
        if not self.BLIT:
            return
        for artists in self.handle_artists.values():
            for artist in artists:
                if artist not in self.moving:
                    self.animate(artist)
        self.view.release()

    def drag_step(self, name: str, x: float, y: float, offset: np.ndarray) -> bool:
        """A move of held handle ``name`` to picture pixel (x, y), taken the app's quicker way.

        The handle's anchor goes to the data point of (x, y) less ``offset``
        (where the press fell from it, in data units), as in :meth:`drag`.
        Return False (as here) for the usual step: :meth:`drag`, then one
        redraw. An app that draws its step from arrays
        (:class:`~course.widgets.array_step.ArrayStep`) returns True.
        """
        return False

    def double_click(self, name: str) -> bool:
        """A double click on handle ``name``; True if it changed something."""
        return False

    # --- the pointer ------------------------------------------------------------

    def pointer(self, kind: str, x: float, y: float) -> None:
        """A press (``"down"``), ``"move"``, release (``"up"``) or ``"double"`` at pixel (x, y).

        (x, y) is a pixel of the picture, x to the right, y down from the top;
        it may lie outside the picture (the browser keeps sending moves once
        a drag leaves it). Redraws when anything changed. The controls a drag
        sets (the points as text) reach the browser at the release, in one
        message: the picture shows every step.
        """
        if not isinstance(kind, str) or kind not in ("down", "move", "up", "double"):
            raise ValueError(
                _("kind must be one of 'down', 'move', 'up', 'double'; got {kind}").format(
                    kind=repr(kind)
                )
            )
        for name, number in (("x", x), ("y", y)):
            if isinstance(number, bool) or not isinstance(number, (int, float, np.number)):
                raise TypeError(
                    _("{name} must be a number of picture pixels; got {number}").format(
                        name=name, number=describe(number)
                    )
                )
        x, y = float(x), float(y)
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(
                _("x and y must be finite picture pixels; got ({x}, {y})").format(x=x, y=y)
            )
        if kind == "down":
            self.status.value = ""
            handle = self.handle_at(x, y)
            self._press = None if handle else (x, y)
            if handle:
                offset = self.data_point(handle.axes, x, y) - np.asarray(handle.at, dtype=float)
                self._held_sync.close()  # a release that never came
                for control in self.controls.values():
                    self._held_sync.enter_context(control.hold_sync())
                self._grab = _Grab(handle, offset, (x, y))
                self.grabbed = handle.name
                self.grab_started(handle.name)
                self.refresh()  # the highlight
        elif kind in ("move", "up") and self._grab is not None:
            grab = self._grab
            if kind == "move" and self.drag_step(grab.handle.name, x, y, grab.offset):
                return
            point = self.data_point(grab.handle.axes, x, y) - grab.offset
            if kind == "up":
                self._grab, self.grabbed = None, None
                self.grab_ended(grab.handle.name)
            try:
                with self.holding():
                    self.drag(grab.handle.name, point)
            finally:
                if kind == "up":
                    self._held_sync.close()  # the controls' last values, in one message
        elif kind == "up" and self._press is not None:
            press, self._press = self._press, None
            axes = self.axes_at(x, y)
            if np.hypot(x - press[0], y - press[1]) <= self.CLICK_SLOP and axes is not None:
                with self.holding():
                    self.click(axes, self.data_point(axes, x, y))
        elif kind == "double":
            handle = self.handle_at(x, y)
            if handle is not None:
                with self.holding():
                    self.double_click(handle.name)

    def _on_message(self, widget: Any, content: Any, buffers: Any) -> None:
        # A message comes from the browser, or from any code that sends to the
        # widget: a malformed one (not a dict, a key missing, null, a string,
        # NaN) is reported on the status line, never raised out of the observer.
        # It is answered once, by the step's patch if one is sent, else by "drawn".
        self.view.awaited = True
        try:
            if not isinstance(content, dict):
                raise TypeError(
                    _("expected a dict with kind, x and y; got {given}").format(
                        given=describe(content)
                    )
                )
            missing = [key for key in ("kind", "x", "y") if key not in content]
            if missing:
                raise ValueError(_("missing {keys}").format(keys=", ".join(missing)))
            self.pointer(content["kind"], content["x"], content["y"])
        except (ValueError, TypeError) as error:
            self.status.value = _("Ignored a pointer message: {error}").format(error=error)
        finally:
            if self.view.awaited:
                self.view.awaited = False
                self.view.image.send({"kind": "drawn"})

    def data_point(self, axes: Axes, x: float, y: float) -> np.ndarray:
        """Picture pixel (x, y), y down, in ``axes``' data coordinates."""
        display = (x, self.figure.bbox.height - y)
        return np.asarray(axes.transData.inverted().transform(display), dtype=float)

    def picture_point(self, axes: Axes, point: Any) -> np.ndarray:
        """Data ``point`` of ``axes`` as a picture pixel (x, y), y down: where to press."""
        x, y = axes.transData.transform(np.asarray(point, dtype=float))
        return np.array([x, self.figure.bbox.height - y])

    def axes_at(self, x: float, y: float) -> Axes | None:
        """The axes whose box holds picture pixel (x, y), if any."""
        display = (x, self.figure.bbox.height - y)
        for axes in self.figure.axes:
            if axes.get_window_extent().contains(*display):
                return axes
        return None

    def handle_named(self, name: str) -> Handle:
        """The first handle called ``name``; KeyError naming the ones there are."""
        for handle in self.handles():
            if handle.name == name:
                return handle
        names = sorted({handle.name for handle in self.handles()})
        raise KeyError(
            _("name: expected one of the handles {names}; got {name}").format(
                names=names, name=repr(name)
            )
        )

    def press_point(self, name: str) -> np.ndarray:
        """Where to press to grab handle ``name``: its point, or its box's middle (pixels)."""
        handle = self.handle_named(name)
        if handle.box is None:
            return self.picture_point(handle.axes, handle.at)
        left, top, right, bottom = self._box_pixels(handle)
        return np.array([(left + right) / 2, (top + bottom) / 2])

    def drag_along(self, name: str, path: Any) -> np.ndarray:
        """Press handle ``name``, move by each offset of ``path`` (pixels), release at the last.

        What a browser test does with the mouse, in plain Python. Returns the
        press point.
        """
        start = self.press_point(name)
        self.pointer("down", *start)
        offsets = np.asarray(path, dtype=float).reshape(-1, 2)
        for offset in offsets:
            self.pointer("move", *(start + offset))
        self.pointer("up", *(start + offsets[-1]))
        return start

    def handle_at(self, x: float, y: float) -> Handle | None:
        """The point nearest (x, y) within the grab radius, else a box that holds it."""
        best, nearest = None, self.GRAB_RADIUS
        boxes = []
        for handle in self.handles():
            if handle.box is not None:
                boxes.append(handle)
                continue
            distance = float(np.hypot(*(self.picture_point(handle.axes, handle.at) - (x, y))))
            if distance <= nearest:
                best, nearest = handle, distance
        if best is not None:
            return best
        for handle in boxes:
            left, top, right, bottom = self._box_pixels(handle)
            if left <= x <= right and top <= y <= bottom:
                return handle
        return None

    def _box_pixels(self, handle: Handle) -> tuple[float, float, float, float]:
        x0, y0, x1, y1 = handle.box
        corners = np.array([self.picture_point(handle.axes, c) for c in ((x0, y0), (x1, y1))])
        (left, top), (right, bottom) = corners.min(axis=0), corners.max(axis=0)
        return float(left), float(top), float(right), float(bottom)

    def highlight_ring(self, axes: Axes) -> tuple[Line2D, Rectangle]:
        """The ring (for a point) and outline (for a box) that mark a grabbed handle in ``axes``."""
        if axes not in self._rings:
            (ring,) = axes.plot(
                [],
                [],
                "o",
                markersize=17,
                markerfacecolor="none",
                markeredgecolor=HIGHLIGHT,
                markeredgewidth=2.5,
                zorder=10,
            )
            outline = Rectangle((0, 0), 0, 0, fill=False, edgecolor=HIGHLIGHT, linewidth=3)
            outline.set_visible(False)
            axes.add_patch(outline)
            self._rings[axes] = (ring, outline)
            if self.BLIT:
                self.animate(ring, outline)
        return self._rings[axes]

    def _place_highlight(self) -> None:
        for ring, outline in self._rings.values():
            ring.set_data([], [])
            outline.set_visible(False)
        if self._grab is None:
            return
        grabbed = self._grab.handle
        held = next(
            (h for h in self.handles() if (h.name, h.axes) == (grabbed.name, grabbed.axes)), None
        )
        if held is None:
            return
        ring, outline = self.highlight_ring(held.axes)
        if held.box is None:
            ring.set_data([held.at[0]], [held.at[1]])
        else:
            x0, y0, x1, y1 = held.box
            outline.set_bounds(x0, y0, x1 - x0, y1 - y0)
            outline.set_visible(True)

    def _publish_handles(self) -> None:
        listed = []
        for handle in self.handles():
            if handle.box is None:
                x, y = self.picture_point(handle.axes, handle.at)
                listed.append(
                    [round(float(x), 1), round(float(y), 1), self.GRAB_RADIUS, 0, 0, 0, 0]
                )
            else:
                listed.append([0, 0, 0, *(round(v, 1) for v in self._box_pixels(handle))])
        if listed != self.view.image.handles:
            self.view.image.handles = listed
