"""Checkers for lesson 03: the lab's ``DrawLine`` and ``DrawTriangleFilled``.

The student's functions return pixels, as :mod:`course.raster` does:
``draw_line(p0, p1)`` the (x, y) pixels of the line from p0 to p1, in
order; ``draw_triangle_filled(p0, p1, p2)`` the pixels whose centres lie
inside, each once, in any order (the lab fills them by scanline; any method
that takes the same pixels passes). A failure shows the missing and extra
pixels as a picture and names the handouts' mistakes: the report's
4-connected staircase, a line drawn backwards or short of an end, and for
triangles the closed and open edge rules, the bottom row filled, vertices
rounded or made whole, the rule mirrored, and pixel corners taken for
centres. Pictures count pixels on their axes and draw the triangle's edges. An answer that calls the
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
    Mistake,
    hint,
    pixel_difference,
    pixel_rows,
    register_hints,
    run_cases,
    same_pixels,
)
from course.check.pictures import pixel_picture
from course.i18n import N_, _
from course.raster import line, line_4connected, triangle

__all__ = ["draw_line", "draw_triangle_filled", "hint"]

_RASTER_FUNCTIONS = (
    raster.line,
    raster.line_4connected,
    raster.triangle,
    raster.triangle_coverage,
    raster.wu_line,
)


def _raster() -> dict[Any, str]:
    """The library's own answers, each with the report's words for a call to it."""
    return {
        function: _(
            "your function calls {name}, the library's own answer: this exercise writes it"
        ).format(name=f"course.raster.{function.__name__}")
        for function in _RASTER_FUNCTIONS
    }


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
    ((1, 1), (9, 2), (4, 8)),
    ((1, 1), (4, 8), (9, 2)),  # the other winding
    ((0, 0), (8, 0), (4, 6)),  # flat top
    ((4, 0), (0, 6), (8, 6)),  # flat bottom
    ((0, 0), (8, 8), (0, 8)),  # an edge through pixel centres
    ((0, 0), (8, 0), (8, 8)),  # its partner
    ((0.5, 0.5), (7.5, 0.5), (0.5, 5.5)),  # edges through centres, vertices on them
    ((1.25, 0.75), (10.6, 3.2), (3.9, 9.35)),  # float vertices
    ((1, 1), (5, 3), (9, 5)),  # zero area: no pixels
    ((2, 2), (2, 2), (7, 4)),  # two equal vertices: no pixels
    ((0, 2), (12, 2.4), (6, 2.2)),  # thinner than a row
    ((0.5, 0.5), (0.5, 5.5), (7.5, 5.5)),  # a flat bottom edge on a row of centres: 16 pixels
    ((0.7, 0.2), (6.6, 1.3), (2.4, 7.8)),  # float vertices whose whole parts fill otherwise
]


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


def _ordered_same(expected: Any, given: Any) -> bool:
    expected = np.asarray(expected, dtype=float).reshape(-1, 2)
    given = np.asarray(given, dtype=float).reshape(-1, 2)
    return expected.shape == given.shape and bool(np.array_equal(expected, given))


def _first_octant_only(p0: Any, p1: Any) -> list[tuple[int, int]]:
    """The lesson's first-octant pseudocode used as is: x from x0 up to x1, y stepping up."""
    (x0, y0), (x1, y1) = (int(v) for v in p0), (int(v) for v in p1)
    dx, dy = x1 - x0, y1 - y0
    decision, y, pixels = 2 * dy - dx, y0, []
    for x in range(x0, x1 + 1):
        pixels.append((x, y))
        if decision > 0:
            y += 1
            decision -= 2 * dx
        decision += 2 * dy
    return pixels


