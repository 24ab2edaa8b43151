"""Lesson 01, de Casteljau's algorithm: its registry entry, pictures and landmarks.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

from course.bezier import de_casteljau
from course.classroom.pictures import CRIMSON, app_picture, landmark_at, still_picture
from course.classroom.registry import DragMove, Landmark, Lesson, Picture, SliderMove
from course.i18n import N_
from course.images import EXAMPLE_POINTS, SEED_000_CUBIC
from course.widgets import de_casteljau_figures as figures
from course.widgets.base import SliderApp, parse_points
from course.widgets.de_casteljau import DeCasteljauApp

UNCHECKED = True  # see the module docstring


def de_casteljau_landmarks(app: SliderApp) -> list[Landmark]:
    """The red dot B(t) where ``de_casteljau`` puts it."""
    points = parse_points(app.value("points"))
    t = float(app.value("t"))
    point = de_casteljau(points, t)
    return [landmark_at(app, app.axes, point, CRIMSON, f"B({t:.2f}) by de_casteljau")]


def de_casteljau_picture(t: float, count: int = 4) -> Picture:
    return Picture(
        f"01_de_casteljau_degree{count - 1}_t{t:.2f}",
        f"de Casteljau's levels for {count} control points at t = {t:.2f}",
        lambda: app_picture(DeCasteljauApp(points=EXAMPLE_POINTS[:count], t=t)),
    )


#: The lesson's tiny example: three points with exact binary-fraction levels at t = 1/4.
THREE_POINTS = ((0.0, 0.0), (2.0, 4.0), (8.0, 0.0))


def preview() -> bytes:
    """The course map's preview: the construction at t = 0.5."""
    return app_picture(DeCasteljauApp())


LESSON = Lesson(
    outcomes=(
        N_("find a point of a Bézier curve by hand, by repeated linear interpolation"),
        N_("write the GAMES101 handout's recursive_bezier and the loop that draws the curve"),
        N_("measure the handouts' pitfalls: a curve run backwards, a loop short of t = 1, gaps"),
    ),
    minutes=60,
    preview=Picture("01_preview", "de Casteljau's construction of a cubic at t = 0.5", preview),
    handout=N_(
        "the GAMES101 handout's basic part (基础部分): recursive_bezier and the bezier "
        "loop; the reversed step and float loops of the any-degree, VS2022 and lab 6 reports"
    ),
    teaches=N_(
        "a Bézier curve by repeated linear interpolation: by hand on three points, "
        "recursive_bezier and the drawing loop written and checked, every level under a t slider "
        "and draggable points; the handouts' pitfalls as pictures and numbers"
    ),
    pictures=(
        de_casteljau_picture(0.5),
        de_casteljau_picture(0.25),
        de_casteljau_picture(0.3, count=10),
        still_picture(
            "01_three_points",
            "de Casteljau by hand on three points at t = 1/4",
            figures.three_points_figure,
            THREE_POINTS,
            0.25,
        ),
        still_picture(
            "01_end_of_curve",
            "the last pixels two handout loops paint, beside B(1)",
            figures.end_of_curve_figure,
            SEED_000_CUBIC,
        ),
        still_picture(
            "01_yellow_check_games101",
            "the GAMES101 report's yellow check: rounding against truncation",
            figures.yellow_check_figure,
            SEED_000_CUBIC,
            "000",
        ),
    ),
    sliders=(
        SliderMove(
            build=DeCasteljauApp,
            control="t",
            moves=(("ArrowRight", "ArrowRight", "ArrowRight"), ("ArrowLeft",), ("End",)),
            landmarks=de_casteljau_landmarks,
        ),
    ),
    drags=(
        DragMove(
            build=DeCasteljauApp,
            handle="P1",
            path=((15, 20), (40, 55), (70, 90)),
            landmarks=de_casteljau_landmarks,
        ),
    ),
)
