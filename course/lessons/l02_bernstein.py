"""Lesson 02, the Bernstein form: its registry entry, pictures and landmarks.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

from dataclasses import replace

from course.bezier import bernstein_basis
from course.classroom.pictures import (
    CRIMSON,
    app_picture,
    landmark_at,
    panel_picture,
    still_picture,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.i18n import N_
from course.images import EXAMPLE_POINTS
from course.widgets import bernstein_figures as figures
from course.widgets.base import SliderApp
from course.widgets.bernstein import BernsteinBasisApp

UNCHECKED = True  # see the module docstring


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


def preview() -> bytes:
    """The course map's preview: the cubic Bernstein basis at t = 0.3."""
    app = BernsteinBasisApp(degree=3, t=0.3)
    return panel_picture(app, app.axes)


LESSON = Lesson(
    outcomes=(
        N_("write a Bézier curve as its control points weighted by Bernstein polynomials"),
        N_("compute binomials exactly by Pascal's rule and write naive_bezier for any degree"),
        N_("read a curve's end tangents and derivative off its control polygon"),
    ),
    minutes=50,
    preview=Picture(
        "02_preview", "the four cubic Bernstein polynomials, and their values at t = 0.3", preview
    ),
    handout=N_(
        "the GAMES101 framework's naive_bezier, generalised to any degree with the "
        "recursive comb of the any-degree report (任意多次的曲线绘制)"
    ),
    teaches=N_(
        "the Bernstein basis under a degree slider; binomials by Pascal's rule, written "
        "and checked, against the handout's exponential recursion and 32-bit int; naive_bezier of "
        "any degree; end tangents and the hodograph; accuracy against the degree"
    ),
    pictures=(
        bernstein_picture(3, 0.3),
        bernstein_picture(9, 0.5),
        still_picture(
            "02_pascal_triangle",
            "Pascal's triangle: each entry the sum of two",
            figures.pascal_figure,
        ),
        still_picture(
            "02_end_tangents",
            "the end tangents along the polygon's edges",
            figures.tangents_figure,
            EXAMPLE_POINTS[:4],
        ),
        still_picture(
            "02_hodograph",
            "velocities along a cubic and its hodograph",
            figures.hodograph_figure,
            EXAMPLE_POINTS[:4],
        ),
        still_picture(
            "02_accuracy_by_degree", "four evaluations' error by degree", figures.accuracy_figure
        ),
    ),
    sliders=(
        SliderMove(
            build=bernstein_app,
            control="t",
            moves=(("ArrowLeft", "ArrowLeft"), ("Home",)),
            landmarks=bernstein_landmarks,
        ),
    ),
)
