"""Lesson 05's exercises: the bilinear splat about pixel centres, and the arc-length weights.

``splat(x, y)`` returns the pixels one curve point lights and their weights;
a failure names the first pixel whose weight is wrong, shows both splats as
pixels around the point, and recognises the GAMES101 report's variants
(corners made of the point itself, which gives the whole point to one
pixel, and pixels taken to sit at their corners) and the usual slips (the
rectangles' areas given to the wrong pixels, x and y swapped).

``arc_length_weights(samples)`` returns the length of curve each sample
stands for; a failure plots both sets of weights along the curve and
recognises counting (every weight 1), a whole chord on one side only, and
whole chords on both sides.

Both are called by position, so the parameters may have any names. An
answer that calls the library's own splat or weights is told to write it.
Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("splat")`` says more at once and
``check.hint("splat", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from course import limits
from course._validate import require_finite
from course.antialias import (
    arc_length_weights as reference_weights,
)
from course.antialias import (
    bilinear_centres,
    bilinear_corners,
    curve_samples,
    nearest_round,
    normalised_centres,
    splats,
)
from course.check.base import (
    AnswerError,
    CheckResult,
    Mistake,
    close,
    first_difference,
    hint,
    register_hints,
    run_cases,
)
from course.check.hints import Hints
from course.check.pictures import EXPECTED, GIVEN, figure_png, image_picture, side_by_side
from course.i18n import N_, _
from course.images import SEED_000_CUBIC

__all__ = [
    "arc_length_weights",
    "bilinear_splat",
    "hint",
    "splat_table",
]

_LIBRARY_FUNCTIONS = (
    splats.splat,
    splats.bilinear_centres,
    splats.bilinear_corners,
    splats.normalised_centres,
    splats.arc_length_weights,
)


def _library() -> dict[Any, str]:
    """The library's own answers, each with what a student who calls it is told."""
    return {
        function: _(
            "your function calls {function}, the library's own answer: this exercise writes it"
        ).format(function=f"course.antialias.splats.{function.__name__}")
        for function in _LIBRARY_FUNCTIONS
    }


_LIBRARY = _library()

# Points that tell the common mistakes apart: a pixel centre (one pixel gets
# everything), a pixel corner (four equal shares), generic points, points
# whose nearest corner rounds the other way, a negative coordinate.
CASES = (
    {"x": 2.5, "y": 1.5},
    {"x": 3.0, "y": 2.0},
    {"x": 3.25, "y": 7.875},
    {"x": 10.125, "y": 4.625},
    {"x": 0.875, "y": 0.375},
    {"x": 5.75, "y": 5.75},
    {"x": -0.25, "y": 1.625},
)
# The picture shows at least this many pixels on each side of the point's own pixel.
_AROUND = 2
# ... and at most this many pixels across, however far a wrong splat strays.
_LARGEST_WINDOW = 16


def splat_table(pixels: Any, weights: Any) -> np.ndarray:
    """A splat in one canonical form: rows (x, y, weight), sorted, zero weights dropped.

    Repeated pixels are merged by adding their weights.

    Examples
    --------
    >>> splat_table([[1, 0], [0, 0], [1, 0], [2, 2]], [0.25, 0.5, 0.25, 0.0])
    array([[0. , 0. , 0.5],
           [1. , 0. , 0.5]])
    """
    coordinates = np.asarray(pixels)
    amounts = np.asarray(weights, dtype=float).reshape(-1)
    if coordinates.size == 0:
        return np.zeros((0, 3))
    if not np.issubdtype(coordinates.dtype, np.number):
        raise TypeError(
            _("pixels must be numbers; got dtype {dtype}").format(dtype=coordinates.dtype)
        )
    coordinates = coordinates.reshape(-1, 2)
    if len(coordinates) != len(amounts):
        raise ValueError(
            _(
                "pixels and weights must match: {coordinates_count} pixels, {amounts_count} weights"
            ).format(coordinates_count=len(coordinates), amounts_count=len(amounts))
        )
    require_finite(amounts, "weights")
    if not np.isfinite(coordinates).all() or not np.array_equal(coordinates, np.round(coordinates)):
        raise ValueError(_("pixels must be whole numbers (x, y)"))
    if np.abs(coordinates).max() > limits.MAX_COORDINATE:
        raise ValueError(
            _("pixels must lie within +-{bound:g}").format(bound=limits.MAX_COORDINATE)
        )
    unique, index = np.unique(coordinates.astype(np.int64), axis=0, return_inverse=True)
    totals = np.bincount(index.ravel(), amounts, minlength=len(unique))
    keep = np.abs(totals) > 1e-12
    return np.column_stack([unique[keep], totals[keep]]).astype(float)


