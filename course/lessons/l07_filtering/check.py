"""Lesson 07 exercises: the lab's ``Blur`` and ``Edge``.

The student writes them as ``blur`` and ``edge``, the names of their checkers and reports;
``check.hint()`` answers to the lab's names too. The notebook reaches the library's filters
as ``filters.blur`` and ``filters.sobel``, so a student's ``blur`` shadows none of them.

A failure names the first wrong pixel as (x, y) with its window (how many of
its nine neighbours lie inside the image), draws a map of where the output
differs, and recognises the usual slips (:mod:`.mistakes` reproduces each):
zero padding (dividing by 9 everywhere), the frame skipped or copied, the
nearest pixel repeated, numpy's mirror or the image wrapped around where the
report averages only the pixels inside, a window sliced from ``y - 1`` at
y = 0 (Python reads ``image[-1:2]`` as empty), sums taken in 8 bits, and a
blur that reads its own updated values; for Sobel also a clipped magnitude,
Gx alone and the frame left as the input. The
border is blamed only when every pixel inside the image is right; otherwise
the report names the first wrong pixel inside. A blur that writes into its
input fails, however right its values. A pass shows the student's output beside the
expected one.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("blur")`` says more at once and
``check.hint("blur", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import filters
from course.check.base import CheckResult, Hints, close, hint, run_cases
from course.check.exercises import exercise
from course.check.pictures import image_picture, side_by_side
from course.filters import blur as reference_blur
from course.filters import sobel
from course.i18n import N_, _
from course.lessons.l07_filtering.mistakes import BLUR_MISTAKES, EDGE_MISTAKES

__all__ = ["blur", "edge", "hint"]

_LIBRARY_FUNCTIONS = (filters.blur, filters.sobel, filters.convolve)


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(7)
    square = np.full((8, 10), 0.2)
    square[2:6, 3:8] = 0.9  # a bright square: its edges and the frame show in the map
    return _images(rng, square)


def _drawn_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``blur`` and ``edge``, in the fixed cases' order and sizes, drawn
    from ``rng``.

    Uniform noise 4 x 4; an 8 x 10 image of one dark level in [0.1, 0.3] holding a bright
    3 to 4 x 4 to 5 square of one level in [0.7, 1], off the frame; noise 5 x 7; the smallest
    and thinnest, 1 x 1, 1 x 6, 6 x 1 and 2 x 2; RGB noise 4 x 5 x 3.
    """
    square = np.full((8, 10), rng.uniform(0.1, 0.3))
    top, left = int(rng.integers(1, 4)), int(rng.integers(1, 5))
    height, width = int(rng.integers(3, 5)), int(rng.integers(4, 6))
    square[top : top + height, left : left + width] = rng.uniform(0.7, 1.0)
    return _images(rng, square)


def _images(rng: np.random.Generator, square: np.ndarray) -> list[dict[str, Any]]:
    """The cases' images in their order: noise 4 x 4 (small enough to read in the report), the
    square, noise 5 x 7, the smallest and thinnest, and RGB noise, the noise from ``rng``."""
    return [
        {"image": rng.random((4, 4))},
        {"image": square},
        {"image": rng.random((5, 7))},
        {"image": rng.random((1, 1))},
        {"image": rng.random((1, 6))},
        {"image": rng.random((6, 1))},
        {"image": rng.random((2, 2))},
        {"image": rng.random((4, 5, 3))},
    ]


def _as_float(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float)


def _summary(value: Any) -> str:
    """An output image in one line; the picture shows it pixel for pixel."""
    array = _as_float(value)
    if array.size == 0:
        return _("an empty array of shape {shape}").format(shape=array.shape)
    return _("shape {shape}, values {low:.4g} to {high:.4g} (see the map)").format(
        shape=array.shape, low=array.min(), high=array.max()
    )


def _picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    return image_picture(expected, given, title=N_("the first case that differs, pixel for pixel"))


