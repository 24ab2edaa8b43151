"""The known mistakes lesson 03's checkers name, each reproduced on the checker's cases.

:data:`LINE_MISTAKES` are the wrong lines :func:`.check.draw_line` names: the
lab report's 4-connected staircase, a line drawn backwards or short of an
end, coordinates truncated, the lesson's first-octant pseudocode used as is.
:data:`FILL_MISTAKES` are the wrong fills :func:`.check.draw_triangle_filled`
names: the closed and open edge rules, the top row left out or the bottom
row filled, vertices rounded or made whole, the rule mirrored, and pixel
corners taken for centres. Beside them, the comparisons that tell a mistake
from its neighbours, and :func:`same_pixel_set`, the fill checker's own.

Only the checkers call these, with their own cases and the student's answer
as :mod:`.check` has read it, so this module checks none (``UNCHECKED = True``;
the fuzz test skips it).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import Mistake, same_pixels
from course.i18n import N_
from course.raster import line, line_4connected, triangle

UNCHECKED = True  # see the module docstring

__all__ = [
    "FILL_MISTAKES",
    "LINE_MISTAKES",
    "bottom_row_filled",
    "corners_inside",
    "first_octant_only",
    "is_staircase",
    "mirrored_rule",
    "open_rule",
    "ordered_same",
    "report_staircase",
    "same_or_nothing",
    "same_pixel_set",
    "top_row_left_out",
    "truncated_steps",
    "unless_same",
]


# --- lines -----------------------------------------------------------------------------


def ordered_same(expected: Any, given: Any) -> bool:
    """Whether two lines hold the same pixels in the same order."""
    expected = np.asarray(expected, dtype=float).reshape(-1, 2)
    given = np.asarray(given, dtype=float).reshape(-1, 2)
    return expected.shape == given.shape and bool(np.array_equal(expected, given))


def first_octant_only(p0: Any, p1: Any) -> list[tuple[int, int]]:
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


def truncated_steps(p0: Any, p1: Any) -> list[tuple[int, int]]:
    """A DDA that steps t evenly and truncates each point with int() instead of rounding."""
    (x0, y0), (x1, y1) = (int(v) for v in p0), (int(v) for v in p1)
    steps = max(abs(x1 - x0), abs(y1 - y0))
    if steps == 0:
        return [(x0, y0)]
    return [
        (int(x0 + i / steps * (x1 - x0)), int(y0 + i / steps * (y1 - y0))) for i in range(steps + 1)
    ]


def report_staircase(p0: Any, p1: Any) -> Any:
    """The lab report's line from p0 to p1: a 4-connected staircase."""
    return line_4connected(p0, p1)


def is_staircase(staircase: Any, given: Any) -> bool:
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


#: The wrong lines :func:`.check.draw_line` names, in the order it tries them.
LINE_MISTAKES = (
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
        report_staircase,
        matches=is_staircase,
    ),
    Mistake(
        N_("drawn backwards"),
        N_("your pixels run from p1 to p0: the lab's DrawLine starts at p0."),
        lambda p0, p1: line(p0, p1)[::-1],
        matches=ordered_same,
    ),
    Mistake(
        N_("the last pixel missing"),
        N_("your loop stops one pixel before p1: a line includes both end pixels."),
        lambda p0, p1: line(p0, p1)[:-1],
        matches=ordered_same,
    ),
    Mistake(
        N_("the first pixel missing"),
        N_("your line starts one pixel after p0: paint p0 before the first step."),
        lambda p0, p1: line(p0, p1)[1:],
        matches=ordered_same,
    ),
    Mistake(
        N_("truncated, not rounded"),
        N_(
            "you stepped along the line and cut each coordinate with int(), which drops the "
            "fraction: that takes the pixel on one side of the line, not the nearest one. "
            "Round to the nearest pixel, or let an error term decide, as Bresenham does."
        ),
        truncated_steps,
        matches=ordered_same,
    ),
    Mistake(
        N_("the first octant only"),
        N_(
            "your line works only in the first octant (x1 >= x0 and 0 <= y1 - y0 <= x1 - x0): "
            "the lesson's pseudocode, used as is. The other seven octants run the same loop: "
            "a steep line swaps the roles of x and y, and a line going left or up steps by -1."
        ),
        first_octant_only,
        matches=ordered_same,
    ),
)


# --- fills -----------------------------------------------------------------------------


def same_pixel_set(expected: np.ndarray, given: np.ndarray) -> bool:
    """Whether two (K, 2) arrays hold the same pixels, each as often, in any order."""

    def ordered(pixels: np.ndarray) -> np.ndarray:
        return pixels[np.lexsort((pixels[:, 0], pixels[:, 1]))]

    return given.shape == expected.shape and np.array_equal(ordered(given), ordered(expected))


