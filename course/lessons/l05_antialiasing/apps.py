"""Lesson 05's apps: zoomed pixel views of anti-aliased curves.

:class:`ZoomApp` shows the same window of several renderings side by side,
each pixel a flat square (nearest interpolation), with the pixel grid and
the true curve drawn on top; a slider moves the window along the curve and
drop-downs pick the variants. :class:`StepApp` changes the t step of a
splat method and shows the gaps at coarse steps, the saturation at fine
ones, and the brightness per unit length along the whole curve. Both are
built from :mod:`.zoom_panel`'s pieces, whose :func:`~.zoom_panel.zoom_figure`
is the still version of the zoomed comparison.
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from course import limits
from course._validate import as_curve, as_int, as_positive_float, as_shape
from course.antialias import SPLATS, WEIGHTINGS, render
from course.antialias._reference import polyline_coverage
from course.antialias.curve_quality import (
    AGG,
    ARC_LENGTH,
    REFERENCE,
    VARIANTS,
    intensity_along,
    uniformity,
)
from course.antialias.windows import render_windows
from course.i18n import N_, _
from course.images import SEED_000_CUBIC, SEED_000_SHAPE
from course.lessons.l05_antialiasing.measurements import WEIGHTING_LABELS
from course.lessons.l05_antialiasing.zoom_panel import CurveWalk, ZoomPanel
from course.metrics import rmse
from course.raster.canvas import crop_extent
from course.widgets.base import Handle, SliderApp, format_points
from course.widgets.picture import bare_axes

__all__ = [
    "VARIANT_LABELS",
    "ZOOM_PICKS",
    "StepApp",
    "ZoomApp",
    "label_of",
]


# Shown through _ where they are used: the zoom app's slots.
_SHOWN_NAMES = (N_("left"), N_("middle"), N_("right"))

#: The three variants the lesson's zoom app starts with: seed 000's three splats.
ZOOM_PICKS = ("bilinear_zero_offset", "bilinear_corners", "bilinear_centres")

#: Short names by role, for drop-downs and panel titles (the library's names are identifiers).
VARIANT_LABELS = {
    "nearest_truncate": N_("plain loop, truncated"),
    "nearest_round": N_("plain loop, rounded"),
    "bilinear_zero_offset": N_("GAMES101 left"),
    "bilinear_corners": N_("GAMES101 middle"),
    "bilinear_centres": N_("GAMES101 right"),
    "subsample_falloff": N_("any-degree falloff"),
    "normalised_centres": N_("VS2022 splat"),
    "stroke_linear": N_("stroke distance"),
    "stroke_area": N_("stroke area"),
    AGG: N_("Agg (matplotlib)"),
    REFERENCE: N_("exact coverage"),
}


def label_of(name: str) -> str:
    """The short name of a variant by role: ``label_of("bilinear_centres + arc length")``.

    Examples
    --------
    >>> label_of("bilinear_centres"), label_of("bilinear_centres + arc length")
    ('GAMES101 right', 'GAMES101 right, by length')
    """
    if isinstance(name, str) and name.endswith(ARC_LENGTH):
        base = name[: -len(ARC_LENGTH)]
        if base in VARIANT_LABELS:
            return _("{label}, by length").format(label=_(VARIANT_LABELS[base]))
    if isinstance(name, str) and name in VARIANT_LABELS:
        return _(VARIANT_LABELS[name])
    names = ", ".join(repr(key) for key in VARIANT_LABELS)
    raise ValueError(
        _("name must be one of {names}, or one of them followed by {suffix}; got {name}").format(
            names=names, suffix=repr(ARC_LENGTH), name=repr(name)
        )
    )


class ZoomApp(SliderApp):
    """Three variants and the exact reference, zoomed where a window sits on the curve.

    Left, the whole curve on its canvas with its control polygon and the
    window; drag a control point and every panel follows, each redrawn in
    its window alone (:func:`course.antialias.windows.render_windows`). The
    window sits ``position`` of the way along the curve (by arc length) and
    shows ``size`` x ``size`` pixels, each a flat square at an integer zoom;
    drop-downs pick the variants of :data:`course.antialias.curve_quality.VARIANTS`.
    The control points can be typed too. The reference takes ``k`` x ``k``
    samples a pixel (16 x 16 while a point is dragged, of the app's own
    polyline where it passes the window: see :meth:`_dragged_reference`).
    """

    BLIT = True
    PANEL = 192  # screen pixels per panel: every window size divides it
    SIZES = (6, 8, 12, 16, 24, 32, 48)

    def __init__(
        self,
        points: Any = SEED_000_CUBIC,
        shape: tuple[int, int] = SEED_000_SHAPE,
        picks: tuple[str, str, str] = ZOOM_PICKS,
        width: float = 1.0,
        k: int = 32,
    ) -> None:
        valid = isinstance(picks, (tuple, list)) and len(picks) == 3
        unknown = [name for name in picks if name not in VARIANTS] if valid else [picks]
        if unknown or not valid:
            raise ValueError(
                _(
                    "picks must be three names from course.antialias.curve_quality.VARIANTS; "
                    "got {picks}"
                ).format(picks=repr(picks))
            )
        self.shape = as_shape(shape)
        self.points, clipped = self._on_canvas(as_curve(points))
        self.stroke_width = as_positive_float(width, "width", largest=100.0)
        self.k = as_int(k, "k", minimum=1, maximum=limits.MAX_RATE)
        self.walk = CurveWalk(self.points)
        controls: dict[str, widgets.ValueWidget] = {
            "position": widgets.FloatSlider(
                value=0.1, min=0.0, max=1.0, step=0.005, description=_("along curve")
            ),
            "size": widgets.SelectionSlider(
                options=self.SIZES, value=16, description=_("window px")
            ),
        }
        for slot, name in zip(("left", "middle", "right"), picks, strict=True):
            controls[slot] = widgets.Dropdown(
                options=[(label_of(variant), variant) for variant in VARIANTS],
                value=name,
                description=_(slot),
            )
        controls["points"] = widgets.Textarea(
            value=format_points(self.points), description="x, y", continuous_update=False
        )
        panel, gap, margin = self.PANEL, 14, 10
        columns = margin + 280 + 2 * gap + 4 * panel + 3 * gap + margin
        rows = 300
        super().__init__(controls, shape=(rows, columns))
        overview = self.figure.add_axes(
            (margin / columns, margin / rows, 280 / columns, 280 / rows), aspect="equal"
        )
        overview.set_xlim(0, shape[1])
        overview.set_ylim(shape[0], 0)
        bare_axes(overview)
        (self.overview_curve,) = overview.plot([], [], color="#e8502f", linewidth=1.2)
        (self.polygon,) = overview.plot([], [], "o--", color="0.4", markersize=6, linewidth=0.8)
        self.window_box = Rectangle((0, 0), 0, 0, fill=False, edgecolor="#3a6ea5", linewidth=1.5)
        overview.add_patch(self.window_box)
        # Never hidden by their point (kept on the canvas anyway): a drag then moves a
        # label's recorded text with its point (TextReplay), not laid out anew.
        self.labels = [
            overview.annotate(
                f"P{i}",
                (0, 0),
                xytext=(4, 4),
                textcoords="offset points",
                fontsize=8,
                annotation_clip=False,
            )
            for i in range(len(self.points))
        ]
        self.overview = overview
        self.panels = []
        for index in range(4):
            left = margin + 280 + 2 * gap + index * (panel + gap)
            axes = self.figure.add_axes((left / columns, 8 / rows, panel / columns, panel / rows))
            self.panels.append(ZoomPanel(axes, self.walk.polyline, app=self))
        self.animate(
            self.overview_curve,
            self.polygon,
            self.window_box,
            *self.labels,
            *(artist for zoom in self.panels for artist in zoom.artists()),
        )
        self.highlight_ring(overview)
        self.handle_artists = {f"P{i}": [label] for i, label in enumerate(self.labels)}
        self.windows: list[np.ndarray] = []
        self._titles: list[str] = []
        self.status.value = clipped

    def centre(self) -> np.ndarray:
        """The window's centre: the curve point at the position slider."""
        return self.walk.at(self.value("position"))

    def read_points(self) -> np.ndarray:
        """The control points, as the text describes them, kept on the canvas."""
        points, clipped = self._on_canvas(
            self.typed_points("points", self.points, len(self.points))
        )
        if clipped:
            self.status.value = clipped
        # A dragged curve's walk is the quick one; the release walks it the usual way.
        dragged = self.grabbed is not None
        if not np.array_equal(points, self.points) or self.walk.quick != dragged:
            self.points = points
            self.walk = CurveWalk(points, quick=dragged)
        return self.points

    def _on_canvas(self, points: np.ndarray) -> tuple[np.ndarray, str]:
        """The points clipped to the canvas, as a drag keeps them, and what was clipped.

        Every picture the app draws lies on the canvas, and the work of
        drawing a curve grows with its length: a control point typed a
        million pixels away would make a curve millions of pixels long, whose
        reference alone takes minutes and gigabytes. So the app draws the
        points clipped to the canvas and says which it moved (the text keeps
        what was typed, for the student to change).
        """
        height, width = self.shape
        inside = np.clip(points, 0.0, (width, height))
        moved = np.flatnonzero((inside != points).any(axis=1))
        if not len(moved):
            return inside, ""
        names = ", ".join(f"P{i}" for i in moved)
        return inside, _(
            "Clipped {names} to the {width} x {height} canvas (x from 0 to {width}, "
            "y from 0 to {height}), where the app draws: {points}"
        ).format(names=names, width=width, height=height, points=format_points(inside[moved]))

    def update(self) -> None:
        points = self.read_points()
        self.overview_curve.set_data(*self.walk.polyline.T)
        self.polygon.set_data(points[:, 0], points[:, 1])
        for label, point in zip(self.labels, points, strict=True):
            label.xy = tuple(point)
        centre, size = self.centre(), self.value("size")
        extent = crop_extent(self.shape, centre, size)
        left, right, bottom, top = extent
        # In the window's pixels from its corner: the panels' data (ZoomPanel).
        line, gaps = self._near_pieces(extent)
        line = line - (left, top)
        titles = [self.value(slot) for slot in ("left", "middle", "right")]
        drawn = titles if self.grabbed is not None else [*titles, REFERENCE]
        k = self.k if self.grabbed is None else min(self.k, 16)
        windows, _extent = render_windows(
            drawn, points, self.shape, centre, size, self.stroke_width, k
        )
        if self.grabbed is None:
            truth = windows[3]
        else:
            truth = self._dragged_reference(line, gaps, (bottom - top, right - left), k)
        near = np.insert(line, np.flatnonzero(gaps) + 1, np.nan, axis=0)
        bounds = (left, top, right - left, bottom - top)
        if self.window_box.get_bbox().bounds != bounds:  # set_bounds always marks it changed
            self.window_box.set_bounds(*bounds)
        self.windows = []
        for zoom, name, window in zip(self.panels, titles, windows, strict=False):
            zoom.curve.set_data(near[:, 0], near[:, 1])
            note = _("RMSE here {error:.3f}").format(error=rmse(window, truth))
            self.windows.append(zoom.show_checked(window, extent, label_of(name), note))
        self.panels[3].curve.set_data(near[:, 0], near[:, 1])
        note = _("{k} x {k} samples a pixel").format(k=k)
        self.windows.append(self.panels[3].show_checked(truth, extent, label_of(REFERENCE), note))
        if [panel.title.get_text() for panel in self.panels] != self._titles:
            self._titles = [panel.title.get_text() for panel in self.panels]
            self.view.invalidate()  # the titles are part of the still background

    def _near_pieces(self, extent: tuple[int, int, int, int]) -> tuple[np.ndarray, np.ndarray]:
        """The pieces of the curve's polyline around the window, and the gaps between them.

        A few dozen vertices: every segment within 2 pixels of the window and
        its neighbours (the polyline's segments are at most a pixel long). The
        panels draw them, a NaN row in each gap: a drag's step sends them as
        they are (the whole polyline, NaN but near the window, was cut down by
        matplotlib at every step). ``gaps[i]`` is True when vertices ``i`` and
        ``i + 1`` are not neighbours on the curve.
        """
        left, right, bottom, top = extent
        line = self.walk.polyline
        inside = (
            (line[:, 0] >= left - 2)
            & (line[:, 0] <= right + 2)
            & (line[:, 1] >= top - 2)
            & (line[:, 1] <= bottom + 2)
        )
        keep = np.flatnonzero(inside | np.roll(inside, 1) | np.roll(inside, -1))  # far ends too
        return line[keep], np.diff(keep) > 1

    def _dragged_reference(
        self, line: np.ndarray, gaps: np.ndarray, window: tuple[int, int], k: int
    ) -> np.ndarray:
        """The reference in the ``window`` (H, W) during a drag, from the pieces of the
        app's polyline moved to its corner.

        That polyline (flattened to 1e-3 pixel for the walk) stands in for the
        reference's own (1e-4, the whole curve flattened again): no sample
        moves by more than 1e-3 pixel, far below the 1/16 pixel between two
        of the 16 x 16. Every segment within reach of the window is among the
        pieces; the release draws the reference as
        :func:`~course.antialias.windows.render_window` does.
        """
        if len(line) < 2:
            return np.zeros(window)
        return polyline_coverage(line, gaps, window, self.stroke_width, k)

    def handles(self) -> list[Handle]:
        return [Handle(f"P{i}", self.overview, tuple(p)) for i, p in enumerate(self.points)]

    def drag(self, name: str, point: np.ndarray) -> None:
        points = self.points.copy()
        height, width = self.shape
        points[int(name[1:])] = np.clip(np.round(point, 1), 0, (width, height))
        self.controls["points"].value = format_points(points)


