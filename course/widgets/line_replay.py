"""A moving line drawn by replaying the Agg calls of its last full draw with its new data.

At every step of a drag, :class:`~course.widgets.figure_view.FigureView` draws
the moving lines again; :class:`LineReplay` spares it most of what
``Line2D.draw`` spends in Python, for Agg and for the browser's drawing
commands (:mod:`course.widgets.browser_drawing`) alike, and :func:`empty_line`
tells it which lines have nothing to draw. Into the browser's recorder a
replay keeps each call's *paint* (what the recorder reads from its graphics
context and transforms), so that a step only turns the line's new data into
vertices.

``FigureView`` is this module's only caller, with artists the apps made
(``UNCHECKED = True``).
"""

from __future__ import annotations

from operator import attrgetter, is_
from typing import Any

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.path import Path as MatplotlibPath

__all__ = ["LinePaint", "LineReplay", "empty_line"]

UNCHECKED = True  # see the module docstring


class _Recorder:
    """A renderer that draws as ``renderer`` does and keeps the calls that draw paths."""

    def __init__(self, renderer: Any) -> None:
        self._renderer = renderer
        self.calls: list[tuple] = []

    def __getattr__(self, name: str) -> Any:
        return getattr(self._renderer, name)

    def draw_path(self, gc: Any, path: Any, transform: Any, rgbFace: Any = None) -> None:
        self.calls.append(("path", gc, path, transform, rgbFace))
        self._renderer.draw_path(gc, path, transform, rgbFace)

    def draw_markers(
        self,
        gc: Any,
        marker_path: Any,
        marker_trans: Any,
        path: Any,
        trans: Any,
        rgbFace: Any = None,
    ) -> None:
        self.calls.append(("markers", gc, marker_path, marker_trans, path, trans, rgbFace))
        self._renderer.draw_markers(gc, marker_path, marker_trans, path, trans, rgbFace)


#: Everything a line's drawing reads besides its data, as the objects it holds. Its setters
#: store a new object (a new float even for an equal width), so a style the line no longer
#: holds shows as one object that is not the recorded one: one C call and a comparison by
#: identity, where comparing values would convert colours at every step.
_HELD_STYLE = attrgetter(
    "_visible", "_color", "_linewidth", "_linestyle", "_dash_pattern",
    "_unscaled_dash_pattern", "_marker", "_markersize", "_markerfacecolor",
    "_markerfacecoloralt", "_markeredgecolor", "_markeredgewidth", "_alpha", "_antialiased",
    "_clipon", "clipbox", "_clippath", "_transform", "_drawstyle", "_markevery", "_gapcolor",
    "_sketch", "_path_effects", "_rasterized", "_agg_filter", "_solidcapstyle",
    "_solidjoinstyle", "_dashcapstyle", "_dashjoinstyle",
)  # fmt: skip


def _holds(line: Line2D, held: tuple) -> bool:
    """Whether ``line`` still holds the style objects ``held`` (:data:`_HELD_STYLE`)."""
    return all(map(is_, _HELD_STYLE(line), held))


class LineReplay:
    """A moving line drawn by replaying its Agg calls with new data.

    ``Line2D.draw`` spends three quarters of its time in Python (unit
    conversion, transform bookkeeping, a graphics context set up property by
    property) for one or two calls into Agg: a drag of lesson 01's P1
    redraws seven lines at every step. :meth:`record` draws the line as
    matplotlib does through a :class:`_Recorder`; :meth:`draw` then makes
    the same calls, with the same graphics contexts and transforms, on a
    path built from the line's new data exactly as ``Line2D.recache`` builds
    it, so Agg gets the same input a full draw gives it. A line is recorded
    only where that holds: affine transforms (the path goes to Agg as it
    is), the default draw style, no mark-every, gap colour, sketch, path
    effects, filter or rasterization; and :meth:`draw` refuses (returns
    False) once the line no longer holds the style it was recorded with
    (:data:`_HELD_STYLE`). New limits of its axes drop its recording
    (``FigureView`` listens for them); axes moved come with
    :meth:`~course.widgets.figure_view.FigureView.invalidate`, as the
    cached background needs it too, and that drops every recording.
    """

    def __init__(self, line: Line2D, calls: list[tuple], held: tuple) -> None:
        self.line, self.calls, self.held = line, calls, held

    @classmethod
    def record(cls, line: Line2D, renderer: Any) -> LineReplay | LinePaint | None:
        """Draw ``line`` into ``renderer``; return its replay, or None if it cannot have one.

        Into the browser's ``CommandRecorder`` the replay is a :class:`LinePaint`.
        """
        plain = (
            line.get_drawstyle() == "default"
            and line.get_markevery() is None
            and line.get_gapcolor() is None
            and line.get_sketch_params() is None
            and not line.get_path_effects()
            and not line.get_rasterized()
            and line.get_agg_filter() is None
        )
        if not plain:
            line.draw(renderer)
            return None
        held = _HELD_STYLE(line)
        recorder = _Recorder(renderer)
        line.draw(recorder)
        data = line._path  # built by the draw's recache
        calls = []
        for call in recorder.calls:
            path = call[2] if call[0] == "path" else call[4]
            if path.vertices is not data.vertices or path.codes is not None:
                return None  # transformed or cut on the way to Agg: not this line's data
            if call[0] == "path" and path is not data:
                return None
            calls.append(call)
        if not calls:
            return None
        if hasattr(renderer, "path_paint"):  # browser_drawing.CommandRecorder
            paints = [_painted(renderer, call) for call in calls]
            paints = [paint for paint in paints if paint[1] is not None]  # None: draws nothing
            return LinePaint(line, paints, held) if paints else None
        return cls(line, calls, held)

    def draw(self, renderer: Any) -> bool:
        """Draw the line with its current data as its recorded draw would; False if it cannot."""
        line = self.line
        if not _holds(line, self.held):
            return False
        if line._invalidx or line._invalidy:  # as Line2D.draw: the path from the new data
            line.recache()
        if line._subslice:
            return False
        path = line._path
        if len(path.vertices) == 0:
            return False
        for call in self.calls:
            if call[0] == "path":
                _, gc, _, transform, face = call
                renderer.draw_path(gc, path, transform, face)
            else:
                _, gc, marker_path, marker_trans, _, trans, face = call
                points = MatplotlibPath._fast_from_codes_and_verts(path.vertices, None, path)
                renderer.draw_markers(gc, marker_path, marker_trans, points, trans, face)
        line.stale = False
        return True


