"""Lesson 07, filtering: its registry entry, pictures and landmarks.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import functools

import numpy as np

from course import filters, images
from course.classroom.pictures import (
    app_picture,
    landmark_at,
    panel_picture,
    read_only,
    rgb_color,
    still_picture,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.i18n import N_
from course.widgets import filtering_figures as figures
from course.widgets.base import SliderApp
from course.widgets.filtering import KernelApp, RepeatedBlurApp, blurred

UNCHECKED = True  # see the module docstring


@functools.cache
def half_size_photograph() -> np.ndarray:
    """The photograph at half size, as the notebook filters it."""
    return read_only(images.photograph()[::2, ::2])


def repeated_blur_app() -> RepeatedBlurApp:
    return RepeatedBlurApp(half_size_photograph(), repeats=8, corner=32)


def repeated_blur_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of each rule's zoomed top-right corner after n blurs by ``filters``."""
    repeats, corner = int(app.value("repeats")), 32
    landmarks = []
    for border in filters.BORDERS:
        result = half_size_photograph()
        for _ in range(repeats):
            result = blurred(result, border)
        window = result[:corner, -corner:]
        axes = app.crops[border].axes
        for row, column in np.ndindex(corner, corner):
            what = f"{border!r} after {repeats} blurs: corner pixel ({column}, {row})"
            color = rgb_color(window[row, column])
            # Tolerance 1: one more blur changes the zero-padded frame by 2 grey levels.
            landmarks.append(landmark_at(app, axes, (column, row), color, what, 1))
    return landmarks


def kernel_app_picture() -> bytes:
    app = KernelApp()
    app.controls["preset"].value = "Sobel x"
    return app_picture(app)


def preview() -> bytes:
    """The course map's preview: a photograph blurred eight times."""
    app = repeated_blur_app()
    return panel_picture(app, app.figure.axes[0])


LESSON = Lesson(
    outcomes=(
        N_("compute a 3 x 3 filter by hand and as a loop: a weighted sum of each pixel's window"),
        N_("write the lab's Blur and Sobel Edge"),
        N_("choose what a window reads past the image's edge, and see what each rule does"),
    ),
    minutes=35,
    preview=Picture(
        "07_preview", "a photograph blurred eight times with the report's border rule", preview
    ),
    handout=N_(
        "the lab report (Lab01 Report), Task 2: 3 x 3 blur with the report's border rule "
        "and Sobel edges"
    ),
    teaches=N_(
        "3 x 3 kernels as weighted sums of a window (the box is lesson 04's box filter), "
        "blur and Sobel edges, any kernel on a photograph; the four border rules and zero "
        "padding's dark frame and false edges, measured"
    ),
    pictures=(
        still_picture(
            "07_blur_and_edges",
            "the face blurred once and five times, and its Sobel magnitude clipped at 1, "
            "each pixel 2 x 2",
            figures.filters_figure,
        ),
        still_picture(
            "07_one_window",
            "one output pixel of the box blur: the mean of its 3 x 3 window, numbers shown",
            figures.window_figure,
        ),
        Picture(
            "07_kernel_app_sobel_x",
            "Sobel x typed into the kernel app: red where the face gets brighter to the "
            "right, blue where darker, the window at the image's edge zoomed",
            kernel_app_picture,
        ),
        still_picture(
            "07_border_after_20_blurs",
            "the face's right edge after 20 blurs under each border rule: zero padding's "
            "dark frame",
            figures.border_figure,
        ),
        Picture(
            "07_repeated_blur_8",
            "eight blurs under each border rule: zero padding darkens the frame, the "
            "other rules keep the edge's brightness (top-right corner zoomed)",
            lambda: app_picture(repeated_blur_app()),
        ),
    ),
    sliders=(
        SliderMove(
            build=repeated_blur_app,
            app=1,  # the notebook's second app: the kernel app comes first
            control="repeats",
            moves=(("ArrowRight", "ArrowRight"), ("Home",), ("End",)),
            landmarks=repeated_blur_landmarks,
        ),
    ),
)
