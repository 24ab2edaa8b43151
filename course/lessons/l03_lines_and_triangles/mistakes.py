"""The wrong fills lesson 03's :func:`.check.draw_triangle_filled` names, each reproduced on
the checker's cases.

:data:`FILL_MISTAKES`: every edge closed, the top row left out or the bottom row filled,
vertices rounded or made whole, the rule mirrored, every edge open, the left edges left out,
a pixel corner tested in place of its centre (either corner, under any edge rule), and the
lab report's slopes divided by an edge's height before the test for a flat edge (it raises
ZeroDivisionError). Beside them, the comparisons that tell a mistake from its neighbours,
and :func:`same_pixel_set`, the fill checker's own. The wrong lines are
:mod:`.line_mistakes`'.

Only the checkers call these, with their own cases and the student's answer
as :mod:`.check` has read it, so this module checks none (``UNCHECKED = True``;
the fuzz test skips it).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any

import numpy as np

from course.check.base import Mistake, same_pixels
from course.i18n import N_
from course.raster import triangle

UNCHECKED = True  # see the module docstring

__all__ = [
    "FILL_MISTAKES",
    "bottom_row_filled",
    "corners_inside",
    "far_corners_inside",
    "left_edges_open",
    "mirrored_rule",
    "open_rule",
    "same_or_nothing",
    "same_pixel_set",
    "slopes_before_the_flat_test",
    "top_row_left_out",
    "unless_same",
]


def same_pixel_set(expected: np.ndarray, given: np.ndarray) -> bool:
    """Whether two (K, 2) arrays hold the same pixels, each as often, in any order."""

    def ordered(pixels: np.ndarray) -> np.ndarray:
        return pixels[np.lexsort((pixels[:, 0], pixels[:, 1]))]

    return given.shape == expected.shape and np.array_equal(ordered(given), ordered(expected))


def corners_inside(p0: Any, p1: Any, p2: Any, rule: str = "top-left") -> np.ndarray:
    """The pixels whose corner (x, y), not centre, is inside, under ``rule`` (a rule of
    :func:`course.raster.triangle`, or ``"mirrored"``, :func:`mirrored_rule`'s).

    Corner (x, y) of the triangle is centre (x + 0.5, y + 0.5) of the triangle moved half a
    pixel right and down: the fill of that triangle.
    """
    return _fill(rule, *(np.add(np.asarray(p, dtype=float), 0.5) for p in (p0, p1, p2)))


def far_corners_inside(p0: Any, p1: Any, p2: Any, rule: str = "top-left") -> np.ndarray:
    """The pixels whose far corner (x + 1, y + 1), not centre, is inside, under ``rule``."""
    return _fill(rule, *(np.subtract(np.asarray(p, dtype=float), 0.5) for p in (p0, p1, p2)))


def _fill(rule: str, p0: Any, p1: Any, p2: Any) -> np.ndarray:
    return mirrored_rule(p0, p1, p2) if rule == "mirrored" else triangle(p0, p1, p2, rule=rule)


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


def left_edges_open(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The lesson's rule with left edges left out too: x_left < x < x_right, top edges in.

    A centre is in when both the lesson's rule and its mirror take it: each takes the top
    edges and leaves out the bottom ones, and between them they leave out the left and the
    right edges.
    """
    rule = np.asarray(triangle(p0, p1, p2), dtype=np.int64).reshape(-1, 2)
    mirrored = mirrored_rule(p0, p1, p2)
    keep = (rule[:, None, :] == mirrored[None, :, :]).all(axis=2).any(axis=1)
    return rule[keep]


def unless_same(
    rule: Callable[..., Any],
    other: Callable[..., Any] | tuple[Callable[..., Any], ...],
    p0: Any,
    p1: Any,
    p2: Any,
) -> np.ndarray | None:
    """``rule``'s pixels when this case tells them from ``other``'s (each of them, if a tuple);
    None when it cannot."""
    pixels = rule(p0, p1, p2)
    others = other if isinstance(other, tuple) else (other,)
    if any(same_pixels(pixels, neighbour(p0, p1, p2)) for neighbour in others):
        return None
    return pixels


def same_or_nothing(answer: Any, given: Any) -> bool:
    """Whether a mistake gave an answer for this case, and ``given`` is that answer."""
    return answer is not None and same_pixel_set(
        np.asarray(answer, dtype=np.int64).reshape(-1, 2), given
    )


def slopes_before_the_flat_test(p0: Any, p1: Any, p2: Any) -> np.ndarray:
    """The lab report's fill: each edge's slope, dx / dy, divided before the test for a flat
    edge. A flat top or bottom (two corners at one y) raises ZeroDivisionError; any other
    triangle is filled right."""
    top, middle, bottom = sorted(
        ((float(x), float(y)) for x, y in (p0, p1, p2)), key=lambda p: p[1]
    )
    for (xa, ya), (xb, yb) in ((top, middle), (middle, bottom), (top, bottom)):
        (xb - xa) / (yb - ya)  # the slope the report computes first: no test before it
    return triangle(p0, p1, p2)


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
        lambda p0, p1, p2: unless_same(mirrored_rule, (open_rule, left_edges_open), p0, p1, p2),
        matches=same_or_nothing,
    ),
    Mistake(
        N_("every edge open"),
        N_(
            "you leave out every centre that lies on an edge, so two triangles sharing that "
            "edge would both skip it: a crack. Include the left and the top ones: "
            "[x_left, x_right), rows over [y_top, y_bottom)."
        ),
        lambda p0, p1, p2: unless_same(open_rule, (mirrored_rule, left_edges_open), p0, p1, p2),
        matches=same_or_nothing,
    ),
    Mistake(
        N_("a centre on a left edge left out"),
        N_(
            "you leave out a centre that lies exactly on a left edge (x_left < x): the left "
            "edge is included and the right one left out, x_left <= x < x_right, so that two "
            "triangles sharing an edge paint each of its centres once."
        ),
        left_edges_open,
    ),
    *(
        Mistake(
            N_("pixel corners for centres"),
            N_(
                "you tested the pixel's corner (x, y), not its centre (x + 0.5, y + 0.5): your "
                "pixels are those of the triangle moved half a pixel right and down. Test the "
                "centre: the row of centres at y = row + 0.5, and a span from "
                "ceil(x_left - 0.5)."
            ),
            partial(corners_inside, rule=rule),
        )
        for rule in ("top-left", "closed", "open", "mirrored")
    ),
    *(
        Mistake(
            N_("pixel corners for centres"),
            N_(
                "you tested the pixel's far corner (x + 1, y + 1), not its centre "
                "(x + 0.5, y + 0.5): your pixels are those of the triangle moved half a pixel "
                "left and up. Test the centre: the row of centres at y = row + 0.5."
            ),
            partial(far_corners_inside, rule=rule),
        )
        for rule in ("top-left", "closed", "open", "mirrored")
    ),
    Mistake(
        N_("the slopes divided before the flat-edge test"),
        N_(
            "the slopes are divided by the height before testing for a flat edge: a flat top "
            "or a flat bottom has an edge of height 0 (two corners at the same y), and dx / dy "
            "on it divides by zero, as the lab report warns. Test first: a half of zero height "
            "holds no row, so skip it before computing its slopes."
        ),
        slopes_before_the_flat_test,
        raises=ZeroDivisionError,
    ),
)
