"""Lesson 01's checkers: one de Casteljau level, ``recursive_bezier`` and the drawing loop.

The exercises keep the handouts' signatures, and the student's function is
called by position, so its parameters may have any names.
``next_level(control_points, t)`` and ``recursive_bezier(control_points, t)``
take the control points as a float array (N, 2) and t as one number; the
first returns the N - 1 points of the next level, the second the curve point
(x, y). ``bezier(control_points, window)`` paints the curve into ``window``,
an (H, W, 3) float image, in green, one pixel per t = 0, 0.001, ..., 1
(seed 000's loop).

Each recognises the handouts' mistakes: the reversed step of seeds 002 and
004, stopping one level early, x and y swapped, a loop that never reaches
t = 1, the GAMES101 report's float32 t, OpenCV's rounding to the nearest
pixel, the two together (the GAMES101 report's loop), a negative index that
wraps around to the other side of the window, and the wrong colour. An
answer that calls the library's own curve is told to write it.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("bezier")`` says more at once and
``check.hint("bezier", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course._validate import as_int
from course.check.base import (
    AnswerError,
    CheckResult,
    Mistake,
    close,
    hint,
    pixel_difference,
    pixel_rows,
    register_hints,
    run_cases,
    same_pixels,
)
from course.check.hints import Hints
from course.check.pictures import curve_picture, pixel_picture, side_by_side
from course.check.sandbox import run_bounded
from course.curves import bezier as library
from course.curves.bezier import de_casteljau, de_casteljau_levels, uniform_parameters
from course.curves.bezier_handouts import de_casteljau_reversed
from course.i18n import N_, _
from course.images import SEED_000_CUBIC
from course.raster import nearest_pixels

__all__ = [
    "BEZIER_SHAPES",
    "LIBRARY_CURVES",
    "as_point",
    "bezier",
    "curve_cases",
    "curve_pass_picture",
    "hint",
    "library_curves",
    "next_level",
    "point_mistakes",
    "point_picture",
    "recursive_bezier",
]

#: The t step of seed 000's loop, and the values it should take: 0, 0.001, ..., 1.
STEP = 0.001
_STEPS = round(1 / STEP)
_LIBRARY_FUNCTIONS = (
    library.de_casteljau,
    library.de_casteljau_recursive,
    library.de_casteljau_levels,
    library.bezier_bernstein,
    library.bernstein_basis,
    library.split,
    library.sample_uniform,
)


def library_curves() -> dict[Any, str]:
    """The library's own curves, each with what a student who calls it is told (in the
    current language)."""
    return {
        function: _(
            "your function calls course.curves.bezier.{function}, the library's own answer: this "
            "exercise writes the curve itself, from the interpolation step"
        ).format(function=function.__name__)
        for function in _LIBRARY_FUNCTIONS
    }


#: The library's own curves: an answer that calls one is told to write it (English).
LIBRARY_CURVES = library_curves()


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
    """A student's point, whatever its container (array, tuple, list), as a flat float array."""
    try:
        point = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise AnswerError(
            _("a point is two numbers (x, y); yours is a {kind} that is not").format(
                kind=type(value).__name__
            )
        ) from None
    # A (1, 2) array holds the right numbers but is a list of one point, not the point.
    if point.ndim != 1:
        raise AnswerError(
            _("the answer is the point (x, y), of shape (2,); yours has shape {shape}").format(
                shape=point.shape
            )
        )
    return point


