"""Lesson 01's drawing loop, ``bezier(control_points, window)``: what its checker runs.

:func:`course.lessons.l01_de_casteljau.check.bezier` runs the student's loop
on the windows of :data:`BEZIER_SHAPES` (:func:`bezier_cases`) and compares
the pixels painted with :func:`bezier_reference`, one pixel per t = 0, 0.001,
..., 1. This module holds those cases and that reference; :class:`Painting`,
the student's window read back (:func:`same_painting`,
:func:`painting_difference`, :func:`show_painting` compare and show it); the
handouts' drawing-loop mistakes the report names (:func:`bezier_mistakes`);
the failure and pass pictures; and :func:`rounding_sensitive_pixels`, which
keeps every case's answer independent of the last bit of a float.

The checker calls these with its own cases; the student's answer is read by
:class:`Painting`, which checks it. So this module checks no input of its own
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import (
    AnswerError,
    Mistake,
    pixel_difference,
    pixel_rows,
    same_pixels,
)
from course.check.pictures import pixel_picture, side_by_side
from course.check.sandbox import run_bounded
from course.curves.bezier import de_casteljau
from course.curves.flattening import uniform_parameters
from course.i18n import _
from course.images import SEED_000_CUBIC
from course.raster import nearest_pixels

__all__ = [
    "ACCUMULATION_PROBE",
    "BEZIER_SHAPES",
    "EDGE_TOLERANCE",
    "GREEN",
    "GREY",
    "GREY_CASE",
    "STEP",
    "Painting",
    "bezier_cases",
    "bezier_mistakes",
    "bezier_pass_picture",
    "bezier_picture",
    "bezier_reference",
    "curve_pixels",
    "loop_parameters",
    "painting_difference",
    "rounding_sensitive_pixels",
    "same_painting",
    "show_painting",
    "window_for",
    "wrapped_pixels",
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
#: A curve that tells t accumulated in float steps from range(1000): it runs right to left
#: two pixels per step, so t a few ulps above k / 1000 lands one pixel to the left. (Its
#: points lie on pixel edges on purpose: it is a probe, never a case.)
ACCUMULATION_PROBE = {"control_points": np.array([[699.0, 0.5], [-1301.0, 0.5]]), "shape": (2, 700)}
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


def _pixels_of(answer: Any) -> Any:
    return answer.pixels if isinstance(answer, Painting) else answer


def _accumulates(student: Callable[..., Any]) -> bool:
    """Whether ``student`` paints the probe curve as t accumulated in float steps would."""
    probe = ACCUMULATION_PROBE
    window = np.zeros((*probe["shape"], 3))
    run_bounded(lambda: student(probe["control_points"].copy(), window))
    steps = uniform_parameters(STEP, accumulate="float64")
    expected = curve_pixels(probe["control_points"], window.shape, steps)
    return bool(same_pixels(expected, _painted(window)[0]))


def bezier_mistakes(student: Callable[..., Any] | None = None) -> list[Mistake]:
    """The handouts' drawing-loop mistakes; ``student`` is probed for t accumulated in steps."""
    accumulated = uniform_parameters(STEP, accumulate="float64")
    float32_loop = uniform_parameters(STEP, accumulate="float32")

    def pixels_match(mistaken: Any, given: Any) -> bool:
        return same_pixels(mistaken, _pixels_of(given))

    def accumulated_match(mistaken: Any, given: Any) -> bool:
        return pixels_match(mistaken, given) and student is not None and _accumulates(student)

    def colour_match(expected: Any, given: Any) -> bool:
        return getattr(given, "wrong_colour", None) is not None and bool(
            same_pixels(expected, _pixels_of(given))
        )

    def copy_match(expected: Any, given: Any) -> bool:
        returned = getattr(given, "returned_pixels", None)
        return (
            len(_pixels_of(given)) == 0
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
                "your t drifts: the handout's float t keeps about 7 digits, and a thousand "
                "additions of 0.001 move the points enough to change pixels in the middle of the "
                "curve. Compute each t from a whole count, in Python's float."
            ),
            lambda control_points, window: curve_pixels(control_points, window.shape, float32_loop),
            matches=pixels_match,
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
            _("the GAMES101 report's loop: float32 t and cv::Point rounding"),
            _(
                "your loop is the GAMES101 report's: a float t advanced by 0.001 a thousand "
                "times, which drifts, and each point rounded to the nearest pixel as cv::Point "
                "does, half a pixel off. Compute each t from a whole count (t = k / 1000, in "
                "Python's float) and paint (int(x), int(y)), the pixel whose square holds the "
                "point."
            ),
            lambda control_points, window: curve_pixels(
                control_points, window.shape, float32_loop, "round"
            ),
            matches=pixels_match,
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


def bezier_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    """A failure's picture: the pixels around the first difference."""
    return pixel_picture(expected, _pixels_of(given), title=_("around the first difference"))


def bezier_pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    """A pass's picture: the student's window beside the expected one."""
    case, expected, given = results[0]
    reference = np.zeros(case["window"].shape)
    reference[expected[:, 1], expected[:, 0]] = GREEN
    return side_by_side(reference, given.window, (_("expected"), _("your window")), shrink="max")
