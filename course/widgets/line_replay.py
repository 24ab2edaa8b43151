"""A moving line drawn by replaying the Agg calls of its last full draw with its new data.

At every step of a drag, :class:`~course.widgets.figure_view.FigureView` draws
the moving lines again; :class:`LineReplay` spares it most of what
``Line2D.draw`` spends in Python, for Agg and for the browser's drawing
commands (:mod:`course.widgets.browser_drawing`) alike, and :func:`empty_line`
tells it which lines have nothing to draw.

``FigureView`` is this module's only caller, with artists the apps made
(``UNCHECKED = True``).
"""

from __future__ import annotations

from typing import Any

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
        return cls(line, calls, style) if calls else None

    def draw(self, renderer: Any) -> bool:
        """Draw the line with its current data as its recorded draw would; False if it cannot."""
        line = self.line
        if _line_style(line) != self.style:
            return False
        if line._invalidx or line._invalidy:  # as Line2D.draw: the path from the new data
            line.recache()
        path = line._path
        if len(path.vertices) == 0 or line._subslice:
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


def empty_line(artist: Any) -> bool:
    """Whether ``artist`` is a line without data (an unused level of a construction)."""
    return isinstance(artist, Line2D) and len(artist.get_xdata(orig=True)) == 0