def _table_of(splat: Callable[..., Any]) -> Callable[[float, float], np.ndarray]:
    return lambda x, y: splat_table(*splat([[x, y]]))


def _student_table(answer: Any) -> np.ndarray:
    """The student's (pixels, weights) as a splat table; AnswerError in their terms."""
    if not isinstance(answer, (list, tuple, np.ndarray)):
        # A dict unpacks into its keys and a generator into whatever it yields: neither is
        # the pair the exercise returns.
        raise AnswerError(
            _("return two lists: pixels, weights; yours is a {kind}").format(
                kind=type(answer).__name__
            )
        )
    try:
        pixels, weights = answer
    except (TypeError, ValueError):
        kind = type(answer).__name__
        if isinstance(answer, (list, tuple)):
            message = _(
                "return two things, the pixels and their weights; yours is a {kind} of "
                "{count} items"
            ).format(kind=kind, count=len(answer))
        else:
            message = _(
                "return two things, the pixels and their weights; yours is a {kind}"
            ).format(kind=kind)
        raise AnswerError(message) from None
    kinds = (list, tuple, np.ndarray)
    if not isinstance(pixels, kinds) or not isinstance(weights, kinds):
        raise AnswerError(
            _("return two lists: pixels, weights; yours are a {pixels} and a {weights}").format(
                pixels=type(pixels).__name__, weights=type(weights).__name__
            )
        )
    try:
        return splat_table(pixels, weights)
    except (TypeError, ValueError) as error:
        raise AnswerError(str(error)) from None


def _weights_by_pixel(table: np.ndarray) -> dict[tuple[int, int], float]:
    return {(int(x), int(y)): float(w) for x, y, w in table}


def _splat_difference(expected: np.ndarray, given: np.ndarray) -> str:
    """The first pixel, by (y, x), whose weight differs, in words.

    Examples
    --------
    >>> _splat_difference(np.array([[0, 0, 0.5], [1, 0, 0.5]]), np.array([[0, 0, 1.0]]))
    'first wrong pixel: (0, 0) should get 0.5, yours gets 1'
    """
    want, have = _weights_by_pixel(expected), _weights_by_pixel(given)
    for pixel in sorted(set(want) | set(have), key=lambda p: (p[1], p[0])):
        should, gets = want.get(pixel, 0.0), have.get(pixel, 0.0)
        if not math.isclose(should, gets, abs_tol=1e-9):
            if should == 0.0:
                return _("first wrong pixel: {pixel} should not be lit, yours gets {gets}").format(
                    pixel=pixel, gets=f"{gets:.4g}"
                )
            return _("first wrong pixel: {pixel} should get {should}, yours gets {gets}").format(
                pixel=pixel, should=f"{should:.4g}", gets=f"{gets:.4g}"
            )
    return _("the same pixels and weights")


def _show_splat(table: np.ndarray) -> str:
    """A splat table in words: each lit pixel and its weight.

    Examples
    --------
    >>> _show_splat(np.array([[2, 1, 0.75], [3, 1, 0.25]]))
    'pixel (2, 1) gets 0.75, pixel (3, 1) gets 0.25'
    """
    if len(table) == 0:
        return _("no pixel lit")
    each = _("pixel ({x}, {y}) gets {weight}")
    return ", ".join(each.format(x=int(x), y=int(y), weight=f"{w:.4g}") for x, y, w in table)


