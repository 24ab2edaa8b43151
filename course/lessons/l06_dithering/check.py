"""Lesson 06 exercises: the lab's ``DitheringOrdered`` and ``DitheringErrorDiffuse``.

The student writes them as ``dithering_ordered`` and ``dithering_error_diffuse``, the names
of their checkers and reports; ``check.hint()`` answers to the lab's names too.

A failure shows the expected and given outputs and their difference, names
the first wrong pixel (for error diffusion, with the value and the error
carried into it), and recognises the slips the lab's reports make or invite:
the matrix read transposed, ``>=`` for ``>``, the dots inverted (the
comparison reversed), the lesson's centred thresholds (M + 0.5) / 9 for the
lab's M / 9, one comparison per pixel without the 3 x 3 enlargement; a left
edge that wraps around, a serpentine scan, the dots inverted, the error's
sign flipped, the kernel mirrored, errors that are never read, and the input
dithered in place (the report copies its const input).
Both checkers end on a small face; a pass shows the student's dithered face
beside the expected one.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("dithering_ordered")`` says more at once and
``check.hint("dithering_ordered", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from course.check.base import CheckResult, Hints, Mistake, close, hint, run_cases
from course.check.exercises import exercise
from course.check.pictures import figure_png, image_picture
from course.halftone import diffusion, dither
from course.halftone.diffusion import (
    error_diffusion,
    error_diffusion_values,
    error_diffusion_wraparound,
)
from course.halftone.dither import ORDERED_MATRIX, ordered, threshold
from course.i18n import N_, _
from course.images import face, photograph, ramp, to_gray

__all__ = ["dithering_error_diffuse", "dithering_ordered", "hint"]

_LIBRARY_FUNCTIONS = (
    dither.ordered,
    diffusion.error_diffusion,
    diffusion.error_diffusion_values,
)


@cache
def _small_face() -> np.ndarray:
    """Lesson 06's face at a quarter of its pixels, 75 x 64: quick to dither in a Python loop."""
    return face()[::2, ::2].copy()


@cache
def _gray_photograph() -> np.ndarray:
    """The whole photograph in gray, 600 x 512: the small faces are cut from it."""
    return to_gray(photograph())


def _drawn_face(rng: np.random.Generator) -> np.ndarray:
    """A face like :func:`_small_face`, 75 x 64, every fourth pixel of the photograph: its
    window moved by up to 20 pixels each way, its tones bent by a gamma in [0.8, 1.25]."""
    top, left = 150 + int(rng.integers(-20, 21)), 128 + int(rng.integers(-20, 21))
    window = _gray_photograph()[top : top + 300 : 4, left : left + 256 : 4]
    return window ** float(np.exp(rng.uniform(np.log(0.8), np.log(1.25))))


#: A pass picture's faces are zoomed to about this many screen pixels down: the face
#: of error diffusion (75 rows) four times, so that every dot shows; the ordered one
#: (225 rows) at 1:1, each dot a screen pixel, never blurred by shrinking.
_PASS_PICTURE_ROWS = 300