def _truncated_steps(p0: Any, p1: Any) -> list[tuple[int, int]]:
    """A DDA that steps t evenly and truncates each point with int() instead of rounding."""
    (x0, y0), (x1, y1) = (int(v) for v in p0), (int(v) for v in p1)
    steps = max(abs(x1 - x0), abs(y1 - y0))
    if steps == 0:
        return [(x0, y0)]
    return [
        (int(x0 + i / steps * (x1 - x0)), int(y0 + i / steps * (y1 - y0))) for i in range(steps + 1)
    ]


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
    mistakes = [
        Mistake(
            N_("the report's staircase"),
            N_(
                "every step of your line moves in x or in y, never both, so each diagonal step "
                "became two and left an extra pixel in the corner: a 4-connected staircase (the "
                "lab report's one test, `if (err2 > -dy) ... else ...`, whose else replaces the "
                "second test, or x and y stepped and painted one after the other). A line steps "
                "diagonally whenever both errors call for it, so it has max(|dx|, |dy|) + 1 "
                "pixels, not |dx| + |dy| + 1."
            ),
            _staircase,
            matches=_is_staircase,
        ),
        Mistake(
            N_("drawn backwards"),
            N_("your pixels run from p1 to p0: the lab's DrawLine starts at p0."),
            lambda p0, p1: line(p0, p1)[::-1],
            matches=_ordered_same,
        ),
        Mistake(
            N_("the last pixel missing"),
            N_("your loop stops one pixel before p1: a line includes both end pixels."),
            lambda p0, p1: line(p0, p1)[:-1],
            matches=_ordered_same,
        ),
        Mistake(
            N_("the first pixel missing"),
            N_("your line starts one pixel after p0: paint p0 before the first step."),
            lambda p0, p1: line(p0, p1)[1:],
            matches=_ordered_same,
        ),
        Mistake(
            N_("truncated, not rounded"),
            N_(
                "you stepped along the line and cut each coordinate with int(), which drops the "
                "fraction: that takes the pixel on one side of the line, not the nearest one. "
                "Round to the nearest pixel, or let an error term decide, as Bresenham does."
            ),
            _truncated_steps,
            matches=_ordered_same,
        ),
        Mistake(
            N_("the first octant only"),
            N_(
                "your line works only in the first octant (x1 >= x0 and 0 <= y1 - y0 <= x1 - x0): "
                "the lesson's pseudocode, used as is. The other seven octants run the same loop: "
                "a steep line swaps the roles of x and y, and a line going left or up steps by -1."
            ),
            _first_octant_only,
            matches=_ordered_same,
        ),
    ]
    return run_cases(
        "draw_line",
        student,
        cases,
        line,
        _is_bresenham_line,
        _as_line_pixels,
        hint=LINE_HINTS,
        mistakes=mistakes,
        difference=_line_difference,
        picture=_picture,
        forbidden=_raster(),
        pass_picture=_pass_picture,
    )


def _staircase(p0: Any, p1: Any) -> Any:
    return line_4connected(p0, p1)


def _is_staircase(staircase: Any, given: Any) -> bool:
    """Whether ``given`` runs from the staircase's first pixel to its last in axis steps only.

    Any 4-connected path of |dx| + |dy| + 1 pixels is one, whichever way its corners turn.
    """
    want, have = np.asarray(staircase, dtype=float), np.asarray(given, dtype=float)
    if have.ndim != 2 or have.shape != want.shape or len(have) < 2:
        return False
    if tuple(have[0]) != tuple(want[0]) or tuple(have[-1]) != tuple(want[-1]):
        return False
    steps = np.abs(np.diff(have, axis=0))
    return bool((steps.sum(axis=1) == 1).all())


LINE_HINTS = register_hints(
    "draw_line",
    Hints(
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
    ),
    "draw_line",
    "DrawLine",
)


