"""The known mistakes lesson 07's checkers name, each reproduced on the checker's cases.

:data:`BLUR_MISTAKES` are the wrong blurs :func:`.check.blur` names: a window sliced from
``y - 1`` at y = 0 (Python reads ``image[-1:2]`` as empty), zero padding (dividing by 9
everywhere), the frame skipped or copied, the nearest pixel repeated, numpy's ``'reflect'``
padding (the mirror about the edge pixel), the image wrapped around (``np.roll``), the sums
taken in 8 bits, which overflow past 255, or the image rounded to 8 bits, and a blur that
reads its own updated values. :data:`EDGE_MISTAKES` are the wrong Sobel magnitudes
:func:`.check.edge` names: zero padding, numpy's ``'reflect'`` padding, the magnitude
clipped to 1, Gx alone, the sum of squares without its root, ``|Gx| + |Gy|``, and the frame
skipped or copied.

Only the checkers call these, with their own cases and the student's answer as
:mod:`.check` has read it, so this module checks none (``UNCHECKED = True``; the fuzz test
skips it).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course.check.base import Mistake
from course.check.views import quiet
from course.filters import BOX, SOBEL_X, convolve, sobel
from course.filters import blur as reference_blur
from course.i18n import N_

UNCHECKED = True  # see the module docstring

__all__ = [
    "BLUR_MISTAKES",
    "EDGE_MISTAKES",
    "correlate",
    "eight_bit_blur",
    "frame_from",
    "running_blur",
    "same_eight_bit",
    "same_or_both_nan",
    "sliced_from_minus_one",
    "wrapped_blur",
]


def frame_from(image: np.ndarray, inner: np.ndarray, fill: np.ndarray | None) -> np.ndarray:
    """``inner`` inside the one-pixel frame, ``fill`` (or 0) on it: a loop from 1 to size - 2."""
    output = np.zeros_like(image) if fill is None else fill.copy()
    output[1:-1, 1:-1] = inner[1:-1, 1:-1]
    return output


def correlate(image: Any, kernel: np.ndarray, border: str) -> np.ndarray:
    # The lab's dot product of kernel and window: a convolution with the flipped kernel.
    return convolve(image, kernel[::-1, ::-1], border)


def sliced_from_minus_one(image: Any) -> np.ndarray:
    """Each pixel the mean of image[y - 1 : y + 2, x - 1 : x + 2]: empty at y = 0 or x = 0."""
    array = np.asarray(image, dtype=float)
    output = np.zeros_like(array)
    with quiet():  # not catch_warnings: it would make a student's warnings show again
        for y in range(array.shape[0]):
            for x in range(array.shape[1]):
                output[y, x] = array[y - 1 : y + 2, x - 1 : x + 2].mean(axis=(0, 1))
    return output


def same_or_both_nan(expected: Any, given: Any) -> bool:
    want, have = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
    return want.shape == have.shape and bool(
        np.allclose(have, want, atol=1e-9, rtol=1e-9, equal_nan=True)
    )


def running_blur(image: Any) -> np.ndarray:
    """The box blur written into the array its windows are read from, row by row."""
    output = np.array(image, dtype=float)
    height, width = output.shape[:2]
    for y in range(height):
        for x in range(width):
            window = output[max(y - 1, 0) : y + 2, max(x - 1, 0) : x + 2]
            output[y, x] = window.mean(axis=(0, 1))
    return output


def wrapped_blur(image: Any) -> np.ndarray:
    """The 3 x 3 mean with the image wrapped around, as ``np.roll`` or ``np.pad(mode="wrap")``
    read it: past the left edge, the right column."""
    array = np.asarray(image, dtype=float)
    padded = np.pad(array, [(1, 1), (1, 1)] + [(0, 0)] * (array.ndim - 2), mode="wrap")
    height, width = array.shape[:2]
    return sum(padded[dy : dy + height, dx : dx + width] for dy in range(3) for dx in range(3)) / 9


def _window_counts(shape: tuple[int, ...]) -> np.ndarray:
    """How many of each pixel's 3 x 3 neighbours lie in an image of ``shape``: 9, 6 or 4."""
    height, width = shape[:2]
    rows = np.minimum(np.arange(height) + 1, height - 1) - np.maximum(np.arange(height) - 1, 0) + 1
    columns = np.minimum(np.arange(width) + 1, width - 1) - np.maximum(np.arange(width) - 1, 0) + 1
    counts = np.outer(rows, columns).astype(float)
    return counts[..., None] if len(shape) == 3 else counts


