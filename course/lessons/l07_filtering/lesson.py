"""Lesson 07, filtering: its registry entry, pictures, landmarks and printed lines.

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
from course.i18n import N_, _, yes_no
from course.lessons.l07_filtering import figures
from course.lessons.l07_filtering.apps import (
    KERNELS,
    PRESET_NAMES,
    KernelApp,
    RepeatedBlurApp,
    blurred,
)
from course.lessons.printed import display_width, padded, title_on_one_line
from course.widgets.base import SliderApp

UNCHECKED = True  # see the module docstring


def print_kernel_presets() -> None:
    """Print the kernel app's presets side by side, each a name over its three rows of weights.

    Examples
    --------
    >>> print_kernel_presets()  # doctest: +NORMALIZE_WHITESPACE
    box           Gaussian         sharpen    Sobel x    Sobel y    identity
    1/9 1/9 1/9   1/16 2/16 1/16    0 -1  0   -1  0  1   -1 -2 -1   0 0 0
    1/9 1/9 1/9   2/16 4/16 2/16   -1  5 -1   -2  0  2    0  0  0   0 1 0
    1/9 1/9 1/9   1/16 2/16 1/16    0 -1  0   -1  0  1    1  2  1   0 0 0
    """
    columns = []
    for name, kernel in KERNELS.items():
        rows = [row.split() for row in kernel.split(";")]
        width = max(len(weight) for row in rows for weight in row)
        columns.append(
            [
                _(PRESET_NAMES[name]),
                *(" ".join(weight.rjust(width) for weight in row) for row in rows),
            ]
        )
    widths = [max(display_width(line) for line in column) for column in columns]
    for lines in zip(*columns, strict=True):
        print(
            "   ".join(
                padded(line, width) for line, width in zip(lines, widths, strict=True)
            ).rstrip()
        )


def print_loop_equals_fast(name: str, equal: bool) -> None:
    """Print whether filter ``name``'s loop and fast forms give equal images.

    Examples
    --------
    >>> print_loop_equals_fast("blur", True)
    blur: loop == fast: yes
    """
    print(_("{name}: loop == fast: {equal}").format(name=name, equal=yes_no(equal)))


def print_uniform_filter(mode: str, border: str, same: bool) -> None:
    """Print whether scipy's ``uniform_filter`` in ``mode`` equals the box blur with ``border``.

    Examples
    --------
    >>> print_uniform_filter("mirror", "reflect", True)
    uniform_filter   mirror against 'reflect': equal below 1e-12: yes
    """
    # {pad} right-aligns the mode, so that a translation can quote it as code: mode='mirror'.
    print(
        _("uniform_filter {pad}{mode} against '{border}': equal below 1e-12: {same}").format(
            pad=" " * max(0, 8 - len(mode)), mode=mode, border=border, same=yes_no(same)
        )
    )


def print_report_rule_against_scipy(inside: bool, frame: float) -> None:
    """Print the report's border rule against scipy's default: equal inside, and on the frame.

    Examples
    --------
    >>> print_report_rule_against_scipy(True, 0.0881)
    the report's rule against scipy's default: inside below 1e-12: yes, on the frame up to 0.088
    """
    print(
        _(
            "the report's rule against scipy's default: inside below 1e-12: {inside}, "
            "on the frame up to {frame:.3f}"
        ).format(inside=yes_no(inside), frame=frame)
    )


def print_sobel_against_scipy(same: bool) -> None:
    """Print whether ``filters.sobel`` equals the hypot of ``ndimage.sobel`` in both directions.

    Examples
    --------
    >>> print_sobel_against_scipy(True)
    sobel against hypot(ndimage.sobel): equal below 1e-12 everywhere: yes
    """
    print(
        _("sobel against hypot(ndimage.sobel): equal below 1e-12 everywhere: {same}").format(
            same=yes_no(same)
        )
    )


def print_correlation_and_convolution(correlation: np.ndarray, convolution: np.ndarray) -> None:
    """Print a row filtered by correlation (the lab's) and by convolution, aligned.

    Examples
    --------
    >>> print_correlation_and_convolution(np.array([0.0, 4.0]), np.array([0.0, -4.0]))
    correlation (the lab): [0. 4.]
    convolution:           [ 0. -4.]
    """
    labels = (_("correlation (the lab):"), _("convolution:"))
    width = max(display_width(label) for label in labels)
    for label, row in zip(labels, (correlation, convolution), strict=True):
        print(label + " " * (width - display_width(label)), row)


def print_largest_magnitude(largest: float) -> None:
    """Print the largest Sobel magnitude on a 0/1 window against sqrt(20); its window follows.

    Examples
    --------
    >>> print_largest_magnitude(20**0.5)
    largest 4.4721 (sqrt(20) = 4.4721), on this window:
    """
    print(
        _("largest {largest:.4f} (sqrt(20) = {root:.4f}), on this window:").format(
            largest=largest, root=np.sqrt(20)
        )
    )


def print_border_titles(app: RepeatedBlurApp) -> None:
    """Print each border's panel title of ``app``, each on one line (its two lines joined)."""
    for border in filters.BORDERS:
        print(title_on_one_line(app.titles[border].get_text()))


def print_frame_depth(repeats: int, depth: int) -> None:
    """Print how deep zero padding's dark frame reaches after ``repeats`` blurs.

    Examples
    --------
    >>> print_frame_depth(5, 3)
     5 blurs: zero padding's frame is 3 px deep on the right
    """
    print(
        _("{repeats:2d} blurs: zero padding's frame is {depth} px deep on the right").format(
            repeats=repeats, depth=depth
        )
    )


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
        for _repeat in range(repeats):
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
