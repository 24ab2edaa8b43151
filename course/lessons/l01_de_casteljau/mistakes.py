"""Lesson 01's drawing loop: the handouts' mistakes its checker names, and how it tells them.

:func:`bezier_mistakes` lists them, in the order the report tries them: the colour
(set, not added; green, not 8-bit), a painted copy, t accumulated in float steps (a
probe curve, :data:`ACCUMULATION_PROBE`, tells it), a loop that stops before t = 1, the
float32 loop of the GAMES101 report (:func:`float32_loop_pixels`: its t, whatever
precision the points are computed in), rounding to the nearest pixel (``round`` and
``int(x + 0.5)``), x and y swapped, negative indices (:func:`wrapped_pixels`) and a
coarse step.

The checker calls these with its own cases, and the student's loop only through
:func:`course.check.sandbox.run_bounded`; this module checks no input of its own
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from course.check.base import Mistake, same_pixels
from course.check.sandbox import run_bounded
from course.curves.bezier import de_casteljau
from course.curves.flattening import uniform_parameters
from course.i18n import _
from course.lessons.l01_de_casteljau.drawing_loop import (
    STEP,
    Painting,
    bezier_reference,
    curve_pixels,
    loop_parameters,
    painted_pixels,
)
from course.raster import nearest_pixels

__all__ = [
    "ACCUMULATION_PROBE",
    "FLOAT32_SPREAD",
    "SpreadPixels",
    "bezier_mistakes",
    "float32_loop_pixels",
    "half_up_pixels",
    "wrapped_pixels",
]

UNCHECKED = True  # see the module docstring

#: A curve that tells t accumulated in float steps from range(1000): it runs right to left
#: two pixels per step, so t a few ulps above k / 1000 lands one pixel to the left. (Its
#: points lie on pixel edges on purpose: it is a probe, never a case.)
ACCUMULATION_PROBE = {"control_points": np.array([[699.0, 0.5], [-1301.0, 0.5]]), "shape": (2, 700)}


#: How far float32 arithmetic may move a curve point, relative to the control points' size:
#: float32 keeps 24 bits (6e-8), and each level of de Casteljau rounds once or twice. A
#: student's float32 t reaches their points through (1 - t) computed in float32, or the whole
#: point in float32 (a Python float times an np.float32 stays float32), or not at all.
FLOAT32_SPREAD = 1e-6


@dataclass(frozen=True)
class SpreadPixels:
    """The pixels a loop paints, up to the precision of its arithmetic.

    ``pixels`` (K, 2) are those its points land in computed exactly; ``certain`` the pixels
    it paints however it rounds, ``unsure`` those it paints or not by its last bits. As an
    array it is ``pixels``, so a stand-in student can paint it.
    """

    pixels: np.ndarray
    certain: frozenset[tuple[int, int]]
    unsure: frozenset[tuple[int, int]]

    def __array__(self, dtype: Any = None, copy: Any = None) -> np.ndarray:
        return np.asarray(self.pixels, dtype=dtype)

    def holds(self, pixels: Any) -> bool:
        """Whether ``pixels`` are these: every certain pixel, and otherwise only unsure ones.

        Examples
        --------
        >>> spread = float32_loop_pixels(np.array([[0.5, 0.5], [3.5, 0.5]]), (1, 4), "floor")
        >>> spread.holds(spread.pixels), spread.holds(spread.pixels[:1])
        (True, False)
        """
        given = set(map(tuple, np.asarray(pixels, dtype=np.int64).reshape(-1, 2).tolist()))
        return self.certain <= given <= self.certain | self.unsure


def float32_loop_pixels(
    control_points: np.ndarray, shape: tuple[int, ...], rounding: str
) -> SpreadPixels:
    """The pixels of the handouts' `float t` loop, ``t += 0.001`` in float32, on a window of
    ``shape``, each point rounded by ``rounding`` (:func:`course.raster.nearest_pixels`'),
    up to :data:`FLOAT32_SPREAD`: however precisely the points are computed from that t.

    Examples
    --------
    >>> spread = float32_loop_pixels(np.array([[0.5, 0.5], [3.0, 0.5]]), (1, 4), "floor")
    >>> spread.pixels[[0, -1]].tolist(), len(spread.unsure)  # its last t is 0.9999907
    ([[0, 0], [2, 0]], 0)
    """
    control = np.asarray(control_points, dtype=float)
    curve = de_casteljau(control, uniform_parameters(STEP, accumulate="float32"))
    spread = FLOAT32_SPREAD * max(1.0, float(np.abs(control).max()))
    low = nearest_pixels(curve - spread, rounding=rounding)
    high = nearest_pixels(curve + spread, rounding=rounding)
    height, width = shape[:2]

    def on_window(pixels: set[tuple[int, int]]) -> frozenset[tuple[int, int]]:
        return frozenset((x, y) for x, y in pixels if 0 <= x < width and 0 <= y < height)

    settled = (low == high).all(axis=1)
    certain = on_window(set(map(tuple, low[settled].tolist())))
    unsure = on_window(
        {
            (x, y)
            for (x_low, y_low), (x_high, y_high) in zip(
                low[~settled].tolist(), high[~settled].tolist(), strict=True
            )
            for x in {x_low, x_high}
            for y in {y_low, y_high}
        }
    )
    pixels = nearest_pixels(curve, rounding=rounding, shape=(height, width))
    return SpreadPixels(pixels, certain, unsure - certain)


def half_up_pixels(control_points: np.ndarray, window: np.ndarray) -> np.ndarray:
    """The pixels of a loop that rounds by hand, ``int(x + 0.5)``: half up, where numpy's and
    Python's ``round`` take a half to the even neighbour (392.5 to 392, 100.5 to 100).

    Examples
    --------
    >>> half_up_pixels(np.array([[0.5, 0.5], [2.5, 0.5]]), np.zeros((2, 4, 3)))[[0, -1]].tolist()
    [[1, 1], [3, 1]]
    """
    curve = de_casteljau(control_points, loop_parameters())
    pixels = np.floor(curve + 0.5).astype(np.int64)
    height, width = window.shape[:2]
    kept = (pixels[:, 0] >= 0) & (pixels[:, 0] < width) & (pixels[:, 1] >= 0)
    return pixels[kept & (pixels[:, 1] < height)]


def wrapped_pixels(rounding: str) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    """The pixels of a loop that tests only ``x < width and y < height``, as a function of
    ``(control_points, window)``; ``rounding`` is :func:`course.raster.nearest_pixels`'.

    A negative index counts from the end of the row or column, so a pixel
    left of or above the window lands on its other side; ``int`` truncates
    toward zero, so a point in (-1, 0) lands in column or row 0 instead.
    """

    def pixels(control_points: np.ndarray, window: np.ndarray) -> np.ndarray:
        height, width = window.shape[:2]
        curve = de_casteljau(control_points, loop_parameters())
        kept = curve[(curve[:, 0] < width) & (curve[:, 1] < height)]
        found = nearest_pixels(kept, rounding=rounding)
        # Python raises past -length, so such a loop stops there: not this mistake.
        inside = (found[:, 0] >= -width) & (found[:, 1] >= -height)
        return found[inside] % (width, height)

    return pixels


def _accumulates(student: Callable[..., Any]) -> bool:
    """Whether ``student`` paints the probe curve as t accumulated in float steps would."""
    probe = ACCUMULATION_PROBE
    window = np.zeros((*probe["shape"], 3))
    run_bounded(lambda: student(probe["control_points"].copy(), window))
    steps = uniform_parameters(STEP, accumulate="float64")
    expected = curve_pixels(probe["control_points"], window.shape, steps)
    return bool(same_pixels(expected, Painting((window, None)).pixels))


def bezier_mistakes(student: Callable[..., Any] | None = None) -> list[Mistake]:
    """The handouts' drawing-loop mistakes; ``student`` is probed for t accumulated in steps."""
    accumulated = uniform_parameters(STEP, accumulate="float64")

    def pixels_match(mistaken: Any, given: Any) -> bool:
        return same_pixels(mistaken, painted_pixels(given))

    def accumulated_match(mistaken: Any, given: Any) -> bool:
        return pixels_match(mistaken, given) and student is not None and _accumulates(student)

    def colour_match(expected: Any, given: Any) -> bool:
        return getattr(given, "wrong_colour", None) is not None and bool(
            same_pixels(expected, painted_pixels(given))
        )

    def added_match(expected: Any, given: Any) -> bool:
        window = getattr(given, "window", None)
        pixels = painted_pixels(given)
        if window is None or not same_pixels(expected, pixels):
            return False
        # The expected pixels keep their repeats: one per t that lands in the pixel.
        painted, times = np.unique(np.asarray(expected, dtype=np.int64), axis=0, return_counts=True)
        colours = window[painted[:, 1], painted[:, 0]].astype(float)
        # Red and blue as they were (black or grey), green higher by 1 for each t.
        before = colours[:, 0]
        return bool(
            (colours[:, 2] == before).all()
            and (colours[:, 1] - before == times).all()
            and (times >= 2).any()
        )

    def spread_match(mistaken: Any, given: Any) -> bool:
        return isinstance(mistaken, SpreadPixels) and mistaken.holds(painted_pixels(given))

    def copy_match(expected: Any, given: Any) -> bool:
        returned = getattr(given, "returned_pixels", None)
        return (
            len(painted_pixels(given)) == 0
            and returned is not None
            and bool(same_pixels(expected, returned))
        )

    wraps = _(
        "a pixel with x < 0 or y < 0 appeared on the other side of the window (or, through "
        "int(), which rounds toward zero, in column or row 0): Python counts a negative index "
        "from the end. Test 0 <= x < width and 0 <= y < height before you paint, and skip "
        "every point off the window."
    )
    return [
        # The colours first: with the right pixels in the wrong colour, every mistake that only
        # compares pixels and agrees with the reference on this case (off-window points
        # wrapped, when there are none) would match too.
        Mistake(
            _("green added, not set"),
            _(
                "you added to the green channel (+= 1) instead of setting it: a pixel that "
                "several values of t land in is painted once per t, and its green grows to 2, "
                "3, ... Set the pixel: window[y, x] = (0, 1, 0), or window[y, x, 1] = 1."
            ),
            bezier_reference,
            matches=added_match,
        ),
        Mistake(
            _("the wrong colour"),
            _(
                "you painted the right pixels in another colour: the window holds floats from 0 "
                "to 1 in the order red, green, blue, so green is (0, 1, 0); (0, 255, 0) is "
                "OpenCV's 8-bit scale, and (1, 0, 0) is red."
            ),
            bezier_reference,
            matches=colour_match,
        ),
        Mistake(
            _("a painted copy"),
            _(
                "your function painted a copy of the window and returned it: the window it was "
                "given stays black. Paint into window itself (window[y, x] = ...), the one "
                "argument this exercise lets you change; there is nothing to return."
            ),
            bezier_reference,
            matches=copy_match,
        ),
        Mistake(
            _("t accumulated in float steps"),
            _(
                "your t is a sum of 0.001 steps (t = 0.0; while t <= 1: ...; t += 0.001), as the "
                "handouts' loop for (t = 0; t <= 1; t += 0.001) does: each addition rounds, the "
                "sum ends a hair above 1 after a thousand steps, so t = 1 is never painted, and on "
                "the way t drifts a few units in the last place. Count whole steps instead: "
                "for k in range(1001): t = k / 1000."
            ),
            lambda control_points, window: curve_pixels(control_points, window.shape, accumulated),
            matches=accumulated_match,
        ),
        Mistake(
            _("the loop stops before t = 1"),
            _(
                "your loop never reaches t = 1, so the curve's last pixel stays dark: range(1000) "
                "and np.arange(0, 1, 0.001) stop at 0.999. Count whole steps up to and including "
                "1000: for k in range(1001): t = k / 1000."
            ),
            lambda control_points, window: curve_pixels(
                control_points, window.shape, loop_parameters()[:-1]
            ),
            matches=pixels_match,
        ),
        Mistake(
            _("the float32 loop of the GAMES101 report"),
            _(
                "your t drifts: the handout's float t (np.float32 in Python) keeps about 7 "
                "digits, and a thousand additions of 0.001 move the points enough to change "
                "pixels in the middle of the curve. Compute each t from a whole count, in "
                "Python's float: t = k / 1000."
            ),
            lambda control_points, window: float32_loop_pixels(
                control_points, window.shape, "floor"
            ),
            matches=spread_match,
        ),
        Mistake(
            _("rounding to the nearest pixel"),
            _(
                "you rounded x and y, as OpenCV's cv::Point does in the GAMES101 report: that "
                "paints the pixel whose corner is nearest, half a pixel off. As the lesson says, "
                "the pixel whose square holds the point (x, y) is (int(x), int(y)) for x, y >= 0: "
                "the whole parts, not the rounded values."
            ),
            lambda control_points, window: curve_pixels(
                control_points, window.shape, loop_parameters(), "round"
            ),
            matches=pixels_match,
        ),
        Mistake(
            _("rounding half up, int(x + 0.5)"),
            _(
                "int(x + 0.5) rounds half up: it paints the pixel whose corner is nearest the "
                "point, half a pixel off, as cv::Point does in the GAMES101 report. As the lesson "
                "says, the pixel whose square holds the point (x, y) is (int(x), int(y)) for "
                "x, y >= 0: the whole parts, without the 0.5."
            ),
            half_up_pixels,
            matches=pixels_match,
        ),
        Mistake(
            _("the GAMES101 report's loop: float32 t and cv::Point rounding"),
            _(
                "your loop is the GAMES101 report's: a float t advanced by 0.001 a thousand "
                "times, which drifts, and each point rounded to the nearest pixel as cv::Point "
                "does, half a pixel off. Compute each t from a whole count (t = k / 1000, in "
                "Python's float) and paint (int(x), int(y)), the pixel whose square holds the "
                "point."
            ),
            lambda control_points, window: float32_loop_pixels(
                control_points, window.shape, "round"
            ),
            matches=spread_match,
        ),
        Mistake(
            _("x and y swapped"),
            _("you wrote window[x, y]: an image is indexed by row first, window[y, x]."),
            lambda control_points, window: curve_pixels(
                control_points, window.shape[1::-1], loop_parameters()
            )[:, ::-1],
            matches=pixels_match,
        ),
        Mistake(
            _("int() before the window test"),
            _(
                "a point just left of or above the window, with x or y between -1 and 0, was "
                "painted in column or row 0: int() rounds toward zero, so int(-0.5) is 0 and "
                "passes a test of the pixel. Test the point itself, 0 <= x < width and "
                "0 <= y < height, before you take int(), or take math.floor."
            ),
            lambda control_points, window: curve_pixels(
                control_points, window.shape, loop_parameters(), "trunc"
            ),
            matches=pixels_match,
        ),
        Mistake(
            _("a negative index wraps around"), wraps, wrapped_pixels("trunc"), matches=pixels_match
        ),
        Mistake(
            _("a negative index wraps around"), wraps, wrapped_pixels("floor"), matches=pixels_match
        ),
        Mistake(
            _("a step of 0.01"),
            _(
                "your step is ten times too coarse: 101 points leave gaps on a curve about 1400 "
                "pixels long. Use 0.001, as the handout does."
            ),
            lambda control_points, window: curve_pixels(
                control_points, window.shape, np.arange(101) / 100
            ),
            matches=pixels_match,
        ),
    ]
