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
wraps around to the other side of the window, and the wrong colour (on one
window painted grey before the loop runs, green is the whole pixel (0, 1, 0) or
the green channel alone, as the reports set it). An
answer that calls the library's own curve is told to write it. The drawing
loop's cases, reference, mistakes and pictures are in
:mod:`~course.lessons.l01_de_casteljau.drawing_loop`.

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
    run_cases,
)
from course.check.exercises import exercise, public_name
from course.check.hints import Hints
from course.check.pictures import curve_picture
from course.curves import bezier as library
from course.curves import bezier_accuracy
from course.curves.bezier import de_casteljau, de_casteljau_levels
from course.curves.bezier_handouts import de_casteljau_reversed
from course.i18n import N_, _
from course.images import SEED_000_CUBIC
from course.lessons.l01_de_casteljau.drawing_loop import (
    Painting,
    bezier_cases,
    bezier_pass_picture,
    bezier_picture,
    bezier_reference,
    painting_difference,
    same_painting,
    show_painting,
)
from course.lessons.l01_de_casteljau.drawn import draw_bezier_cases, draw_curve_cases
from course.lessons.l01_de_casteljau.mistakes import bezier_mistakes

__all__ = [
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

_LIBRARY_FUNCTIONS = (
    library.de_casteljau,
    library.de_casteljau_recursive,
    library.de_casteljau_levels,
    library.bezier_bernstein,
    library.bernstein_basis,
    library.split,
    library.sample_uniform,
    bezier_accuracy.bezier_exact,
    bezier_accuracy.bezier_power,
)


def library_curves() -> dict[Any, str]:
    """The library's own curves, each with what a student who calls it is told (in the
    current language)."""
    return {
        function: _(
            "your function calls {function}, the library's own answer: this exercise writes the "
            "curve itself, from the interpolation step"
        ).format(function=public_name(function))
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


# The first step names where each of the named mistakes lives: the step along the edge (the
# reversed step), the end of the recursion (one level short), the point returned (x and y).
RECURSIVE_HINTS = Hints(
    where=N_(
        "look at where each call puts its new points (t of the way along each edge, from its "
        "first end), at when the recursion stops, and at the point you return."
    ),
    more=N_(
        "each call makes one level with one point fewer (your next_level), and passes "
        "it on with the same t; the call that gets a single point has B(t), (x, y)."
    ),
    recipe=N_(
        "if len(control_points) == 1, return control_points[0]; otherwise return "
        "recursive_bezier(next_level(control_points, t), t)."
    ),
)


def _graded_recursive_bezier(control_points: Any, t: float) -> Any:
    """The grader's answer to ``recursive_bezier``: steps until one point is left."""
    points = np.asarray(control_points, dtype=float)
    while len(points) > 1:
        points = _graded_next_level(points, t)
    return points[0]


def _drawn_curve_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """The graded cases of ``recursive_bezier`` and ``next_level``: :func:`draw_curve_cases`'
    families (a quadratic, a line, a cubic, curves of 5 to 10 points, each at five t)."""
    return draw_curve_cases(rng, max_points=10)


@exercise(
    hints=RECURSIVE_HINTS,
    refuses=library_curves,
    grader_reference=_graded_recursive_bezier,
    draw=_drawn_curve_cases,
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
        mistakes=point_mistakes(_curve),
        picture=point_picture(_curve, N_("your recursive_bezier")),
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


def _level_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
    """A failure's picture: the control polygon and its curve, the next level expected (crosses)
    and the student's (dots)."""
    control = np.asarray(case["control_points"], dtype=float)
    theirs = np.asarray(given, dtype=float)
    theirs = theirs.reshape(-1, 2) if theirs.size % 2 == 0 else np.full((1, 2), np.nan)
    return curve_picture(
        control,
        _curve(control, np.linspace(0.0, 1.0, 41)),
        theirs,
        _("your next_level, t = {t}").format(t=f"{case['t']:g}"),
        mark_start=False,
        given_label=_("your level"),
        expected_point=np.asarray(expected, dtype=float).reshape(-1, 2),
        expected_label=_("expected level"),
    )


NEXT_LEVEL_HINTS = Hints(
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
)


def _graded_next_level(control_points: Any, t: float) -> Any:
    """The grader's answer to ``next_level``: one de Casteljau step, in plain numpy.

    nbgrader grades a later exercise that calls ``next_level`` with it, so that a mistake
    is charged once; it is not the library's, which the checkers refuse.
    """
    points = np.asarray(control_points, dtype=float)
    return (1 - t) * points[:-1] + t * points[1:]


@exercise(
    hints=NEXT_LEVEL_HINTS,
    refuses=library_curves,
    grader_reference=_graded_next_level,
    draw=_drawn_curve_cases,
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
        mistakes=_level_mistakes(),
        picture=_level_picture,
        pass_picture=_level_pass_picture,
    )


BEZIER_HINTS = Hints(
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
)


@exercise(
    hints=BEZIER_HINTS,
    refuses=library_curves,
    draw=draw_bezier_cases,
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
        bezier_cases(),
        reference=bezier_reference,
        compare=same_painting,
        convert=Painting,
        mistakes=bezier_mistakes(function),
        difference=painting_difference,
        picture=bezier_picture,
        show=show_painting,
        answer=lambda returned, arguments: (arguments[1], returned),
        writable=("window",),
        pass_picture=bezier_pass_picture,
    )