class StepApp(SliderApp):
    """One splat method at a chosen t step: a zoomed window and brightness along the curve.

    Coarse steps leave gaps between the splats; fine steps pile samples
    into the same pixels, which the handouts' saturating sum clips at 1, so
    the brightness follows how fast the curve moves. With
    ``weighting="arc_length"`` the brightness per unit length stays at 1
    for every step fine enough to leave no gaps. The profile's y-axis runs
    from 0 to 1.6, or higher when the ink along the curve goes above it.
    """

    FLOOR_TOP = 1.6

    def __init__(
        self, points: Any = SEED_000_CUBIC, shape: tuple[int, int] = SEED_000_SHAPE
    ) -> None:
        self.points = as_curve(points)
        self.shape = as_shape(shape)
        self.walk = CurveWalk(self.points)
        controls = {
            "step": widgets.FloatLogSlider(
                value=0.001,
                base=10,
                min=-4,
                max=-1.3,
                step=0.05,
                description=_("t step"),
                readout_format=".2g",
            ),
            "method": widgets.Dropdown(
                options=[(label_of(splat), splat) for splat in SPLATS],
                value="bilinear_centres",
                description=_("splat"),
            ),
            "weighting": widgets.ToggleButtons(
                options=[(_(WEIGHTING_LABELS[name]), name) for name in WEIGHTINGS],
                value="count",
                description=_("weighting"),
            ),
            "position": widgets.FloatSlider(
                value=0.02, min=0.0, max=1.0, step=0.005, description=_("along curve")
            ),
        }
        super().__init__(controls, shape=(380, 900))
        grid = self.figure.add_gridspec(1, 2, width_ratios=(1, 1.6))
        self.panel = ZoomPanel(self.figure.add_subplot(grid[0]), self.walk.polyline)
        self.profile_axes = self.figure.add_subplot(grid[1])
        (self.profile,) = self.profile_axes.plot(
            [], [], color="#0072B2", linewidth=1.2, label=_("this splat")
        )
        self.profile_axes.axhline(
            1.0, color="black", linewidth=0.8, linestyle="--", label=_("1: evenly bright")
        )
        self.marker = self.profile_axes.axvline(
            0.0, color="gray", linewidth=0.8, linestyle=":", label=_("the zoomed window")
        )
        self.profile_axes.set_xlabel(_("distance along the curve (px)"))
        self.profile_axes.set_ylabel(_("ink per px of length"))
        self.profile_axes.set_xlim(0, self.walk.lengths[-1])
        self.profile_axes.set_ylim(0, self.FLOOR_TOP)
        curve_key = Line2D(
            [], [], color=self.panel.curve.get_color(), label=_("left: the true curve")
        )
        handles, _labels = self.profile_axes.get_legend_handles_labels()
        self.profile_axes.legend(
            handles=[curve_key, *handles], fontsize=8, loc="lower center", ncols=2
        )
        self.profile_title = self.profile_axes.set_title("", fontsize=9)
        self.figure.subplots_adjust(left=0.02, right=0.98, bottom=0.14, top=0.9, wspace=0.2)
        self.image = np.zeros(shape)
        self.density = np.zeros(0)

    def update(self) -> None:
        method, weighting = self.value("method"), self.value("weighting")
        self.image = render(
            self.points, self.shape, method, step=self.value("step"), weighting=weighting
        )
        positions, self.density = intensity_along(self.image, self.points)
        self.profile.set_data(positions, self.density)
        # Fine steps pile ink up to 2 and beyond: the axis grows to show it, never below 0..1.6.
        top = max(self.FLOOR_TOP, 1.15 * float(self.density.max(initial=0.0)))
        self.profile_axes.set_ylim(0, top)
        fraction = self.value("position")
        self.marker.set_xdata([fraction * self.walk.lengths[-1]] * 2)
        cv = uniformity(self.image, self.points)
        self.profile_title.set_text(
            _("{method}, {weighting}: CV {cv:.1f}%, mean {mean:.2f}").format(
                method=label_of(method),
                weighting=_(WEIGHTING_LABELS[weighting]),
                cv=100 * cv,
                mean=self.density.mean(),
            )
        )
        self.panel.show(
            self.image,
            self.walk.at(fraction),
            24,
            _("t step {step:.2g}").format(step=self.value("step")),
        )