def corners_inside(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The pixels whose top-left corner (x, y), not centre, is inside: a half-pixel shift."""
    shifted = [np.subtract(p, 0.5) for p in (p0, p1, p2)]
    return triangle(*shifted)


def bottom_row_filled(p0: Any, p1: Any, p2: Any) -> np.ndarray:
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


def top_row_left_out(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The fill with rows over (top, bottom): a row of centres on a flat top edge dropped."""
    inside = np.asarray(triangle(p0, p1, p2), dtype=np.int64).reshape(-1, 2)
    corners = np.array([p0, p1, p2], dtype=float)
    top = corners[:, 1].min()
    if (corners[:, 1] == top).sum() != 2 or (top - 0.5) != np.floor(top - 0.5):
        return inside
    return inside[inside[:, 1] != int(top - 0.5)]


def open_rule(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The fill that leaves out every centre on an edge."""
    return triangle(p0, p1, p2, rule="open")


def mirrored_rule(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The lesson's rule seen in a mirror: right edges in, left edges out (top still in)."""
    mirrored = [(-float(p[0]), float(p[1])) for p in (p0, p1, p2)]
    pixels = np.asarray(triangle(*mirrored), dtype=np.int64).reshape(-1, 2).copy()
    pixels[:, 0] = -pixels[:, 0] - 1  # pixel c's centre c + 1/2 mirrors to pixel -c - 1's
    return pixels


def unless_same(
    rule: Callable[..., Any], other: Callable[..., Any], p0: Any, p1: Any, p2: Any
) -> np.ndarray | None:
    """``rule``'s pixels when this case tells them from ``other``'s; None when it cannot."""
    pixels = rule(p0, p1, p2)
    return None if same_pixels(pixels, other(p0, p1, p2)) else pixels


def same_or_nothing(answer: Any, given: Any) -> bool:
    """Whether a mistake gave an answer for this case, and ``given`` is that answer."""
    return answer is not None and same_pixel_set(
        np.asarray(answer, dtype=np.int64).reshape(-1, 2), given
    )


#: The wrong fills :func:`.check.draw_triangle_filled` names, in the order it tries them.
FILL_MISTAKES = (
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
        top_row_left_out,
    ),
    Mistake(
        N_("the vertices rounded"),
        N_(
            "your triangle's vertices were rounded to whole numbers (round()) before "
            "filling: a vertex at (1.25, 0.75) moved to (1, 1). Keep them as floats; only the "
            "pixels are whole."
        ),
        lambda p0, p1, p2: triangle(*(np.round(np.asarray(p, dtype=float)) for p in (p0, p1, p2))),
    ),
    Mistake(
        N_("the vertices made whole"),
        N_(
            "your triangle's vertices were cut to whole numbers (int() or a cast) before "
            "filling: a vertex at (0.7, 0.2) moved to (0, 0). Keep them as floats; only the "
            "pixels are whole."
        ),
        lambda p0, p1, p2: triangle(*(np.trunc(np.asarray(p, dtype=float)) for p in (p0, p1, p2))),
    ),
    Mistake(
        N_("the bottom row filled"),
        N_(
            "your rows run over [y_top, y_bottom], the last one included: a row of centres "
            "exactly on a flat bottom edge belongs to the triangle below. Take the rows over "
            "[y_top, y_bottom)."
        ),
        bottom_row_filled,
    ),
    Mistake(
        N_("the rule mirrored"),
        N_(
            "you include a centre on a right edge and leave out one on a left edge: the rule "
            "mirrored, x_left < x <= x_right. Two triangles still share the edge fairly, but "
            "every other triangle of the mesh uses the lesson's rule: [x_left, x_right)."
        ),
        lambda p0, p1, p2: unless_same(mirrored_rule, open_rule, p0, p1, p2),
        matches=same_or_nothing,
    ),
    Mistake(
        N_("every edge open"),
        N_(
            "you leave out every centre that lies on an edge, so two triangles sharing that "
            "edge would both skip it: a crack. Include the left and the top ones: "
            "[x_left, x_right), rows over [y_top, y_bottom)."
        ),
        lambda p0, p1, p2: unless_same(open_rule, mirrored_rule, p0, p1, p2),
        matches=same_or_nothing,
    ),
    Mistake(
        N_("a centre on a left edge left out"),
        N_(
            "you leave out a centre that lies exactly on a left edge (x_left < x): the left "
            "edge is included and the right one left out, x_left <= x < x_right, so that two "
            "triangles sharing an edge paint each of its centres once."
        ),
        open_rule,
    ),
    Mistake(
        N_("pixel corners for centres"),
        N_(
            "you tested the pixel's corner (x, y), not its centre (x + 0.5, y + 0.5): the "
            "whole triangle is off by half a pixel, up and left."
        ),
        corners_inside,
    ),
)