def _explain(case: dict[str, Any], expected: Any, given: Any) -> str:
    """The first wrong pixel as (x, y), and how much of its window lies inside the image."""
    want, have = _as_float(expected), _as_float(given)
    if want.shape != have.shape:
        return _("your output has shape {given}; the image has shape {expected}").format(
            given=have.shape, expected=want.shape
        )
    wrong_values = ~np.isclose(want, have, atol=1e-9, rtol=1e-9)
    wrong = wrong_values.any(axis=2) if wrong_values.ndim == 3 else wrong_values
    height, width = want.shape[:2]
    interior = np.zeros((height, width), dtype=bool)
    interior[1:-1, 1:-1] = True
    row, column = (int(i) for i in np.argwhere(wrong)[0])
    inside = (min(row + 1, height - 1) - max(row - 1, 0) + 1) * (
        min(column + 1, width - 1) - max(column - 1, 0) + 1
    )
    # The border is blamed only when every pixel inside is right: a wrong kernel or sum shows
    # inside too, and the first wrong pixel in reading order is usually the corner (0, 0).
    wrong_inside = np.argwhere(wrong & interior)
    if inside == 9:
        where = _("inside the image")
    elif len(wrong_inside):
        where = _(
            "on the border, but pixels inside the image are wrong too, the first at "
            "(x, y) = ({x}, {y}), where all 9 neighbours exist: start there"
        ).format(x=int(wrong_inside[0][1]), y=int(wrong_inside[0][0]))
    elif interior.any():
        where = _(
            "on the border: {inside} of 9 inside, and every pixel inside the image is right"
        ).format(inside=inside)
    else:
        where = _("on the border: {inside} of 9 inside").format(inside=inside)
    count = int(wrong.sum())
    differ = _("1 pixel differs") if count == 1 else _("{count} pixels differ").format(count=count)
    return _("the first wrong pixel is (x, y) = ({x}, {y}), {where}; {differ}").format(
        x=column, y=row, where=where, differ=differ
    )


_CHANNELS = (N_("red"), N_("green"), N_("blue"))


def _explain_nan(case: dict[str, Any], given: Any) -> str:
    """Which output pixel is NaN, where it lies, and the border slip that makes one."""
    have = _as_float(given)
    image = _as_float(case["image"])
    if have.shape != image.shape:
        return ""
    bad = ~np.isfinite(have)
    row, column, *channel = (int(i) for i in np.argwhere(bad)[0])
    height, width = have.shape[:2]
    inside = (min(row + 1, height - 1) - max(row - 1, 0) + 1) * (
        min(column + 1, width - 1) - max(column - 1, 0) + 1
    )
    pixel = _("output pixel (x, y) = ({x}, {y})").format(x=column, y=row)
    if channel:
        pixel = _("output pixel (x, y) = ({x}, {y}), channel {channel} ({colour}),").format(
            x=column, y=row, channel=channel[0], colour=_(_CHANNELS[channel[0]])
        )
        whole = [c for c in range(3) if bad[..., c].all()]
        if whole and not bad[..., [c for c in range(3) if c not in whole]].any():
            names = _(" and ").join(_(_CHANNELS[c]) for c in whole)
            return _(
                "{pixel} is NaN, and so is {channels} at every pixel, inside the image too: "
                "your padding added NaN along the colour axis. np.pad(image, 1, ...) pads all "
                "three axes of an RGB image, so each pixel gets 5 channels, the first and last "
                "NaN; pad the rows and the columns only, ((1, 1), (1, 1), (0, 0)), and keep the "
                "3 channels"
            ).format(pixel=pixel, channels=names)
    border = np.zeros((height, width), dtype=bool)
    border[[0, -1], :] = border[:, [0, -1]] = True
    nan_pixels = bad.any(axis=2) if bad.ndim == 3 else bad
    on_border, off_border = int(nan_pixels[border].sum()), int(nan_pixels[~border].sum())
    if inside == 9:
        return _(
            "{pixel} is NaN, inside the image, where all 9 of its neighbours exist: a NaN "
            "there comes from your own arithmetic (0 / 0, or the mean of an empty window)"
        ).format(pixel=pixel)
    return _(
        "{pixel} is NaN; it lies on the border, where only {inside} of its 9 neighbours are "
        "inside the image ({on_border} of the {border} border pixels are NaN, {off_border} "
        "inside): NaN comes from what your window reads past the edge. np.mean of a window "
        "that holds NaN padding is NaN (np.nanmean skips it), and the mean of an empty slice "
        "is NaN (image[y - 1 : y + 2] is empty at y = 0: start at max(y - 1, 0)). Average "
        "only the neighbours inside the image"
    ).format(
        pixel=pixel,
        inside=inside,
        on_border=on_border,
        border=int(border.sum()),
        off_border=off_border,
    )


