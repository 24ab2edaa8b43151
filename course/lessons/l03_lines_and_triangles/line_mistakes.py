"""The wrong lines lesson 03's :func:`.check.draw_line` names, each reproduced on its cases.

:data:`LINE_MISTAKES`: a 4-connected staircase, told by its cause where the pixels show it
(the lab report's loop, or a float t stepped finely with the repeated pixels dropped), a
line drawn backwards or short of an end, a single pixel (p0 == p1) left empty, coordinates
truncated; the lesson's pseudocode with a slip: used as is (the first octant only), without
the steep swap, with the swap not undone when plotting, or with ``D -= dx`` for
``D -= 2 dx``; and every pixel returned as (y, x). Beside them, the comparisons that tell a
mistake from its neighbours, and :func:`is_bresenham_line`, the checker's own.

Only the checker calls these, with its own cases and the student's answer as :mod:`.check`
has read it, so this module checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from functools import partial
from typing import Any

import numpy as np

from course.check.base import Mistake
from course.i18n import N_
from course.raster import line, line_4connected

UNCHECKED = True  # see the module docstring

__all__ = [
    "LINE_MISTAKES",
    "crosses_the_line_only",
    "fine_t_steps",
    "first_octant_only",
    "is_bresenham_line",
    "is_staircase",
    "lesson_loop",
    "one_pixel_left_empty",
    "ordered_same",
    "report_staircase",
    "separate_steps",
    "short_of",
    "transposed",
    "transposed_line",
    "truncated_steps",
]


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


def lesson_loop(
    p0: Any,
    p1: Any,
    *,
    steep_swap: bool = True,
    swap_back: bool = True,
    step_back: int = 2,
    step_at_zero: bool = False,
) -> list[tuple[int, int]]:
    """The lesson's pseudocode in all eight octants, as a student extends it, with a slip if
    asked: a steep line swaps x and y of its ends (unless not ``steep_swap``) and each pixel
    back when plotted (unless not ``swap_back``); a line going left or up steps by -1; when y
    steps, ``D`` goes back by ``step_back`` dx (2 in the lesson). y steps when D > 0, or
    D >= 0 if ``step_at_zero`` (a tie broken the other way).

    Examples
    --------
    >>> lesson_loop((2, 3), (4, 11), steep_swap=False)
    [(2, 3), (3, 4), (4, 5)]
    """
    (x0, y0), (x1, y1) = (int(v) for v in p0), (int(v) for v in p1)
    steep = steep_swap and abs(y1 - y0) > abs(x1 - x0)
    if steep:
        x0, y0, x1, y1 = y0, x0, y1, x1
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx, sy = (1 if x1 >= x0 else -1), (1 if y1 >= y0 else -1)
    decision, y, pixels = 2 * dy - dx, y0, []
    for x in range(x0, x1 + sx, sx):
        pixels.append((y, x) if steep and swap_back else (x, y))
        if decision > 0 or (step_at_zero and decision == 0):
            y += sy
            decision -= step_back * dx
        decision += 2 * dy
    return pixels


def one_pixel_left_empty(p0: Any, p1: Any) -> Any:
    """The right line, but no pixel at all when p0 == p1."""
    return [] if tuple(p0) == tuple(p1) else line(p0, p1)


def short_of(end: str, p0: Any, p1: Any) -> Any:
    """The right line without its ``end`` pixel ("first" or "last"); None when p0 == p1, whose
    one pixel is both ends (:func:`one_pixel_left_empty` names that)."""
    if tuple(p0) == tuple(p1):
        return None
    return line(p0, p1)[1:] if end == "first" else line(p0, p1)[:-1]


def transposed(p0: Any, p1: Any) -> Any:
    """The right line with every pixel given as (y, x)."""
    return line(p0, p1)[:, ::-1]


def transposed_line(answer: Any, given: Any) -> bool:
    """Whether ``given``, each pixel's x and y swapped back, is a right line between the ends of
    ``answer`` swapped back (a line given as (y, x)), ties broken either way."""
    if answer is None:
        return False
    want = np.asarray(answer, dtype=float).reshape(-1, 2)[:, ::-1]
    have = np.asarray(given, dtype=float)
    if have.ndim != 2 or have.shape[1:] != (2,) or len(want) == 0:
        return False
    return is_bresenham_line(want, have[:, ::-1])


def is_bresenham_line(expected: np.ndarray, given: np.ndarray) -> bool:
    """Whether ``given`` is a right line between ``expected``'s ends: one pixel per step along
    the longer axis, from p0 to p1, each an 8-neighbour of the one before, every one within
    half a pixel of the ideal line along the shorter axis (a tie either way).

    Examples
    --------
    >>> is_bresenham_line(np.array([[0, 0], [1, 0], [2, 1]]), np.array([[0, 0], [1, 1], [2, 1]]))
    True
    """
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
            "report's loop, whose one test if (err2 > -dy) ... else ... steps y only when it "
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
        N_("a single pixel left empty"),
        N_(
            "when p0 == p1 the line is one pixel, p0 itself, and you returned none: a line "
            "includes both end pixels, here the same one. Return [p0]."
        ),
        one_pixel_left_empty,
        matches=ordered_same,
    ),
    Mistake(
        N_("the last pixel missing"),
        N_("your loop stops one pixel before p1: a line includes both end pixels."),
        partial(short_of, "last"),
        matches=ordered_same,
    ),
    Mistake(
        N_("the first pixel missing"),
        N_("your line starts one pixel after p0: paint p0 before the first step."),
        partial(short_of, "first"),
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
        N_("no swap for a steep line"),
        N_(
            "your line is right while |dy| <= |dx|, but a steep line takes one pixel per "
            "column, |dx| + 1 in all, where it needs one per row, |dy| + 1: your loop steps x "
            "every time, and y at most once per x. When |dy| > |dx|, swap the roles of x and y: "
            "swap x and y of both ends before the loop, and each pixel back, (y, x), when you "
            "plot it."
        ),
        partial(lesson_loop, steep_swap=False),
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
    Mistake(
        N_("the steep swap not undone"),
        N_(
            "your steep lines come out mirrored in the diagonal: for a steep line you swapped x "
            "and y of the ends, as you should, but plotted the swapped loop's (x, y). Swap each "
            "pixel back when you plot it: (y, x) when the line is steep."
        ),
        partial(lesson_loop, swap_back=False),
        matches=transposed_line,
    ),
    Mistake(
        N_("pixels as (y, x)"),
        N_(
            "your pixels are (y, x), the line mirrored in the diagonal: a pixel is (x, y), x "
            "first, as p0 and p1 are (an image is indexed image[y, x], but the list holds "
            "(x, y))."
        ),
        transposed,
        matches=transposed_line,
    ),
    *(
        Mistake(
            N_("D stepped back by dx, not 2 dx"),
            N_(
                "your y steps too often: when y steps, your D goes back by dx. D is the distance "
                "past the middle times 2 dx, so a step of one whole row takes 2 dx off it: "
                "D = D - 2 dx, as in the lesson's loop (each step of x adds 2 dy)."
            ),
            partial(lesson_loop, step_back=1, step_at_zero=at_zero),
            matches=ordered_same,
        )
        for at_zero in (False, True)  # y stepping at D > 0, as the lesson, or at D >= 0
    ),
)
