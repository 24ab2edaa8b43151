"""Lesson 05, anti-aliasing a curve: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import numpy as np

from course._validate import as_choice
from course.antialias import WEIGHTINGS
from course.antialias.coverage import curve_polyline
from course.antialias.curve_quality import REFERENCE
from course.antialias.windows import render_window
from course.classroom.pictures import (
    app_picture,
    clear_point,
    gray_color,
    landmark_in_box,
    panel_picture,
    segments_of,
    still_picture,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.i18n import N_, _
from course.images import SEED_000_CUBIC, SEED_000_SHAPE
from course.lessons.l05_antialiasing import figures, measurements
from course.lessons.l05_antialiasing.apps import ZOOM_PICKS, StepApp, ZoomApp
from course.lessons.l05_antialiasing.zoom_panel import CurveWalk
from course.lessons.printed import padded
from course.widgets.base import SliderApp

UNCHECKED = True  # see the module docstring

#: The two Agg renderings the lesson measures, as its notebook names them.
AGG_RENDERINGS = (N_("Agg, CURVE4 path"), N_("Agg, fine polyline"))


def print_arc_length_step(step: float, gap: float) -> None:
    """Print the arc-length parameter step and the largest gap between its samples, in pixels.

    Examples
    --------
    >>> print_arc_length_step(0.0001734, 0.3512)
    by length: step 0.000173, samples at most 0.35 px apart
    """
    print(
        _("by length: step {step:.3g}, samples at most {gap:.2f} px apart").format(
            step=step, gap=gap
        )
    )


def print_closed_form_difference(k: int, difference: float) -> None:
    """Print the reference at ``k`` x ``k`` subsamples against a band's closed-form coverage.

    Examples
    --------
    >>> print_closed_form_difference(16, 0.0036)
    k = 16: largest difference from the closed form 0.0036
    """
    print(
        _("k = {k:2d}: largest difference from the closed form {difference:.4f}").format(
            k=k, difference=difference
        )
    )


def print_reference_against_finest(k: int, rmse: float, worst: float, finest: int = 64) -> None:
    """Print the exact reference at ``k`` x ``k`` subsamples against the finest one's.

    Examples
    --------
    >>> print_reference_against_finest(16, 0.00045, 0.03125)
    reference k=16 against k=64: RMSE 0.00045, max 0.0312
    """
    print(
        _("reference k={k:2d} against k={finest}: RMSE {rmse:.5f}, max {worst:.4f}").format(
            k=k, finest=finest, rmse=rmse, worst=worst
        )
    )


def print_total_ink(exact: float, length: float) -> None:
    """Print a unit-width stroke's total ink: its length plus its two round caps' pi/4.

    Examples
    --------
    >>> print_total_ink(1140.85, 1140.05)
    total ink: exact 1140.85 ≈ length 1140.05 + the round caps' 0.785
    """
    print(
        _("total ink: exact {exact:.2f} ≈ length {length:.2f} + the round caps' {caps:.3f}").format(
            exact=exact, length=length, caps=np.pi / 4
        )
    )


def print_agg_error(name: str, rmse: float, worst: float, position: float) -> None:
    """Print an Agg rendering's error against the exact coverage; ``name`` is an
    :data:`AGG_RENDERINGS`, shown in the current language.

    Examples
    --------
    >>> print_agg_error("Agg, CURVE4 path", 0.0037, 0.131, 0.05)
    Agg, CURVE4 path     RMSE 0.0037, max 0.131, position 0.050 px
    """
    print(
        _("{name} RMSE {rmse:.4f}, max {worst:.3f}, position {position:.3f} px").format(
            name=padded(_(name), 20), rmse=rmse, worst=worst, position=position
        )
    )


def print_loop_position_error(name: str, error: float) -> None:
    """Print a rendering's position error in pixels; ``name`` is a key of
    :data:`course.lessons.l05_antialiasing.measurements.ROLES`, shown by its role's name.

    Examples
    --------
    >>> print_loop_position_error("nearest_round", 0.39)
    plain loop, rounded: position error 0.390 px
    """
    print(
        _("{role}: position error {error:.3f} px").format(
            role=_(measurements.ROLES[name][0]), error=error
        )
    )


# Computed once for the lesson, its pictures and the tests that read them.
seed_000_renderings = measurements.seed_000_renderings


def zoom_app() -> ZoomApp:
    """Lesson 05's zoom app (its second; the step app comes first), as its notebook builds it."""
    return ZoomApp(SEED_000_CUBIC, SEED_000_SHAPE, picks=ZOOM_PICKS, k=64)


