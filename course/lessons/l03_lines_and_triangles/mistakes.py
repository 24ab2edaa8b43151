"""The known mistakes lesson 03's checkers name, each reproduced on the checker's cases.

:data:`LINE_MISTAKES` are the wrong lines :func:`.check.draw_line` names: a 4-connected
staircase, told by its cause where the pixels show it (the lab report's loop, or a float t
stepped finely with the repeated pixels dropped), a line drawn backwards or short of an end,
coordinates truncated, the lesson's first-octant pseudocode used as is.
:data:`FILL_MISTAKES` are the wrong fills :func:`.check.draw_triangle_filled` names: every
edge closed, the top row left out or the bottom row filled, vertices rounded or made whole,
the rule mirrored, every edge open, the left edges left out, and a pixel corner tested in
place of its centre (either corner, under any edge rule). Beside them, the comparisons that
tell a mistake from its neighbours, and :func:`same_pixel_set`, the fill checker's own.

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
from course.raster import line, line_4connected, triangle

UNCHECKED = True  # see the module docstring

__all__ = [
    "FILL_MISTAKES",
    "LINE_MISTAKES",
    "bottom_row_filled",
    "corners_inside",
    "crosses_the_line_only",
    "far_corners_inside",
    "fine_t_steps",
    "first_octant_only",
    "is_staircase",
    "left_edges_open",
    "mirrored_rule",
    "open_rule",
    "ordered_same",
    "report_staircase",
    "same_or_nothing",
    "same_pixel_set",
    "separate_steps",
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


def fine_t_steps(p0: Any, p1: Any, steps_per_pixel: int = 64) -> list[tuple[int, int]]:
    """A float t stepped finely from 0 to 1, each point rounded, a pixel kept when it is new.

    The samples visit every pixel the ideal line passes through, in order, and where the line
    leaves a pixel through a side, the next pixel shares that side: a 4-connected staircase.
    """
    (x0, y0), (x1, y1) = (int(v) for v in p0), (int(v) for v in p1)
    count = steps_per_pixel * max(abs(x1 - x0), abs(y1 - y0), 1)
    pixels: list[tuple[int, int]] = []
    for k in range(count + 1):
        t = k / count
        pixel = (round(x0 + t * (x1 - x0)), round(y0 + t * (y1 - y0)))
        if not pixels or pixels[-1] != pixel:
            pixels.append(pixel)
    return pixels


def separate_steps(p0: Any, p1: Any) -> list[tuple[int, int]]:
    """Bresenham's two tests, with a pixel painted after each step: x, then y.

    Where both tests call for a step, the diagonal step becomes two and the pixel between them,
    in the corner, is painted too.
    """
    (x, y), (x1, y1) = (int(v) for v in p0), (int(v) for v in p1)
    dx, dy = abs(x1 - x), abs(y1 - y)
    sx, sy = (1 if x1 >= x else -1), (1 if y1 >= y else -1)
    error, pixels = dx - dy, [(x, y)]
    while (x, y) != (x1, y1):
        doubled = 2 * error
        if doubled > -dy:
            error, x = error - dy, x + sx
            pixels.append((x, y))
        if doubled < dx:
            error, y = error + dx, y + sy
            pixels.append((x, y))
    return pixels


def crosses_the_line_only(answer: Any, given: Any) -> bool:
    """Whether ``given`` is a path of more pixels than a line has, each touched by the ideal line.

    ``answer`` is :func:`fine_t_steps`' line, whose first and last pixels are p0 and p1. The
    path must run from p0 to p1, each pixel a neighbour of the one before (by a side or a
    corner), and the segment between the two end centres must touch every pixel's square
    (edges included): what a line sampled more finely than its pixels gives, whatever the
    step and however its ties were rounded.
    """
    want = np.asarray(answer, dtype=np.int64).reshape(-1, 2)
    have = np.asarray(given, dtype=float)
    if have.ndim != 2 or have.shape[1:] != (2,) or len(want) == 0:
        return False
    (x0, y0), (x1, y1) = want[0], want[-1]
    if len(have) <= max(abs(x1 - x0), abs(y1 - y0)) + 1:
        return False  # as many pixels as a line has: not a staircase
    if tuple(have[0]) != (x0, y0) or tuple(have[-1]) != (x1, y1):
        return False
    steps = np.abs(np.diff(have, axis=0))
    if not ((steps.max(axis=1) == 1) & (steps.sum(axis=1) <= 2)).all():
        return False
    # Doubled, every coordinate below is a whole number: the test is exact.
    xs, ys = 2 * have[:, 0], 2 * have[:, 1]
    in_box = (
        (xs + 1 >= 2 * min(x0, x1))
        & (xs - 1 <= 2 * max(x0, x1))
        & (ys + 1 >= 2 * min(y0, y1))
        & (ys - 1 <= 2 * max(y0, y1))
    )
    dx, dy = 2 * (x1 - x0), 2 * (y1 - y0)
    sides = np.stack(
        [dx * (ys + oy - 2 * y0) - dy * (xs + ox - 2 * x0) for ox in (-1, 1) for oy in (-1, 1)]
    )
    straddles = (sides.min(axis=0) <= 0) & (sides.max(axis=0) >= 0)
    return bool((in_box & straddles).all())


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
            "every step of your line moves in x or in y, never both: your pixels are the lab "
            "report's loop, whose one test, if (err2 > -dy) ... else ..., steps y only when it "
            "does not step x. Each diagonal step became two, with an extra pixel in the corner: "
            "a 4-connected staircase. Test both errors, each with its own if, so that a step "
            "moves diagonally when both call for it: a line has max(|dx|, |dy|) + 1 pixels, "
            "not |dx| + |dy| + 1."
        ),
        report_staircase,
        matches=ordered_same,
    ),
    Mistake(
        N_("every pixel the line crosses"),
        N_(
            "your pixels are every pixel the ideal line passes through, in order, as a float t "
            "stepped finely from 0 to 1 gives when each repeated pixel is dropped: where the "
            "line passes from one row to the next within a column, both pixels are kept, so "
            "your line is a 4-connected staircase of |dx| + |dy| + 1 pixels. A line takes one "
            "pixel per step along its longer axis: n = max(|dx|, |dy|) steps, t = i / n, the "
            "other coordinate rounded; or Bresenham's error term."
        ),
        fine_t_steps,
        matches=crosses_the_line_only,
    ),
    Mistake(
        N_("a 4-connected staircase"),
        N_(
            "every step of your line moves in x or in y, never both, so each diagonal step "
            "became two and left an extra pixel in the corner: a 4-connected staircase of "
            "|dx| + |dy| + 1 pixels. Decide both steps first, then paint once, so that a step "
            "moves diagonally when both call for it: a line has max(|dx|, |dy|) + 1 pixels."
        ),
        separate_steps,
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
)
