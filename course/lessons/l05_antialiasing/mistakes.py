"""The known mistakes lesson 05's checkers name, each reproduced on the checker's cases.

:func:`splat_mistakes` are the wrong splats :func:`.check.splat`
names, each answer a splat table (:mod:`.splat_tables`): the whole point
given to one pixel (the handouts' plain loop, the GAMES101 report's left
addColor) or to the pixel under it, pixels taken at their corners (its
middle addColor), its right addColor with the first version's dx (a weight
below 0), the weights times 255 (its colour), the pixels off the canvas left
out (or their share normalised away), each pixel given its own rectangle, x
and y swapped, the VS2022 report's normalised splat, and int() for floor.
:func:`weight_mistakes` are the wrong weights :func:`.check.arc_length_weights`
names: counting, a whole chord on one side only, whole chords on both sides.
Each is built in the current language; :data:`SPLAT_MISTAKES` and
:data:`WEIGHT_MISTAKES` are the ones built at import.

Only the checkers call these, with their own cases, so this module checks
none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from course.antialias import arc_length_weights as reference_weights
from course.antialias import (
    bilinear_centres,
    bilinear_corners,
    nearest_round,
    normalised_centres,
)
from course.check.base import Mistake
from course.i18n import _
from course.lessons.l05_antialiasing.splat_tables import splat_table, table_of

UNCHECKED = True  # see the module docstring

__all__ = [
    "SPLAT_MISTAKES",
    "WEIGHT_MISTAKES",
    "chords",
    "in_255",
    "nearest_floor",
    "on_the_canvas",
    "one_pixel_where_they_differ",
    "own_rectangles",
    "right_addcolor_as_written",
    "splat_mistakes",
    "swapped",
    "truncated",
    "weight_mistakes",
]


# --- splats ----------------------------------------------------------------------------


def swapped(x: float, y: float) -> np.ndarray:
    """The bilinear splat with each pixel given as (row, column)."""
    table = splat_table(*bilinear_centres([[x, y]]))
    return splat_table(table[:, [1, 0]], table[:, 2])


def nearest_floor(samples: Any) -> tuple[np.ndarray, np.ndarray]:
    """One pixel per sample, the one whose square holds it (floor); weight 1."""
    points = np.asarray(samples, dtype=float).reshape(-1, 2)
    return np.floor(points).astype(np.int64), np.ones(len(points))


def one_pixel_where_they_differ(
    one_pixel: Callable[..., Any], other: Callable[..., Any]
) -> Callable[[float, float], np.ndarray | None]:
    """``one_pixel``'s splat where it lights another pixel than ``other`` (rounding and
    truncation), else None, which matches nothing: such a point cannot tell them apart."""

    def answer(x: float, y: float) -> np.ndarray | None:
        table, rival = table_of(one_pixel)(x, y), table_of(other)(x, y)
        return None if np.array_equal(table, rival) else table

    return answer


def own_rectangles(x: float, y: float) -> np.ndarray:
    """The bilinear splat with each pixel given the rectangle between the point and its centre."""
    left, top = math.floor(x - 0.5), math.floor(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return splat_table(pixels, [dx * dy, (1 - dx) * dy, dx * (1 - dy), (1 - dx) * (1 - dy)])


def truncated(x: float, y: float) -> np.ndarray:
    """The splat with int() for floor: left of or above 0.5 it picks the wrong pixels."""
    left, top = int(x - 0.5), int(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return splat_table(pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy])


def right_addcolor_as_written(x: float, y: float) -> np.ndarray:
    """The GAMES101 report's right addColor with its first version's dx, in Python.

    Its pixels are round(point) - 1 and round(point) (Python's round: half to even), but dx =
    point.x - p1.x is measured from p1's corner, not its centre, so it runs from 0.5 to 1.5 and
    a neighbour's weight falls below 0.
    """
    left, top = round(x) - 1, round(y) - 1
    dx, dy = x - left, y - top
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return splat_table(pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy])


def in_255(x: float, y: float) -> np.ndarray:
    """The bilinear splat with each weight multiplied by 255, the report's colour (0, 255, 0)."""
    table = splat_table(*bilinear_centres([[x, y]]))
    return splat_table(table[:, :2], 255 * table[:, 2])


def on_the_canvas(renormalised: bool) -> Callable[[float, float], np.ndarray]:
    """The bilinear splat without its pixels left of or above the canvas, their weight lost or
    (``renormalised``) shared among the rest: the right splat where all four are on it."""

    def answer(x: float, y: float) -> np.ndarray:
        table = splat_table(*bilinear_centres([[x, y]]))
        kept = table[(table[:, 0] >= 0) & (table[:, 1] >= 0)]
        total = kept[:, 2].sum()
        weights = kept[:, 2] / total if renormalised and total > 0 else kept[:, 2]
        return splat_table(kept[:, :2], weights)

    return answer


def splat_mistakes() -> tuple[Mistake, ...]:
    """The wrong splats :func:`.check.splat` names, in the current language."""
    return (
        Mistake(
            _("the whole point to one pixel"),
            _(
                "your splat gives the whole point to one pixel, weight 1: no anti-aliasing. That "
                "is the handout's plain loop, and also the GAMES101 report's left addColor, "
                "whose corners p1..p4 are built from the point itself (cv::Point2f p1(point.x, "
                "point.y)), so dx = point.x - p1.x is always 0. Share the point among the four "
                "pixels whose centres surround it, with dx and dy measured from a pixel centre."
            ),
            one_pixel_where_they_differ(nearest_round, nearest_floor),
        ),
        Mistake(
            _("the pixel under the point (truncated)"),
            _(
                "your splat gives the whole point to the pixel under it, (floor(x), floor(y)) as "
                "int() truncates it, weight 1: no anti-aliasing. Share the point "
                "among the four pixels whose centres surround it, with dx and dy measured from a "
                "pixel centre."
            ),
            one_pixel_where_they_differ(nearest_floor, nearest_round),
        ),
        # Where rounding and truncation light the same pixel, the point cannot tell which.
        Mistake(
            _("the whole point to one pixel"),
            _(
                "your splat gives the whole point to one pixel, weight 1: no anti-aliasing. At "
                "this point the pixel under it (truncated) and the nearest one (rounded, as the "
                "GAMES101 report's left addColor) are the same pixel. Share the point among the "
                "four pixels whose centres surround it, with dx and dy measured from a pixel "
                "centre."
            ),
            table_of(nearest_round),
        ),
        Mistake(
            _("pixels at their corners"),
            _(
                "your four pixels are those around the point's integer corner: the GAMES101 "
                "report's middle addColor, whose cv::Point p1(point.x, point.y) drops the "
                "fractions (C++ converts a float argument to int by truncating), and so treats "
                "pixel (c, r) as if it sat at (c, r). Its centre is (c + 0.5, r + 0.5): the "
                "curve moves half a pixel right and down. (The report's right addColor, p1 = "
                "round(point) - 1, gives these weights too at a pixel's centre if its dx is "
                "point.x - p1.x: measure dx from p1's centre, point.x - (p1.x + 0.5).)"
            ),
            table_of(bilinear_corners),
        ),
        Mistake(
            _("the right addColor read literally"),
            _(
                "your four pixels are the GAMES101 report's right addColor's, round(point) - 1 "
                "and round(point), but your dx = point.x - p1.x is measured from p1's corner: it "
                "runs from 0.5 to 1.5, and a neighbour gets a weight below 0. Measure it from "
                "p1's centre: dx = point.x - (p1.x + 0.5), and dy likewise."
            ),
            right_addcolor_as_written,
        ),
        Mistake(
            _("weights times 255"),
            _(
                "your weights are 255 times too large: the GAMES101 report multiplies its colour "
                "(0, 255, 0) by each weight, but the splat returns the weights themselves, "
                "areas between 0 and 1 that add up to 1."
            ),
            in_255,
        ),
        Mistake(
            _("pixels off the canvas left out"),
            _(
                "you left out the pixels left of or above the canvas, such as (0, -1): the "
                "exercise keeps them, with their weights (whoever draws drops them later). "
                "Return all four pixels."
            ),
            on_the_canvas(renormalised=False),
        ),
        Mistake(
            _("pixels off the canvas left out"),
            _(
                "you left out the pixels left of or above the canvas, such as (0, -1), and "
                "normalised the rest to add up to 1: the exercise keeps them, with their "
                "weights. Return all four pixels; the four bilinear weights add up to 1 already."
            ),
            on_the_canvas(renormalised=True),
        ),
        Mistake(
            _("each pixel its own rectangle"),
            _(
                "each of your four pixels gets the rectangle between the point and its own centre: "
                "the nearest pixel gets the least. A pixel's weight is the area of the rectangle "
                "opposite it: (1 - dx)(1 - dy) for the top-left one."
            ),
            own_rectangles,
        ),
        Mistake(
            _("x and y swapped"),
            _("your pixels are (row, column): give each as (x, y), the column first."),
            swapped,
        ),
        Mistake(
            _("the normalised splat"),
            _(
                "your weights never vanish: a point at a pixel's centre still gives its neighbours "
                "some. That is the VS2022 report's splat: sqrt(2) minus each distance, "
                "normalised. Bilinear weights are areas of rectangles, and give a centre's pixel "
                "everything."
            ),
            table_of(normalised_centres),
        ),
        Mistake(
            _("int() for floor"),
            _(
                "left of or above the first centres your pixels are one off: int() rounds toward "
                "zero, so int(-0.25) is 0, while the column left of pixel 0, or the row above it, "
                "is floor(-0.25) = -1."
            ),
            truncated,
        ),
    )


SPLAT_MISTAKES = splat_mistakes()


# --- arc-length weights ----------------------------------------------------------------


def chords(samples: Any) -> np.ndarray:
    """The distances between neighbouring samples."""
    return np.hypot(*np.diff(np.asarray(samples, dtype=float), axis=0).T)


def weight_mistakes() -> tuple[Mistake, ...]:
    """The wrong weights :func:`.check.arc_length_weights` names, in the current language."""
    return (
        Mistake(
            _("counting"),
            _(
                "every sample weighs 1, as in the handouts' loop: a pixel's brightness then "
                "counts the samples in it, and follows the curve's speed. Weigh each by the "
                "length of curve it stands for."
            ),
            # A lone sample cannot tell counting from a slip at the ends alone: no answer.
            lambda samples: np.ones(len(samples)) if len(samples) > 1 else None,
        ),
        Mistake(
            _("the chord after each sample"),
            _(
                "each sample has the whole chord to the next one (and the last none): the curve "
                "shifts its ink backwards by half a chord. Give each sample half the chord on "
                "each side."
            ),
            lambda samples: np.append(chords(samples), 0.0),
        ),
        Mistake(
            _("the chord before each sample"),
            _(
                "each sample has the whole chord from the previous one (and the first none). Give "
                "each sample half the chord on each side."
            ),
            lambda samples: np.insert(chords(samples), 0, 0.0),
        ),
        Mistake(
            _("whole chords on both sides"),
            _(
                "each sample has both chords beside it in full: every piece of curve is counted "
                "twice. Halve them."
            ),
            lambda samples: 2 * reference_weights(samples),
        ),
    )


WEIGHT_MISTAKES = weight_mistakes()