def eight_bit_blur(image: Any, overflow: bool = True) -> np.ndarray:
    """The handout's blur of ``(image * 255).astype(np.uint8)``, in [0, 1]: each window's
    sum taken in 8 bits, so past 255 it wraps (``overflow``), divided by its count."""
    levels = np.floor(np.clip(np.asarray(image, dtype=float), 0.0, 1.0) * 255)  # astype truncates
    padded = np.pad(levels, [(1, 1), (1, 1)] + [(0, 0)] * (levels.ndim - 2))
    height, width = levels.shape[:2]
    total = sum(padded[dy : dy + height, dx : dx + width] for dy in range(3) for dx in range(3))
    if overflow:
        total = total % 256
    return total / _window_counts(levels.shape) / 255


def same_eight_bit(answer: Any, given: Any) -> bool:
    """``given`` is :func:`eight_bit_blur`'s ``answer`` as a student's 8-bit code returns it: in
    [0, 1] or left in grey levels (0 to 255), divided exactly or rounded down to a whole level,
    so within one grey level of it and a whole number of levels once times its window's count
    (a float blur a little off is not)."""
    want = np.asarray(answer, dtype=float) * 255
    have = np.asarray(given, dtype=float)
    if have.shape != want.shape or not np.isfinite(have).all():
        return False
    counts = _window_counts(have.shape)
    for levels in (have * 255, have):  # an output in [0, 1], or in grey levels
        sums = levels * counts
        if np.abs(levels - want).max() <= 1 + 1e-9 and np.allclose(sums, np.round(sums), atol=1e-6):
            return True
    return False


BLUR_MISTAKES = (
    Mistake(
        N_("a window sliced from y - 1 at y = 0"),
        N_(
            "at y = 0 (or x = 0) your window image[y - 1 : y + 2] starts at -1, which Python "
            "reads as the last row, so the slice is empty and its mean is NaN. Start the slice "
            "at max(y - 1, 0)."
        ),
        sliced_from_minus_one,
        matches=same_or_both_nan,
    ),
    Mistake(
        N_("zero padding"),
        N_(
            "you divide by 9 everywhere, as if the pixels outside the image were black: the frame "
            "darkens. The report averages only the neighbours inside the image (6 on an edge, 4 at "
            "a corner)."
        ),
        lambda image: convolve(image, BOX, "zero"),
    ),
    Mistake(
        N_("the frame skipped"),
        N_(
            "your loops run from 1 to size - 2 and leave the frame at 0. Blur every pixel, "
            "averaging the neighbours that exist."
        ),
        lambda image: frame_from(image, reference_blur(image), None),
    ),
    Mistake(
        N_("the frame copied"),
        N_(
            "your loops skip the one-pixel frame and copy it from the input. Blur every pixel, "
            "averaging the neighbours that exist."
        ),
        lambda image: frame_from(image, reference_blur(image), np.asarray(image, dtype=float)),
    ),
    Mistake(
        N_("the edge pixel repeated"),
        N_(
            "outside the image you read the nearest pixel inside (replicate), so the edge row "
            "counts twice. The report's rule averages only the pixels inside."
        ),
        lambda image: convolve(image, BOX, "replicate"),
    ),
    Mistake(
        N_("numpy's 'reflect' padding"),
        N_(
            "you padded like np.pad(mode='reflect'), which mirrors about the edge pixel "
            "(d c b | a b c d), and divided by 9: on the border your window counts pixels from "
            "inside the image twice. The report reads nothing outside the image: average only "
            "the neighbours inside (6 on an edge, 4 at a corner)."
        ),
        lambda image: convolve(image, BOX, "reflect"),
    ),
    Mistake(
        N_("the image wrapped around"),
        N_(
            "on the border your window reads the opposite side of the image, as np.roll (or "
            "np.pad's mode='wrap') does: the left column's window takes in the right column. "
            "The report reads nothing outside the image: average only the neighbours inside "
            "(6 on an edge, 4 at a corner)."
        ),
        wrapped_blur,
    ),
    # Before the overflow: on a case where no window's sum passes 255 the two agree, and then
    # nothing wrapped.
    Mistake(
        N_("the image cut to 8 bits"),
        N_(
            "you blurred (image * 255).astype(np.uint8), the image cut to whole grey levels, so "
            "each pixel is off by up to 1/255. Blur the image as it is given, floats in [0, 1]."
        ),
        lambda image: eight_bit_blur(image, overflow=False),
        matches=same_eight_bit,
    ),
    Mistake(
        N_("8-bit sums that overflow"),
        N_(
            "you added the window's pixels as uint8 (the image times 255, as np.uint8), and a "
            "uint8 sum wraps past 255: 200 + 100 gives 44, so bright windows come out dark. "
            "Blur the image as it is given, floats in [0, 1] (or convert to float before you add)."
        ),
        eight_bit_blur,
        matches=same_eight_bit,
    ),
    Mistake(
        N_("a blur that reads its own updated values"),
        N_(
            "your loop writes each blurred pixel into the array it reads its windows from, so "
            "every later window averages pixels that are already blurred (the picture smears "
            "down and to the right). Read every window from the input as it was, and write "
            "into a separate output array."
        ),
        running_blur,
    ),
)

