"""Lesson 01's drawing loop, ``bezier(control_points, window)``: what its checker runs.

:func:`course.lessons.l01_de_casteljau.check.bezier` runs the student's loop
on the windows of :data:`BEZIER_SHAPES` (:func:`bezier_cases`) and compares
the pixels painted with :func:`bezier_reference`, one pixel per t = 0, 0.001,
..., 1. This module holds those cases and that reference; :class:`Painting`,
the student's window read back (:func:`same_painting`,
:func:`painting_difference`, :func:`show_painting` compare and show it); the
handouts' drawing-loop mistakes the report names (:func:`bezier_mistakes`);
and the failure and pass pictures.

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
    "GREEN",
    "STEP",
    "Painting",
    "bezier_cases",
    "bezier_mistakes",
    "bezier_pass_picture",
    "bezier_picture",
    "bezier_reference",
    "draw_bezier_cases",
    "painting_difference",
    "same_painting",
    "show_painting",
]

UNCHECKED = True  # see the module docstring

#: The t step of seed 000's loop, and the values it should take: 0, 0.001, ..., 1.
STEP = 0.001
_STEPS = round(1 / STEP)


#: The drawing loop's windows: seed 000's curve on its 700 x 700 window, a curve that
#: leaves a small window on every side (its pixels off the window must be skipped, and it
#: crosses x = width and y = height, where a test `x <= width` indexes past the end), a
#: curve on a 24 x 24 window, then lines along the window's edges, where a test one off
#: (`0 < x`, `x <= width`, `0 < y`, `y <= height`, `-1 <= y`) paints too much or too little:
#: x = 0 and y = 0 exactly (painted), x = width and y = height exactly (skipped), and
#: y = -0.5 (skipped, although int(-0.5) is row 0).
BEZIER_SHAPES = (
    (SEED_000_CUBIC, (700, 700)),
    (np.array([[-20.0, 50.0], [30.0, -40.0], [70.0, 90.0], [100.0, 20.0]]), (60, 80)),
    (np.array([[2.2, 20.5], [5.0, 1.5], [21.0, 3.5]]), (24, 24)),
    (np.array([[0.0, 10.0], [0.0, 100.0]]), (700, 700)),
    (np.array([[650.0, 100.0], [700.0, 100.0]]), (700, 700)),
    (np.array([[100.0, 0.0], [300.0, 0.0]]), (700, 700)),
    (np.array([[100.0, 700.0], [300.0, 700.0]]), (700, 700)),
    (np.array([[100.0, -0.5], [300.0, -0.5]]), (700, 700)),
)
#: A curve that tells t accumulated in float steps from range(1000): it runs right to left
#: two pixels per step, so t a few ulps above k / 1000 lands one pixel to the left.
ACCUMULATION_PROBE = {"control_points": np.array([[699.0, 0.5], [-1301.0, 0.5]]), "shape": (2, 700)}
GREEN = (0.0, 1.0, 0.0)


def bezier_cases() -> list[dict[str, Any]]:
    """The checker's cases: each of :data:`BEZIER_SHAPES`, its points and a black window."""
    return [
        {"control_points": points.copy(), "window": np.zeros((*shape, 3))}
        for points, shape in BEZIER_SHAPES
    ]


