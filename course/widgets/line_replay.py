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

from typing import Any

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.path import Path as MatplotlibPath

__all__ = ["LineReplay", "empty_line"]

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


def _line_style(line: Line2D) -> tuple:
    """What a line's Agg calls depend on besides its data: a change means a new recording."""
    return (
        line.get_visible(),
        str(line.get_color()),
        line.get_linewidth(),
        line.get_linestyle(),
        str(line.get_marker()),
        line.get_markersize(),
        str(line.get_markerfacecolor()),
        str(line.get_markeredgecolor()),
        line.get_markeredgewidth(),
        line.get_alpha(),
        line.get_antialiased(),
        line.get_clip_on(),
        id(line.get_transform()),
    )


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
    False) once the line's style differs from the recorded. A new view
    (limits, axes moved) comes with
    :meth:`~course.widgets.figure_view.FigureView.invalidate`, as the
    cached background needs it too, and that drops every recording.
    """

    def __init__(self, line: Line2D, calls: list[tuple], style: tuple) -> None:
        self.line, self.calls, self.style = line, calls, style

    @classmethod
    def record(cls, line: Line2D, renderer: Any) -> LineReplay | None:
        """Draw ``line`` into ``renderer``; return its replay, or None if it cannot have one."""
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
        style = _line_style(line)
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
        if hasattr(renderer, "path_paint"):  # browser_drawing.CommandRecorder
            painted = (_painted(renderer, call) for call in calls)
            calls = [call for call in painted if call[1] is not None]  # None: draws nothing
        return cls(line, calls, style) if calls else None

    def draw(self, renderer: Any) -> bool:
        """Draw the line with its current data as its recorded draw would; False if it cannot."""
        line = self.line
        if _line_style(line) != self.style:
            return False
        # A CommandRecorder's paints need only the vertices; Agg's calls, the line's path.
        path = _fresh_path(line) if self.calls[0][0].endswith("paint") else None
        if path is None:
            if line._invalidx or line._invalidy:  # as Line2D.draw: the path from the new data
                line.recache()
            if line._subslice:
                return False
            path = line._path
        if len(path.vertices) == 0:
            return False
        for call in self.calls:
            kind = call[0]
            if kind == "path":
                _, gc, _, transform, face = call
                renderer.draw_path(gc, path, transform, face)
            elif kind == "markers":
                _, gc, marker_path, marker_trans, _, trans, face = call
                points = MatplotlibPath._fast_from_codes_and_verts(path.vertices, None, path)
                renderer.draw_markers(gc, marker_path, marker_trans, points, trans, face)
            elif kind == "path paint":
                renderer.add_path(call[1], path)
            else:  # "markers paint"
                renderer.add_markers(call[1], path)
        line.stale = False
        return True


def _fresh_path(line: Line2D) -> MatplotlibPath | None:
    """The path ``Line2D.recache`` would build of ``line``'s new data, where that is all it does.

    That is, for data that are 1-D float64 arrays or lists of floats, of the
    same length and at most 1000 points (no subslicing to the view):
    ``recache`` converts units (none for floats) and stacks them. The line
    is left as ``set_data`` left it: its next full draw recaches it itself.
    None when ``recache`` must run.
    """
    if not (line._invalidx or line._invalidy):
        return None  # recached already
    x, y = _floats(line._xorig), _floats(line._yorig)
    if x is None or y is None or not len(x) == len(y) <= 1000:
        return None
    return MatplotlibPath(np.column_stack((x, y)))


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
    return isinstance(artist, Line2D) and len(artist.get_xdata(orig=True)) == 0
