"""Lesson 06, dithering: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable

import numpy as np

from course import images
from course.classroom.pictures import (
    app_picture,
    gray_color,
    landmark_at,
    png_of_gray,
    read_only,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.halftone import dither
from course.i18n import N_, _, yes_no
from course.lessons.l06_dithering import figures
from course.lessons.l06_dithering.apps import GrayLevelApp, VoidAndClusterApp
from course.lessons.printed import padded
from course.widgets.base import SliderApp

UNCHECKED = True  # see the module docstring


def print_method_table(rows: Iterable[tuple[str, float, float]]) -> None:
    """Print each dithering method's mean difference and blurred error, as a table.

    ``rows`` are (method, mean difference, blurred error); a method's name is
    :func:`course.halftone.dither.all_methods`'s, shown in the current language.

    Examples
    --------
    >>> print_method_table([("threshold", -0.01524, 0.22041)])
    method                       mean difference  blurred error
    threshold                            -0.0152         0.2204
    """
    print(
        padded(_("method"), 28)
        + padded(_("mean difference"), 16, ">")
        + padded(_("blurred error"), 15, ">")
    )
    for name, mean, blurred in rows:
        print(f"{padded(_(name), 28)}{mean:>+16.4f}{blurred:>15.4f}")


def print_ordered_error(mean: float, worst: float) -> None:
    """Print the ordered 3x3 matrix's mean and worst error over the gray levels.

    Examples
    --------
    >>> print_ordered_error(0.05494, 0.11)
    mean error +0.0549, worst 0.1100
    """
    print(_("mean error {mean:+.4f}, worst {worst:.4f}").format(mean=mean, worst=worst))


def print_pixel_count(pixels: int) -> None:
    """Print how many pixels the image has, with thousands separators.

    Examples
    --------
    >>> print_pixel_count(76800)
    76,800 pixels
    """
    print(_("{pixels:,} pixels").format(pixels=pixels))  # an image: never one pixel


#: What each of :data:`course.halftone.dither.ERROR_DIFFUSION_METHODS` does, for the printout.
_DIFFUSION_FORMS = {
    "wavefront": N_("all pixels of one number t = x + 2 y at once"),
    "rows": N_("a loop along each row, its pushes to the rows below added a whole row at once"),
    "loop": N_("the lab's loop, pixel by pixel, run a second time"),
}


def print_equal_to_loop(method: str, same: bool) -> None:
    """Print whether error diffusion by ``method`` equals the loop's bit for bit, and what the
    method does.

    Examples
    --------
    >>> print_equal_to_loop("rows", True)
    method="rows" (a loop along each row, its pushes to the rows below added a whole row at
    once): equal to the loop bit for bit: yes
    """
    form = _(_DIFFUSION_FORMS[method]) if method in _DIFFUSION_FORMS else ""
    print(
        _('method="{method}" ({form}): equal to the loop bit for bit: {same}').format(
            method=method, form=form, same=yes_no(same)
        )
    )


def print_wavefront_against_pillow(wavefront: float, pillow: float) -> None:
    """Print the wavefront's and Pillow's time for one dithering (in seconds), and their ratio.

    Examples
    --------
    >>> print_wavefront_against_pillow(0.0791, 0.00051)
    wavefront 79.1 ms, Pillow 0.51 ms: 155x
    """
    print(
        _("wavefront {wavefront:.1f} ms, Pillow {pillow:.2f} ms: {ratio:.0f}x").format(
            wavefront=wavefront * 1e3, pillow=pillow * 1e3, ratio=wavefront / pillow
        )
    )


@functools.cache
def half_size_gray_photograph() -> np.ndarray:
    """The photograph in gray at half size, as the notebook dithers it."""
    return read_only(images.to_gray(images.photograph())[::2, ::2])


@functools.cache
def blue_noise_32() -> np.ndarray:
    return read_only(dither.blue_noise_mask(32, np.random.default_rng(0)))


def gray_level_app() -> GrayLevelApp:
    return GrayLevelApp(level=0.3, size=24)


def gray_level_landmarks(app: SliderApp) -> list[Landmark]:
    """The flat patch at the new level as ``dither`` makes it, and the ordered pattern marked.

    For each of ordered 3 x 3, Bayer 8 x 8, blue noise and Floyd-Steinberg,
    every pixel of the library's output for a flat patch (but the outermost,
    under the panel's frame); and the red frame around pattern k = the
    number of sub-pixels ``dither.ordered`` lights for one pixel at this level.
    """
    level, size = GrayLevelApp.snapped(float(app.value("level"))), 24
    patch = np.full((size, size), level)
    outputs = {
        "ordered 3x3": dither.ordered(patch),
        "Bayer 8x8": dither.bayer(patch, 8),
        "blue noise": dither.blue_noise(patch, blue_noise_32()),
        "Floyd-Steinberg": dither.error_diffusion(patch),
    }
    landmarks = []
    for name, output in outputs.items():
        scale = output.shape[0] // size  # ordered dithering shows 3 sub-pixels per pixel
        axes = app.panels[name].axes
        # Not the patch's outer pixels, which the panel's frame covers in part.
        inner = np.zeros(output.shape, dtype=bool)
        inner[scale:-scale, scale:-scale] = True
        for row, column in zip(*np.nonzero(inner), strict=True):
            value = float(output[row, column])
            centre = (column + 0.5, row + 0.5)  # the panel counts in its own pixels
            what = f"{name} of a flat {level:.3f} patch: pixel ({column}, {row}) = {value:g}"
            landmarks.append(landmark_at(app, axes, centre, gray_color(value), what, 24))
    lit = int(dither.ordered([[level]]).sum())
    # The frame's left side, or its right side for pattern 0 (at the strip's edge).
    side = 4 * lit - 0.1 if lit > 0 else 3.1
    what = f"red frame around pattern k = {lit} (dither.ordered lights {lit} of 9 at {level:.3f})"
    landmarks.append(landmark_at(app, app.highlight.axes, (side, 1.5), (255, 0, 0), what))
    return landmarks


def dithering_table() -> bytes:
    gray = half_size_gray_photograph()
    table = {"original": gray, **dither.all_methods(gray)}
    return figures.methods_figure(table, centre=(150, 80)).data


def dithering_ramp() -> bytes:
    gradient = images.ramp((32, 256))
    table = {"ramp": gradient, **dither.all_methods(gradient)}
    return figures.methods_figure(table, centre=(64, 16), size=24, shrink=1, columns=4).data


def void_and_cluster_picture() -> bytes:
    return app_picture(VoidAndClusterApp(size=32, dots=120))


def preview() -> bytes:
    """The course map's preview: the photograph in black and white dots, at 1:1."""
    gray = images.to_gray(images.photograph())[:240, :320]
    dots = dither.error_diffusion(gray)
    return png_of_gray(dots)


