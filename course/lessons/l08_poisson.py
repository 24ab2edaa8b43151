"""Lesson 08, Poisson image editing: its registry entry, pictures and landmarks."""

from __future__ import annotations

import functools

import numpy as np

from course import images, poisson
from course.classroom.pictures import (
    app_picture,
    colormap_color,
    figure_picture,
    landmark_at,
    panel_picture,
    read_only,
    rgb_color,
)
from course.classroom.registry import DragMove, Landmark, Lesson, Picture, SliderMove
from course.widgets.base import SliderApp
from course.widgets.poisson import MARGIN, CloneApp, PoissonIterationApp, half_size, show_images

PLANE_OFFSET = (500, 300)
AROUND_THE_PLANE = (slice(280, 430), slice(470, 800))


@functools.cache
def lake_and_plane() -> tuple[np.ndarray, np.ndarray]:
    return read_only(images.lake()), read_only(images.plane())


def poisson_app() -> PoissonIterationApp:
    """Lesson 08's app as the notebook shows it: 1000 sweeps of Jacobi."""
    app = PoissonIterationApp()
    app.controls["sweeps"].value = 1000
    return app


def poisson_landmarks(app: SliderApp) -> list[Landmark]:
    """Region pixels of ``seamless_clone`` after n sweeps, and their error against ``solve``."""
    lake, plane = lake_and_plane()
    method, sweeps = app.value("method"), int(app.value("sweeps"))
    problem = poisson.clone_problem(lake, plane, PLANE_OFFSET)
    exact = poisson.solve(problem)
    iterate = poisson.solve(problem, method, iterations=sweeps)
    clone = poisson.seamless_clone(lake, plane, PLANE_OFFSET, method=method, iterations=sweeps)
    start = float(np.abs(problem.values - exact)[problem.region].max() * 255)
    error = np.abs(iterate - exact).max(axis=2) * 255
    x0, y0 = problem.corner
    height, width = problem.region.shape
    left, top = x0 - MARGIN, y0 - MARGIN  # the app's view: the region and a margin
    landmarks = []
    for row in (height // 4, height // 2, 3 * height // 4):
        for column in (width // 4, width // 2, 3 * width // 4):
            x, y = x0 + column, y0 + row
            what = f"{method}, {sweeps} sweeps: pixel ({x}, {y})"
            point = (x - left, y - top)
            color = rgb_color(clone[y, x])
            landmarks.append(landmark_at(app, app.picture.axes, point, color, what, 12))
            color = colormap_color("magma", float(error[row, column]), 0.0, start)
            landmarks.append(
                landmark_at(app, app.error_image.axes, point, color, f"{what}: error", 12)
            )
    return landmarks


def clone_landmarks(app: SliderApp) -> list[Landmark]:
    """Both panels where the foreground sits, as ``naive_paste`` and ``seamless_clone`` make them.

    Shown at half size, each screen pixel the mean of 2 x 2 image pixels:
    the landmarks are a 5 x 5 grid over the region and a ring of points just
    outside it, where a seam would show.
    """
    lake, plane = app.background, app.foreground
    x, y = (int(v) for v in app.offset)
    height, width = plane.shape[:2]
    pictures = {
        "naive paste": half_size(poisson.naive_paste(lake, plane, (x, y))),
        "seamless clone": half_size(poisson.seamless_clone(lake, plane, (x, y))),
    }
    columns = [x + 2 + round(k * (width - 5) / 4) for k in range(5)] + [x - 3, x + width + 2]
    rows = [y + 2 + round(k * (height - 5) / 4) for k in range(5)] + [y - 3, y + height + 2]
    landmarks = []
    for name, shown in pictures.items():
        axes = app.panels[name]
        for column in columns:
            for row in rows:
                half_row, half_column = row // 2, column // 2
                if not (0 <= half_row < shown.shape[0] and 0 <= half_column < shown.shape[1]):
                    continue
                centre = (2 * half_column + 1, 2 * half_row + 1)  # the block's middle
                color = rgb_color(shown[half_row, half_column])
                what = f"{name} at ({x}, {y}): image pixels around {centre}"
                # JPEG: a block of 8 x 8 screen pixels may shift each channel a little.
                landmarks.append(landmark_at(app, axes, centre, color, what, 24))
    return landmarks


def clone_comparison() -> bytes:
    lake, plane = lake_and_plane()
    pictures = {
        "naive paste": poisson.naive_paste(lake, plane, PLANE_OFFSET),
        "seamless clone": poisson.seamless_clone(lake, plane, PLANE_OFFSET),
    }
    return figure_picture(show_images(pictures, window=AROUND_THE_PLANE))


def inpainting() -> bytes:
    scratched, scratches = images.scratched_photograph()
    pictures = {
        "scratched": scratched,
        "inpainted": poisson.inpaint(scratched, scratches),
        "original": images.photograph(),
    }
    return figure_picture(show_images(pictures, window=(slice(120, 420), slice(60, 460))))


def preview() -> bytes:
    """The course map's preview: the plane cloned seamlessly into the lake."""
    app = CloneApp()
    return panel_picture(app, app.panels["seamless clone"])


LESSON = Lesson(
    outcomes=(
        "paste an image seamlessly by solving a Poisson equation",
        "fill a hole by the membrane through its border",
        "compare iterative solvers with an exact one, by their error after each sweep",
    ),
    minutes=60,
    preview=Picture("08_preview", "a plane cloned seamlessly into a lake", preview),
    handout="Lab 1 report (seed 001), Task 3: Poisson image editing, the plane pasted "
    "into the lake with the lab's 8000 'Jacobi' sweeps",
    teaches="seamless cloning and inpainting as a Poisson equation, solved exactly "
    "(DST, sparse) and by Jacobi, Gauss-Seidel and SOR; why 8000 sweeps are not enough",
    pictures=(
        Picture(
            "08_drag_the_plane",
            "the plane dragged over the lake: the copied pixels leave a frame, the "
            "seamless clone, solved again at every step, has none",
            lambda: app_picture(CloneApp()),
        ),
        Picture(
            "08_naive_paste_and_seamless_clone",
            "the plane pasted into the lake: copied pixels leave a frame, the seamless "
            "clone has none",
            clone_comparison,
        ),
        Picture(
            "08_jacobi_1000_sweeps",
            "1000 Jacobi sweeps: the result and its error against the exact solution, "
            "still large in the middle of the region",
            lambda: app_picture(poisson_app()),
        ),
        Picture(
            "08_inpainting",
            "seven scratches across the photograph, filled by solving Laplace's "
            "equation, beside the original",
            inpainting,
        ),
    ),
    sliders=(
        SliderMove(
            build=poisson_app,
            control="sweeps",
            moves=(("ArrowRight",), ("ArrowLeft", "ArrowLeft"), ("End",)),
            landmarks=poisson_landmarks,
            app=1,
        ),
    ),
    drags=(
        DragMove(
            build=CloneApp,
            handle="foreground",
            path=((-20, -10), (-60, -35), (-100, -55)),
            landmarks=clone_landmarks,
        ),
    ),
)
