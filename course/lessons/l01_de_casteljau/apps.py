"""Lesson 01's app: de Casteljau's construction, level by level, as t moves.

The control polygon and every intermediate level are drawn in their own
colours and markers, with the point B(t) and the curve traced from B(0) up to
B(t). Drag a control point to move it; click on empty space to add one (up to
12); double-click a point to remove it (down to 2). The points can also be
typed (``x, y; x, y; ...``, image space, y down), and the number of points
set with a slider; text, slider and picture stay in step.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import ipywidgets as widgets
import numpy as np
from matplotlib._path import affine_transform
from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.transforms import IdentityTransform

from course._validate import as_app_points, as_int, as_unit
from course.curves._bezier_fast import de_casteljau_chunked, levels_at
from course.i18n import _
from course.images import EXAMPLE_POINTS
from course.lessons.printed import degree_numeral
from course.widgets.array_step import ArrayStep
from course.widgets.base import Handle, SliderApp, format_points, parse_points
from course.widgets.text_cache import FixedText

__all__ = ["DeCasteljauApp"]

MIN_POINTS, MAX_POINTS = 2, len(EXAMPLE_POINTS)
_CURVE_SAMPLES = 201
_WHOLE_CURVE_AT = np.linspace(0.0, 1.0, _CURVE_SAMPLES)


@functools.lru_cache(maxsize=4)
def _samples(t: float) -> tuple[np.ndarray, np.ndarray]:
    """The traced part's parameters, and the whole curve's followed by them: a drag keeps t."""
    traced_at = np.linspace(0.0, t, _CURVE_SAMPLES)
    both_at = np.concatenate([_WHOLE_CURVE_AT, traced_at])
    traced_at.flags.writeable = both_at.flags.writeable = False
    return traced_at, both_at


# The handouts' 700 x 700 window: the view, unless typed points lie outside it.
_WINDOW = (0.0, 700.0)
_MARKERS = ("s", "^", "D", "v", "p", "h", "<", "*", ">", "P")
# Paul Tol's muted palette: told apart with any colour vision, and none of it
# crimson (B(t)) or orange (what the student holds).
_LEVEL_COLORS = (
    "#332288",
    "#44AA99",
    "#AA4499",
    "#117733",
    "#88CCEE",
    "#999933",
    "#882255",
    "#DDCC77",
)


class _HeldView(NamedTuple):
    """What a drag's steps read of the view, which stays as it is while a point is held."""

    t: float
    to_data: np.ndarray  # picture (x, height - y) to data: the axes' inverse transData
    to_display: np.ndarray  # data to display pixels, y up: the axes' transData
    height: float  # the figure's, in pixels
    limits: tuple[tuple[float, float], tuple[float, float]]  # get_xlim(), get_ylim()


def _numbers(point: np.ndarray) -> str:
    """B(t) as the title shows it: ``(x, y)`` to 0.1."""
    return f"({point[0]:.1f}, {point[1]:.1f})"


def _level_style(level: int) -> dict:
    """Level 0 is the control polygon; each later level has its own colour and marker."""
    if level == 0:
        return {"color": "0.35", "marker": "o", "markersize": 7, "linewidth": 1.5}
    return {
        "color": _LEVEL_COLORS[(level - 1) % len(_LEVEL_COLORS)],
        "marker": _MARKERS[(level - 1) % len(_MARKERS)],
        "markersize": 5,
        "linewidth": 1.2,
        "linestyle": "-" if level % 2 else "--",
    }