BLUR_HINTS = Hints(
    where=N_(
        "first check one pixel inside the image by hand (the mean of its 9 neighbours, "
        "read from the input as it was); then the border: which neighbours you read "
        "there, and what you divide by."
    ),
    more=N_(
        "each output pixel is the mean of those of its 3 x 3 neighbours that exist: 9 "
        "inside, 6 on an edge, 4 at a corner; nothing outside the image is read, and the "
        "input is left as it was."
    ),
    recipe=N_(
        "output = zeros_like(image); for each (x, y): window = image[max(y - 1, 0) : "
        "y + 2, max(x - 1, 0) : x + 2]; output[y, x] = window.mean(axis=(0, 1))."
    ),
)


@exercise(
    hints=BLUR_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("Blur",),
    draw=_drawn_cases,
)
def blur(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image)``: the 3 x 3 box blur with the handout's border rule.

    ``image`` is gray (H, W) or RGB (H, W, 3) in [0, 1]; each output pixel is
    the mean of the pixels of its 3 x 3 neighbourhood that lie in the image
    (9 inside, 6 on an edge, 4 in a corner), per channel. Compared with
    ``course.filters.blur`` within 1e-9.

    Examples
    --------
    >>> blur(lambda image: image).passed
    False
    """
    return run_cases(
        "blur",
        student,
        _cases(),
        reference_blur,
        close(1e-9),
        _as_float,
        mistakes=BLUR_MISTAKES,
        picture=_picture,
        explain=_explain,
        explain_nan=_explain_nan,
        show=_summary,
        pass_picture=_pass_picture,
    )


def _pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    _, expected, given = results[1]  # the bright square
    top = max(float(np.max(expected)), 1.0)
    return side_by_side(expected / top, _as_float(given) / top, (N_("expected"), N_("your output")))


EDGE_HINTS = Hints(
    where=N_(
        "first check one pixel inside the image by hand: the two kernels, their signs, "
        "and how you combine Gx and Gy; then the border pixels (what you read outside "
        "the image)."
    ),
    more=N_(
        "outside the image, read the nearest pixel inside; Gx and Gy are the dot "
        "products of the two Sobel kernels with each 3 x 3 window, and the output is the "
        "length of (Gx, Gy), not clipped."
    ),
    recipe=N_(
        "pad the image by one pixel with its edge values (np.pad, mode='edge'); for "
        "each (x, y), window = padded[y : y + 3, x : x + 3]; gx, gy = the sums of SOBEL_X and "
        "SOBEL_Y times window; output[y, x] = sqrt(gx**2 + gy**2)."
    ),
)


@exercise(
    hints=EDGE_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("Edge",),
    draw=_drawn_cases,
)
def edge(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image)``: the Sobel gradient magnitude, border replicated.

    ``Gx`` and ``Gy`` are the dot products of ``[[-1, 0, 1], [-2, 0, 2],
    [-1, 0, 1]]`` and its transpose with each 3 x 3 window, a pixel outside
    the image taking the value of the nearest one inside; the output is
    ``sqrt(Gx**2 + Gy**2)``, per channel, not clipped. Compared with
    ``course.filters.sobel(image, border="replicate")`` within 1e-9.

    Examples
    --------
    >>> edge(lambda image: image).passed
    False
    """
    return run_cases(
        "edge",
        student,
        _cases(),
        _sobel_replicated,
        close(1e-9),
        _as_float,
        mistakes=EDGE_MISTAKES,
        picture=_picture,
        explain=_explain,
        explain_nan=_explain_nan,
        show=_summary,
        pass_picture=_pass_picture,
    )


def _sobel_replicated(image: Any) -> np.ndarray:
    return sobel(image, border="replicate")