class LinePaint:
    """A moving line's browser commands: its paints read once, its new vertices at each step.

    What ``CommandRecorder`` reads from a line's graphics contexts and
    transforms (its *paints*) is read at the recording; :meth:`draw` checks
    that the line still holds the style it was recorded with (the same
    objects: :data:`_HELD_STYLE`) and adds the commands of its new data
    (``CommandRecorder.add_line``, ``add_markers``). A lesson's drag moves
    seven such lines at every step, so this is all a step spends on one.
    """

    def __init__(self, line: Line2D, paints: list[tuple], held: tuple) -> None:
        self.line, self.paints, self.held = line, paints, held

    def draw(self, recorder: Any) -> bool:
        """Add the line's commands with its current data; False if it must be recorded anew."""
        line = self.line
        if not self.holds_style():
            return False
        vertices = _data_vertices(line)
        if vertices is None or len(vertices) == 0:
            return False
        self.draw_vertices(recorder, vertices)
        line.stale = False
        return True

    def draw_vertices(self, recorder: Any, vertices: np.ndarray) -> None:
        """Add the commands of the line through ``vertices``, (N, 2) data, N > 0, finite.

        What :meth:`draw` adds for a line whose data are those vertices; the
        line itself is not read (:class:`~course.widgets.array_step.ArrayStep`).
        """
        for kind, paint in self.paints:
            if kind == "path paint":
                recorder.add_line(paint, vertices)
            else:
                recorder.add_markers(paint, vertices)

    def holds_style(self) -> bool:
        """Whether the line still holds the style it was recorded with."""
        return _holds(self.line, self.held)


def _data_vertices(line: Line2D) -> np.ndarray | None:
    """The (N, 2) vertices ``Line2D.draw`` would draw of ``line``'s data; None if it cuts them.

    Data that are 1-D float64 arrays or short lists of floats, of the same
    length and at most 1000 points (no subslicing to the view), are all
    ``recache`` would make of them, without the conversions; the line is
    left as ``set_data`` left it, and its next full draw recaches it itself.
    Other data are recached as ``Line2D.draw`` does.
    """
    if line._invalidx or line._invalidy:
        x, y = _floats(line._xorig), _floats(line._yorig)
        if x is not None and y is not None and len(x) == len(y) <= 1000:
            vertices = np.empty((len(x), 2))
            vertices[:, 0], vertices[:, 1] = x, y
            return vertices
        line.recache()
    return None if line._subslice else line._path.vertices


def _floats(data: Any) -> np.ndarray | None:
    """``data`` as ``recache`` reads it, if a 1-D float64 array or a short list of floats."""
    if type(data) is np.ndarray:
        return data if data.dtype == np.float64 and data.ndim == 1 else None
    if type(data) is list and len(data) <= 8 and all(isinstance(v, float) for v in data):
        return np.array(data)
    return None


def _painted(recorder: Any, call: tuple) -> tuple:
    """A recorded call as the paint a ``CommandRecorder`` reads from its ``gc`` and transforms.

    The browser's commands of a call depend on the line's data only through
    its vertices: what the rest says is read once, not at every step.
    """
    if call[0] == "path":
        _, gc, _, transform, face = call
        return ("path paint", recorder.path_paint(gc, transform, face))
    _, gc, marker_path, marker_trans, _, trans, face = call
    return ("markers paint", recorder.marker_paint(gc, marker_path, marker_trans, trans, face))


def empty_line(artist: Any) -> bool:
    """Whether ``artist`` is a line without data (an unused level of a construction)."""
    return isinstance(artist, Line2D) and len(artist._xorig) == 0  # get_xdata(orig=True)