class DeCasteljauApp(SliderApp):
    """De Casteljau's algorithm at one t: every level, B(t), and the curve so far.

    Controls: ``t`` (0 to 1), ``count`` (number of control points, 2 to 12)
    and ``points`` (the control points as text). Changing ``count`` cuts the
    list or extends it with :data:`course.images.EXAMPLE_POINTS`. On the
    picture, each control point ``P0`` ... ``Pn`` can be dragged.
    """

    BLIT = True

    def __init__(self, points: np.ndarray | None = None, t: float = 0.5, size: int = 500) -> None:
        if points is None:
            start = EXAMPLE_POINTS[:4]
        else:
            start = parse_points(format_points(as_app_points(points, "points")))
            if not MIN_POINTS <= len(start) <= MAX_POINTS:
                raise ValueError(
                    _("points must hold {low} to {high} points; got {count}").format(
                        low=MIN_POINTS, high=MAX_POINTS, count=len(start)
                    )
                )
        t = as_unit(t, "t")
        size = as_int(size, "size", minimum=100, maximum=4000)
        controls = {
            "t": widgets.FloatSlider(value=t, min=0.0, max=1.0, step=0.01, description="t"),
            "count": widgets.IntSlider(
                value=len(start), min=MIN_POINTS, max=MAX_POINTS, description=_("points")
            ),
            "points": widgets.Textarea(
                value=format_points(start), description="x, y", continuous_update=False
            ),
        }
        super().__init__(controls, shape=(size, size))
        self.view.image.clickable = True
        self._syncing = False
        self._count_changed = False
        self.points = np.array(start, dtype=float)
        self._drawn_points: np.ndarray | None = None
        # True after a step drawn from arrays (drag_step): the artists still show the points
        # before it, which are not to refit the view at the release (the step's had no fit).
        self._artists_behind = False
        self._legend_count = 0
        self._title_position: tuple[float, float] = (0.5, 1.0)  # where a drag found it
        self._held_view: _HeldView | None = None  # while a point is held (drag_step)

        axes = self.figure.add_axes((0.08, 0.06, 0.9, 0.88))
        axes.tick_params(labelsize=8)
        axes.set_aspect("equal", adjustable="box")
        self.axes = axes
        (self.full_curve,) = axes.plot(
            [], [], color="0.75", linewidth=1, label=_("the whole curve")
        )
        self.level_lines: list[Line2D] = []
        for level in range(MAX_POINTS - 1):
            (line,) = axes.plot([], [], **_level_style(level))
            self.level_lines.append(line)
        (self.traced,) = axes.plot([], [], color="crimson", linewidth=2.5, label=_("B(s), s <= t"))
        (self.point_marker,) = axes.plot(
            [], [], "o", color="crimson", markersize=9, label="B(t)", zorder=5
        )
        self.labels = [
            axes.annotate(
                f"P{i}",
                (0, 0),
                xytext=(7, 7),
                textcoords="offset points",
                fontsize=9,
                color="0.2",
                visible=False,
                # Drawn wherever its point is (a drag stops at the view's edge): no test
                # of the point against the axes at every step.
                annotation_clip=False,
            )
            for i in range(MAX_POINTS)
        ]
        self.title = axes.set_title("", fontsize=10)
        # While a point is dragged only B(t)'s numbers change: the title's start is drawn
        # once into the background and the numbers beside it (text costs the most to draw),
        # placed once and laid out from their characters (FixedText).
        self.title_start = self.figure.text(
            0, 0, "", transform=IdentityTransform(), fontsize=10, visible=False
        )
        self.title_numbers = FixedText(
            0, 0, "", transform=IdentityTransform(), fontsize=10, visible=False
        )
        self.figure.add_artist(self.title_numbers)
        # Everything that moves is drawn over a cached background (blitting):
        # the axes, the ticks and the legend are drawn only when they change.
        self.animate(
            self.full_curve,
            *self.level_lines,
            self.traced,
            self.point_marker,
            *self.labels,
            self.title,
            self.title_numbers,
        )
        self.highlight_ring(axes)
        self.handle_artists = {f"P{i}": [label] for i, label in enumerate(self.labels)}

    def _on_change(self, change: dict) -> None:
        if self._syncing:  # our own write-back of count and text
            return
        self._count_changed = change["owner"] is self.controls["count"]
        self.status.value = ""
        super()._on_change(change)

    def _read_points(self) -> np.ndarray:
        """The control points the controls describe; keeps the text and count in step."""
        try:
            points = parse_points(self.value("points"))
            if len(points) < MIN_POINTS:
                raise ValueError(
                    _("at least {low} points are needed; got {count}").format(
                        low=MIN_POINTS, count=len(points)
                    )
                )
        except ValueError as error:
            self.status.value = _("Kept the last points: {error}").format(error=error)
            points = self.points  # the typed text stays, for the student to fix
        count = self.value("count")
        if self._count_changed:
            points = np.vstack([points, EXAMPLE_POINTS[len(points) : count]])[:count]
        cut = len(points) > MAX_POINTS
        if cut:
            self.status.value = _(
                "Kept the first {high} of the {count} points typed: "
                "the app draws at most {high} (degree {degree})."
            ).format(high=MAX_POINTS, count=len(points), degree=degree_numeral(MAX_POINTS - 1))
            points = points[:MAX_POINTS]
        if cut or len(points) != count or self._count_changed:
            self._write_points(points)
        self._count_changed = False
        return points

    def _write_points(self, points: np.ndarray) -> None:
        self._syncing = True
        try:
            self.controls["count"].value = len(points)
            self.controls["points"].value = format_points(points)
        finally:
            self._syncing = False

    def update(self) -> None:
        # A drag's points are the app's own (drag): the controls get them at the release.
        points = self._read_points() if self.grabbed is None else self.points
        t = float(self.value("t"))
        # The points were validated as they were read: the unchecked kernels, at every step.
        # A drag moves them at every step: the whole curve and the traced part in one call.
        traced_at, both_at = _samples(t)
        moved = self._drawn_points is None or not np.array_equal(points, self._drawn_points)
        if moved or self._artists_behind:
            both = de_casteljau_chunked(points, both_at)
            self._set_points(points, both[:_CURVE_SAMPLES], fit=moved)
            traced = both[_CURVE_SAMPLES:]
        else:
            traced = de_casteljau_chunked(points, traced_at)
        levels = levels_at(points, t)
        for line, level in zip(self.level_lines, levels[:-1], strict=False):
            line.set_data(level[:, 0], level[:, 1])
        for line in self.level_lines[len(levels) - 1 :]:
            if len(line.get_xdata(orig=True)):  # emptied once: not again at every step
                line.set_data([], [])
        point = levels[-1][0]
        self.point_marker.set_data([point[0]], [point[1]])
        self.traced.set_data(traced[:, 0], traced[:, 1])
        start = _("degree {degree}, t = {t:.2f}: B(t) = ").format(
            degree=degree_numeral(len(points) - 1), t=t
        )
        numbers = _numbers(point)
        self.title.set_text(start + numbers)
        if self.title_numbers.get_visible():
            self.title_numbers.set_text(numbers)
            if start != self.title_start.get_text():  # only a drag moves the points: never
                self.title_start.set_text(start)
                self.view.invalidate()

    def _set_points(self, points: np.ndarray, curve: np.ndarray, fit: bool = True) -> None:
        """New control points and their whole curve: the labels, and the view if they left it.

        ``fit=False`` leaves the view: points a drag's step showed already.
        """
        self.points = np.array(points, dtype=float)
        self._drawn_points = self.points.copy()
        self._artists_behind = False
        self.full_curve.set_data(curve[:, 0], curve[:, 1])
        for index, label in enumerate(self.labels):
            label.set_visible(index < len(points))
            if index < len(points):
                label.xy = tuple(points[index])
        if fit and self.grabbed is None:  # never rescale under a dragging hand
            self._fit_view(np.vstack([points, curve]))
        if len(points) != self._legend_count:
            self._legend(len(points))

    def _fit_view(self, shown: np.ndarray) -> None:
        low = np.minimum(shown.min(axis=0), _WINDOW[0])
        high = np.maximum(shown.max(axis=0), _WINDOW[1])
        centre, half = (low + high) / 2, float((high - low).max()) * 0.52
        limits = (centre[0] - half, centre[0] + half, centre[1] + half, centre[1] - half)
        if limits != (*self.axes.get_xlim(), *self.axes.get_ylim()):
            self.axes.set_xlim(limits[0], limits[1])
            self.axes.set_ylim(limits[2], limits[3])  # image space: y down
            self.view.invalidate()

    def _legend(self, count: int) -> None:
        """A legend for the levels this many points have; it lives in the background."""
        for level, line in enumerate(self.level_lines):
            line.set_label(
                _("control polygon P")
                if level == 0
                else _("level {level}").format(level=level)
                if level < count
                else ""
            )
        shown = [self.level_lines[0], *self.level_lines[1 : count - 1], self.traced]
        shown.append(self.point_marker)
        legend = self.axes.legend(
            handles=shown,
            loc="lower right",
            fontsize=7,
            ncols=2 if count > 6 else 1,
            framealpha=0.85,
        )
        legend.set_animated(False)
        self._legend_count = count
        self.view.invalidate()

    # --- dragging ---------------------------------------------------------------

    def grab_started(self, name: str) -> None:
        super().grab_started(name)
        if not self.BLIT:
            return
        # The title as two texts where it stands: its start still, its numbers redrawn.
        renderer = self.view.canvas.get_renderer()
        box = self.title.get_window_extent(renderer)
        start, numbers = self.title.get_text().split("B(t) = ")
        for text, shown in ((self.title_start, start + "B(t) = "), (self.title_numbers, numbers)):
            text.set_text(shown)
            text.set_verticalalignment("bottom")
            text.set_visible(True)  # before measuring: a hidden text has no extent
        self.title_start.set_position((box.x0, box.y0))
        after = self.title_start.get_window_extent(renderer).width
        self.title_numbers.set_position((box.x0 + after, box.y0))
        self.title.set_visible(False)
        # A whole figure drawn during the drag places the hidden title as if it had no
        # extent; the release draws it where it stood, over the background kept.
        self._title_position = self.title.get_position()
        self.view.hold([self.title_start])  # it was hidden: drawn into the background now
        axes = self.axes
        self._held_view = _HeldView(
            float(self.value("t")),
            axes.transData.inverted().get_matrix(),
            axes.transData.get_matrix(),
            self.figure.bbox.height,
            (axes.get_xlim(), axes.get_ylim()),
        )

    def grab_ended(self, name: str) -> None:
        self._held_view = None
        super().grab_ended(name)
        self.title.set_position(self._title_position)
        self.title.set_visible(True)
        self.title_start.set_visible(False)
        self.title_numbers.set_visible(False)

    def drag_step(self, name: str, x: float, y: float, offset: np.ndarray) -> bool:
        """A step of a drag drawn from the construction's arrays (ArrayStep).

        What :meth:`drag` and :meth:`update` do at a step, without the
        artists: the point moves as :meth:`drag` moves it, and the levels, the
        curve, B(t), the label, B(t)'s numbers and the highlight ring go to the
        browser with the paints their last step recorded. The artists get the
        new points at the next :meth:`update` (the release's at the latest).
        """
        held = self._held_view
        if held is None or float(self.value("t")) != held.t:
            return False  # a new t: drawn the usual way, which moves the title's start
        index = int(name[1:])
        label = self.labels[index]
        ring = self.highlight_ring(self.axes)[0]
        levels_drawn = self.level_lines[: len(self.points) - 1]
        shapes = {self.full_curve, *levels_drawn, self.traced, self.point_marker, ring}
        step = ArrayStep.start(self.view, self.moving, {*shapes, label, self.title_numbers})
        if step is None:
            return False
        # As data_point and drag: the matrices the axes' transforms use, read at the press.
        point = affine_transform(np.array([[x, held.height - y]]), held.to_data)[0] - offset
        points = self.points.copy()
        points[index] = self._inside_view(point, held.limits)
        self.points, self._drawn_points, self._artists_behind = points, points.copy(), True
        _, both_at = _samples(held.t)
        both = de_casteljau_chunked(points, both_at)
        levels = levels_at(points, held.t)
        lines = dict(zip(levels_drawn, levels, strict=False))
        lines[self.full_curve], lines[self.traced] = both[:_CURVE_SAMPLES], both[_CURVE_SAMPLES:]
        lines[self.point_marker], lines[ring] = levels[-1], points[index : index + 1]
        anchor = affine_transform(points[index : index + 1], held.to_display)[0]
        numbers = _numbers(levels[-1][0])
        # The titles' texts stay the app's state, as update sets them.
        self.title.set_text(self.title_start.get_text() + numbers)
        self.title_numbers.set_text(numbers)
        if step.draw(lines, {label: anchor}, {self.title_numbers: numbers}):
            step.send()
            self.renders += 1
        else:
            self.refresh()  # a string FixedText does not place: drawn the usual way
        return True

    def handles(self) -> list[Handle]:
        return [Handle(f"P{i}", self.axes, tuple(p)) for i, p in enumerate(self.points)]

    def drag(self, name: str, point: np.ndarray) -> None:
        index = int(name[1:])
        points = self.points.copy()
        points[index] = self._inside_view(point)
        # The steps of a drag show the points; the release writes them (grab_ended
        # comes first): formatting and parsing them again at every step bought nothing.
        if self.grabbed is None:
            self._write_points(points)
        else:
            self.points = points

    def click(self, axes: Axes, point: np.ndarray) -> bool:
        """A click on empty space adds a point there, at the end of the list."""
        if len(self.points) >= MAX_POINTS:
            self.status.value = _("At most {high} points: double-click one to remove it.").format(
                high=MAX_POINTS
            )
            return False
        self._write_points(np.vstack([self.points, self._inside_view(point)]))
        return True

    def double_click(self, name: str) -> bool:
        """A double click on a point removes it, down to two points."""
        if len(self.points) <= MIN_POINTS:
            self.status.value = _("At least {low} points: a curve needs two ends.").format(
                low=MIN_POINTS
            )
            return False
        self._write_points(np.delete(self.points, int(name[1:]), axis=0))
        return True

    def _inside_view(self, point: np.ndarray, limits: tuple | None = None) -> np.ndarray:
        """The point, kept inside the view (a drag past the edge stops at it), rounded to 0.1.

        ``limits``: the view's ``(get_xlim(), get_ylim())``, if read already.
        """
        (x0, x1), (y1, y0) = limits or (self.axes.get_xlim(), self.axes.get_ylim())
        x = min(max(float(point[0]), min(x0, x1)), max(x0, x1))
        y = min(max(float(point[1]), min(y0, y1)), max(y0, y1))
        return np.round([x, y], 1)