LESSON = Lesson(
    outcomes=(
        N_("turn gray levels into black and white dots five ways (the lab's Task 1)"),
        N_(
            "write ordered dithering with the lab's 3 x 3 matrix and "
            "Floyd-Steinberg error diffusion"
        ),
        N_("tell the methods apart by the tone they keep and how visible their dots are"),
    ),
    minutes=45,
    preview=Picture(
        "06_preview", "a photograph in black and white dots, by error diffusion", preview
    ),
    handout=N_(
        "the lab report (Lab01 Report), Task 1: threshold, uniform random, blue noise, "
        "ordered 3 x 3 and Floyd-Steinberg error diffusion"
    ),
    teaches=N_(
        "gray levels from black and white dots: the lab's five methods side by side, "
        "ordered dithering and Floyd-Steinberg written and checked, blue noise by "
        "void-and-cluster, tone and visible error measured, the ordered bias and the x - 1 slip"
    ),
    pictures=(
        Picture(
            "06_dithering_table",
            "the photograph and every dithering method, each above the same window "
            "zoomed to show single dots",
            dithering_table,
        ),
        Picture(
            "06_dithering_ramp",
            "a gray ramp from 0 to 1 through every method",
            dithering_ramp,
        ),
        Picture(
            "06_gray_level_0.30",
            "a flat 0.30 patch: the ten ordered 3 x 3 patterns (k = 3 framed) and what "
            "each method makes of it",
            lambda: app_picture(gray_level_app()),
        ),
        Picture(
            "06_void_and_cluster_120_dots",
            "void-and-cluster after 120 dots of a 32 x 32 mask: the dots over their "
            "energy, the next dot circled, and the spectrum against white noise",
            void_and_cluster_picture,
        ),
    ),
    sliders=(
        SliderMove(
            build=gray_level_app,
            control="level",
            moves=(("ArrowLeft",), ("ArrowRight",) * 5, ("End",)),
            landmarks=gray_level_landmarks,
        ),
    ),
)
