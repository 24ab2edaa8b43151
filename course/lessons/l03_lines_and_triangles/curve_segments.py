"""The lab's Task 7 as an app: a cubic drawn as Bresenham segments, against the curve itself.

:class:`CurveSegmentsApp` draws the report's curve as ``segments`` straight
lines on a 40 x 40 grid and marks the pixels that stray off the curve, the
stretches of curve no pixel covers, and the joints drawn twice, with those
counts for 1 to 64 segments beside it
(:func:`course.curves.bezier_handouts.segments_report`). The notebook imports
it from :mod:`.apps`, which lists every app of the lesson.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from course._validate import as_app_points, as_int
from course.curves.bezier import de_casteljau
from course.curves.bezier_handouts import bresenham_curve, segments_report
from course.i18n import _
from course.images import EXAMPLE_POINTS
from course.lessons.l03_lines_and_triangles.grid import pixel_grid
from course.widgets.base import Handle, SliderApp, format_points
from course.widgets.picture import PixelPanel, pixel_axes

__all__ = ["CURVE_GRID", "CurveSegmentsApp"]

CURVE_GRID = 40
_SEGMENT_COUNTS = (1, 2, 4, 8, 16, 32, 64)
# Who draws a pixel: nobody, the segments on the curve, the segments off it,
# or nobody although the curve is more than a pixel from every drawn one.
_DRAWN = ListedColormap(["white", "black", "#D55E00", "#56B4E9"])


class CurveSegmentsApp(SliderApp):
    """The lab's Task 7: a cubic drawn as ``segments`` Bresenham lines, against the curve.

    Left, the pixels on a 40 x 40 grid, ten screen pixels each: black where
    a line pixel lies on the curve, vermillion where the lines stray off it,
    sky blue where the curve is more than a pixel from every drawn pixel; a
    white dot marks a pixel drawn twice (the joints). The blue line is the
    true curve; drag its control points. Right, those counts for 1 to 64
    segments (:func:`course.curves.bezier_handouts.segments_report`).
    """

    BLIT = True
    ZOOM = 10

    def __init__(self, points: np.ndarray | None = None, segments: int = 4) -> None:
        if points is None:
            start = EXAMPLE_POINTS[:4] * (CURVE_GRID / 700)
        else:
            start = as_app_points(points, "points", low=0, high=CURVE_GRID)
            if len(start) < 2:
                raise ValueError(
                    _("points must hold at least 2 points; got {start_count}").format(
                        start_count=len(start)
                    )
                )
        segments = as_int(segments, "segments", minimum=1, maximum=max(_SEGMENT_COUNTS))
        self.control = np.round(np.asarray(start, dtype=float), 1)
        controls = {
            "segments": widgets.IntSlider(
                value=segments, min=1, max=max(_SEGMENT_COUNTS), description=_("segments")
            ),
            "points": widgets.Textarea(
                value=format_points(self.control), description="x, y", continuous_update=False
            ),
        }
        super().__init__(controls, shape=(500, 900))
        side = CURVE_GRID * self.ZOOM  # the grid at an integer zoom: 10 screen pixels each
        grid_axes = pixel_axes(self.figure, 40, 60, side, side)
        grid_lines = pixel_grid(grid_axes, CURVE_GRID)
        grid_axes.set_xticks(np.arange(0, CURVE_GRID + 1, 8))
        grid_axes.set_yticks(np.arange(0, CURVE_GRID + 1, 8))
        self.grid_axes = grid_axes
        self.pixels = PixelPanel(
            self, grid_axes, (CURVE_GRID, CURVE_GRID), self.ZOOM, _DRAWN, vmin=0, vmax=3
        )
        (self.twice,) = grid_axes.plot(
            [], [], "o", color="white", markeredgecolor="0.3", markersize=3.5
        )
        grid_axes.legend(
            handles=[
                Patch(facecolor=_DRAWN.colors[1], edgecolor="0.5", label=_("drawn, on the curve")),
                Patch(facecolor=_DRAWN.colors[2], edgecolor="0.5", label=_("drawn, off the curve")),
                Patch(
                    facecolor=_DRAWN.colors[3],
                    edgecolor="0.5",
                    label=_("curve missed (> 1 px away)"),
                ),
                Line2D(
                    [],
                    [],
                    marker="o",
                    color="white",
                    mec="0.3",
                    ls="",
                    ms=4,
                    label=_("drawn twice"),
                ),
                Line2D([], [], color="#0072B2", lw=1.5, label=_("the curve")),
            ],
            loc="upper center",
            bbox_to_anchor=(0.5, -0.05),
            ncols=3,
            fontsize=7,
            frameon=False,
        )
        (self.polygon,) = grid_axes.plot([], [], "o--", color="0.45", markersize=6, linewidth=1)
        (self.curve,) = grid_axes.plot([], [], color="#0072B2", linewidth=1.5)
        self.labels = [
            grid_axes.annotate(f"P{i}", (0, 0), xytext=(6, 6), textcoords="offset points")
            for i in range(len(self.control))
        ]
        chart = pixel_axes(self.figure, 520, 90, 350, 370)
        chart.set_xscale("log", base=2)
        chart.set_xticks(_SEGMENT_COUNTS, [str(n) for n in _SEGMENT_COUNTS])
        chart.set_xlabel(_("segments"), fontsize=9)
        chart.set_ylabel(_("pixels"), fontsize=9)
        chart.tick_params(labelsize=8)
        self.counts = {
            "off": chart.plot([], [], "s-", color="#D55E00", label=_("off the curve"))[0],
            "missed": chart.plot([], [], "^--", color="#56B4E9", label=_("curve missed"))[0],
            "twice": chart.plot([], [], "o:", color="0.2", label=_("drawn twice"))[0],
        }
        self.now = chart.axvline(segments, color="0.6", linewidth=1)
        chart.legend(fontsize=8, loc="upper center")
        self.chart = chart
        self.animate(
            grid_lines,
            self.twice,
            self.polygon,
            self.curve,
            *self.labels,
            grid_axes.title,
            *self.counts.values(),
            self.now,
        )
        self.highlight_ring(grid_axes)
        self.handle_artists = {f"P{i}": [label] for i, label in enumerate(self.labels)}

    def read_control(self) -> np.ndarray:
        """The control points, as the text describes them."""
        self.control = self.typed_points("points", self.control, len(self.control), 0, CURVE_GRID)
        return self.control

    def update(self) -> None:
        control = self.read_control()
        segments = int(self.value("segments"))
        report = segments_report(control, segments)
        picture = np.zeros((CURVE_GRID, CURVE_GRID))
        drawn = bresenham_curve(control, segments)
        painted, counts = np.unique(drawn, axis=0, return_counts=True)
        for pixels, code in ((painted, 1), (report["off_pixels"], 2), (report["missed_pixels"], 3)):
            inside = (pixels >= 0).all(axis=1) & (pixels < CURVE_GRID).all(axis=1)
            picture[pixels[inside, 1], pixels[inside, 0]] = code
        self.pixels.set_data(picture)
        doubled = painted[counts > 1] + 0.5
        self.twice.set_data(doubled[:, 0], doubled[:, 1])
        self.polygon.set_data(control[:, 0], control[:, 1])
        curve = de_casteljau(control, np.linspace(0.0, 1.0, 200))
        self.curve.set_data(curve[:, 0], curve[:, 1])
        for label, point in zip(self.labels, control, strict=True):
            label.xy = tuple(point)
        self.grid_axes.set_title(
            _(
                "{segments} segments: {pixels} pixels, {twice} drawn twice\n"
                "{off} off the curve, {missed} of its {curve} missed"
            ).format(segments=segments, **report),
            fontsize=9,
        )
        sweep = [segments_report(control, n) for n in _SEGMENT_COUNTS]
        for key, plotted in self.counts.items():
            plotted.set_data(_SEGMENT_COUNTS, [row[key] for row in sweep])
        self.chart.set_ylim(
            0, max(max(row["twice"], row["off"], row["missed"]) for row in sweep) + 4
        )
        self.now.set_xdata([segments, segments])

    def handles(self) -> list[Handle]:
        return [Handle(f"P{i}", self.grid_axes, tuple(p)) for i, p in enumerate(self.control)]

    def drag(self, name: str, point: np.ndarray) -> None:
        control = self.control.copy()
        control[int(name[1:])] = np.clip(np.round(point, 1), 0, CURVE_GRID)
        self.controls["points"].value = format_points(control)
