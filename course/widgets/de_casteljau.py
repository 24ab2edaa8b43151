"""Lesson 01's app: de Casteljau's construction, level by level, as t moves.

The control polygon and every intermediate level are drawn in their own
colours, with the point B(t) and the curve traced from B(0) up to B(t).
Control points are edited as text (``x, y; x, y; ...``, image space, y
down), and the number of points goes from 2 to 12; seed 000's four points
are the default.
"""

from __future__ import annotations

import re

import ipywidgets as widgets
import matplotlib
import numpy as np

from course.bezier import de_casteljau, de_casteljau_levels
from course.images import EXAMPLE_POINTS
from course.widgets.base import SliderApp

__all__ = ["DeCasteljauApp", "format_points", "parse_points"]

MIN_POINTS, MAX_POINTS = 2, len(EXAMPLE_POINTS)
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_CURVE_SAMPLES = 201


def parse_points(text: str) -> np.ndarray:
    """Read ``"x, y; x, y; ..."`` (any separators) into an (N, 2) array.

    Examples
    --------
    >>> parse_points("10, 10; 690, 10.5; (3, 4)")
    array([[ 10. ,  10. ],
           [690. ,  10.5],
           [  3. ,   4. ]])
    """
    numbers = [float(value) for value in _NUMBER.findall(text)]
    if len(numbers) % 2:
        raise ValueError(f"points need an x and a y each; got {len(numbers)} numbers")
    if len(numbers) < 2 * MIN_POINTS:
        raise ValueError(f"at least {MIN_POINTS} points are needed; got {len(numbers) // 2}")
    return np.array(numbers).reshape(-1, 2)


def format_points(points: np.ndarray) -> str:
    """The text form :func:`parse_points` reads.

    Examples
    --------
    >>> format_points(np.array([[10.0, 10.0], [2.5, 3.0]]))
    '10, 10; 2.5, 3'
    """
    return "; ".join(f"{x:g}, {y:g}" for x, y in points)


class DeCasteljauApp(SliderApp):
    """De Casteljau's algorithm at one t: every level, B(t), and the curve so far.

    Controls: ``t`` (0 to 1), ``count`` (number of control points, 2 to 12)
    and ``points`` (the control points as text). Changing ``count`` cuts the
    list or extends it with :data:`EXAMPLE_POINTS`.
    """

    def __init__(self, points: np.ndarray | None = None, t: float = 0.5, size: int = 500) -> None:
        start = EXAMPLE_POINTS[:4] if points is None else parse_points(format_points(points))
        controls = {
            "t": widgets.FloatSlider(value=t, min=0.0, max=1.0, step=0.01, description="t"),
            "count": widgets.IntSlider(
                value=len(start), min=MIN_POINTS, max=MAX_POINTS, description="points"
            ),
            "points": widgets.Textarea(
                value=format_points(start), description="x, y", continuous_update=False
            ),
        }
        super().__init__(controls, shape=(size, size))
        self.status = widgets.Label()
        self.widget.children[1].children += (self.status,)
        self._syncing = False
        self._count_changed = False
        self.points = start
        self._drawn_points: np.ndarray | None = None

        axes = self.figure.add_axes((0.08, 0.06, 0.9, 0.88))
        axes.invert_yaxis()  # image space: y down
        axes.tick_params(labelsize=8)
        self.axes = axes
        colors = matplotlib.colormaps["tab10"](np.arange(MAX_POINTS - 1) % 10)
        (self.full_curve,) = axes.plot([], [], color="0.8", linewidth=1)
        self.level_lines = []
        for level in range(MAX_POINTS - 1):
            (line,) = axes.plot(
                [],
                [],
                color="0.35" if level == 0 else colors[level - 1],
                marker="o",
                markersize=6 if level == 0 else 4,
                linewidth=1.5 if level == 0 else 1,
            )
            self.level_lines.append(line)
        (self.traced,) = axes.plot([], [], color="crimson", linewidth=2.5)
        (self.point_marker,) = axes.plot([], [], "o", color="crimson", markersize=9)
        self.title = axes.set_title("", fontsize=10)
        # Everything that moves with t is drawn over a cached background
        # (blitting): the axes, ticks and the faint full curve are drawn only
        # when the control points change.
        self._moving = [*self.level_lines, self.traced, self.point_marker, self.title]
        for artist in self._moving:
            artist.set_animated(True)

    def refresh(self) -> bytes:
        """Update the artists and render the picture, redrawing only what moved."""
        self.update()
        self.renders += 1
        return self.view.render_moving(self._moving)

    def _on_change(self, change: dict) -> None:
        if self._syncing:  # our own write-back of count and text
            return
        self._count_changed = change["owner"] is self.controls["count"]
        super()._on_change(change)

    def _read_points(self) -> np.ndarray:
        """The control points the controls describe; keeps the text and count in step."""
        try:
            points = parse_points(self.value("points"))
        except ValueError as error:
            self.status.value = f"Kept the last points: {error}"
            points = self.points
        else:
            self.status.value = ""
        count = self.value("count")
        if self._count_changed:
            points = np.vstack([points, EXAMPLE_POINTS[len(points) : count]])[:count]
        points = points[:MAX_POINTS]
        if len(points) != count or self._count_changed:
            self._syncing = True
            try:
                self.controls["count"].value = len(points)
                self.controls["points"].value = format_points(points)
            finally:
                self._syncing = False
        return points

    def update(self) -> None:
        points = self._read_points()
        if self._drawn_points is None or not np.array_equal(points, self._drawn_points):
            self._set_points(points)
        t = float(self.value("t"))
        levels = de_casteljau_levels(points, t)
        for line, level in zip(self.level_lines, levels[:-1], strict=False):
            line.set_data(level[:, 0], level[:, 1])
        for line in self.level_lines[len(levels) - 1 :]:
            line.set_data([], [])
        point = levels[-1][0]
        self.point_marker.set_data([point[0]], [point[1]])
        traced = de_casteljau(points, np.linspace(0.0, t, _CURVE_SAMPLES))
        self.traced.set_data(traced[:, 0], traced[:, 1])
        self.title.set_text(
            f"degree {len(points) - 1}, t = {t:.2f}: B(t) = ({point[0]:.1f}, {point[1]:.1f})"
        )

    def _set_points(self, points: np.ndarray) -> None:
        """New control points: refit the view and redraw the whole curve faintly."""
        self.points = points
        self._drawn_points = points
        self.view.invalidate()
        curve = de_casteljau(points, np.linspace(0.0, 1.0, _CURVE_SAMPLES))
        self.full_curve.set_data(curve[:, 0], curve[:, 1])
        low = np.minimum(points.min(axis=0), curve.min(axis=0))
        high = np.maximum(points.max(axis=0), curve.max(axis=0))
        centre, half = (low + high) / 2, max(float((high - low).max()) * 0.55, 1.0)
        self.axes.set_xlim(centre[0] - half, centre[0] + half)
        self.axes.set_ylim(centre[1] + half, centre[1] - half)
