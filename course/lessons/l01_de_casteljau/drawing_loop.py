"""Lesson 01's drawing loop, ``bezier(control_points, window)``: what its checker runs.

:func:`course.lessons.l01_de_casteljau.check.bezier` runs the student's loop
on the windows of :data:`BEZIER_SHAPES` (:func:`bezier_cases`) and compares
the pixels painted with :func:`bezier_reference`, one pixel per t = 0, 0.001,
..., 1. This module holds those cases and that reference; :class:`Painting`,
the student's window read back (:func:`same_painting`,
:func:`painting_difference`, :func:`show_painting` compare and show it); the
failure and pass pictures; and :func:`rounding_sensitive_pixels`, which
keeps every case's answer independent of the last bit of a float. The
handouts' drawing-loop mistakes the report names are in
:mod:`course.lessons.l01_de_casteljau.mistakes`.

The checker calls these with its own cases; the student's answer is read by
:class:`Painting`, which checks it. So this module checks no input of its own
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course.check.base import (
    AnswerError,
    pixel_difference,
    pixel_rows,
    same_pixels,
)
from course.check.pictures import pixel_picture, side_by_side
from course.curves.bezier import de_casteljau
from course.i18n import _
from course.images import SEED_000_CUBIC
from course.raster import nearest_pixels

__all__ = [
    "BEZIER_SHAPES",
    "EDGE_TOLERANCE",
    "GREEN",
    "GREY",
    "GREY_CASE",
    "STEP",
    "Painting",
    "bezier_cases",
    "bezier_pass_picture",
    "bezier_picture",
    "bezier_reference",
    "curve_pixels",
    "loop_parameters",
    "painted_pixels",
    "painting_difference",
    "rounding_sensitive_pixels",
    "same_painting",
    "show_painting",
    "window_for",
]

UNCHECKED = True  # see the module docstring

#: The t step of seed 000's loop, and the values it should take: 0, 0.001, ..., 1.
STEP = 0.001
_STEPS = round(1 / STEP)


#: The drawing loop's windows: seed 000's curve on its 700 x 700 window, a curve that
#: leaves a small window on every side (its pixels off the window must be skipped, and it
#: crosses x = width and y = height, where a test `x <= width` indexes past the end), a
#: curve on a 24 x 24 window already painted grey (:data:`GREY`: a pixel painted green is
#: (0, 1, 0), or keeps its red and blue when only its green channel is set, as the reports
#: do; the rest of the window stays grey), then lines on the window's edges, where a
#: test one off (`0 < x`, `x <= width`, `0 < y`, `y <= height`, `-1 <= y`) paints too much or
#: too little: x = 0 and y = 0 exactly (painted), a line that ends at x = width and one that
#: ends at y = height (their last point skipped), and y = -0.5 (skipped, although int(-0.5)
#: is row 0). No point lies within rounding of a pixel edge where its side matters
#: (:func:`rounding_sensitive_pixels`): y = 100.5 and x = 100.5, not 100, which
#: (1 - t) 100 + t 100 computes as 99.99999999999999 for some t.
BEZIER_SHAPES = (
    (SEED_000_CUBIC, (700, 700)),
    (np.array([[-20.0, 50.0], [30.0, -40.0], [70.0, 90.0], [100.0, 20.0]]), (60, 80)),
    (np.array([[2.2, 20.5], [5.0, 1.5], [21.0, 3.5]]), (24, 24)),
    (np.array([[0.0, 10.0], [0.0, 100.0]]), (700, 700)),
    (np.array([[650.0, 100.5], [700.0, 100.5]]), (700, 700)),
    (np.array([[100.0, 0.0], [300.0, 0.0]]), (700, 700)),
    (np.array([[100.5, 600.0], [100.5, 700.0]]), (700, 700)),
    (np.array([[100.0, -0.5], [300.0, -0.5]]), (700, 700)),
)
#: The case painted grey before the student's loop runs: the third, the 24 x 24 window.
GREY_CASE = 2
GREEN = (0.0, 1.0, 0.0)
#: The colour of the window painted before the loop runs: a loop must leave the pixels it
#: does not paint as they are, and a pixel's red and blue as they are or at 0.
GREY = (0.25, 0.25, 0.25)
#: How near a whole x or y, relative to the control points' size, a curve point counts as
#: within rounding of a pixel edge: a thousand times the few units in the last place that any
#: way of computing B(t) or t loses, far below the float32 loop's drift, which is a mistake.
EDGE_TOLERANCE = 1e-10


def window_for(shape: tuple[int, int], grey: bool = False) -> np.ndarray:
    """A case's window: black, or painted :data:`GREY` all over.

    Examples
    --------
    >>> window_for((2, 3)).shape, window_for((2, 3), grey=True)[0, 0].tolist()
    ((2, 3, 3), [0.25, 0.25, 0.25])
    """
    window = np.zeros((*shape, 3))
    if grey:
        window[...] = GREY
    return window


def bezier_cases() -> list[dict[str, Any]]:
    """The checker's cases: each of :data:`BEZIER_SHAPES`, its points and its window."""
    return [
        {"control_points": points.copy(), "window": window_for(shape, number == GREY_CASE)}
        for number, (points, shape) in enumerate(BEZIER_SHAPES)
    ]


