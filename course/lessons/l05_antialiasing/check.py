"""Lesson 05's exercises: the bilinear splat about pixel centres, and the arc-length weights.

``splat(x, y)`` returns the pixels one curve point lights and their weights;
a failure names the first pixel whose weight is wrong, shows both splats as
pixels around the point, and recognises the GAMES101 report's variants
(corners made of the point itself, which gives the whole point to one
pixel, and pixels taken to sit at their corners) and the usual slips (the
rectangles' areas given to the wrong pixels, x and y swapped). Splats are
compared as tables (:mod:`.splat_tables`), and :mod:`.mistakes` reproduces
the mistakes of both exercises.

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
from matplotlib.ticker import MaxNLocator

from course.antialias import (
    arc_length_weights as reference_weights,
)
from course.antialias import (
    bilinear_centres,
    curve_samples,
    splats,
)
from course.check.base import (
    AnswerError,
    CheckResult,
    close,
    first_difference,
    hint,
    run_cases,
)
from course.check.exercises import exercise
from course.check.hints import Hints
from course.check.pictures import EXPECTED, GIVEN, figure_png
from course.i18n import N_, _
from course.images import SEED_000_CUBIC
from course.lessons.graded_cases import drawn_in_order
from course.lessons.l05_antialiasing.mistakes import splat_mistakes, weight_mistakes
from course.lessons.l05_antialiasing.splat_pictures import failure_picture, pass_picture
from course.lessons.l05_antialiasing.splat_tables import splat_table, table_of

__all__ = [
    "arc_length_weights",
    "hint",
    "splat",
]

_LIBRARY_FUNCTIONS = (
    splats.splat,
    splats.bilinear_centres,
    splats.bilinear_corners,
    splats.normalised_centres,
    splats.arc_length_weights,
)


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


def _drawn_splat_cases(rng: np.random.Generator) -> list[dict[str, float]]:
    """Graded cases of :data:`CASES`' families, in their order, drawn from ``rng``.

    Points in eighths of a pixel: a pixel centre, a pixel corner, two generic points, one
    right of a first column of centres and above the first row (x in (0.5, 1), y in (0, 0.5)),
    one on the diagonal x = y, and one left of the image (x in (-0.5, 0)). Each named mistake
    is caught, and named, at the case where the fixed cases catch it
    (:func:`~course.lessons.graded_cases.drawn_in_order`).
    """

    def eighths(low: float, high: float) -> float:
        return float(rng.integers(round(low * 8), round(high * 8) + 1)) / 8

    def generic() -> list[dict[str, float]]:
        while True:
            x, y = eighths(1, 11), eighths(1, 11)
            if x % 0.5 and y % 0.5 and x != y:
                return [{"x": x, "y": y}]

    def diagonal() -> list[dict[str, float]]:
        x = eighths(1, 11)
        return [{"x": x, "y": x}]

    families = [
        lambda: [{"x": int(rng.integers(0, 12)) + 0.5, "y": int(rng.integers(0, 12)) + 0.5}],
        lambda: [{"x": float(rng.integers(1, 12)), "y": float(rng.integers(1, 12))}],
        generic,
        generic,
        lambda: [{"x": eighths(0.625, 0.875), "y": eighths(0.125, 0.375)}],
        diagonal,
        lambda: [{"x": eighths(-0.375, -0.125), "y": eighths(1.125, 1.875)}],
    ]
    return drawn_in_order(
        CASES,
        families,
        table_of(bilinear_centres),
        close(atol=1e-9, rtol=0.0),
        splat_mistakes(),
    )


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
    if _weights_first(pixels, weights):
        raise AnswerError(
            _(
                "you returned the weights first: your first list holds {count} numbers and your "
                "second {count} (x, y) pairs. Return pixels, weights, the pixels first."
            ).format(count=len(weights))
        )
    try:
        return splat_table(pixels, weights)
    except (TypeError, ValueError) as error:
        raise AnswerError(str(error)) from None


def _weights_first(pixels: Any, weights: Any) -> bool:
    """Whether ``(pixels, weights)`` is a splat returned the other way round: as many
    plain numbers first as (x, y) pairs second.

    Examples
    --------
    >>> _weights_first([0.25, 0.75], [(2, 1), (3, 1)]), _weights_first([(2, 1)], [1.0])
    (True, False)
    """
    try:
        first, second = np.asarray(pixels), np.asarray(weights)
    except (TypeError, ValueError):  # ragged: not the other way round, and splat_table says so
        return False
    return (
        first.ndim == 1
        and second.ndim == 2
        and second.shape[1] == 2
        and len(first) == len(second) > 0
    )


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
    return _(", ").join(each.format(x=int(x), y=int(y), weight=f"{w:.4g}") for x, y, w in table)


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


SPLAT_HINTS = Hints(
    where=N_("look at which four pixels you light, and from which point you measure the offsets."),
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
)


@exercise(
    hints=SPLAT_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    draw=_drawn_splat_cases,
)
def splat(student: Callable[[float, float], Any]) -> CheckResult:
    """Check ``student(x, y) -> (pixels, weights)`` against the bilinear splat about centres.

    The correct splat lights the four pixels whose centres (c + 0.5,
    r + 0.5) surround the point, with weights ``(1 - dx)(1 - dy)``,
    ``dx (1 - dy)``, ``(1 - dx) dy``, ``dx dy``, where (dx, dy) is the
    point's offset from the top-left one of those centres. Pixels may come
    in any order; pixels of weight 0 may be left out.

    Examples
    --------
    >>> splat(lambda x, y: ([(int(x), int(y))], [1.0])).mistake
    'the whole point to one pixel'
    """
    return run_cases(
        "splat",
        student,
        CASES,
        reference=table_of(bilinear_centres),
        compare=close(atol=1e-9, rtol=0.0),
        convert=_student_table,
        mistakes=splat_mistakes(),
        difference=_splat_difference,
        picture=failure_picture,
        explain=_splat_explain,
        show=_show_splat,
        # Case 3, (3.25, 7.875): four unequal weights.
        pass_picture=lambda results: pass_picture(*results[2]),
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


def _drawn_weight_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``arc_length_weights``, in the fixed cases' order, drawn from ``rng``.

    Three samples with a long chord and then a short one; two samples; a cubic across the
    700 x 700 window at t = 0, 1/8, ..., 1 (far apart at the ends, close in the middle); a
    random walk of 12 samples; a lone sample. Each named mistake is caught, and named, at the
    case where the fixed cases catch it (:func:`~course.lessons.graded_cases.drawn_in_order`).
    """

    def step(low: float, high: float) -> np.ndarray:
        angle = rng.uniform(0, 2 * np.pi)
        return rng.uniform(low, high) * np.array([np.cos(angle), np.sin(angle)])

    def three() -> list[dict[str, Any]]:
        start = rng.uniform(0, 5, 2)
        return [{"samples": np.cumsum([start, step(3, 6), step(0.5, 1.5)], axis=0).round(2)}]

    families = [
        three,
        lambda: [{"samples": rng.uniform(0, 5, (2, 2)).round(2)}],
        lambda: [{"samples": curve_samples(rng.uniform(10, 690, (4, 2)).round(1), 0.125)}],
        lambda: [{"samples": np.cumsum(rng.uniform(-2, 2, size=(12, 2)), axis=0)}],
        lambda: [{"samples": rng.uniform(0, 10, (1, 2)).round(2)}],
    ]
    return drawn_in_order(
        _weight_cases(),
        families,
        reference_weights,
        close(atol=1e-9, rtol=1e-9),
        weight_mistakes(),
        lambda answer: np.asarray(answer, dtype=float),
    )


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
    axes.plot(index, have, "x--", color=GIVEN, label=_("your result"), markersize=6)
    # Samples are counted: ticks on whole numbers only, never "sample 0.25".
    axes.xaxis.set_major_locator(MaxNLocator(integer=True))
    axes.set_xlabel(_("sample"), fontsize=8)
    axes.set_ylabel(_("weight (px of curve)"), fontsize=8)
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=7)
    axes.set_title(_(title), fontsize=9)
    figure.tight_layout()
    return figure_png(figure)


WEIGHT_HINTS = Hints(
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
)


@exercise(
    hints=WEIGHT_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    draw=_drawn_weight_cases,
)
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
        mistakes=weight_mistakes(),
        difference=first_difference,
        picture=_weights_picture,
        pass_picture=lambda results: _weights_picture(*results[2], "your weights along the cubic"),
    )