def _face_pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    """The expected face beside the student's, each dot a flat square at a whole zoom."""
    _case, expected, given = results[-1]
    panels = ((_as_output(expected), _("expected")), (_as_output(given), _("your dithered face")))
    height, width = panels[0][0].shape
    zoom = max(1, _PASS_PICTURE_ROWS // max(height, width))
    gap, above = 16, 22
    columns, rows = 2 * width * zoom + 3 * gap, height * zoom + above + gap // 2
    figure = Figure(figsize=(columns / 100, rows / 100), dpi=100)
    for index, (dots, title) in enumerate(panels):
        left = gap + index * (width * zoom + gap)
        box = (left / columns, (gap // 2) / rows, width * zoom / columns, height * zoom / rows)
        axes = figure.add_axes(box)
        axes.imshow(dots, cmap="gray", vmin=0.0, vmax=1.0, interpolation="nearest")
        axes.set_axis_off()
        axes.set_title(title, fontsize=8, pad=3)
    return figure_png(figure)


def _as_output(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float)


def _first_wrong(expected: Any, given: Any) -> tuple[int, int] | None:
    """The first pixel, in the lab's raster order, where the outputs differ: (x, y)."""
    want, have = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
    if want.shape != have.shape:
        return None
    wrong = np.argwhere(want != have)
    return None if len(wrong) == 0 else (int(wrong[0][1]), int(wrong[0][0]))


def _eight_bit(reference: Callable[..., Any]) -> Mistake:
    return Mistake(
        N_("0 and 255 for 0 and 1"),
        N_(
            "your pixels are right, but lit is 255 and dark 0, as in an 8-bit image: the lesson's "
            "images are floats in [0, 1], so a lit pixel is 1. Write 1.0 where you wrote 255."
        ),
        _in_255(reference),
    )


def _ordered_cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(9)
    levels = np.arange(10).reshape(2, 5) / 9  # exactly on M / 9: > and >= differ
    return [
        {"gray": levels},
        {"gray": np.array([[0.3, 0.75, 0.05], [0.55, 0.95, 0.45]])},
        {"gray": rng.random((4, 7))},
        {"gray": _small_face()},
    ]


def _drawn_ordered_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``dithering_ordered``, in the fixed cases' order, drawn from ``rng``.

    The ten levels 0, 1/9, ..., 1, exactly on M / 9 (where > and >= differ), shuffled into a
    2 x 5 image; 2 x 3 and 4 x 7 images of uniform noise; a face (:func:`_drawn_face`).
    """
    return [
        {"gray": rng.permutation(np.arange(10)).reshape(2, 5) / 9},
        {"gray": rng.random((2, 3)).round(2)},
        {"gray": rng.random((4, 7))},
        {"gray": _drawn_face(rng)},
    ]


def _ordered_with(matrix: np.ndarray, compare: Callable[..., Any]) -> Callable[..., np.ndarray]:
    def halftone(gray: Any) -> np.ndarray:
        values = np.asarray(gray, dtype=float)
        cells = np.kron(values, np.ones((3, 3)))
        levels = np.tile(matrix / 9, values.shape)
        return compare(cells, levels).astype(float)

    return halftone


def _one_per_pixel(gray: Any) -> np.ndarray:
    values = np.asarray(gray, dtype=float)
    height, width = values.shape
    levels = np.tile(ORDERED_MATRIX / 9, (-(-height // 3), -(-width // 3)))[:height, :width]
    return (values > levels).astype(float)


def _inverted(
    explanation: str, reference: Callable[..., Any], *reversed_comparisons: Callable[..., Any]
) -> tuple[Mistake, ...]:
    """The dots inverted: the right output negated (the 1 and the 0 swapped), and each of
    ``reversed_comparisons`` (``<`` or ``<=`` for ``>``, which differ on a tie)."""
    name = N_("the dots inverted")
    negated = Mistake(name, explanation, lambda gray: 1.0 - np.asarray(reference(gray), float))
    return (negated, *(Mistake(name, explanation, answer) for answer in reversed_comparisons))


def _in_255(reference: Callable[..., Any]) -> Callable[..., np.ndarray]:
    """The right dithering written as 8-bit levels, 0 and 255: the slip's answer."""
    return lambda gray: 255 * np.asarray(reference(gray), dtype=float)


def _levels(given: Any) -> str:
    """What is wrong with an output whose values are not the lesson's 0 and 1, if anything."""
    values = np.unique(_as_output(given))
    if values.size == 0 or np.isin(values, (0.0, 1.0)).all():
        return ""
    shown = ", ".join(f"{v:g}" for v in values[:4]) + (", ..." if values.size > 4 else "")
    return _(
        "your output holds the values {values}: the lesson's output is 0 (dark) or 1 (lit), "
        "as its input is a gray level in [0, 1]"
    ).format(values=shown)


def _picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    return image_picture(expected, given, title=N_("first case that differs"))


ORDERED_HINTS = Hints(
    where=N_(
        "look at the output's size, at which sub-pixel of a cell compares with which "
        "entry of M, and at the comparison itself."
    ),
    more=N_(
        "each input pixel becomes a 3 x 3 cell; row i, column j of the cell compares "
        "the pixel's value with M[i][j] / 9, lit only where the value is greater."
    ),
    recipe=N_(
        "output = zeros(3 H, 3 W); for each (x, y) and i, j in range(3): output[3 y + "
        "i, 3 x + j] = 1 if gray[y, x] > M[i][j] / 9 else 0."
    ),
)


@exercise(
    hints=ORDERED_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("DitheringOrdered",),
    draw=_drawn_ordered_cases,
)
def dithering_ordered(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(gray)``: each pixel a 3 x 3 cell, sub-pixel (i, j) lit where v > M[i, j] / 9.

    ``M = [[6, 8, 4], [1, 0, 3], [5, 2, 7]]`` as on the slide: row i of the
    cell is row i of M. The output is 3 times larger in each direction.

    Examples
    --------
    >>> dithering_ordered(_ordered_with(ORDERED_MATRIX.T, np.greater)).mistake
    'the matrix transposed'
    """
    mistakes = [
        Mistake(
            N_("the matrix transposed"),
            N_(
                "your cells are the slide's patterns mirrored on the diagonal: i and j are "
                "swapped, in the output (output[3 y + j, 3 x + i]) or in the matrix (M[j][i]). "
                "Row i of a cell is row i of M: output[3 y + i, 3 x + j] compares with M[i][j]."
            ),
            _ordered_with(ORDERED_MATRIX.T, np.greater),
        ),
        Mistake(
            N_(">= for >"),
            N_(
                "you lit a sub-pixel where the value equals M[i][j] / 9: the lab's rule is "
                "strictly greater, so a level of exactly k / 9 lights k sub-pixels, not k + 1."
            ),
            _ordered_with(ORDERED_MATRIX, np.greater_equal),
        ),
        *_inverted(
            N_(
                "your dots are the negative: you lit a sub-pixel where the value is not above "
                "its threshold (the comparison reversed, or the 1 and the 0 swapped), so dark "
                "pixels come out lit. Light it (1) where gray[y, x] > M[i][j] / 9, else 0."
            ),
            ordered,
            _ordered_with(ORDERED_MATRIX, np.less),
        ),
        Mistake(
            N_("centred thresholds"),
            N_(
                "you compared with (M[i][j] + 0.5) / 9, the centred thresholds the lesson shows "
                "remove the bias; the lab's rule, and this exercise, compare with M[i][j] / 9 "
                "exactly."
            ),
            _ordered_with(ORDERED_MATRIX + 0.5, np.greater),
        ),
        Mistake(
            N_("one comparison per pixel"),
            N_(
                "your output is the size of the input: you compared each pixel with one entry of "
                "M. Ordered dithering here makes every pixel a 3 x 3 cell of nine comparisons."
            ),
            _one_per_pixel,
        ),
        _eight_bit(ordered),
    ]
    return run_cases(
        "dithering_ordered",
        student,
        _ordered_cases(),
        reference=ordered,
        compare=close(atol=0, rtol=0),
        convert=_as_output,
        mistakes=mistakes,
        picture=_picture,
        explain=lambda case, expected, given: _levels(given),
        pass_picture=_face_pass_picture,
    )


def _diffusion_cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(6)
    # The ramp first: on the flat 0.5 the sign flipped and the errors never read both give
    # all black, so a slip recognised on the first wrong case would be named wrongly there.
    return [
        {"gray": ramp((4, 16))},
        {"gray": np.full((4, 6), 0.5)},
        {"gray": rng.random((1, 10))},
        {"gray": np.full((8, 1), 0.3)},
        {"gray": rng.random((9, 13))},
        {"gray": rng.random((16, 16))},
        {"gray": _small_face()},
    ]


def _drawn_diffusion_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``dithering_error_diffuse``, in the fixed cases' order, drawn from ``rng``.

    First a 4 x 16 ramp from a dark level in [0, 0.15] to a light one in [0.85, 1], either
    way round; then flat 0.5, the threshold itself, 4 x 6; a row of 10 noisy pixels; a column
    of 8 at one level in [0.2, 0.4]; 9 x 13 and 16 x 16 of uniform noise; a face
    (:func:`_drawn_face`).
    """
    low, high = rng.uniform(0.0, 0.15), rng.uniform(0.85, 1.0)
    gradient = low + (high - low) * ramp((4, 16))
    return [
        {"gray": gradient if rng.random() < 0.5 else gradient[:, ::-1].copy()},
        {"gray": np.full((4, 6), 0.5)},
        {"gray": rng.random((1, 10))},
        {"gray": np.full((8, 1), round(float(rng.uniform(0.2, 0.4)), 2))},
        {"gray": rng.random((9, 13))},
        {"gray": rng.random((16, 16))},
        {"gray": _drawn_face(rng)},
    ]


#: Floyd-Steinberg's pushes as the lab writes them: (dx, dy, sixteenths).
_KERNEL = ((1, 0, 7), (-1, 1, 3), (0, 1, 5), (1, 1, 1))
_MIRRORED = ((1, 0, 7), (1, 1, 3), (0, 1, 5), (-1, 1, 1))


def _diffused(
    gray: Any,
    kernel: tuple = _KERNEL,
    sign: float = 1.0,
    lit: Callable[[float], bool] = lambda value: value > 0.5,
) -> np.ndarray:
    """The lab's loop with a given kernel, the error's sign flipped or another rule for a lit
    dot: the slips' answers."""
    buffer = np.array(gray, dtype=float)
    height, width = buffer.shape
    output = np.zeros_like(buffer)
    for y in range(height):
        for x in range(width):
            output[y, x] = 1.0 if lit(buffer[y, x]) else 0.0
            error = sign * (buffer[y, x] - output[y, x])
            for dx, dy, weight in kernel:
                if 0 <= x + dx < width and y + dy < height:
                    buffer[y + dy, x + dx] += error * weight / 16
    return output


def _carried(case: dict[str, Any], expected: Any, given: Any) -> str:
    """What the first wrong pixel held when the right loop thresholded it."""
    levels = _levels(given)
    if levels:
        return levels
    where = _first_wrong(expected, given)
    if where is None:
        return _("the output must have the input's shape, one value per pixel")
    x, y = where
    gray = np.asarray(case["gray"], dtype=float)
    value = float(error_diffusion_values(gray, method="loop")[y, x])
    verdict = _("lit, since it is > 0.5") if value > 0.5 else _("dark, since it is not > 0.5")
    return _(
        "first wrong pixel (x={x}, y={y}): its value {value:.4f} plus the error carried into it, "
        "{carried:+.4f}, is {total:.4f}: {verdict}"
    ).format(x=x, y=y, value=gray[y, x], carried=value - gray[y, x], total=value, verdict=verdict)


DIFFUSION_HINTS = Hints(
    where=N_(
        "look at the order you visit the pixels in, at what each pixel is compared "
        "with, and at where its error goes."
    ),
    more=N_(
        "visit the pixels row by row, left to right, in a copy of the image; each is "
        "thresholded at 0.5 with the errors it has received, and its own error (what it "
        "wanted minus what it got) is shared among the four neighbours not yet visited."
    ),
    recipe=N_(
        "buffer = gray.copy(); for y, for x: output = 1 if buffer[y, x] > 0.5 else 0; "
        "error = buffer[y, x] - output; add 7/16 of it right, 3/16 below left, 5/16 below, "
        "1/16 below right, skipping pushes off the image."
    ),
)


@exercise(
    hints=DIFFUSION_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("DitheringErrorDiffuse",),
    draw=_drawn_diffusion_cases,
)
def dithering_error_diffuse(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(gray)`` against Floyd-Steinberg as the lab specifies it.

    The function takes a gray float image ``gray`` (H, W) in [0, 1] and
    returns an (H, W) array of 0s and 1s: pixels in raster order (row by
    row, left to right), each 1 where its value plus the errors received is
    > 0.5, the error pushed 7/16 right, 3/16 below left, 5/16 below, 1/16
    below right, pushes off the image dropped. Compared exactly with
    ``course.halftone.dither.error_diffusion(gray, method="loop")``; a failure names
    the first wrong pixel and the error that should have reached it.

    Examples
    --------
    >>> dithering_error_diffuse(error_diffusion_wraparound).mistake
    'the left edge wraps around'
    """
    mistakes = [
        Mistake(
            N_("the left edge wraps around"),
            N_(
                "at x = 0 your push to (x - 1, y + 1) went to buffer[y + 1, -1], the last pixel of "
                "the next row: Python reads a negative index from the end. Check x - 1 >= 0, as "
                "the lab report's unsigned x could not."
            ),
            error_diffusion_wraparound,
        ),
        Mistake(
            N_("a serpentine scan"),
            N_(
                "you ran every other row right to left: a fine variant, but the lab's loop runs "
                "every row left to right, and the checker compares with it exactly."
            ),
            lambda gray: error_diffusion(gray, serpentine=True, method="loop"),
        ),
        Mistake(
            N_("the error's sign flipped"),
            N_(
                "you pushed output - value instead of value - output: each neighbour then moves "
                "away from the tone it should keep. The error is what the pixel wanted minus "
                "what it got."
            ),
            lambda gray: _diffused(gray, sign=-1.0),
        ),
        *_inverted(
            N_(
                "your dots are the negative: you lit a pixel where its value is not above 0.5 "
                "(the comparison reversed, or the 1 and the 0 swapped), so dark pixels come out "
                "lit. Light it (1) where buffer[y, x] > 0.5; the error is then what it wanted "
                "minus what it got."
            ),
            _loop_reference,
            lambda gray: _diffused(gray, lit=lambda value: value < 0.5),
            lambda gray: _diffused(gray, lit=lambda value: value <= 0.5),
        ),
        Mistake(
            N_("the kernel mirrored"),
            N_(
                "your 3/16 and 1/16 are swapped: 3/16 goes below left, (x - 1, y + 1), and 1/16 "
                "below right, (x + 1, y + 1), as on the slide."
            ),
            lambda gray: _diffused(gray, kernel=_MIRRORED),
        ),
        Mistake(
            N_("the errors are never read"),
            N_(
                "you thresholded the input itself: the errors must go into a copy of the image "
                "(the report's inputcopy), and each pixel is thresholded with what it received."
            ),
            threshold,
        ),
        _eight_bit(_loop_reference),
    ]
    return run_cases(
        "dithering_error_diffuse",
        student,
        _diffusion_cases(),
        reference=_loop_reference,
        compare=close(atol=0, rtol=0),
        convert=_as_output,
        mistakes=mistakes,
        picture=_picture,
        explain=_carried,
        on_change=N_(
            "The lab report avoids this slip: its input is const, so it pushes the errors "
            "into a copy (inputcopy). Do the same (buffer = gray.copy()), so that the "
            "caller's image stays as it was."
        ),
        pass_picture=_face_pass_picture,
    )


def _loop_reference(gray: Any) -> np.ndarray:
    return error_diffusion(gray, method="loop")
