"""Lesson 08, Poisson image editing: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import numpy as np

from course import images, poisson
from course.classroom.pictures import (
    app_picture,
    colormap_color,
    landmark_at,
    panel_picture,
    rgb_color,
    still_picture,
)
from course.classroom.registry import DragMove, Landmark, Lesson, Picture, SliderMove
from course.i18n import N_, _, yes_no
from course.lessons.l08_poisson import figures
from course.lessons.l08_poisson.apps import MARGIN, CloneApp, PoissonIterationApp, half_size
from course.lessons.l08_poisson.convergence import convergence_figure
from course.lessons.printed import padded
from course.widgets.base import SliderApp

UNCHECKED = True  # see the module docstring


def print_sor_omega(omega: float) -> None:
    """Print SOR's optimal relaxation factor omega for the app's region.

    Examples
    --------
    >>> print_sor_omega(1.9612)
    SOR's omega on this region: 1.96
    """
    print(_("SOR's omega on this region: {omega:.2f}").format(omega=omega))


#: The exact solvers' names, as :func:`course.poisson.solve` takes them, in the student's language.
SOLVER_NAMES = {"dst": N_("dst"), "direct": N_("direct"), "capacitance": N_("capacitance")}


def print_residual_below(method: str, below: bool) -> None:
    """Print whether the solver ``method``'s residual is below 1e-10.

    Examples
    --------
    >>> print_residual_below("dst", True)
             dst: residual below 1e-10: yes
    """
    name = padded(_(SOLVER_NAMES[method]) if method in SOLVER_NAMES else method, 12, ">")
    print(_("{method}: residual below 1e-10: {below}").format(method=name, below=yes_no(below)))


def print_lab_clone_time(per_pixel: float, pixels: int = 30302, sweeps: int = 8000) -> None:
    """Print the lab's loop time per pixel per sweep (in seconds), per sweep of the plane's
    ``pixels`` and for ``sweeps`` sweeps.

    Examples
    --------
    >>> print_lab_clone_time(56.5e-6)
    56.5 us per pixel per sweep: 1.712 s per sweep of the plane, 228 min for 8000
    """
    print(
        _(
            "{micro:.1f} us per pixel per sweep: {sweep:.3f} s per sweep of the plane, "
            "{minutes:.0f} min for {sweeps}"
        ).format(
            micro=per_pixel * 1e6,
            sweep=per_pixel * pixels,
            minutes=per_pixel * pixels * sweeps / 60,
            sweeps=sweeps,
        )
    )


def print_plane_colour(colour: np.ndarray) -> None:
    """Print the plane's own mean colour, RGB to 2 decimals.

    Examples
    --------
    >>> print_plane_colour(np.array([0.721, 0.709, 0.78]))
    the plane itself: RGB [0.72 0.71 0.78]
    """
    print(_("the plane itself: RGB {rgb}").format(rgb=np.round(colour, 2)))


def print_cloned_colour(x: int, y: int, colour: np.ndarray) -> None:
    """Print the mean colour of the plane cloned at ``(x, y)``, RGB to 2 decimals.

    Examples
    --------
    >>> print_cloned_colour(420, 50, np.array([0.54, 0.551, 0.69]))
    cloned at (420, 50): RGB [0.54 0.55 0.69]
    """
    print(_("cloned at ({x}, {y}): RGB {rgb}").format(x=x, y=y, rgb=np.round(colour, 2)))


PLANE_OFFSET = (500, 300)


def poisson_app() -> PoissonIterationApp:
    """Lesson 08's app as the notebook shows it: 1000 sweeps of Jacobi."""
    app = PoissonIterationApp()
    app.controls["sweeps"].value = 1000
    return app


def poisson_landmarks(app: SliderApp) -> list[Landmark]:
    """Region pixels of ``seamless_clone`` after n sweeps, and their error against ``solve``."""
    lake, plane = figures.lab_scene()
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


def day_clone_app() -> CloneApp:
    """Lesson 08's second app, as its notebook builds it: the day plane in the lake's sky."""
    return CloneApp(foreground=images.plane(sky="day"), offset=figures.DAY_OFFSET)


def preview() -> bytes:
    """The course map's preview: the plane cloned seamlessly into the lake."""
    app = day_clone_app()
    return panel_picture(app, app.panels["seamless clone"])


LESSON = Lesson(
    outcomes=(
        N_("paste one image into another with no seam, by solving a Poisson equation"),
        N_("write the lab's boundary ring and its sweep, stopping on the residual"),
        N_("say why 8000 sweeps are not enough, and when cloning cannot keep the colours"),
    ),
    minutes=60,
    preview=Picture("08_preview", "a plane cloned seamlessly into a lake's sky", preview),
    handout=N_(
        "the lab report (Lab01 Report), Task 3 (titled 'Image Inpainting'): Poisson image "
        "editing, the report's update and boundary ring, and the lab skeleton's 8000 sweeps"
    ),
    teaches=N_(
        "seamless cloning as a Poisson equation: the correction g over the ring's "
        "mismatch, the lab's sweep with a stop on the residual, why 8000 sweeps (Gauss-Seidel, "
        "not Jacobi) are not enough, and the colours a clone cannot keep"
    ),
    pictures=(
        still_picture(
            "08_naive_paste_and_seamless_clone",
            "the day plane pasted into the lake's sky: copied pixels leave a frame, the "
            "seamless clone has none",
            figures.headline_figure,
        ),
        still_picture(
            "08_correction",
            "the plane, the correction g stretched over the ring's mismatch, and their sum",
            figures.correction_figure,
        ),
        Picture(
            "08_jacobi_1000_sweeps",
            "1000 Jacobi sweeps: the result and its error against the exact solution, "
            "still large in the middle of the region",
            lambda: app_picture(poisson_app()),
        ),
        still_picture(
            "08_sweeps_to_the_solution",
            "the largest error after each sweep for Jacobi, Gauss-Seidel and SOR on the lab's "
            "scene: neither of the first two is done after 8000",
            convergence_figure,
        ),
        Picture(
            "08_drag_the_plane",
            "the day plane dragged over the lake: the copied pixels leave a frame, the "
            "seamless clone, solved again at every step, has none",
            lambda: app_picture(day_clone_app()),
        ),
        still_picture(
            "08_colours_it_cannot_keep",
            "the lab's evening plane over the water: the clone has no seam, but the white "
            "plane turns blue",
            figures.colour_figure,
        ),
    ),
    sliders=(
        SliderMove(
            build=poisson_app,
            control="sweeps",
            moves=(("ArrowRight",), ("ArrowLeft", "ArrowLeft"), ("End",)),
            landmarks=poisson_landmarks,
            app=0,
        ),
    ),
    drags=(
        DragMove(
            build=day_clone_app,
            handle="foreground",
            path=((-20, 10), (-60, 35), (-100, 55)),
            landmarks=clone_landmarks,
            app=1,
        ),
    ),
)