EDGE_MISTAKES = (
    Mistake(
        N_("zero padding"),
        N_(
            "you read the pixels outside the image as 0: the frame lights up as a false edge. "
            "Read the nearest pixel inside (clamp the index)."
        ),
        lambda image: sobel(image, border="zero"),
    ),
    Mistake(
        N_("numpy's 'reflect' padding"),
        N_(
            "you padded like np.pad(mode='reflect'), which mirrors about the edge pixel "
            "(d c b | a b c d): on the left and right edges Gx comes out 0, on the top and bottom "
            "Gy. Repeat the edge pixel instead: np.pad's mode='edge' (scipy calls that rule "
            "'reflect'; the two libraries use the name for different rules)."
        ),
        lambda image: sobel(image, border="reflect"),
    ),
    Mistake(
        N_("clipped to 1"),
        N_(
            "your magnitude stops at 1, as writing it into an 8-bit image would: Sobel's runs up "
            "to sqrt(20), about 4.47 (Gx = 4 with Gy = 2). Return sqrt(Gx^2 + Gy^2) as it is."
        ),
        lambda image: np.clip(sobel(image, border="replicate"), 0.0, 1.0),
    ),
    Mistake(
        N_("Gx alone"),
        N_(
            "your output is |Gx|: horizontal changes only. Add Gy, the same sum with the "
            "transposed kernel, and take sqrt(Gx^2 + Gy^2)."
        ),
        lambda image: np.abs(correlate(image, SOBEL_X, "replicate")),
    ),
    Mistake(
        N_("the sum of squares, no root"),
        N_(
            "you returned Gx^2 + Gy^2, the sum of squares the lab report names: the "
            "magnitude is its square root, sqrt(Gx^2 + Gy^2)."
        ),
        lambda image: (
            correlate(image, SOBEL_X, "replicate") ** 2
            + correlate(image, SOBEL_X.T, "replicate") ** 2
        ),
    ),
    Mistake(
        N_("|Gx| + |Gy|"),
        N_(
            "you added |Gx| and |Gy|, a cheaper estimate that comes out up to 1.41 times too "
            "large on a diagonal edge; the magnitude is sqrt(Gx^2 + Gy^2)."
        ),
        lambda image: (
            np.abs(correlate(image, SOBEL_X, "replicate"))
            + np.abs(correlate(image, SOBEL_X.T, "replicate"))
        ),
    ),
    Mistake(
        N_("the frame skipped"),
        N_(
            "your loops run from 1 to size - 2 and leave the frame at 0. Compute every pixel, "
            "reading outside pixels from the nearest one inside."
        ),
        lambda image: frame_from(image, sobel(image, border="replicate"), None),
    ),
    Mistake(
        N_("the frame copied"),
        N_(
            "your loops skip the one-pixel frame and leave the input's values there. Compute "
            "every pixel, reading outside pixels from the nearest one inside."
        ),
        lambda image: frame_from(
            image, sobel(image, border="replicate"), np.asarray(image, dtype=float)
        ),
    ),
)