def _corners_inside(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The pixels whose top-left corner (x, y), not centre, is inside: a half-pixel shift."""
    shifted = [np.subtract(p, 0.5) for p in (p0, p1, p2)]
    return triangle(*shifted)


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
    mistakes = [
        Mistake(
            N_("every edge closed"),
            N_(
                "you count a centre on any edge as inside: x_left <= x <= x_right, or <= on the "
                "last row. Two triangles sharing that edge would both paint it. Take each row's "
                "centres over [x_left, x_right) and the rows over [y_top, y_bottom)."
            ),
            lambda p0, p1, p2: triangle(p0, p1, p2, rule="closed"),
        ),
        Mistake(
            N_("the top row left out"),
            N_(
                "your rows start after y_top: a row of centres exactly on a flat top edge "
                "belongs to this triangle (the top-left rule), so the rows run over "
                "[y_top, y_bottom), the first one included."
            ),
            _top_row_left_out,
        ),
        Mistake(
            N_("the vertices rounded"),
            N_(
                "your triangle's vertices were rounded to whole numbers (round()) before "
                "filling: a vertex at (1.25, 0.75) moved to (1, 1). Keep them as floats; only the "
                "pixels are whole."
            ),
            lambda p0, p1, p2: triangle(
                *(np.round(np.asarray(p, dtype=float)) for p in (p0, p1, p2))
            ),
        ),
        Mistake(
            N_("the vertices made whole"),
            N_(
                "your triangle's vertices were cut to whole numbers (int() or a cast) before "
                "filling: a vertex at (0.7, 0.2) moved to (0, 0). Keep them as floats; only the "
                "pixels are whole."
            ),
            lambda p0, p1, p2: triangle(
                *(np.trunc(np.asarray(p, dtype=float)) for p in (p0, p1, p2))
            ),
        ),
        Mistake(
            N_("the bottom row filled"),
            N_(
                "your rows run over [y_top, y_bottom], the last one included: a row of centres "
                "exactly on a flat bottom edge belongs to the triangle below. Take the rows over "
                "[y_top, y_bottom)."
            ),
            _bottom_row_filled,
        ),
        Mistake(
            N_("the rule mirrored"),
            N_(
                "you include a centre on a right edge and leave out one on a left edge: the rule "
                "mirrored, x_left < x <= x_right. Two triangles still share the edge fairly, but "
                "every other triangle of the mesh uses the lesson's rule: [x_left, x_right)."
            ),
            lambda p0, p1, p2: _unless_same(_mirrored_rule, _open_rule, p0, p1, p2),
            matches=_same_or_nothing,
        ),
        Mistake(
            N_("every edge open"),
            N_(
                "you leave out every centre that lies on an edge, so two triangles sharing that "
                "edge would both skip it: a crack. Include the left and the top ones: "
                "[x_left, x_right), rows over [y_top, y_bottom)."
            ),
            lambda p0, p1, p2: _unless_same(_open_rule, _mirrored_rule, p0, p1, p2),
            matches=_same_or_nothing,
        ),
        Mistake(
            N_("a centre on a left edge left out"),
            N_(
                "you leave out a centre that lies exactly on a left edge (x_left < x): the left "
                "edge is included and the right one left out, x_left <= x < x_right, so that two "
                "triangles sharing an edge paint each of its centres once."
            ),
            _open_rule,
        ),
        Mistake(
            N_("pixel corners for centres"),
            N_(
                "you tested the pixel's corner (x, y), not its centre (x + 0.5, y + 0.5): the "
                "whole triangle is off by half a pixel, up and left."
            ),
            _corners_inside,
        ),
    ]
    return run_cases(
        "draw_triangle_filled",
        student,
        cases,
        triangle,
        _same_pixel_set,
        _as_pixel_array,
        hint=TRIANGLE_HINTS,
        mistakes=mistakes,
        difference=pixel_difference,
        picture=_picture,
        forbidden=_raster(),
        pass_picture=_pass_picture,
    )


def _bottom_row_filled(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The fill with rows over [top, bottom]: a row of centres on a flat bottom edge taken too.

    That row's centres are taken as any row's, over [x_left, x_right); a bottom that is
    one vertex adds nothing.
    """
    inside = triangle(p0, p1, p2)
    corners = np.array([p0, p1, p2], dtype=float)
    bottom = corners[:, 1].max()
    on_bottom = corners[corners[:, 1] == bottom]
    (ux, uy), (vx, vy) = corners[1] - corners[0], corners[2] - corners[0]
    twice_area = ux * vy - uy * vx
    if len(on_bottom) != 2 or twice_area == 0 or (bottom - 0.5) != np.floor(bottom - 0.5):
        return inside
    left, right = np.sort(on_bottom[:, 0])
    columns = np.arange(np.ceil(left - 0.5), np.ceil(right - 0.5), dtype=np.int64)
    row = np.column_stack([columns, np.full(len(columns), int(bottom - 0.5), dtype=np.int64)])
    return np.unique(np.vstack([np.asarray(inside, dtype=np.int64).reshape(-1, 2), row]), axis=0)


def _top_row_left_out(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The fill with rows over (top, bottom): a row of centres on a flat top edge dropped."""
    inside = np.asarray(triangle(p0, p1, p2), dtype=np.int64).reshape(-1, 2)
    corners = np.array([p0, p1, p2], dtype=float)
    top = corners[:, 1].min()
    if (corners[:, 1] == top).sum() != 2 or (top - 0.5) != np.floor(top - 0.5):
        return inside
    return inside[inside[:, 1] != int(top - 0.5)]


def _open_rule(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    return triangle(p0, p1, p2, rule="open")


def _mirrored_rule(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The lesson's rule seen in a mirror: right edges in, left edges out (top still in)."""
    mirrored = [(-float(p[0]), float(p[1])) for p in (p0, p1, p2)]
    pixels = np.asarray(triangle(*mirrored), dtype=np.int64).reshape(-1, 2).copy()
    pixels[:, 0] = -pixels[:, 0] - 1  # pixel c's centre c + 1/2 mirrors to pixel -c - 1's
    return pixels


def _unless_same(
    rule: Callable[..., Any], other: Callable[..., Any], p0: Any, p1: Any, p2: Any
) -> np.ndarray | None:
    """``rule``'s pixels when this case tells them from ``other``'s; None when it cannot."""
    pixels = rule(p0, p1, p2)
    return None if same_pixels(pixels, other(p0, p1, p2)) else pixels


def _same_or_nothing(answer: Any, given: Any) -> bool:
    return answer is not None and _same_pixel_set(
        np.asarray(answer, dtype=np.int64).reshape(-1, 2), given
    )


TRIANGLE_HINTS = register_hints(
    "draw_triangle_filled",
    Hints(
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
    ),
    "draw_triangle_filled",
    "DrawTriangleFilled",
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


def _is_bresenham_line(expected: np.ndarray, given: np.ndarray) -> bool:
    (x0, y0), (x1, y1) = expected[0], expected[-1]
    if given.shape != expected.shape or not np.array_equal(given, np.round(given)):
        return False
    if tuple(given[0]) != (x0, y0) or tuple(given[-1]) != (x1, y1):
        return False
    if len(given) > 1 and not (np.abs(np.diff(given, axis=0)).max(axis=1) == 1).all():
        return False
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    if n == 0:
        return True
    x, y = given[:, 0] - x0, given[:, 1] - y0
    # Offset from the ideal line along the shorter axis, times n.
    offset = y * dx - x * dy if abs(dx) >= abs(dy) else x * dy - y * dx
    return bool((2 * np.abs(offset) <= n).all())


def _same_pixel_set(expected: np.ndarray, given: np.ndarray) -> bool:
    def ordered(pixels: np.ndarray) -> np.ndarray:
        return pixels[np.lexsort((pixels[:, 0], pixels[:, 1]))]

    return given.shape == expected.shape and np.array_equal(ordered(given), ordered(expected))