def draw_bezier_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of :data:`BEZIER_SHAPES`' families, drawn from ``rng``, each with a black
    window.

    In the same order: a cubic across a 700 x 700 window with a long last leg, on which the
    drawing loop's mistakes each paint pixels of their own (the loop stopped before t = 1,
    float32 t, rounding, both, x and y swapped, a step of 0.01); a cubic that leaves a window
    of about 60 x 80 on the left and the right, on which int() before the window test and
    the two wrapped negative indices each paint pixels of their own; a quadratic inside a
    24 x 24 window; then lines of drawn lengths along the 700 x 700 window's edges, either way
    round: on x = 0, ending at x = width, on y = 0, on y = height and on y = -0.5.

    Examples
    --------
    >>> cases = draw_bezier_cases(np.random.default_rng(1))
    >>> [case["window"].shape[:2] for case in cases][:3], len(cases)
    ([(700, 700), (63, 81), (24, 24)], 8)
    >>> cases[3]["control_points"][:, 0].tolist(), cases[7]["control_points"][:, 1].tolist()
    ([0.0, 0.0], [-0.5, -0.5])
    """
    shapes = [(700, 700)]

    def spanning() -> np.ndarray:  # a long last leg: the pixel of t = 1 is its own
        while True:
            points = rng.uniform(10, 690, (4, 2)).round(1)
            if np.hypot(*(points[3] - points[2])) >= 300:
                return points

    float32_loop = uniform_parameters(STEP, accumulate="float32")
    cubic = _drawn_until_apart(
        spanning,
        shapes[0],
        [
            lambda points, shape: _loop_pixels(points, shape, _every_t()),
            lambda points, shape: _loop_pixels(points, shape, float32_loop),
            lambda points, shape: _loop_pixels(points, shape, _every_t()[:-1]),
            lambda points, shape: _loop_pixels(points, shape, _every_t(), "round"),
            lambda points, shape: _loop_pixels(points, shape, float32_loop, "round"),
            lambda points, shape: _loop_pixels(points, shape[1::-1], _every_t())[:, ::-1],
            lambda points, shape: _loop_pixels(points, shape, np.arange(101) / 100),
        ],
    )
    height, width = int(rng.integers(50, 71)), int(rng.integers(70, 91))
    shapes.append((height, width))

    def leaving() -> np.ndarray:
        while True:
            points = np.array(
                [
                    [-rng.uniform(15, 30), rng.uniform(0.7, 0.9) * height],
                    [rng.uniform(0.3, 0.45) * width, -rng.uniform(0.5, 0.8) * height],
                    [rng.uniform(0.8, 0.95) * width, rng.uniform(1.3, 1.6) * height],
                    [rng.uniform(1.15, 1.35) * width, rng.uniform(0.25, 0.45) * height],
                ]
            ).round(1)
            curve = de_casteljau(points, _every_t())
            if curve[:, 0].min() < -1 and curve[:, 0].max() > width:
                return points

    off_window = _drawn_until_apart(
        leaving,
        shapes[1],
        [
            lambda points, shape: _loop_pixels(points, shape, _every_t()),
            lambda points, shape: _loop_pixels(points, shape, _every_t(), "trunc"),
            lambda points, shape: _wrapped("trunc")(points, np.zeros(shape)),
            lambda points, shape: _wrapped("floor")(points, np.zeros(shape)),
        ],
    )
    shapes.append((24, 24))
    polygons = [cubic, off_window, rng.uniform(1.5, 22.5, (3, 2)).round(1)]

    def along(start: float, stop: float) -> tuple[float, float]:
        first = round(float(rng.uniform(start, stop)), 1)
        return first, round(first + float(rng.uniform(50, 350)), 1)

    top, bottom = along(5, 300)
    left, right = along(50, 300)
    edges = [
        [[0.0, top], [0.0, bottom]],
        [[round(float(rng.uniform(550, 680)), 1), float(rng.integers(20, 680))], [700.0, 0.0]],
        [[left, 0.0], [right, 0.0]],
        [[left + 30, 700.0], [right + 30, 700.0]],
        [[left + 60, -0.5], [right + 60, -0.5]],
    ]
    edges[1][1][1] = edges[1][0][1]  # the line ends at x = width, on the row it started in
    for points in edges:
        polygons.append(np.array(points if rng.random() < 0.5 else points[::-1]))
        shapes.append((700, 700))
    return [
        {"control_points": points, "window": np.zeros((*shape, 3))}
        for points, shape in zip(polygons, shapes, strict=True)
    ]


def _drawn_until_apart(
    draw: Callable[[], np.ndarray],
    shape: tuple[int, int],
    paintings: list[Callable[[np.ndarray, tuple[int, int]], np.ndarray]],
) -> np.ndarray:
    """Control points from ``draw``, drawn again until the ``paintings`` of them (the
    reference's and mistakes') are pixel sets all different from each other."""
    while True:
        points, seen = draw(), set()
        for painting in paintings:
            pixels = frozenset(map(tuple, painting(points, shape).tolist()))
            if pixels in seen:
                break
            seen.add(pixels)
        else:
            return points


def _loop_pixels(
    control_points: np.ndarray, shape: tuple[int, ...], t: np.ndarray, rounding: str = "floor"
) -> np.ndarray:
    curve = de_casteljau(control_points, t)
    return nearest_pixels(curve, rounding=rounding, shape=shape[:2])


def _every_t() -> np.ndarray:
    return np.arange(_STEPS + 1) / _STEPS


def bezier_reference(control_points: np.ndarray, window: np.ndarray) -> np.ndarray:
    """The pixels to paint: the one holding B(t) for each t = 0, 0.001, ..., 1 on the window."""
    return _loop_pixels(control_points, window.shape, _every_t())


def _wrapped(rounding: str) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    """The pixels of a loop that tests only ``x < width and y < height``.

    A negative index counts from the end of the row or column, so a pixel
    left of or above the window lands on its other side; ``int`` truncates
    toward zero, so a point in (-1, 0) lands in column or row 0 instead.
    """

    def pixels(control_points: np.ndarray, window: np.ndarray) -> np.ndarray:
        height, width = window.shape[:2]
        curve = de_casteljau(control_points, _every_t())
        kept = curve[(curve[:, 0] < width) & (curve[:, 1] < height)]
        found = nearest_pixels(kept, rounding=rounding)
        # Python raises past -length, so such a loop stops there: not this mistake.
        inside = (found[:, 0] >= -width) & (found[:, 1] >= -height)
        return found[inside] % (width, height)

    return pixels


class Painting:
    """The pixels a student painted (any channel not 0), and the first in the wrong colour.

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
    painted = (image != 0).any(axis=2)
    rows, columns = np.nonzero(painted)
    pixels = np.column_stack([columns, rows]).astype(np.int64)
    colours = image[rows, columns].astype(float)
    wrong = ~(colours == GREEN).all(axis=1)
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
    expected = _loop_pixels(probe["control_points"], window.shape, steps)
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
        # First: with the right pixels in the wrong colour, every mistake that only compares
        # pixels and agrees with the reference on this case (off-window points wrapped, when
        # there are none) would match too.
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
                "handouts' loop `for (t = 0; t <= 1; t += 0.001)` does: each addition rounds, the "
                "sum ends a hair above 1 after a thousand steps, so t = 1 is never painted, and on "
                "the way t drifts a few units in the last place. Count whole steps instead: "
                "for k in range(1001): t = k / 1000."
            ),
            lambda control_points, window: _loop_pixels(control_points, window.shape, accumulated),
            matches=accumulated_match,
        ),
        Mistake(
            _("the loop stops before t = 1"),
            _(
                "your loop never reaches t = 1, so the curve's last pixel stays dark: range(1000) "
                "and np.arange(0, 1, 0.001) stop at 0.999. Count whole steps up to and including "
                "1000: for k in range(1001): t = k / 1000."
            ),
            lambda control_points, window: _loop_pixels(
                control_points, window.shape, _every_t()[:-1]
            ),
            matches=pixels_match,
        ),
        Mistake(
            _("the float32 loop of the GAMES101 report"),
            _(
                "your t drifts: the handout's `float t` keeps about 7 digits, and a thousand "
                "additions of 0.001 move the points enough to change pixels in the middle of the "
                "curve. Compute each t from a whole count, in Python's float."
            ),
            lambda control_points, window: _loop_pixels(control_points, window.shape, float32_loop),
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
            lambda control_points, window: _loop_pixels(
                control_points, window.shape, _every_t(), "round"
            ),
            matches=pixels_match,
        ),
        Mistake(
            _("the GAMES101 report's loop: float32 t and cv::Point rounding"),
            _(
                "your loop is the GAMES101 report's: a `float t` advanced by 0.001 a thousand "
                "times, which drifts, and each point rounded to the nearest pixel as cv::Point "
                "does, half a pixel off. Compute each t from a whole count (t = k / 1000, in "
                "Python's float) and paint (int(x), int(y)), the pixel whose square holds the "
                "point."
            ),
            lambda control_points, window: _loop_pixels(
                control_points, window.shape, float32_loop, "round"
            ),
            matches=pixels_match,
        ),
        Mistake(
            _("x and y swapped"),
            _("you wrote window[x, y]: an image is indexed by row first, window[y, x]."),
            lambda control_points, window: _loop_pixels(
                control_points, window.shape[1::-1], _every_t()
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
            lambda control_points, window: _loop_pixels(
                control_points, window.shape, _every_t(), "trunc"
            ),
            matches=pixels_match,
        ),
        Mistake(_("a negative index wraps around"), wraps, _wrapped("trunc"), matches=pixels_match),
        Mistake(_("a negative index wraps around"), wraps, _wrapped("floor"), matches=pixels_match),
        Mistake(
            _("a step of 0.01"),
            _(
                "your step is ten times too coarse: 101 points leave gaps on a curve about 1400 "
                "pixels long. Use 0.001, as the handout does."
            ),
            lambda control_points, window: _loop_pixels(
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
