"""Checkers for lesson 03: the lab's ``DrawLine`` and ``DrawTriangleFilled``.

The student's functions return pixels, as :mod:`course.raster` does:
``draw_line(p0, p1)`` the (x, y) pixels of the line from p0 to p1, in
order; ``draw_triangle_filled(p0, p1, p2)`` the pixels whose centres lie
inside, each once, in any order (the lab fills them by scanline; any method
that takes the same pixels passes). A failure shows the missing and extra
pixels as a picture and names the handouts' mistakes: a 4-connected
staircase (the report's loop, or every pixel a finely stepped float t
crosses), a line drawn backwards or short of an end, a single pixel left
empty, the lesson's loop without the steep swap, with the swap not undone or
with ``D -= dx``, pixels as (y, x) (:mod:`.line_mistakes` reproduces them);
and for triangles every edge closed or open, the rule mirrored, the left
edges left out, the top row left out or the bottom row filled, vertices
rounded or made whole, a pixel corner tested for its centre, and the slopes
divided before the test for a flat edge (:mod:`.mistakes` reproduces them).
Pictures frame the case, number pixels as the lesson's figures do (ticks
on pixel corners) and draw the triangle's edges. An answer that calls the
library's own line or fill is told to write it.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("draw_line")`` says more at once and
``check.hint("draw_line", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import raster
from course.check.answers import AnswerError
from course.check.base import (
    CheckResult,
    Hints,
    hint,
    pixel_difference,
    pixel_rows,
    run_cases,
    same_pixels,
)
from course.check.exercises import exercise
from course.check.pictures import pixel_picture
from course.i18n import N_, _
from course.lessons.graded_cases import drawn_like
from course.lessons.l03_lines_and_triangles.line_mistakes import LINE_MISTAKES, is_bresenham_line
from course.lessons.l03_lines_and_triangles.mistakes import FILL_MISTAKES, same_pixel_set
from course.raster import line, triangle

__all__ = ["draw_line", "draw_triangle_filled", "hint"]

_LIBRARY_FUNCTIONS = (
    raster.line,
    raster.line_4connected,
    raster.triangle,
    raster.triangle_coverage,
    raster.wu_line,
)


# Every octant, both axes, a single pixel, slopes of exactly 1 and 1/2, and
# lines with ties (the ideal line midway between two pixels).
_LINE_CASES = [
    ((2, 3), (9, 5)),
    ((9, 5), (2, 3)),
    ((2, 3), (4, 11)),
    ((4, 11), (2, 3)),
    ((9, 3), (2, 5)),
    ((2, 5), (9, 3)),
    ((4, 3), (2, 11)),
    ((2, 11), (4, 3)),
    ((0, 0), (7, 0)),
    ((0, 7), (0, 0)),
    ((5, 5), (5, 5)),
    ((0, 0), (6, 6)),
    ((6, 0), (0, 6)),
    ((0, 0), (8, 4)),
    ((1, 1), (13, 6)),
]

_TRIANGLE_CASES = [
    ((1, 1), (9, 2), (5, 8)),  # no centre on an edge
    ((1, 1), (5, 8), (9, 2)),  # the other winding
    ((0, 0), (8, 0), (4, 6)),  # flat top
    ((4, 0), (0, 6), (8, 6)),  # flat bottom
    # Centres on a left, a top and a right edge (a vertex): the first case that fails an edge
    # rule tells each rule from the others.
    ((0.5, 0.5), (7.5, 0.5), (0.5, 5.5)),
    ((0, 0), (8, 8), (0, 8)),  # an edge through pixel centres
    ((0, 0), (8, 0), (8, 8)),  # its partner
    ((1.25, 0.75), (10.6, 3.2), (3.9, 9.35)),  # float vertices
    ((1, 1), (5, 3), (9, 5)),  # zero area: no pixels
    ((2, 2), (2, 2), (7, 4)),  # two equal vertices: no pixels
    ((0, 2), (12, 2.4), (6, 2.2)),  # thinner than a row
    ((0.5, 0.5), (0.5, 5.5), (7.5, 5.5)),  # a flat bottom edge on a row of centres: 16 pixels
    ((0.7, 0.2), (6.6, 1.3), (2.4, 7.8)),  # float vertices whose whole parts fill otherwise
]


def _drawn_line_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``_LINE_CASES``' families, in their order, drawn from ``rng``.

    A line in each of the four octant pairs, each followed by itself reversed (shallow and
    steep, going right and going left), 4 to 10 pixels long; a horizontal line and a
    vertical one drawn upward; a single pixel; slopes of exactly 1, -1 and 1/2; a shallow line
    with a tie (the ideal line midway between two pixels). Start points lie in [0, 6]; each
    case tells the named mistakes apart as its fixed case does
    (:func:`~course.lessons.graded_cases.drawn_like`).
    """

    def start() -> tuple[int, int]:
        return int(rng.integers(0, 7)), int(rng.integers(0, 7))

    def octant(steep: bool, left: bool) -> list[dict[str, Any]]:
        (x, y), long = start(), int(rng.integers(4, 11))
        short = int(rng.integers(1, long))
        dx, dy = (short, long) if steep else (long, short)
        p0, p1 = ((x + dx, y), (x, y + dy)) if left else ((x, y), (x + dx, y + dy))
        return [{"p0": p0, "p1": p1}, {"p0": p1, "p1": p0}]

    def with_a_tie() -> list[dict[str, Any]]:
        while True:
            (x, y), dx = start(), int(rng.integers(6, 15))
            dy = int(rng.integers(1, dx))
            if any(2 * dy * k % (2 * dx) == dx for k in range(1, dx)):
                return [{"p0": (x, y), "p1": (x + dx, y + dy)}]

    def single(line: Callable[[int, int, int], tuple[Any, Any]]) -> Callable[[], list]:
        def draw() -> list[dict[str, Any]]:
            (x, y), length = start(), int(rng.integers(4, 11))
            p0, p1 = line(x, y, length)
            return [{"p0": p0, "p1": p1}]

        return draw

    families = [
        lambda: octant(steep=False, left=False),
        lambda: octant(steep=True, left=False),
        lambda: octant(steep=False, left=True),
        lambda: octant(steep=True, left=True),
        single(lambda x, y, n: ((x, y), (x + n, y))),
        single(lambda x, y, n: ((x, y + n), (x, y))),
        single(lambda x, y, n: ((x, y), (x, y))),
        single(lambda x, y, n: ((x, y), (x + n, y + n))),
        single(lambda x, y, n: ((x + n, y), (x, y + n))),
        single(lambda x, y, n: ((x, y), (x + 2 * (n // 2), y + n // 2))),
        with_a_tie,
    ]
    fixed = [{"p0": p0, "p1": p1} for p0, p1 in _LINE_CASES]
    cases: list[dict[str, Any]] = []
    for family in families:
        count = 2 if len(cases) < 8 else 1
        like = fixed[len(cases) : len(cases) + count]
        cases += drawn_like(like, family, line, is_bresenham_line, LINE_MISTAKES, _as_line_pixels)
    return cases


def _drawn_triangle_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``_TRIANGLE_CASES``' families, in their order, drawn from ``rng``.

    With integer vertices: a triangle and the same in the other winding, a flat top and a flat
    bottom; with vertices on pixel centres, a flat top on a row of centres; with integer
    vertices again, a right isosceles triangle whose long edge runs through pixel centres and
    its partner; float vertices; a triangle of zero area and one with two equal vertices; one
    thinner than a row; a flat bottom on a row of centres; float vertices again. Vertices lie
    in [0, 13]; each case tells the named mistakes apart as its fixed case does
    (:func:`~course.lessons.graded_cases.drawn_like`).
    """

    def whole(low: int = 0, high: int = 12) -> int:
        return int(rng.integers(low, high + 1))

    def two_windings() -> list[dict[str, Any]]:
        p0, p1, p2 = wound((whole(), whole()) for _ in range(3))
        return [{"p0": p0, "p1": p1, "p2": p2}, {"p0": p0, "p1": p2, "p2": p1}]

    def one(draw: Callable[[], tuple[Any, Any, Any]]) -> Callable[[], list[dict[str, Any]]]:
        return lambda: [dict(zip(("p0", "p1", "p2"), draw(), strict=True))]

    def flat(top: bool, on_centres: bool = False) -> tuple[Any, Any, Any]:
        """A flat top (two vertices above the third) or bottom, its ends on centres or not."""
        shift = 0.5 if on_centres else 0
        x, y = whole(0, 3) + shift, whole(0, 4) + shift
        width, height = whole(4, 9), whole(3, 7)
        if on_centres:  # a right angle at (x, y), as the fixed cases have
            if top:
                return (x, y), (x + width, y), (x, y + height)
            return (x, y), (x, y + height), (x + width, y + height)
        apex = (whole(), y + height if top else y)
        if top:
            return (x, y), (x + width, y), apex
        return apex, (x, y + height), (x + width, y + height)

    def right_isosceles(partner: bool) -> tuple[Any, Any, Any]:
        """A long edge along a diagonal of pixel centres."""
        x, y, size = whole(0, 4), whole(0, 4), whole(5, 9)
        if partner:
            return (x, y), (x + size, y), (x + size, y + size)
        return (x, y), (x + size, y + size), (x, y + size)

    def wound(corners: Any) -> tuple[Any, Any, Any]:
        """The corners in the fixed cases' first winding (clockwise on the screen, y down)."""
        a, b, c = corners
        twice_area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (a, b, c) if twice_area > 0 else (a, c, b)

    def floats() -> tuple[Any, Any, Any]:
        """Float vertices of a triangle of 10 pixels or more, as the fixed ones, no pixel
        centre within :data:`_CLEARANCE` of an edge."""
        while True:
            corners = rng.uniform(0, 11, (3, 2)).round(2)
            (ax, ay), (bx, by), (cx, cy) = corners.tolist()
            area_enough = abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) >= 20
            if area_enough and _centres_clear_of_edges(corners):
                return wound(((ax, ay), (bx, by), (cx, cy)))

    def collinear() -> tuple[Any, Any, Any]:
        x, y, dx, dy = whole(0, 4), whole(0, 4), whole(1, 4), whole(1, 3)
        return (x, y), (x + dx, y + dy), (x + 2 * dx, y + 2 * dy)

    def two_equal() -> tuple[Any, Any, Any]:
        x, y = whole(0, 6), whole(0, 6)
        return (x, y), (x, y), (whole(), whole())

    def thin() -> tuple[Any, Any, Any]:
        """Three vertices within one row, above its centres."""
        x, y, width = whole(0, 3), whole(0, 10), whole(6, 10)
        low, high = sorted(rng.integers(0, 5, size=2) / 10)
        low, high = float(low), float(high)
        return (x, y + low), (x + width, y + high + 0.05), (x + width / 2, y + (low + high) / 2)

    families = [
        two_windings,
        one(lambda: flat(top=True)),
        one(lambda: flat(top=False)),
        one(lambda: flat(top=True, on_centres=True)),
        one(lambda: right_isosceles(partner=False)),
        one(lambda: right_isosceles(partner=True)),
        one(floats),
        one(collinear),
        one(two_equal),
        one(thin),
        one(lambda: flat(top=False, on_centres=True)),
        one(floats),
    ]
    fixed = [{"p0": p0, "p1": p1, "p2": p2} for p0, p1, p2 in _TRIANGLE_CASES]
    cases: list[dict[str, Any]] = []
    for family in families:
        count = 2 if not cases else 1
        like = fixed[len(cases) : len(cases) + count]
        cases += drawn_like(like, family, triangle, same_pixel_set, FILL_MISTAKES, _as_pixel_array)
    return cases


#: How far a drawn float triangle keeps every pixel centre from its edges, in pixels. The
#: library snaps vertices to 1/256 of a pixel, as GPUs do; a student's fill computes with
#: the floats as given. A centre nearer an edge than the snap moves it would be inside for one
#: and outside for the other: a right answer failed by rounding.
_CLEARANCE = 0.01


def _centres_clear_of_edges(corners: np.ndarray) -> bool:
    """Whether every pixel centre is at least :data:`_CLEARANCE` from each edge of the triangle.

    Examples
    --------
    >>> _centres_clear_of_edges(np.array([[3.37, 6.96], [3.73, 2.91], [8.91, 7.81]]))
    False
    >>> _centres_clear_of_edges(np.array([[1.25, 0.75], [10.6, 3.2], [3.9, 9.35]]))
    True
    """
    low, high = np.floor(corners.min(axis=0)), np.ceil(corners.max(axis=0))
    xs, ys = np.meshgrid(np.arange(low[0], high[0]) + 0.5, np.arange(low[1], high[1]) + 0.5)
    centres = np.column_stack([xs.ravel(), ys.ravel()])
    for start, end in zip(corners, np.roll(corners, -1, axis=0), strict=True):
        along = end - start
        length = float(np.dot(along, along))
        if length == 0:
            continue
        t = np.clip((centres - start) @ along / length, 0.0, 1.0)
        nearest = start + t[:, None] * along
        if (np.hypot(*(centres - nearest).T) < _CLEARANCE).any():
            return False
    return True


def _picture(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
    if same_pixels(expected, given):
        return None  # the same pixels, some repeated: the words say it, a picture cannot
    outline = [case[name] for name in ("p0", "p1", "p2") if name in case]
    return pixel_picture(
        expected,
        given,
        title=N_("around the first difference"),
        outline=outline if len(outline) == 3 else None,
    )


def _pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
    case, expected, given = results[0]
    outline = [case[name] for name in ("p0", "p1", "p2") if name in case]
    return pixel_picture(
        expected,
        given,
        window=14,
        zoom=12,
        title=N_("your pixels for case 1"),
        outline=outline if len(outline) == 3 else None,
    )


def _line_difference(expected: Any, given: Any) -> str:
    """Missing and extra pixels, each with its first one along the line (not in reading order).

    Examples
    --------
    >>> _line_difference([[9, 5], [8, 5], [7, 4]], [])
    '3 pixels missing, first at (x, y) = (9, 5)'
    """
    want = [tuple(int(v) for v in pixel) for pixel in np.asarray(expected).reshape(-1, 2)]
    have = [tuple(int(v) for v in pixel) for pixel in np.asarray(given).reshape(-1, 2)]
    missing = [pixel for pixel in want if pixel not in set(have)]
    extra = [pixel for pixel in have if pixel not in set(want)]
    parts = []
    if missing:
        if len(missing) == 1:
            missing_text = _("{count} pixel missing, first at (x, y) = {pixel}")
        else:
            missing_text = _("{count} pixels missing, first at (x, y) = {pixel}")
        parts.append(missing_text.format(count=len(missing), pixel=missing[0]))
    if extra:
        parts.append(
            _("{count} extra, first at (x, y) = {pixel}").format(count=len(extra), pixel=extra[0])
        )
    if parts:
        return _("; ").join(parts)
    return pixel_difference(expected, given)


LINE_HINTS = Hints(
    where=N_(
        "look at the first and the last pixel, and at each step: how far it moves "
        "along each axis, and when the loop stops."
    ),
    more=N_(
        "step one pixel at a time along the longer axis; an error term says when the "
        "line has drifted half a pixel along the shorter one, and then that step moves "
        "along both (diagonally). The loop stops at p1."
    ),
    recipe=N_(
        "dx = |x1 - x0|, dy = |y1 - y0|, sx and sy the signs, error = dx - dy; "
        "paint (x, y); while not at p1: e2 = 2 error; if e2 > -dy: error -= dy, x += sx; "
        "if e2 < dx: error += dx, y += sy; paint (x, y)."
    ),
)


@exercise(
    hints=LINE_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("DrawLine",),
    draw=_drawn_line_cases,
)
def draw_line(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(p0, p1)`` -> the Bresenham pixels from p0 to p1, in order.

    A line passes when it has one pixel per step along the longer axis,
    starts at p0, ends at p1, steps to an 8-neighbour each time, and every
    pixel is within half a pixel of the ideal line along the shorter axis.
    Where two pixels are equally near, either is accepted.

    Examples
    --------
    >>> draw_line(lambda p0, p1: [p0, p1]).passed
    False
    """
    cases = [{"p0": p0, "p1": p1} for p0, p1 in _LINE_CASES]
    return run_cases(
        "draw_line",
        student,
        cases,
        line,
        is_bresenham_line,
        _as_line_pixels,
        mistakes=LINE_MISTAKES,
        difference=_line_difference,
        picture=_picture,
        pass_picture=_pass_picture,
    )


TRIANGLE_HINTS = Hints(
    where=N_(
        "look at which rows your loop fills (the first and the last), and at the "
        "pixels where a row of centres meets an edge."
    ),
    more=N_(
        "a pixel is in when its centre (x + 0.5, y + 0.5) is inside; a centre exactly "
        "on an edge belongs to the triangle only on the left or the top edge, so a row on a "
        "flat bottom edge, and a centre on a right edge, are left out."
    ),
    recipe=N_(
        "sort the vertices by y; for each row of centres from ceil(y_top - 0.5) to "
        "ceil(y_bottom - 0.5) - 1, find the two edges' x at y + 0.5 and take the pixels "
        "from ceil(x_left - 0.5) to ceil(x_right - 0.5) - 1, splitting at the middle vertex."
    ),
)


@exercise(
    hints=TRIANGLE_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("DrawTriangleFilled",),
    draw=_drawn_triangle_cases,
)
def draw_triangle_filled(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(p0, p1, p2)`` -> the pixels whose centres lie inside.

    The pixels must be exactly those of :func:`course.raster.triangle`: each
    pixel whose centre (x + 0.5, y + 0.5) is inside, centres on an edge
    decided by the top-left rule, each pixel once, in any order. A triangle
    of zero area has no pixels. A scanline fill takes exactly these pixels
    when each row of centres is filled over ``[x_left, x_right)`` and the
    rows over ``[y_top, y_bottom)``.

    Examples
    --------
    >>> draw_triangle_filled(lambda p0, p1, p2: [p0, p1, p2]).passed
    False
    """
    cases = [{"p0": p0, "p1": p1, "p2": p2} for p0, p1, p2 in _TRIANGLE_CASES]
    return run_cases(
        "draw_triangle_filled",
        student,
        cases,
        triangle,
        same_pixel_set,
        _as_pixel_array,
        mistakes=FILL_MISTAKES,
        difference=pixel_difference,
        picture=_picture,
        pass_picture=_pass_picture,
    )


def _as_pixel_array(given: Any) -> np.ndarray:
    """The student's pixels as a (K, 2) int64 array; a list of (x, y) pairs is fine."""
    return pixel_rows(given)


def _as_line_pixels(given: Any) -> np.ndarray:
    """A line's pixels in order; a set or a dict has none, so it is refused with why."""
    if isinstance(given, (set, frozenset, dict)):
        raise AnswerError(
            _(
                "you returned a {type}, which has no order; a line's pixels are a list, in order "
                "from p0 to p1"
            ).format(type=type(given).__name__)
        )
    return pixel_rows(given)
