"""Lesson 01's checkers: one de Casteljau level, ``recursive_bezier`` and the drawing loop.

The exercises keep the handouts' signatures. ``next_level(control_points,
t)`` and ``recursive_bezier(control_points, t)`` take the control points as a
float array (N, 2) and t as one number; the first returns the N - 1 points
of the next level, the second the curve point (x, y). ``bezier(control_points,
window)`` paints the curve into ``window``, an (H, W, 3) float image, in
green, one pixel per t = 0, 0.001, ..., 1 (seed 000's loop).

Each recognises the handouts' mistakes: the reversed step of seeds 002 and
004, stopping one level early, x and y swapped, a float loop that never
reaches t = 1, OpenCV's rounding to the nearest pixel, and a negative index
that wraps around to the other side of the window.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course._validate import as_int
from course.bezier import de_casteljau, de_casteljau_levels, uniform_parameters
from course.bezier_handouts import de_casteljau_reversed
from course.check.base import CheckResult, Mistake, close, pixel_difference, run_cases, same_pixels
from course.check.pictures import curve_picture, pixel_picture
from course.images import SEED_000_CUBIC
from course.raster import nearest_pixels

__all__ = [
    "BEZIER_CASES",
    "as_point",
    "bezier",
    "curve_cases",
    "curve_picture_of",
    "next_level",
    "point_mistakes",
    "positional",
    "recursive_bezier",
]

#: The t step of seed 000's loop, and the values it should take: 0, 0.001, ..., 1.
STEP = 0.001
_STEPS = round(1 / STEP)


def curve_cases(max_points: int) -> list[dict[str, Any]]:
    """Curves of 2 to ``max_points`` control points, each at five values of t.

    The first curve is asymmetric, so that a curve run backwards fails at
    once, and t = 0.25 comes first, so that every mistake shows at the first
    case rather than at an end where several agree.
    """
    max_points = as_int(max_points, "max_points", minimum=2, maximum=100)
    rng = np.random.default_rng(2024)
    polygons = [
        np.array([[0.0, 0.0], [1.0, 2.0], [4.0, 0.5]]),
        np.array([[0.0, 0.0], [4.0, 2.0]]),
        SEED_000_CUBIC.copy(),
    ]
    polygons += [rng.uniform(0, 700, (count, 2)).round(1) for count in range(5, max_points + 1)]
    cases = []
    for points in polygons:
        for t in (0.25, 0.5, 0.0, 1.0, 0.8):
            cases.append({"control_points": points, "t": t})
    return cases


def as_point(value: Any) -> np.ndarray:
    """A student's point, whatever its container, as a flat float array."""
    return np.asarray(value, dtype=float).reshape(-1)


def positional(function: Callable[..., Any]) -> Callable[..., Any]:
    """Call with positional arguments, so the student may name them as they like."""
    if not callable(function):
        return function  # run_cases reports it
    return lambda control_points, t: function(control_points, t)


