"""Lesson 07, filtering: its registry entry, pictures and landmarks."""

from __future__ import annotations

import functools

import numpy as np

from course import filters, images
from course.classroom.pictures import (
    app_picture,
    figure_picture,
    landmark_at,
    panel_picture,
    read_only,
    rgb_color,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.widgets.base import SliderApp
from course.widgets.dithering import side_by_side
from course.widgets.filtering import RepeatedBlurApp, blurred


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


def blur_and_edges() -> bytes:
    rgb = half_size_photograph()
    gray = images.to_gray(rgb)
    five_blurs = rgb
    for _ in range(5):
        five_blurs = filters.blur(five_blurs)
    pictures = {
        "original": rgb,
        "blur": filters.blur(rgb),
        "blur 5 times": five_blurs,
        "Sobel (gray), clipped": np.clip(filters.sobel(gray), 0, 1),
        "Sobel per channel, clipped": np.clip(filters.sobel(rgb), 0, 1),
    }
    return figure_picture(side_by_side(pictures, centre=(150, 80), size=40, figure_width=1000))


def preview() -> bytes:
    """The course map's preview: a photograph blurred eight times."""
    app = repeated_blur_app()
    return panel_picture(app, app.figure.axes[0])


LESSON = Lesson(
    outcomes=(
        "blur and find edges with 3 x 3 kernels, as a loop and separably",
        "choose a border rule and see what each does to the image's edge",
        "explain why repeated blurring spreads like a Gaussian",
    ),
    minutes=35,
    preview=Picture(
        "07_preview", "a photograph blurred eight times with the report's border rule", preview
    ),
    handout="Lab 1 report (seed 001), Task 2: 3 x 3 blur with the report's border rule "
    "and Sobel edges",
    teaches="blur and Sobel edges with 3 x 3 kernels, separable and fast; the four "
    "border rules and zero padding's dark frame, measured; scipy.ndimage agrees inside",
    pictures=(
        Picture(
            "07_blur_and_edges",
            "the photograph blurred once and five times, and its Sobel magnitude (gray "
            "and per channel, clipped to 1), each above a zoomed window",
            blur_and_edges,
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
            control="repeats",
            moves=(("ArrowRight", "ArrowRight"), ("Home",), ("End",)),
            landmarks=repeated_blur_landmarks,
        ),
    ),
)