def zoom_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of each panel: the variant drawn in the window around the curve point.

    The window's centre is the point ``position`` of the way along the curve
    (by arc length); each panel must show that window of the variant, as
    ``windows.render_window`` draws it, and of the exact reference.
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


def step_app_picture(weighting: str) -> bytes:
    weighting = as_choice(weighting, "weighting", WEIGHTINGS)
    app = StepApp(SEED_000_CUBIC, SEED_000_SHAPE)
    app.controls["weighting"].value = weighting
    return app_picture(app)


def preview() -> bytes:
    """The course map's preview: one zoomed window of an anti-aliased curve."""
    app = zoom_app()
    return panel_picture(app, app.panels[2].axes)


LESSON = Lesson(
    outcomes=(
        N_("say what a pixel of a drawn curve should hold: the area of it the stroke covers"),
        N_("write the handout's bilinear splat and weight it by the length of curve it stands for"),
        N_("measure the handouts' splats for error and even brightness against the exact coverage"),
    ),
    minutes=60,
    preview=Picture(
        "05_preview", "an anti-aliased curve, zoomed until each pixel is a square", preview
    ),
    handout=N_(
        "the GAMES101 handout's improvement part (提高部分) in the GAMES101, any-degree "
        "and VS2022 reports: anti-aliasing the curve with the GAMES101 report's three addColor "
        "splats, the any-degree report's sub-sample falloff and the VS2022 "
        "report's normalised splat"
    ),
    teaches=N_(
        "a curve's pixels as the coverage of a stroke: the bilinear splat, the t-step "
        "pitfall and the arc-length fix, every handout splat measured against the exact coverage"
    ),
    pictures=(
        still_picture(
            "05_aliased_and_antialiased",
            "the handouts' curve near t = 0.06, one pixel per sample beside each pixel's "
            "coverage by a stroke of width 1, each pixel 12 x 12",
            figures.opening_figure,
        ),
        still_picture(
            "05_pixel_area",
            "a stroke of width 1 across six pixels, each shaded and labelled by the area it covers",
            figures.pixel_area_figure,
        ),
        still_picture(
            "05_one_splat",
            "the point (3.3, 2.8) shared among the four pixels whose centres surround it",
            figures.splat_figure,
        ),
        still_picture(
            "05_brightness_along_the_curve",
            "ink per px of length along the curve at four t steps, counted and weighted by "
            "arc length",
            figures.brightness_figure,
        ),
        Picture(
            "05_seed000_three_splats_position0.10",
            "the handouts' curve whole, and the GAMES101 report's left, middle and right "
            "addColor beside the exact coverage, 10% of the way along the curve, with each "
            "window's RMSE",
            lambda: app_picture(zoom_app()),
        ),
        Picture(
            "05_t_step_0.001_count",
            "the GAMES101 report's right splat at the handouts' t step 0.001, splats counted "
            "as the handouts do: the brightness follows the curve's speed",
            lambda: step_app_picture("count"),
        ),
    ),
    sliders=(
        SliderMove(
            build=zoom_app,
            app=1,  # the notebook's second app: StepApp comes first
            control="position",
            moves=(("ArrowRight", "ArrowRight"), ("ArrowRight",) * 4, ("End",), ("Home",)),
            landmarks=zoom_landmarks,
        ),
    ),
)