def curve_pixels(
    control_points: np.ndarray, shape: tuple[int, ...], t: np.ndarray, rounding: str = "floor"
) -> np.ndarray:
    """The pixels a loop over ``t`` paints on a window of ``shape``: one per point on it.

    Examples
    --------
    >>> curve_pixels(np.array([[0.5, 0.5], [3.5, 0.5]]), (1, 3), np.array([0, 0.5, 1])).tolist()
    [[0, 0], [2, 0]]
    """
    curve = de_casteljau(control_points, t)
    return nearest_pixels(curve, rounding=rounding, shape=shape[:2])


def loop_parameters() -> np.ndarray:
    """The t of seed 000's loop, each from a whole count: 0, 0.001, ..., 1 (1001 values)."""
    return np.arange(_STEPS + 1) / _STEPS


def rounding_sensitive_pixels(control_points: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """The pixels a right drawing loop may paint or not, by the last bits of its arithmetic.

    A point of the curve within rounding of a pixel edge (a whole x or y, to
    :data:`EDGE_TOLERANCE`) lands on either side of it, by how the loop
    computed it: ``(1 - t) P0 + t P1`` or ``P0 + t (P1 - P0)``, ``k / 1000`` or
    ``k * 0.001``. That is harmless where every pixel it may land in is
    painted anyway by a point clear of all edges, or is off the window; the
    pixels where it is not are returned, (K, 2) (x, y). The points every way
    computes exactly are not within rounding: at t = 0 (P0), at t = 1 (Pn, when
    ``P[i] + (P[i+1] - P[i])`` is P[i+1] in floats), a coordinate 0 in every
    control point, and whole coordinates at t a multiple of 1/8. The checker's
    cases, fixed and drawn, have none.

    Examples
    --------
    >>> rounding_sensitive_pixels(np.array([[650.0, 100.0], [700.0, 100.0]]), (700, 700))[:2]
    array([[650,  99],
           [651,  99]])
    >>> rounding_sensitive_pixels(np.array([[650.0, 100.5], [700.0, 100.5]]), (700, 700)).size
    0
    """
    control = np.asarray(control_points, dtype=float)
    t = loop_parameters()
    curve = de_casteljau(control, t)
    whole = np.round(curve)
    scale = max(1.0, float(np.abs(control).max()))
    near = (np.abs(curve - whole) <= EDGE_TOLERANCE * scale) & ~_computed_exactly(control, t)
    low = np.where(near, whole - 1, np.floor(curve)).astype(np.int64)
    high = np.where(near, whole, np.floor(curve)).astype(np.int64)
    height, width = shape[:2]
    settled = ~near.any(axis=1)
    on_window = (low[:, 0] >= 0) & (low[:, 0] < width) & (low[:, 1] >= 0) & (low[:, 1] < height)
    certain = set(map(tuple, low[settled & on_window].tolist()))
    sensitive = {
        (x, y)
        for (x_low, y_low), (x_high, y_high) in zip(
            low[~settled].tolist(), high[~settled].tolist(), strict=True
        )
        for x in {x_low, x_high}
        for y in {y_low, y_high}
        if 0 <= x < width and 0 <= y < height and (x, y) not in certain
    }
    return np.array(sorted(sensitive), dtype=np.int64).reshape(-1, 2)


def _computed_exactly(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d): whether every way of computing coordinate d of B(t) gets it exactly."""
    degree = len(control) - 1
    whole = (control == np.round(control)).all(axis=0)
    # Whole coordinates times powers of 1/8 up to the degree, summed: exact within 53 bits.
    whole &= np.abs(control).max(axis=0) < 2.0 ** (52 - 4 * degree)
    exact = (t * 8 == np.round(t * 8))[:, None] & whole[None, :]
    exact |= (control == 0).all(axis=0)[None, :]
    exact[t == 0] = True
    level = control
    while len(level) > 1:
        level = level[:-1] + (level[1:] - level[:-1])  # the step P0 + t (P1 - P0) at t = 1
    exact[t == 1] |= level[0] == control[-1]
    return exact


def bezier_reference(control_points: np.ndarray, window: np.ndarray) -> np.ndarray:
    """The pixels to paint: the one holding B(t) for each t = 0, 0.001, ..., 1 on the window."""
    return curve_pixels(control_points, window.shape, loop_parameters())


class Painting:
    """The pixels a student painted (neither black nor :data:`GREY`), and the first in the
    wrong colour.

    Made from ``(window, returned)``: the window after the call, and what the
    function returned, kept to recognise a painted copy returned instead.
    """

    def __init__(self, answer: Any) -> None:
        window, returned = answer
        image = np.asarray(window)
        if image.ndim != 3 or image.shape[2] != 3 or image.dtype.kind not in "biuf":
            raise AnswerError(
                _("the window must stay an (H, W, 3) image of numbers; yours is {shape}").format(
                    shape=image.shape
                )
            )
        self.window = image
        self.pixels, self.wrong_colour = _painted(image)
        self.returned_pixels = None
        if isinstance(returned, np.ndarray) and returned.shape == image.shape:
            self.returned_pixels = _painted(returned)[0]


def _painted(image: np.ndarray) -> tuple[np.ndarray, tuple[int, int, tuple] | None]:
    painted = (image != 0).any(axis=2) & ~(image == GREY).all(axis=2)
    rows, columns = np.nonzero(painted)
    pixels = np.column_stack([columns, rows]).astype(np.int64)
    colours = image[rows, columns].astype(float)
    # Green either way the lesson allows: the whole pixel (0, 1, 0), or the green channel
    # alone, as every report writes it (window[y, x, 1] = 1), red and blue left as they were.
    green_channel = (colours == (GREY[0], 1.0, GREY[2])).all(axis=1)
    wrong = ~((colours == GREEN).all(axis=1) | green_channel)
    wrong_colour = None
    if wrong.any():
        k = int(np.argmax(wrong))
        wrong_colour = (int(columns[k]), int(rows[k]), tuple(colours[k].tolist()))
    return pixels, wrong_colour


def same_painting(expected: np.ndarray, given: Painting) -> bool:
    """Whether the student painted exactly the expected pixels, all of them green."""
    return given.wrong_colour is None and same_pixels(expected, given.pixels)


def painting_difference(expected: np.ndarray, given: Painting) -> str:
    """How the painting differs: a pixel in the wrong colour, or pixels missing or extra."""
    if given.wrong_colour is not None and same_pixels(expected, given.pixels):
        x, y, colour = given.wrong_colour
        shown = ", ".join(f"{c:g}" for c in colour)
        return _(
            "the right pixels, but pixel ({x}, {y}) is ({colour}): paint the curve green, (0, 1, 0)"
        ).format(x=x, y=y, colour=shown)
    return pixel_difference(expected, given.pixels)


def show_painting(answer: Any) -> str:
    """An answer as the report shows it: how many pixels it paints."""
    if isinstance(answer, Painting):
        count = len(answer.pixels)
    else:
        count = len(np.unique(pixel_rows(answer, "expected"), axis=0))
    # Always "pixels", as before the reports were translated: English stays what it was.
    return _("{count} pixels painted").format(count=count)


def painted_pixels(answer: Any) -> Any:
    """The pixels of an answer: a :class:`Painting`'s, or the answer itself (a mistake's)."""
    return answer.pixels if isinstance(answer, Painting) else answer


def bezier_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    """A failure's picture: the pixels around the first difference."""
    return pixel_picture(expected, painted_pixels(given), title=_("around the first difference"))


def bezier_pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    """A pass's picture: the student's window beside the expected one."""
    case, expected, given = results[0]
    reference = np.zeros(case["window"].shape)
    reference[expected[:, 1], expected[:, 0]] = GREEN
    return side_by_side(reference, given.window, (_("expected"), _("your window")), shrink="max")
