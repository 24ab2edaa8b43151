"""Lesson 05, anti-aliasing a curve: its registry entry, pictures and landmarks."""

from __future__ import annotations

import functools

import numpy as np

from course.bezier import de_casteljau
from course.classroom.pictures import (
    app_picture,
    clear_point,
    figure_picture,
    gray_color,
    landmark_in_box,
    panel_picture,
    read_only,
    segments_of,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.coverage import curve_polyline, reference
from course.curve_quality import REFERENCE, render_window, variants
from course.images import SEED_000_CUBIC, SEED_000_SHAPE
from course.widgets.antialiasing import ZOOM_PICKS, CurveWalk, StepApp, ZoomApp, zoom_figure
from course.widgets.base import SliderApp

# The variants the notebook zooms into, in its order (its "Every variant" cell).
ZOOMED_VARIANTS = (
    "nearest_round",
    "bilinear_zero_offset",
    "bilinear_corners",
    "bilinear_centres",
    "subsample_falloff",
    "normalised_centres",
    "stroke_linear",
    "stroke_area",
    "bilinear_centres + arc length",
    "nearest_truncate + arc length",
    "Agg (matplotlib)",
)


@functools.cache
def seed_000_renderings() -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Every variant of seed 000's test and the exact reference (k = 64), computed once."""
    renderings = {
        name: read_only(image) for name, image in variants(SEED_000_CUBIC, SEED_000_SHAPE).items()
    }
    exact = reference(SEED_000_CUBIC, SEED_000_SHAPE, width=1.0, k=64)
    return renderings, read_only(exact)


def zoom_app() -> ZoomApp:
    """Lesson 05's first app, as its notebook builds it."""
    return ZoomApp(SEED_000_CUBIC, SEED_000_SHAPE, picks=ZOOM_PICKS)


def zoom_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of each panel: the variant drawn in the window around the curve point.

    The window's centre is the point ``position`` of the way along the curve
    (by arc length); each panel must show that window of the variant, as
    ``curve_quality.render_window`` draws it, and of the exact reference.
    """
    points = np.asarray(app.points)
    position, size = float(app.value("position")), int(app.value("size"))
    centre = CurveWalk(points).at(position)
    segments = segments_of(curve_polyline(points, 1e-3))
    names = [app.value(slot) for slot in ("left", "middle", "right")] + [REFERENCE]
    landmarks = []
    for panel, name in zip(app.panels, names, strict=True):
        window, extent = render_window(name, points, SEED_000_SHAPE, centre, size, k=app.k)
        left, _, _, top = extent
        for row, column in np.ndindex(*window.shape):
            x, y = left + column, top + row
            value = float(window[row, column])
            point = clear_point(x, y, segments)
            what = f"{name} at position {position:.3f}: pixel ({x}, {y}) = {value:.2f}"
            landmarks.append(
                landmark_in_box(app, panel.axes, extent, point, gray_color(value), what, 16)
            )
    return landmarks


def zoom_every_variant() -> bytes:
    """The notebook's still grid: every variant zoomed where the curve leaves P0."""
    renderings, exact = seed_000_renderings()
    panels = {name: renderings[name] for name in ZOOMED_VARIANTS} | {"exact reference": exact}
    centre = de_casteljau(SEED_000_CUBIC, 0.08)
    figure = zoom_figure(panels, SEED_000_CUBIC, centre=centre, size=14, columns=4)
    return figure_picture(figure)


def step_app_picture(weighting: str) -> bytes:
    app = StepApp(SEED_000_CUBIC, SEED_000_SHAPE)
    app.controls["weighting"].value = weighting
    return app_picture(app)


def preview() -> bytes:
    """The course map's preview: one zoomed window of an anti-aliased curve."""
    app = zoom_app()
    return panel_picture(app, app.panels[2].axes)


LESSON = Lesson(
    outcomes=(
        "draw a curve's pixels as the coverage of a stroke",
        "compare the handouts' anti-aliasing splats with the exact coverage, pixel by pixel",
        "fix a splat's offset and its brightness along the curve",
    ),
    minutes=60,
    preview=Picture(
        "05_preview", "an anti-aliased curve, zoomed until each pixel is a square", preview
    ),
    handout="GAMES101 homework 4, improvement part (seeds 000, 002, 003): anti-aliasing "
    "the curve with seed 000's three addColor splats, seed 002's sub-sample falloff and "
    "seed 003's normalised splat",
    teaches="a curve's pixels as the coverage of a stroke: every handout splat measured "
    "against an exact reference and Agg, the t-step pitfall and the arc-length fix",
    pictures=(
        Picture(
            "05_every_variant_zoomed",
            "seed 000's curve near its first control point, every variant as 14 x 14 "
            "flat pixels under the true curve (red), beside the exact reference",
            zoom_every_variant,
        ),
        Picture(
            "05_seed000_three_splats_position0.10",
            "seed 000's curve whole, and its left, middle and right addColor beside the "
            "exact reference, 10% of the way along the curve, with each window's RMSE",
            lambda: app_picture(zoom_app()),
        ),
        Picture(
            "05_t_step_0.001_count",
            "bilinear_centres at the handouts' t step 0.001, splats counted as the "
            "handouts do: the brightness per unit length follows the curve's speed, "
            "about half at the fast ends",
            lambda: step_app_picture("count"),
        ),
        Picture(
            "05_t_step_0.001_arc_length",
            "the same splats weighted by arc length: brightness 1 per unit length "
            "along the curve, dipping only near the fast ends, where samples 0.001 "
            "apart leave gaps",
            lambda: step_app_picture("arc_length"),
        ),
    ),
    sliders=(
        SliderMove(
            build=zoom_app,
            control="position",
            moves=(("ArrowRight", "ArrowRight"), ("ArrowRight",) * 4, ("End",), ("Home",)),
            landmarks=zoom_landmarks,
        ),
    ),
)