def point_picture(
    reference: Callable[..., Any], title: str
) -> Callable[[dict[str, Any], Any, Any], bytes | None]:
    """The failing case's picture: its curve, the point expected at its t and the student's."""

    def draw(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
        control = np.asarray(case["control_points"], dtype=float)
        curve = reference(control, np.linspace(0.0, 1.0, 41))
        theirs = np.asarray(given, dtype=float).reshape(-1)
        theirs = theirs[:2].reshape(1, 2) if theirs.size >= 2 else np.full((1, 2), np.nan)
        return curve_picture(
            control,
            curve,
            theirs,
            _("{title}, t = {t}").format(title=_(title), t=f"{case['t']:g}"),
            mark_start=False,
            given_label=_("your point at t = {t}").format(t=f"{case['t']:g}"),
            expected_point=np.asarray(expected, dtype=float).reshape(1, 2),
        )

    return draw


def curve_pass_picture(reference: Callable[..., Any], name: str) -> Callable[[list], bytes]:
    """A pass's picture: the student's points on seed 000's curve, beside the reference's."""

    def draw(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
        chosen = [
            (c, g) for c, _, g in results if np.array_equal(c["control_points"], SEED_000_CUBIC)
        ]
        chosen.sort(key=lambda pair: pair[0]["t"])
        theirs = np.array([np.asarray(g, dtype=float).reshape(-1)[:2] for _, g in chosen])
        curve = reference(SEED_000_CUBIC, np.linspace(0.0, 1.0, 41))
        ts = ", ".join(f"{c['t']:g}" for c, _ in chosen)
        return curve_picture(
            SEED_000_CUBIC,
            curve,
            theirs,
            _("your {name} at t = {ts}").format(name=name, ts=ts),
            width_inches=3.0,
        )

    return draw


def point_mistakes(curve: Callable[[np.ndarray, float], np.ndarray]) -> list[Mistake]:
    """The mistakes of a function that returns the curve point at t."""
    return [
        Mistake(
            _("the reversed step"),
            _(
                "your curve runs backwards: you wrote t P[i] + (1 - t) P[i+1], as two of the "
                "reports do. The point at t on an edge is t of the way from its first end, so "
                "that B(0) = P0 and B(1) = Pn."
            ),
            lambda control_points, t: de_casteljau_reversed(control_points, t),
        ),
        Mistake(
            _("one level short"),
            _(
                "you stopped when two points were left and returned the first of them: that is "
                "a point of the last level's segment, not B(t). Interpolate once more, down to "
                "one point."
            ),
            lambda control_points, t: de_casteljau_levels(control_points, t)[-2][0],
        ),
        Mistake(
            _("x and y swapped"),
            _("your point is (y, x): return x first, as the control points' columns are x, y."),
            lambda control_points, t: curve(control_points, t)[::-1],
        ),
    ]


def _curve(control_points: np.ndarray, t: Any) -> np.ndarray:
    return de_casteljau(control_points, t)


RECURSIVE_HINTS = register_hints(
    "recursive_bezier",
    Hints(
        where=N_("look at what one call hands to the next, and at when the recursion stops."),
        more=N_(
            "each call makes one level with one point fewer (your next_level), and passes "
            "it on with the same t; the call that gets a single point has B(t)."
        ),
        recipe=N_(
            "if len(control_points) == 1, return control_points[0]; otherwise return "
            "recursive_bezier(next_level(control_points, t), t)."
        ),
    ),
)


def recursive_bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's de Casteljau ``recursive_bezier(control_points, t)``.

    Compared with the library's curve on curves of 2 to 10 control points,
    to 1e-9. A pass shows the student's points on seed 000's curve.

    Examples
    --------
    >>> from course.curves.bezier_handouts import de_casteljau_reversed
    >>> recursive_bezier(de_casteljau_reversed).mistake
    'the reversed step'
    """
    return run_cases(
        "recursive_bezier",
        function,
        curve_cases(max_points=10),
        reference=_curve,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=as_point,
        hint=RECURSIVE_HINTS,
        mistakes=point_mistakes(_curve),
        picture=point_picture(_curve, N_("your recursive_bezier")),
        forbidden=library_curves(),
        pass_picture=curve_pass_picture(_curve, "recursive_bezier"),
    )


def _reference_level(control_points: np.ndarray, t: float) -> np.ndarray:
    return de_casteljau_levels(control_points, t)[1]


def _level_mistakes() -> list[Mistake]:
    return [
        Mistake(
            _("the reversed step"),
            _(
                "your points sit at 1 - t along each edge: you wrote t P[i] + (1 - t) P[i+1]. "
                "The point at t on the edge from P[i] to P[i+1] is P[i] at t = 0."
            ),
            lambda control_points, t: de_casteljau_levels(control_points, 1 - t)[1],
        ),
        Mistake(
            _("one point short"),
            _(
                "your level has N - 2 points: there is one new point per edge of the polygon, "
                "and N points make N - 1 edges."
            ),
            lambda control_points, t: _reference_level(control_points, t)[:-1],
        ),
        Mistake(
            _("an edge from the last point back to the first"),
            _(
                "your level has N points: an index taken modulo N (P[(i + 1) % N]) or np.roll "
                "joins the last control point to the first, but the control polygon is open; it "
                "has N - 1 edges."
            ),
            lambda control_points, t: _reference_level(
                np.vstack([control_points, control_points[:1]]), t
            ),
        ),
        Mistake(
            _("x and y swapped"),
            _("your points are (y, x): keep the columns in the order x, y."),
            lambda control_points, t: _reference_level(control_points, t)[:, ::-1],
        ),
    ]


def _as_level(value: Any) -> np.ndarray:
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise AnswerError(
            _("a level is a list or array of (x, y) points, all of the same length")
        ) from None


def _level_pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    chosen = [
        (c, g)
        for c, _, g in results
        if np.array_equal(c["control_points"], SEED_000_CUBIC) and c["t"] == 0.25
    ]
    _case, given = chosen[0]
    return curve_picture(
        SEED_000_CUBIC,
        _curve(SEED_000_CUBIC, np.linspace(0.0, 1.0, 41)),
        np.asarray(given, dtype=float).reshape(-1, 2),
        _("your next level of seed 000's cubic, t = 0.25"),
        width_inches=3.8,
        mark_start=False,
        given_label=_("your level"),
    )


NEXT_LEVEL_HINTS = register_hints(
    "next_level",
    Hints(
        where=N_(
            "look at the edges of the control polygon: how many there are, and where on "
            "each your new point sits."
        ),
        more=N_(
            "each edge from P[i] to P[i+1] gets one new point, t of the way from P[i]: "
            "at t = 0 it is P[i], at t = 1 it is P[i+1]."
        ),
        recipe=N_(
            "the new point on edge i is (1 - t) P[i] + t P[i+1], for i = 0 ... N - 2; "
            "with numpy, the first N - 1 rows and the last N - 1 rows of control_points."
        ),
    ),
)


def next_level(function: Callable[..., Any]) -> CheckResult:
    """Check ``next_level(control_points, t)``: the N - 1 points of one de Casteljau step.

    Compared with the library's level 1, to 1e-9. A pass shows the
    student's level on seed 000's control polygon.

    Examples
    --------
    >>> next_level(lambda points, t: points).passed
    False
    """
    return run_cases(
        "next_level",
        function,
        curve_cases(max_points=10),
        reference=_reference_level,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=_as_level,
        hint=NEXT_LEVEL_HINTS,
        mistakes=_level_mistakes(),
        forbidden=library_curves(),
        pass_picture=_level_pass_picture,
    )


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


def _bezier_cases() -> list[dict[str, Any]]:
    return [
        {"control_points": points.copy(), "window": np.zeros((*shape, 3))}
        for points, shape in BEZIER_SHAPES
    ]


def _loop_pixels(
    control_points: np.ndarray, shape: tuple[int, ...], t: np.ndarray, rounding: str = "floor"
) -> np.ndarray:
    curve = de_casteljau(control_points, t)
    return nearest_pixels(curve, rounding=rounding, shape=shape[:2])


def _every_t() -> np.ndarray:
    return np.arange(_STEPS + 1) / _STEPS


def _bezier_reference(control_points: np.ndarray, window: np.ndarray) -> np.ndarray:
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


class _Painting:
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


def _same_painting(expected: np.ndarray, given: _Painting) -> bool:
    return given.wrong_colour is None and same_pixels(expected, given.pixels)


def _painting_difference(expected: np.ndarray, given: _Painting) -> str:
    if given.wrong_colour is not None and same_pixels(expected, given.pixels):
        x, y, colour = given.wrong_colour
        shown = ", ".join(f"{c:g}" for c in colour)
        return _(
            "the right pixels, but pixel ({x}, {y}) is ({colour}): paint the curve green, (0, 1, 0)"
        ).format(x=x, y=y, colour=shown)
    return pixel_difference(expected, given.pixels)


def _show_painting(answer: Any) -> str:
    if isinstance(answer, _Painting):
        count = len(answer.pixels)
    else:
        count = len(np.unique(pixel_rows(answer, "expected"), axis=0))
    # Always "pixels", as before the reports were translated: English stays what it was.
    return _("{count} pixels painted").format(count=count)


def _pixels_of(answer: Any) -> Any:
    return answer.pixels if isinstance(answer, _Painting) else answer


def _accumulates(student: Callable[..., Any]) -> bool:
    """Whether ``student`` paints the probe curve as t accumulated in float steps would."""
    probe = ACCUMULATION_PROBE
    window = np.zeros((*probe["shape"], 3))
    run_bounded(lambda: student(probe["control_points"].copy(), window))
    steps = uniform_parameters(STEP, accumulate="float64")
    expected = _loop_pixels(probe["control_points"], window.shape, steps)
    return bool(same_pixels(expected, _painted(window)[0]))


def _bezier_mistakes(student: Callable[..., Any] | None = None) -> list[Mistake]:
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
            _bezier_reference,
            matches=colour_match,
        ),
        Mistake(
            _("a painted copy"),
            _(
                "your function painted a copy of the window and returned it: the window it was "
                "given stays black. Paint into window itself (window[y, x] = ...), the one "
                "argument this exercise lets you change; there is nothing to return."
            ),
            _bezier_reference,
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


def _bezier_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    return pixel_picture(expected, _pixels_of(given), title=_("around the first difference"))


def _bezier_pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    case, expected, given = results[0]
    reference = np.zeros(case["window"].shape)
    reference[expected[:, 1], expected[:, 0]] = GREEN
    return side_by_side(reference, given.window, (_("expected"), _("your window")), shrink="max")


BEZIER_HINTS = register_hints(
    "bezier",
    Hints(
        where=N_(
            "look at the values t takes (the first and the last), at which pixel each point "
            "lands in, and at points off the window."
        ),
        more=N_(
            "t must run from 0 to exactly 1 in steps of 0.001; the pixel holding (x, y) has "
            "the whole parts of x and y, rows first in the window; a point with x or y below "
            "0, or at width or height and beyond, is skipped."
        ),
        recipe=N_(
            "for k in range(1001): t = k / 1000; x, y = recursive_bezier(control_points, "
            "t); if 0 <= x < width and 0 <= y < height: window[int(y), int(x)] = (0, 1, 0)."
        ),
    ),
)


def bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's drawing loop ``bezier(control_points, window)``.

    It must paint green, ``(0, 1, 0)``, the pixel that holds the curve point
    at each t = 0, 0.001, ..., 1, nothing else, and skip points off the
    window. Writing into ``window`` is the exercise; the control points must
    stay as they were. A pass shows the student's window beside the
    expected one.

    Examples
    --------
    >>> print(bezier(lambda control_points, window: None))  # doctest: +ELLIPSIS
    FAIL bezier: case 1 is wrong
      inputs: control_points=...
      expected: 955 pixels painted
      given:    0 pixels painted
      955 pixels missing, first at (x, y) = (10, 10)
    ...
    """
    return run_cases(
        "bezier",
        function,
        _bezier_cases(),
        reference=_bezier_reference,
        compare=_same_painting,
        convert=_Painting,
        hint=BEZIER_HINTS,
        mistakes=_bezier_mistakes(function),
        difference=_painting_difference,
        picture=_bezier_picture,
        show=_show_painting,
        answer=lambda returned, arguments: (arguments[1], returned),
        writable=("window",),
        forbidden=library_curves(),
        pass_picture=_bezier_pass_picture,
    )