def _window(case: dict[str, Any], tables: list[np.ndarray]) -> tuple[int, int, int, int]:
    """(left, top, width, height): the point's pixel and every lit pixel, within limits."""
    px, py = math.floor(case["x"]), math.floor(case["y"])
    xs = [px - _AROUND, px + _AROUND] + [int(x) for t in tables for x in t[:, 0]]
    ys = [py - _AROUND, py + _AROUND] + [int(y) for t in tables for y in t[:, 1]]
    left = max(min(xs), px - _LARGEST_WINDOW // 2)
    top = max(min(ys), py - _LARGEST_WINDOW // 2)
    right = min(max(xs), left + _LARGEST_WINDOW - 1)
    bottom = min(max(ys), top + _LARGEST_WINDOW - 1)
    return left, top, right - left + 1, bottom - top + 1


def _painted(table: np.ndarray, window: tuple[int, int, int, int]) -> np.ndarray:
    left, top, width, height = window
    image = np.zeros((height, width))
    for x, y, weight in table:
        column, row = int(x) - left, int(y) - top
        if 0 <= row < height and 0 <= column < width:
            image[row, column] += weight
    return image


def _splat_picture(case: dict[str, Any], expected: np.ndarray, given: np.ndarray) -> bytes:
    window = _window(case, [expected, given])
    left, top, width, height = window
    return image_picture(
        _painted(expected, window),
        _painted(given, window),
        title=_("the splat of ({x}, {y}): pixels x {left}..{right}, y {top}..{bottom}").format(
            x=case["x"],
            y=case["y"],
            left=left,
            right=left + width - 1,
            top=top,
            bottom=top + height - 1,
        ),
    )


def _splat_explain(case: dict[str, Any], expected: np.ndarray, given: np.ndarray) -> str:
    x, y = case["x"], case["y"]
    left, top = math.floor(x - 0.5), math.floor(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    return _(
        "the point ({x}, {y}) lies between the centres of pixels x {left}..{right}, "
        "y {top}..{bottom}; from the top-left centre ({centre_x}, {centre_y}) "
        "dx = {dx}, dy = {dy}"
    ).format(
        x=x,
        y=y,
        left=left,
        right=left + 1,
        top=top,
        bottom=top + 1,
        centre_x=left + 0.5,
        centre_y=top + 0.5,
        dx=f"{dx:g}",
        dy=f"{dy:g}",
    )


def _swapped(x: float, y: float) -> np.ndarray:
    table = splat_table(*bilinear_centres([[x, y]]))
    return splat_table(table[:, [1, 0]], table[:, 2])


def _nearest_floor(samples: Any) -> tuple[np.ndarray, np.ndarray]:
    """One pixel per sample, the one whose square holds it (floor); weight 1."""
    points = np.asarray(samples, dtype=float).reshape(-1, 2)
    return np.floor(points).astype(np.int64), np.ones(len(points))


def _one_pixel_where_they_differ(
    one_pixel: Callable[..., Any], other: Callable[..., Any]
) -> Callable[[float, float], np.ndarray | None]:
    """``one_pixel``'s splat where it lights another pixel than ``other`` (rounding and
    truncation), else None, which matches nothing: such a point cannot tell them apart."""

    def answer(x: float, y: float) -> np.ndarray | None:
        table, rival = _table_of(one_pixel)(x, y), _table_of(other)(x, y)
        return None if np.array_equal(table, rival) else table

    return answer


def _own_rectangles(x: float, y: float) -> np.ndarray:
    left, top = math.floor(x - 0.5), math.floor(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return splat_table(pixels, [dx * dy, (1 - dx) * dy, dx * (1 - dy), (1 - dx) * (1 - dy)])


def _truncated(x: float, y: float) -> np.ndarray:
    """The splat with int() for floor: left of or above 0.5 it picks the wrong pixels."""
    left, top = int(x - 0.5), int(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return splat_table(pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy])


def _splat_mistakes() -> tuple[Mistake, ...]:
    """The known mistakes, in the current language."""
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
            _one_pixel_where_they_differ(nearest_round, _nearest_floor),
        ),
        Mistake(
            _("the pixel under the point (truncated)"),
            _(
                "your splat gives the whole point to the pixel under it, (floor(x), floor(y)) as "
                "int() or cv::Point truncates it, weight 1: no anti-aliasing. Share the point "
                "among the four pixels whose centres surround it, with dx and dy measured from a "
                "pixel centre."
            ),
            _one_pixel_where_they_differ(_nearest_floor, nearest_round),
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
            _table_of(nearest_round),
        ),
        Mistake(
            _("pixels at their corners"),
            _(
                "your four pixels are those around the point's integer corner: the GAMES101 "
                "report's middle addColor (cv::Point truncates), which treats pixel (c, r) as if "
                "it sat at (c, r). Its centre is (c + 0.5, r + 0.5): the curve moves half a "
                "pixel right and down."
            ),
            _table_of(bilinear_corners),
        ),
        Mistake(
            _("each pixel its own rectangle"),
            _(
                "each of your four pixels gets the rectangle between the point and its own centre: "
                "the nearest pixel gets the least. A pixel's weight is the area of the rectangle "
                "opposite it: (1 - dx)(1 - dy) for the top-left one."
            ),
            _own_rectangles,
        ),
        Mistake(
            _("x and y swapped"),
            _("your pixels are (row, column): give each as (x, y), the column first."),
            _swapped,
        ),
        Mistake(
            _("the normalised splat"),
            _(
                "your weights never vanish: a point at a pixel's centre still gives its neighbours "
                "some. That is the VS2022 report's splat: sqrt(2) minus each distance, "
                "normalised. Bilinear weights are areas of rectangles, and give a centre's pixel "
                "everything."
            ),
            _table_of(normalised_centres),
        ),
        Mistake(
            _("int() for floor"),
            _(
                "left of or above the first centres your pixels are one off: int() rounds toward "
                "zero, so int(-0.75) is 0, while the pixel to the left is floor(-0.75) = -1."
            ),
            _truncated,
        ),
    )


SPLAT_MISTAKES = _splat_mistakes()


def bilinear_splat(student: Callable[[float, float], Any]) -> CheckResult:
    """Check ``student(x, y) -> (pixels, weights)`` against the bilinear splat about centres.

    The correct splat lights the four pixels whose centres (c + 0.5,
    r + 0.5) surround the point, with weights ``(1 - dx)(1 - dy)``,
    ``dx (1 - dy)``, ``(1 - dx) dy``, ``dx dy``, where (dx, dy) is the
    point's offset from the top-left one of those centres. Pixels may come
    in any order; pixels of weight 0 may be left out.

    Examples
    --------
    >>> bilinear_splat(lambda x, y: ([(int(x), int(y))], [1.0])).mistake
    'the whole point to one pixel'
    """
    return run_cases(
        "splat",
        student,
        CASES,
        reference=_table_of(bilinear_centres),
        compare=close(atol=1e-9, rtol=0.0),
        convert=_student_table,
        hint=SPLAT_HINTS,
        mistakes=_splat_mistakes(),
        difference=_splat_difference,
        picture=_splat_picture,
        explain=_splat_explain,
        show=_show_splat,
        forbidden=_library(),
        pass_picture=_splat_pass_picture,
    )


def _splat_pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    case, expected, given = results[2]  # (3.25, 7.875): four unequal weights
    window = _window(case, [expected, given])
    return side_by_side(
        _painted(expected, window),
        _painted(given, window),
        (_("expected"), _("your splat of ({x}, {y})").format(x=case["x"], y=case["y"])),
    )


SPLAT_HINTS = register_hints(
    "splat",
    Hints(
        where=N_(
            "look at which four pixels you light, and from which point you measure the offsets."
        ),
        more=N_(
            "pixel (c, r) is centred at (c + 0.5, r + 0.5); the four pixels are those whose "
            "centres surround the point, and each gets more the nearer the point is to its "
            "centre: 1 at its own centre, 0 at a neighbour's."
        ),
        recipe=N_(
            "left = floor(x - 0.5), top = floor(y - 0.5); dx, dy = the point minus the "
            "centre (left + 0.5, top + 0.5); weights (1 - dx)(1 - dy), dx (1 - dy), (1 - dx) dy, "
            "dx dy for (left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)."
        ),
    ),
    "splat",
    "bilinear_splat",
)


def _weight_cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(11)
    # Lesson 05's cubic at t = 0, 1/8, ..., 1: far apart at the ends, close in the middle.
    curve = curve_samples(SEED_000_CUBIC, 0.125)
    return [
        {"samples": np.array([[0.0, 0.0], [3.0, 4.0], [3.0, 5.0]])},
        {"samples": np.array([[1.0, 1.0], [2.0, 1.0]])},
        {"samples": curve},
        {"samples": np.cumsum(rng.uniform(-2, 2, size=(12, 2)), axis=0)},
        {"samples": np.array([[4.0, 4.0]])},
    ]


def _weights_picture(
    case: dict[str, Any],
    expected: Any,
    given: Any,
    title: str = N_("the weight of each sample along the curve"),
) -> bytes | None:
    want, have = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
    if have.shape != want.shape:
        return None
    figure = Figure(figsize=(4.6, 2.4), dpi=100)
    axes = figure.add_subplot()
    index = np.arange(len(want))
    axes.plot(index, want, "o-", color=EXPECTED, label=_("expected"), markersize=5)
    axes.plot(index, have, "x--", color=GIVEN, label=_("yours"), markersize=6)
    axes.set_xlabel(_("sample"), fontsize=8)
    axes.set_ylabel(_("weight (px of curve)"), fontsize=8)
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=7)
    axes.set_title(_(title), fontsize=9)
    figure.tight_layout()
    return figure_png(figure)


def _chords(samples: Any) -> np.ndarray:
    return np.hypot(*np.diff(np.asarray(samples, dtype=float), axis=0).T)


def _weight_mistakes() -> tuple[Mistake, ...]:
    """The known mistakes, in the current language."""
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
            lambda samples: np.append(_chords(samples), 0.0),
        ),
        Mistake(
            _("the chord before each sample"),
            _(
                "each sample has the whole chord from the previous one (and the first none). Give "
                "each sample half the chord on each side."
            ),
            lambda samples: np.insert(_chords(samples), 0, 0.0),
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


WEIGHT_MISTAKES = _weight_mistakes()


def arc_length_weights(student: Callable[[Any], Any]) -> CheckResult:
    """Check ``student(samples)``: the length of curve each of the (N, 2) samples stands for.

    ``w[i] = (|p[i] - p[i-1]| + |p[i+1] - p[i]|) / 2``, the missing chord at
    either end counted as 0; the weights add up to the polyline's length.

    Examples
    --------
    >>> arc_length_weights(lambda samples: [1.0] * len(samples)).mistake
    'counting'
    """
    return run_cases(
        "arc_length_weights",
        student,
        _weight_cases(),
        reference=reference_weights,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=lambda answer: np.asarray(answer, dtype=float),
        hint=WEIGHT_HINTS,
        mistakes=_weight_mistakes(),
        difference=first_difference,
        picture=_weights_picture,
        forbidden=_library(),
        pass_picture=lambda results: _weights_picture(*results[2], "your weights along the cubic"),
    )


WEIGHT_HINTS = register_hints(
    "arc_length_weights",
    Hints(
        where=N_("look at the chords beside each sample, and at the first and the last sample."),
        more=N_(
            "a sample stands for the curve from halfway to its previous sample to halfway "
            "to its next one; the ends have one neighbour only, and all the weights add up to "
            "the polyline's length."
        ),
        recipe=N_(
            "chords = the distances between neighbouring samples; pad them with 0 at "
            "both ends; w[i] = (padded[i] + padded[i + 1]) / 2."
        ),
    ),
)
