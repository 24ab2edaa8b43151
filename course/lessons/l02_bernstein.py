"""Lesson 02, the Bernstein form: its registry entry, pictures and landmarks."""

from __future__ import annotations

from dataclasses import replace

from course.bezier import bernstein_basis
from course.classroom.pictures import CRIMSON, app_picture, landmark_at
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.widgets.base import SliderApp
from course.widgets.bernstein import BernsteinBasisApp


def bernstein_landmarks(app: SliderApp) -> list[Landmark]:
    """Each basis function's marker at (t, B_i,n(t)) from ``bernstein_basis``."""
    degree, t = int(app.value("degree")), float(app.value("t"))
    weights = bernstein_basis(degree, t)[0]
    landmarks = []
    for i, weight in enumerate(weights):
        centre = landmark_at(app, app.axes, (t, weight), CRIMSON, f"B_{i},{degree}({t:.2f})")
        # The vertical line at t is crimson too: look 2 px to its right, still
        # inside the marker (radius about 2.8 px), where only the marker is red.
        landmarks.append(replace(centre, column=centre.column + 2))
    return landmarks


def bernstein_app() -> BernsteinBasisApp:
    return BernsteinBasisApp(degree=3, t=0.3)


def bernstein_picture(degree: int, t: float) -> Picture:
    return Picture(
        f"02_bernstein_degree{degree}_t{t:.2f}",
        f"the degree-{degree} Bernstein basis and its weights at t = {t:.2f}",
        lambda: app_picture(BernsteinBasisApp(degree=degree, t=t)),
    )


LESSON = Lesson(
    handout="GAMES101 homework 4's naive_bezier (seed 000), generalised to any degree "
    "with the recursive binomial (seed 002)",
    teaches="the Bernstein basis under a degree slider; binomials three ways; "
    "from Bernstein to de Casteljau; accuracy against the degree",
    pictures=(bernstein_picture(3, 0.3), bernstein_picture(9, 0.5)),
    sliders=(
        SliderMove(
            build=bernstein_app,
            control="t",
            moves=(("ArrowLeft", "ArrowLeft"), ("Home",)),
            landmarks=bernstein_landmarks,
        ),
    ),
)
