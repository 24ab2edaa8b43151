"""Lesson 01, de Casteljau's algorithm: its registry entry, pictures and landmarks."""

from __future__ import annotations

from course.bezier import de_casteljau
from course.classroom.pictures import CRIMSON, app_picture, landmark_at
from course.classroom.registry import DragMove, Landmark, Lesson, Picture, SliderMove
from course.images import EXAMPLE_POINTS
from course.widgets.base import SliderApp, parse_points
from course.widgets.de_casteljau import DeCasteljauApp


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


LESSON = Lesson(
    handout="GAMES101 homework 4, basic part (seed 000): recursive_bezier and the bezier "
    "loop; seeds 002-004's reversed step and float loop",
    teaches="a Bézier curve by repeated linear interpolation, every level under a t "
    "slider; recursion vs iteration; the handouts' pitfalls measured",
    pictures=(
        de_casteljau_picture(0.5),
        de_casteljau_picture(0.25),
        de_casteljau_picture(0.75),
        de_casteljau_picture(0.3, count=10),
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