def curve_picture_of(
    function: Callable[[np.ndarray, float], Any], reference: Callable[..., Any], title: str
) -> Callable[[dict[str, Any], Any, Any], bytes | None]:
    """A checker's picture: the student's function along the failing case's curve.

    Draws ``function(control_points, t)`` at 41 values of t against the
    reference curve; a point the student's code cannot give is left out.
    """

    def draw(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
        control = case["control_points"]
        ts = np.linspace(0.0, 1.0, 41)
        theirs = []
        for t in ts:
            try:
                point = np.asarray(function(control.copy(), float(t)), dtype=float).reshape(-1)
            except Exception:  # the report already names the failing case
                point = np.full(2, np.nan)
            theirs.append(point[:2] if point.size >= 2 else np.full(2, np.nan))
        ours = np.array([reference(control, float(t)) for t in ts])
        return curve_picture(control, ours, np.array(theirs), title)

    return draw


def point_mistakes(curve: Callable[[np.ndarray, float], np.ndarray]) -> list[Mistake]:
    """The mistakes of a function that returns the curve point at t."""
    return [
        Mistake(
            "the reversed step",
            "your curve runs backwards: you wrote t P[i] + (1 - t) P[i+1], as two of the "
            "reports do. The textbook step is (1 - t) P[i] + t P[i+1], so that B(0) = P0 and "
            "B(1) = Pn.",
            lambda control_points, t: de_casteljau_reversed(control_points, t),
        ),
        Mistake(
            "one level short",
            "you stopped when two points were left and returned the first of them: that is a "
            "point of the last level's segment, not B(t). Interpolate once more, down to one "
            "point.",
            lambda control_points, t: de_casteljau_levels(control_points, t)[-2][0],
        ),
        Mistake(
            "x and y swapped",
            "your point is (y, x): return x first, as the control points' columns are x, y.",
            lambda control_points, t: curve(control_points, t)[::-1],
        ),
    ]


def _curve(control_points: np.ndarray, t: float) -> np.ndarray:
    return de_casteljau(control_points, t)


def recursive_bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's de Casteljau ``recursive_bezier(control_points, t)``.

    Compared with :func:`course.bezier.de_casteljau` on curves of 2 to 10
    control points, to 1e-9.

    Examples
    --------
    >>> from course.bezier import de_casteljau
    >>> recursive_bezier(lambda control_points, t: de_casteljau(control_points, t))
    PASS recursive_bezier: all 45 cases pass
    >>> from course.bezier_handouts import de_casteljau_reversed
    >>> recursive_bezier(de_casteljau_reversed).mistake
    'the reversed step'
    """
    student = positional(function)
    return run_cases(
        "recursive_bezier",
        student,
        curve_cases(max_points=10),
        reference=_curve,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=as_point,
        hint="each call computes the next level (one point fewer, as next_level does) and "
        "hands it to the next call; the call that gets a single point returns it.",
        mistakes=point_mistakes(_curve),
        picture=curve_picture_of(student, _curve, "your recursive_bezier along the curve")
        if callable(function)
        else None,
    )


def _next_level(control_points: np.ndarray, t: float) -> np.ndarray:
    return de_casteljau_levels(control_points, t)[1]


def next_level(function: Callable[..., Any]) -> CheckResult:
    """Check ``next_level(control_points, t)``: the N - 1 points of one de Casteljau step.

    Compared with level 1 of :func:`course.bezier.de_casteljau_levels`, to 1e-9.

    Examples
    --------
    >>> next_level(lambda p, t: (1 - t) * p[:-1] + t * p[1:])
    PASS next_level: all 45 cases pass
    >>> next_level(lambda p, t: t * p[:-1] + (1 - t) * p[1:]).mistake
    'the reversed step'
    """
    student = positional(function)
    mistakes = [
        Mistake(
            "the reversed step",
            "your points sit at 1 - t along each edge: you wrote t P[i] + (1 - t) P[i+1]. "
            "The point at t on the edge from P[i] to P[i+1] is (1 - t) P[i] + t P[i+1]: at "
            "t = 0 it is P[i].",
            lambda control_points, t: de_casteljau_levels(control_points, 1 - t)[1],
        ),
        Mistake(
            "one point short",
            "your level has N - 2 points: the loop over i must run to N - 2 inclusive, "
            "range(len(control_points) - 1), one point per edge of the polygon.",
            lambda control_points, t: _next_level(control_points, t)[:-1],
        ),
        Mistake(
            "an edge from the last point back to the first",
            "your level has N points: np.roll joins the last control point to the first, but "
            "the control polygon is open; it has N - 1 edges.",
            lambda control_points, t: (
                (1 - t) * control_points + t * np.roll(control_points, -1, axis=0)
            ),
        ),
        Mistake(
            "x and y swapped",
            "your points are (y, x): keep the columns in the order x, y.",
            lambda control_points, t: _next_level(control_points, t)[:, ::-1],
        ),
    ]
    return run_cases(
        "next_level",
        student,
        curve_cases(max_points=10),
        reference=_next_level,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=lambda value: np.asarray(value, dtype=float),
        hint="one new point on each edge of the control polygon, at t of the way from its "
        "first end to its second: N points make N - 1 edges.",
        mistakes=mistakes,
    )


#: The drawing loop's cases: seed 000's curve on its 700 x 700 window, and a curve that
#: leaves a small window on every side (its pixels off the window must be skipped).
BEZIER_CASES = (
    {"control_points": SEED_000_CUBIC.copy(), "shape": (700, 700)},
    {
        "control_points": np.array([[-20.0, 50.0], [30.0, -40.0], [70.0, 90.0], [100.0, 20.0]]),
        "shape": (60, 80),
    },
)


def _loop_pixels(
    control_points: np.ndarray, shape: tuple[int, int], t: np.ndarray, rounding: str = "floor"
) -> np.ndarray:
    curve = de_casteljau(control_points, t)
    return nearest_pixels(curve, rounding=rounding, shape=shape)


def _bezier_reference(control_points: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    return _loop_pixels(control_points, shape, np.arange(_STEPS + 1) / _STEPS)


def _wrapped(control_points: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    height, width = shape
    pixels = nearest_pixels(de_casteljau(control_points, np.arange(_STEPS + 1) / _STEPS))
    # Python counts a negative index from the end; one past the end raises instead.
    keep = (pixels[:, 0] >= -width) & (pixels[:, 0] < width)
    keep &= (pixels[:, 1] >= -height) & (pixels[:, 1] < height)
    return pixels[keep] % (width, height)


def _green_pixels(window: Any) -> np.ndarray:
    """The pixels a student painted green: (x, y) where the green channel is over one half."""
    image = np.asarray(window, dtype=float)
    rows, columns = np.nonzero(image[..., 1] > 0.5)
    return np.column_stack([columns, rows])


def bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's drawing loop ``bezier(control_points, window)``.

    It must paint green (``window[y, x] = (0, 1, 0)``) the pixel that holds
    the curve point at each t = 0, 0.001, ..., 1, and skip points off the
    window: the painted pixels must be those of :func:`course.bezier.de_casteljau`
    at those 1001 values, each in the pixel whose square holds it.

    Examples
    --------
    >>> from course.canvas import paint
    >>> def good(control_points, window):
    ...     t = np.arange(1001) / 1000
    ...     points = de_casteljau(control_points, t)
    ...     paint(window, nearest_pixels(points), (0.0, 1.0, 0.0), mode="over")
    >>> bezier(good)
    PASS bezier: all 2 cases pass
    """

    def paint_into_window(control_points: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
        window = np.zeros((*shape, 3))
        function(control_points, window)
        return _green_pixels(window)

    float_loop = uniform_parameters(STEP, accumulate="float64")
    mistakes = [
        Mistake(
            "the float loop that stops short of t = 1",
            "you add 0.001 to t a thousand times; in floating point the sum passes 1 after "
            "0.999, so the loop ends without t = 1 and the curve's last pixel stays dark. "
            "Count whole steps instead: for k in range(1001): t = k / 1000.",
            lambda control_points, shape: _loop_pixels(control_points, shape, float_loop),
        ),
        Mistake(
            "rounding to the nearest pixel",
            "you rounded x and y, as OpenCV's cv::Point does in the GAMES101 report: that "
            "paints the pixel whose corner is nearest, half a pixel off. The pixel that holds "
            "(x, y) is (int(x), int(y)) for x, y >= 0 (floor).",
            lambda control_points, shape: _loop_pixels(
                control_points, shape, np.arange(_STEPS + 1) / _STEPS, "round"
            ),
        ),
        Mistake(
            "x and y swapped",
            "you wrote window[x, y]: an image is indexed by row first, window[y, x].",
            lambda control_points, shape: _bezier_reference(control_points, shape[::-1])[:, ::-1],
        ),
        Mistake(
            "a negative index wraps around",
            "a pixel with x < 0 or y < 0 appeared on the other side of the window: Python "
            "counts a negative index from the end. Skip every point with x < 0, y < 0, "
            "x >= width or y >= height.",
            _wrapped,
        ),
        Mistake(
            "a step of 0.01",
            "your step is ten times too coarse: 101 points leave gaps on a curve about 1400 "
            "pixels long. Use 0.001, as the handout does.",
            lambda control_points, shape: _loop_pixels(control_points, shape, np.arange(101) / 100),
        ),
    ]

    def picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
        return pixel_picture(expected, given, title="around the first difference")

    return run_cases(
        "bezier",
        paint_into_window if callable(function) else function,
        BEZIER_CASES,
        reference=_bezier_reference,
        compare=same_pixels,
        hint="count the steps with a whole number, so that the last t is exactly 1; paint the "
        "pixel whose square holds the point (rows are y); skip the points off the window.",
        mistakes=mistakes,
        difference=pixel_difference,
        picture=picture,
    )
